// collide2d's own cosine, sine, arc tangent and hypotenuse (shapes/elementary.h) against
// Boost.Multiprecision: every result must be one of the two doubles around the exact value (an error
// under one ulp), on random arguments over the whole range of doubles and on the hard cases: angles
// nearest multiples of pi/2 (where the reduction cancels most digits), ratios at the arc tangent's
// breakpoints, squares that would overflow or underflow. The special values follow C's functions.
// The double-double cosine and sine must be within 2^-102 of the exact values on the same angles,
// and the double-double operators (shapes/double_double.h) within 2^-103 relative.
#include "shapes/elementary.h"

#include <gtest/gtest.h>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace collide2d {
namespace {

namespace mp = boost::multiprecision;
using Real50 = mp::cpp_bin_float_50;
// Enough bits to reduce the largest double by pi/2 with 250 bits to spare.
using Real1300 = mp::number<mp::cpp_bin_float<1300, mp::digit_base_2>>;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Whether got is one of the two doubles around exact; `worst` keeps the largest error in ulps of
// the double nearest exact.
template <class Real>
bool faithful(double got, const Real& exact, double& worst) {
  const double nearest = static_cast<double>(exact);
  const double ulp = std::nextafter(std::abs(nearest), kInf) - std::abs(nearest);
  worst = std::max(worst, static_cast<double>(abs(Real(got) - exact) / Real(ulp)));
  if (got == nearest) return true;
  const Real n(nearest);
  return exact != n && got == std::nextafter(nearest, exact > n ? kInf : -kInf);
}

// A double with a random 53-bit significand and an exponent in [low, high], of either sign.
double random_double(std::mt19937_64& rng, int low, int high) {
  const double significand = 1.0 + static_cast<double>(rng() >> 12) * 0x1p-52;
  const int exponent = low + static_cast<int>(rng() % static_cast<std::uint64_t>(high - low + 1));
  return (rng() & 1 ? -1.0 : 1.0) * std::ldexp(significand, exponent);
}

// The largest errors seen: of the doubles in ulps, of the double-doubles in units of 2^-102.
struct Worst {
  double ulps = 0;
  double extended = 0;
};

template <class Real>
void expect_cos_sin(double angle, Worst& worst) {
  const detail::CosSin got = detail::cos_sin(angle);
  const Real x(angle), c = cos(x), s = sin(x);
  ASSERT_TRUE(faithful(got.c, c, worst.ulps)) << "cos " << std::hexfloat << angle << " gave " << got.c;
  ASSERT_TRUE(faithful(got.s, s, worst.ulps)) << "sin " << std::hexfloat << angle << " gave " << got.s;
  const detail::ExtendedCosSin wide = detail::cos_sin_extended(angle);
  for (const auto& [value, exact] : {std::pair{wide.c, c}, std::pair{wide.s, s}}) {
    const Real error = abs(Real(value.hi) + Real(value.lo) - exact) * Real(0x1p102);
    worst.extended = std::max(worst.extended, static_cast<double>(error));
  }
}

TEST(Elementary, CosSinAreFaithfulOnAnglesOfGames) {
  std::mt19937_64 rng(1);
  Worst worst;
  for (int k = 0; k < 20000; ++k) expect_cos_sin<Real50>(random_double(rng, -30, 5), worst);
  EXPECT_LT(worst.ulps, 1.0);
  EXPECT_LT(worst.extended, 1.0);
  std::printf("cos and sin, |angle| below 64: largest error %.3f ulp, double-double %.3g x 2^-102\n", worst.ulps,
              worst.extended);
}

// Every exponent up to the largest double reads another stretch of the table of 2/pi.
TEST(Elementary, CosSinAreFaithfulOverTheWholeRange) {
  std::mt19937_64 rng(2);
  Worst worst;
  for (int exponent = 6; exponent <= 1023; exponent += 3) {
    expect_cos_sin<Real1300>(random_double(rng, exponent, exponent), worst);
  }
  expect_cos_sin<Real1300>(std::numeric_limits<double>::max(), worst);
  EXPECT_LT(worst.ulps, 1.0);
  EXPECT_LT(worst.extended, 1.0);
}

// The doubles nearest k pi/2 leave the smallest reduced angles: there the reduction must keep its
// digits. Also the double closest to a multiple of pi/2 of all (Muller, "Elementary Functions",
// chapter 11: 6381956970095103 2^797).
TEST(Elementary, CosSinKeepTheirDigitsNearMultiplesOfHalfPi) {
  const Real50 half_pi = boost::math::constants::half_pi<Real50>();
  Worst worst;
  // Small multiples, and those either side of 2^20, where the reduction changes method.
  std::vector<int> multiples;
  for (int k = 1; k <= 3000; ++k) multiples.push_back(k);
  for (int k = 666544; k <= 668544; ++k) multiples.push_back(k);
  for (const int k : multiples) {
    const double nearest = static_cast<double>(k * half_pi);
    for (const double angle : {nearest, std::nextafter(nearest, 0.0), std::nextafter(nearest, kInf)}) {
      expect_cos_sin<Real50>(angle, worst);
      expect_cos_sin<Real50>(-angle, worst);
    }
  }
  expect_cos_sin<Real1300>(std::ldexp(6381956970095103.0, 797), worst);
  EXPECT_LT(worst.ulps, 1.0);
  EXPECT_LT(worst.extended, 1.0);
}

TEST(Elementary, CosSinOfSpecialValues) {
  EXPECT_EQ(detail::cos_sin(0.0).c, 1.0);
  EXPECT_TRUE(std::signbit(detail::cos_sin(-0.0).s));
  EXPECT_FALSE(std::signbit(detail::cos_sin(0.0).s));
  for (const double bad : {kInf, -kInf, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_TRUE(std::isnan(detail::cos_sin(bad).c));
    EXPECT_TRUE(std::isnan(detail::cos_sin(bad).s));
    EXPECT_TRUE(std::isnan(detail::cos_sin_extended(bad).c.hi));
    EXPECT_TRUE(std::isnan(detail::cos_sin_extended(bad).s.hi));
  }
}

void expect_atan2(double y, double x, double& worst) {
  const double got = detail::arc_tangent(y, x);
  ASSERT_TRUE(faithful(got, Real50(atan2(Real50(y), Real50(x))), worst))
      << "atan2(" << std::hexfloat << y << ", " << x << ") gave " << got;
}

TEST(Elementary, ArcTangentIsFaithful) {
  std::mt19937_64 rng(3);
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    const double x = random_double(rng, -20, 20);
    expect_atan2(random_double(rng, -20, 20), x, worst);
  }
  // Either side of each breakpoint (2i + 1)/16 of the reduction, both octants, all four quadrants.
  for (int i = 0; i < 8; ++i) {
    const double z = (2 * i + 1) / 16.0;
    for (const double r : {z, std::nextafter(z, 0.0), std::nextafter(z, 1.0), 1.0, std::nextafter(1.0, 0.0)}) {
      for (const double sx : {1.0, -1.0}) {
        for (const double sy : {1.0, -1.0}) {
          expect_atan2(sy * r * 3.0, sx * 3.0, worst);
          expect_atan2(sy * 3.0, sx * r * 3.0, worst);
        }
      }
    }
  }
  // Far apart and far from 1: ratios that underflow, magnitudes whose products would.
  for (int k = 0; k < 2000; ++k) {
    const double x = random_double(rng, -1074, 1023);
    expect_atan2(random_double(rng, -1074, 1023), x, worst);
    const double near = x * (1 + static_cast<double>(rng() >> 40) * 0x1p-30);
    if (std::isfinite(near)) expect_atan2(near, x, worst);
  }
  EXPECT_LT(worst, 1.0);
  std::printf("atan2: largest error %.3f ulp\n", worst);
}

// C's atan2 at zeros and infinities (C17 F.10.1.4), compared with its values rounded from 50 digits.
TEST(Elementary, ArcTangentOfSpecialValuesIsCs) {
  const double pi = static_cast<double>(boost::math::constants::pi<Real50>());
  const double half = static_cast<double>(boost::math::constants::half_pi<Real50>());
  const double quarter = static_cast<double>(boost::math::constants::pi<Real50>() / 4);
  const double three_quarters = static_cast<double>(3 * boost::math::constants::pi<Real50>() / 4);
  struct Case {
    double y, x, expected;
  };
  const std::vector<Case> cases{{0.0, 0.0, 0.0},
                                {-0.0, 0.0, -0.0},
                                {0.0, -0.0, pi},
                                {-0.0, -0.0, -pi},
                                {0.0, 2.0, 0.0},
                                {-0.0, 2.0, -0.0},
                                {0.0, -2.0, pi},
                                {-0.0, -2.0, -pi},
                                {2.0, 0.0, half},
                                {-2.0, -0.0, -half},
                                {kInf, 2.0, half},
                                {-kInf, -2.0, -half},
                                {2.0, kInf, 0.0},
                                {-2.0, kInf, -0.0},
                                {2.0, -kInf, pi},
                                {-2.0, -kInf, -pi},
                                {kInf, kInf, quarter},
                                {-kInf, kInf, -quarter},
                                {kInf, -kInf, three_quarters},
                                {-kInf, -kInf, -three_quarters}};
  for (const Case& c : cases) {
    const double got = detail::arc_tangent(c.y, c.x);
    EXPECT_EQ(got, c.expected) << "atan2(" << c.y << ", " << c.x << ")";
    EXPECT_EQ(std::signbit(got), std::signbit(c.expected)) << "atan2(" << c.y << ", " << c.x << ")";
  }
  EXPECT_TRUE(std::isnan(detail::arc_tangent(std::nan(""), 1.0)));
  EXPECT_TRUE(std::isnan(detail::arc_tangent(1.0, std::nan(""))));
}

void expect_hypot(double x, double y, double& worst) {
  const double got = detail::hypotenuse(x, y);
  const Real50 exact = sqrt(Real50(x) * Real50(x) + Real50(y) * Real50(y));
  ASSERT_TRUE(faithful(got, exact, worst)) << "hypot(" << std::hexfloat << x << ", " << y << ") gave " << got;
}

TEST(Elementary, HypotenuseIsFaithfulWithoutOverflowOrUnderflow) {
  std::mt19937_64 rng(4);
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    const double x = random_double(rng, -30, 30);
    expect_hypot(x, random_double(rng, -30, 30), worst);
    const double big = random_double(rng, -1074, 1023);
    expect_hypot(big, random_double(rng, -1074, 1023), worst);
    expect_hypot(big, big * (1 + static_cast<double>(rng() >> 40) * 0x1p-26), worst);
  }
  EXPECT_LT(worst, 1.0);
  std::printf("hypot: largest error %.3f ulp\n", worst);
  // Pythagorean triples at every scale are exact.
  for (int e = -1070; e <= 1020; e += 10) {
    EXPECT_EQ(detail::hypotenuse(std::ldexp(3.0, e), std::ldexp(4.0, e)), std::ldexp(5.0, e)) << e;
  }
  EXPECT_EQ(detail::hypotenuse(kInf, std::nan("")), kInf);
  EXPECT_EQ(detail::hypotenuse(std::nan(""), -kInf), kInf);
  EXPECT_TRUE(std::isnan(detail::hypotenuse(std::nan(""), 1.0)));
  EXPECT_EQ(detail::hypotenuse(-0.0, 0.0), 0.0);
}

