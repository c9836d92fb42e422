// collide2d's own cosine, sine, arc tangent and hypotenuse (shapes/elementary.h) against
// Boost.Multiprecision: every result must be one of the two doubles around the exact value (an error
// under one ulp), on random arguments over the whole range of doubles and on the hard cases: angles
// nearest multiples of pi/2 (where the reduction cancels most digits), ratios at the arc tangent's
// breakpoints, squares that would overflow or underflow. The special values follow C's functions.
#include "shapes/elementary.h"

#include <gtest/gtest.h>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
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

template <class Real>
void expect_cos_sin(double angle, double& worst) {
  const detail::CosSin got = detail::cos_sin(angle);
  const Real x(angle);
  ASSERT_TRUE(faithful(got.c, Real(cos(x)), worst)) << "cos " << std::hexfloat << angle << " gave " << got.c;
  ASSERT_TRUE(faithful(got.s, Real(sin(x)), worst)) << "sin " << std::hexfloat << angle << " gave " << got.s;
}

TEST(Elementary, CosSinAreFaithfulOnAnglesOfGames) {
  std::mt19937_64 rng(1);
  double worst = 0;
  for (int k = 0; k < 20000; ++k) expect_cos_sin<Real50>(random_double(rng, -30, 5), worst);
  EXPECT_LT(worst, 1.0);
  std::printf("cos and sin, |angle| below 64: largest error %.3f ulp\n", worst);
}

// Every exponent up to the largest double reads another stretch of the table of 2/pi.
TEST(Elementary, CosSinAreFaithfulOverTheWholeRange) {
  std::mt19937_64 rng(2);
  double worst = 0;
  for (int exponent = 6; exponent <= 1023; exponent += 3) {
    expect_cos_sin<Real1300>(random_double(rng, exponent, exponent), worst);
  }
  expect_cos_sin<Real1300>(std::numeric_limits<double>::max(), worst);
  EXPECT_LT(worst, 1.0);
}

// The doubles nearest k pi/2 leave the smallest reduced angles: there the reduction must keep its
// digits. Also the double closest to a multiple of pi/2 of all (Muller, "Elementary Functions",
// chapter 11: 6381956970095103 2^797).
TEST(Elementary, CosSinKeepTheirDigitsNearMultiplesOfHalfPi) {
  const Real50 half_pi = boost::math::constants::half_pi<Real50>();
  double worst = 0;
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
  EXPECT_LT(worst, 1.0);
}

TEST(Elementary, CosSinOfSpecialValues) {
  EXPECT_EQ(detail::cos_sin(0.0).c, 1.0);
  EXPECT_TRUE(std::signbit(detail::cos_sin(-0.0).s));
  EXPECT_FALSE(std::signbit(detail::cos_sin(0.0).s));
  for (const double bad : {kInf, -kInf, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_TRUE(std::isnan(detail::cos_sin(bad).c));
    EXPECT_TRUE(std::isnan(detail::cos_sin(bad).s));
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

}  // namespace
}  // namespace collide2d
