#!/usr/bin/env bash
# The link audit (ctest link_audit): the library's object files call none of the C library's
# transcendental functions, whose last bits differ between platforms, and hold no x87 instruction,
# whose 80-bit registers round differently from doubles (docs/determinism.md). The library computes
# its own functions, and its extended precision in double-double.
#
#   bash scripts/check_numerics.sh path/to/libcollide2d.a
set -euo pipefail
library=${1:?usage: check_numerics.sh LIBRARY}
names='sin|cos|tan|sincos|asin|acos|atan|atan2|sinh|cosh|tanh|asinh|acosh|atanh|exp|exp2|expm1|log|log2|log10|log1p|pow|cbrt|hypot|erf|erfc|tgamma|lgamma'
calls=$(nm -u -A "$library" | grep -E " U (${names})[fl]?$" || true)
if [[ -n $calls ]]; then
  echo "the library calls the C library's transcendental functions:"
  echo "$calls"
  exit 1
fi
# Every x87 mnemonic begins with f; no SSE or AVX one does.
x87=$(objdump -d --no-show-raw-insn "$library" |
  awk '/^[0-9a-f]+ <.*>:$/ { name = $2 } $1 ~ /^[0-9a-f]+:$/ && $2 ~ /^f/ { print name, $2 }' | sort | uniq -c)
if [[ -n $x87 ]]; then
  echo "the library holds x87 instructions (count, function, mnemonic):"
  echo "$x87"
  exit 1
fi
echo "no transcendental function of the C library and no x87 instruction in $(basename "$library")"