// A normalized double-double of either sign with its high part's exponent in [low, high] and a
// random low part.
detail::DoubleDouble random_double_double(std::mt19937_64& rng, int low, int high) {
  const double hi = random_double(rng, low, high);
  const double lo = hi * 0x1p-53 * (static_cast<double>(rng() >> 11) * 0x1p-53 - 0.5);
  return detail::fast_two_sum(hi, lo);
}

Real50 exact(const detail::DoubleDouble& x) { return Real50(x.hi) + Real50(x.lo); }

// The double-double angle of double-double vectors in every quadrant, from a hair off an axis to
// the diagonals, within 2^-102 of the exact angle and of it relatively below 1.
TEST(Elementary, ExtendedArcTangentIsWithinTwoToTheMinus102) {
  std::mt19937_64 rng(6);
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    const detail::DoubleDouble x = random_double_double(rng, -20, 20);
    const detail::DoubleDouble y = random_double_double(rng, -20 - static_cast<int>(rng() % 80), 20);
    for (const auto& [yy, xx] : {std::pair{y, x}, std::pair{x, y}}) {
      const Real50 want = atan2(exact(yy), exact(xx));
      const Real50 error = abs(exact(detail::arc_tangent_extended(yy, xx)) - want);
      const Real50 unit = (abs(want) < 1 ? Real50(abs(want)) : Real50(1)) * Real50(0x1p-102);
      worst = std::max(worst, static_cast<double>(error / unit));
    }
  }
  EXPECT_LT(worst, 1.0);
  std::printf("extended atan2: largest error %.3f of 2^-102\n", worst);
}

