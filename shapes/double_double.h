// Private: exact sums and products of doubles as unevaluated pairs hi + lo (Dekker, "A floating-point
// technique for extending the available precision", 1971; Knuth's TwoSum), and the number type built
// on them that the extended-precision fallbacks compute in (the algorithms of Hida, Li and Bailey,
// "Library for double-double and quad-double arithmetic", 2007). Plain double operations only: they
// give the same bits on every IEEE machine that rounds to nearest, provided the compiler does not fuse
// a multiply and an add (the library builds with -ffp-contract=off).
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace collide2d::detail {

// hi + lo. The operators below take and give normalized pairs, |lo| <= ulp(hi) / 2, with a relative
// error within 2^-103 (test_elementary measures them), over magnitudes from 2^-960 to 2^990; an
// infinite or NaN result is carried in hi, with lo 0. Mixed with doubles as long double would be.
struct DoubleDouble {
  double hi = 0;
  double lo = 0;

  constexpr DoubleDouble() = default;
  constexpr DoubleDouble(double x) : hi(x) {}  // NOLINT: implicit, as a double widens to long double
  constexpr DoubleDouble(double h, double l) : hi(h), lo(l) {}
  constexpr explicit operator double() const { return hi + lo; }
};

// Whether x is finite, in a form constant expressions accept (std::isfinite is not constexpr).
constexpr bool finite(double x) { return x - x == 0; }

// a + b exactly, for any a and b (Knuth).
constexpr DoubleDouble two_sum(double a, double b) {
  const double s = a + b;
  const double b_part = s - a;
  const double a_part = s - b_part;
  return {s, (a - a_part) + (b - b_part)};
}

// a + b exactly, given |a| >= |b| or a = 0 (Dekker).
constexpr DoubleDouble fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

// a as hi + lo with 26 significant bits each, so that their products are exact (Dekker's split;
// |a| below 2^996).
constexpr DoubleDouble split(double a) {
  const double t = 134217729.0 * a;  // 2^27 + 1
  const double hi = t - (t - a);
  return {hi, a - hi};
}

// a * b exactly, when neither the product nor its parts underflow or overflow (Dekker).
constexpr DoubleDouble two_product(double a, double b) {
  const double p = a * b;
  const DoubleDouble x = split(a), y = split(b);
  return {p, ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo};
}

constexpr DoubleDouble operator-(const DoubleDouble& a) { return {-a.hi, -a.lo}; }

// The accurate sum: both parts' errors kept, so that cancelling operands lose nothing.
constexpr DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
  const DoubleDouble s = two_sum(a.hi, b.hi);
  if (!finite(s.hi)) return {s.hi, 0};
  const DoubleDouble t = two_sum(a.lo, b.lo);
  const DoubleDouble u = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(u.hi, u.lo + t.lo);
}
constexpr DoubleDouble operator-(const DoubleDouble& a, const DoubleDouble& b) { return a + -b; }

constexpr DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
  const DoubleDouble p = two_product(a.hi, b.hi);
  if (!finite(p.hi)) return {p.hi, 0};
  return fast_two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

// The double quotient and a second one of its remainder, computed exactly.
constexpr DoubleDouble operator/(const DoubleDouble& a, const DoubleDouble& b) {
  const double q1 = a.hi / b.hi;
  if (!finite(q1) || q1 == 0) return {q1, 0};
  const DoubleDouble p = two_product(q1, b.hi);
  const double q2 = ((a.hi - p.hi) - p.lo + a.lo - q1 * b.lo) / b.hi;
  return fast_two_sum(q1, q2);
}

constexpr DoubleDouble& operator+=(DoubleDouble& a, const DoubleDouble& b) { return a = a + b; }
constexpr DoubleDouble& operator-=(DoubleDouble& a, const DoubleDouble& b) { return a = a - b; }
constexpr DoubleDouble& operator*=(DoubleDouble& a, const DoubleDouble& b) { return a = a * b; }
constexpr DoubleDouble& operator/=(DoubleDouble& a, const DoubleDouble& b) { return a = a / b; }

// Normalized pairs order as their high parts, then their low parts; NaN compares false.
constexpr bool operator==(const DoubleDouble& a, const DoubleDouble& b) { return a.hi == b.hi && a.lo == b.lo; }
constexpr bool operator<(const DoubleDouble& a, const DoubleDouble& b) {
  return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo);
}
constexpr bool operator<=(const DoubleDouble& a, const DoubleDouble& b) {
  return a.hi < b.hi || (a.hi == b.hi && a.lo <= b.lo);
}
constexpr bool operator>(const DoubleDouble& a, const DoubleDouble& b) { return b < a; }
constexpr bool operator>=(const DoubleDouble& a, const DoubleDouble& b) { return b <= a; }

constexpr DoubleDouble abs(const DoubleDouble& a) { return a.hi < 0 ? -a : a; }

// The double root, corrected by one Newton step on the exact residual.
inline DoubleDouble sqrt(const DoubleDouble& a) {
  const double x = std::sqrt(a.hi);
  if (!(a.hi > 0) || !finite(a.hi)) return {x, 0};
  const DoubleDouble p = two_product(x, x);
  return fast_two_sum(x, ((a.hi - p.hi) - p.lo + a.lo) / (2 * x));
}

}  // namespace collide2d::detail

template <>
struct std::numeric_limits<collide2d::detail::DoubleDouble> {
  using T = collide2d::detail::DoubleDouble;
  static constexpr bool is_specialized = true;
  static constexpr bool is_signed = true;
  static constexpr bool is_integer = false;
  static constexpr bool is_exact = false;
  static constexpr bool has_infinity = true;
  static constexpr bool has_quiet_NaN = true;
  static constexpr int digits = 104;
  static constexpr int digits10 = 31;
  static constexpr int radix = 2;
  // The unit of the operators' relative error: the error bounds of the fallbacks are multiples of it.
  static constexpr T epsilon() { return 0x1p-104; }
  static constexpr T min() { return 0x1p-969; }  // the least whose low part is still normal
  static constexpr T max() { return {0x1.fffffffffffffp1023, 0x1.fffffffffffffp969}; }
  static constexpr T lowest() { return -max(); }
  static constexpr T infinity() { return std::numeric_limits<double>::infinity(); }
  static constexpr T quiet_NaN() { return std::numeric_limits<double>::quiet_NaN(); }
};

template <>
struct Eigen::NumTraits<collide2d::detail::DoubleDouble> : Eigen::GenericNumTraits<collide2d::detail::DoubleDouble> {
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 0,
    ReadCost = 2,
    AddCost = 20,
    MulCost = 20
  };
};
