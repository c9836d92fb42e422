// Private: exact sums and products of doubles as unevaluated pairs hi + lo (Dekker, "A floating-point
// technique for extending the available precision", 1971; Knuth's TwoSum). Plain double operations
// only: they give the same bits on every IEEE machine that rounds to nearest, provided the compiler
// does not fuse a multiply and an add (the library builds with -ffp-contract=off).
#pragma once

namespace collide2d::detail {

struct DoubleDouble {
  double hi = 0;
  double lo = 0;
};

// a + b exactly, for any a and b (Knuth).
inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b;
  const double b_part = s - a;
  const double a_part = s - b_part;
  return {s, (a - a_part) + (b - b_part)};
}

// a + b exactly, given |a| >= |b| or a = 0 (Dekker).
inline DoubleDouble fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

// a as hi + lo with 26 significant bits each, so that their products are exact (Dekker's split;
// |a| below 2^996).
inline DoubleDouble split(double a) {
  const double t = 134217729.0 * a;  // 2^27 + 1
  const double hi = t - (t - a);
  return {hi, a - hi};
}

// a * b exactly, when neither the product nor its parts underflow or overflow (Dekker).
inline DoubleDouble two_product(double a, double b) {
  const double p = a * b;
  const DoubleDouble x = split(a), y = split(b);
  return {p, ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo};
}

}  // namespace collide2d::detail