// The largest relative error of each operator over random operands, cancelling sums among them.
TEST(DoubleDouble, OperatorsAreWithinTwoToTheMinus103) {
  std::mt19937_64 rng(5);
  double worst[5] = {};
  const auto check = [&](int op, const detail::DoubleDouble& got, const Real50& want) {
    ASSERT_EQ(got.hi, got.hi + got.lo) << "not normalized, operator " << op;
    if (want == 0) return;
    worst[op] = std::max(worst[op], static_cast<double>(abs((exact(got) - want) / want)) * 0x1p104);
  };
  for (int k = 0; k < 100000; ++k) {
    const detail::DoubleDouble a = random_double_double(rng, -40, 40), b = random_double_double(rng, -40, 40);
    // b's high part near a's: the sum cancels most of a's digits.
    const detail::DoubleDouble near =
        detail::fast_two_sum(-a.hi * (1 + static_cast<double>(rng() >> 40) * 0x1p-50), b.lo * 0x1p-40);
    check(0, a + b, exact(a) + exact(b));
    check(0, a + near, exact(a) + exact(near));
    check(1, a - b, exact(a) - exact(b));
    check(2, a * b, exact(a) * exact(b));
    check(3, a / b, exact(a) / exact(b));
    check(4, sqrt(abs(a)), sqrt(abs(exact(a))));
  }
  for (const double w : worst) EXPECT_LT(w, 2.0);
  std::printf("double-double + - * / sqrt: largest relative errors %.3f %.3f %.3f %.3f %.3f x 2^-104\n", worst[0],
              worst[1], worst[2], worst[3], worst[4]);
}

