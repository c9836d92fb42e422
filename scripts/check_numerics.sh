#!/usr/bin/env bash
# The link audit (ctest link_audit): the library's object files call none of the C library's
# transcendental functions, whose last bits differ between platforms (docs/determinism.md); the
# library computes its own. The one exception is the long double fallback's cosine and sine
# (sincosl with GCC, cosl and sinl with clang), outside the guarantee as docs/determinism.md says.
#
#   bash scripts/check_numerics.sh path/to/libcollide2d.a
set -euo pipefail
library=${1:?usage: check_numerics.sh LIBRARY}
names='sin|cos|tan|sincos|asin|acos|atan|atan2|sinh|cosh|tanh|asinh|acosh|atanh|exp|exp2|expm1|log|log2|log10|log1p|pow|cbrt|hypot|erf|erfc|tgamma|lgamma'
found=$(nm -u -A "$library" | grep -E " U (${names})[fl]?$" | grep -vE ' U (sincosl|cosl|sinl)$' || true)
if [[ -n $found ]]; then
  echo "the library calls the C library's transcendental functions:"
  echo "$found"
  exit 1
fi
echo "no transcendental function of the C library in $(basename "$library")"
