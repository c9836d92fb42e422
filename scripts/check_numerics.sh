#!/usr/bin/env bash
# The link audit (ctest link_audit): the library's object files, every Highway target's code among
# them, call none of the C library's transcendental functions, whose last bits differ between
# platforms; hold no x87 instruction, whose 80-bit registers round differently from doubles; and no
# fused multiply-add or approximate reciprocal or square root, whose results differ between CPUs
# that have them and CPUs that do not (docs/determinism.md). The library computes its own
# functions, and its extended precision in double-double.
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
# The functions and mnemonics matching an extended regular expression, counted.
instructions() {
  objdump -d --no-show-raw-insn "$library" |
    awk -v pattern="$1" '/^[0-9a-f]+ <.*>:$/ { name = $2 } $1 ~ /^[0-9a-f]+:$/ && $2 ~ pattern { print name, $2 }' |
    sort | uniq -c
}
# Every x87 mnemonic begins with f, and no SSE or AVX one does.
for check in 'x87:^f' 'fused multiply-add:^vf(n)?m(add|sub)' 'approximate reciprocal or square root:^v?(rcp|rsqrt)'; do
  found=$(instructions "${check#*:}")
  if [[ -n $found ]]; then
    echo "the library holds ${check%%:*} instructions (count, function, mnemonic):"
    echo "$found"
    exit 1
  fi
done
echo "no transcendental function of the C library, no x87, fused multiply-add or approximate instruction in $(basename "$library")"