TEST(DoubleDouble, ComparisonsOrderAsTheExactValues) {
  std::mt19937_64 rng(6);
  for (int k = 0; k < 100000; ++k) {
    const detail::DoubleDouble a = random_double_double(rng, -3, 3);
    // Half the pairs share the high part, so the low parts decide.
    const detail::DoubleDouble b =
        k % 2 == 0 ? random_double_double(rng, -3, 3) : detail::fast_two_sum(a.hi, random_double_double(rng, -3, 3).lo);
    const Real50 x = exact(a), y = exact(b);
    ASSERT_EQ(a < b, x < y);
    ASSERT_EQ(a <= b, x <= y);
    ASSERT_EQ(a > b, x > y);
    ASSERT_EQ(a >= b, x >= y);
    ASSERT_EQ(a == b, x == y);
  }
}

// Infinities stay in the high part, as they would in a long double.
TEST(DoubleDouble, InfinitiesAndNaNs) {
  const detail::DoubleDouble inf = std::numeric_limits<detail::DoubleDouble>::infinity();
  EXPECT_EQ((inf / 2).hi, kInf);
  EXPECT_EQ((inf * 3).hi, kInf);
  EXPECT_EQ((inf + 1).hi, kInf);
  EXPECT_EQ((detail::DoubleDouble(1) / inf).hi, 0.0);
  EXPECT_TRUE(detail::DoubleDouble(1e300) < inf);
  EXPECT_TRUE(-inf < detail::DoubleDouble(-1e300));
  EXPECT_TRUE(std::isnan((inf - inf).hi));
  EXPECT_TRUE(std::isnan((detail::DoubleDouble(0) / 0).hi));
  EXPECT_TRUE(std::isnan(sqrt(detail::DoubleDouble(-1)).hi));
  const detail::DoubleDouble nan = std::numeric_limits<detail::DoubleDouble>::quiet_NaN();
  EXPECT_FALSE(nan < 1 || nan > 1 || nan == nan || nan <= 1 || nan >= 1);
}

}  // namespace
}  // namespace collide2d
