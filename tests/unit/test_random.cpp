#include "tools/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

namespace collide2d::tool {
namespace {

// A generator that returns the numbers it is given, in turn.
struct Fixed {
  using result_type = std::uint64_t;
  std::vector<std::uint64_t> values;
  std::size_t next = 0;
  std::uint64_t operator()() { return values[next++]; }
};

// uniform() maps the generator's numbers as libstdc++'s distribution does (where the tests are
// built with it), and stays in [lo, hi) at the generator's extremes.
TEST(Random, UniformIsLibstdcxxsDistributionWrittenOut) {
#ifdef __GLIBCXX__
  std::mt19937_64 ours(42), theirs(42);
  for (int k = 0; k < 100000; ++k) {
    const double lo = k % 7 - 3.0, hi = lo + 0.5 + k % 5;
    ASSERT_EQ(Uniform(lo, hi)(ours), std::uniform_real_distribution<double>(lo, hi)(theirs)) << k;
  }
#endif
  // The largest numbers round to 2^64, a u of 1, which is kept below 1; the smallest give lo.
  Fixed top{{~std::uint64_t{0}, ~std::uint64_t{0}}}, bottom{{0}};
  EXPECT_EQ(uniform(top, 0.0, 1.0), std::nextafter(1.0, 0.0));
  EXPECT_LT(uniform(top, -2.0, 3.0), 3.0);
  EXPECT_EQ(uniform(bottom, -2.0, 3.0), -2.0);
}

// uniform_index() draws the numbers libstdc++'s std::uniform_int_distribution draws, over small and
// large ranges (the large ones reject a draw now and then).
TEST(Random, UniformIndexIsLibstdcxxsDistributionWrittenOut) {
#ifdef __GLIBCXX__
  std::mt19937_64 ours(7), theirs(7);
  const std::size_t sizes[] = {1, 2, 3, 10, 1000, (std::size_t{1} << 32) + 3, (std::size_t{3} << 62) + 1};
  for (int k = 0; k < 100000; ++k) {
    const std::size_t n = sizes[k % std::size(sizes)];
    ASSERT_EQ(uniform_index(ours, n), std::uniform_int_distribution<std::size_t>(0, n - 1)(theirs)) << k;
  }
  EXPECT_EQ(ours(), theirs());  // both drew as many numbers
#endif
}

// Worked by hand: the index is the high word of x * n. With n = 3 the threshold is (2^64 - 3) mod 3
// = 1, so the draw 0 (low word 0) is drawn again; 2^63 * 3 = 2^64 + 2^63 gives 1, and
// (2^64 - 1) * 3 = 2 * 2^64 + (2^64 - 3) gives 2.
TEST(Random, UniformIndexRejectsTheBiasedSliver) {
  Fixed rng{{0, std::uint64_t{1} << 63, ~std::uint64_t{0}}};
  EXPECT_EQ(uniform_index(rng, 3), 1u);
  EXPECT_EQ(rng.next, 2u);
  EXPECT_EQ(uniform_index(rng, 3), 2u);
  EXPECT_EQ(rng.next, 3u);
}

// The generators' e^x and ln x against the C library's (within half an ulp or so, here glibc's):
// within 4 ulps over the range the generators use and far beyond it, and exact where the value is.
TEST(Random, ExponentialAndLogarithmAreWithinAFewUlps) {
  const auto ulps = [](double got, double want) {
    return std::abs(got - want) / (std::nextafter(std::abs(want), INFINITY) - std::abs(want));
  };
  std::mt19937_64 rng(3);
  double worst_exp = 0, worst_log = 0;
  for (int k = 0; k < 100000; ++k) {
    const double x = uniform(rng, -700.0, 700.0);
    worst_exp = std::max(worst_exp, ulps(exponential(x), std::exp(x)));
    const double y = std::ldexp(uniform(rng, 0.5, 1.0), static_cast<int>(uniform(rng, -1000, 1000)));
    worst_log = std::max(worst_log, ulps(logarithm(y), std::log(y)));
  }
  EXPECT_LE(worst_exp, 4.0);
  EXPECT_LE(worst_log, 4.0);
  EXPECT_EQ(exponential(0.0), 1.0);
  EXPECT_EQ(logarithm(1.0), 0.0);
  EXPECT_EQ(logarithm(0.5), -std::log(2.0));
  std::printf("[random] exponential within %.2f ulp, logarithm within %.2f ulp of the C library's\n", worst_exp,
              worst_log);
}

// log_uniform's logarithm is uniform: a tenth of the draws in each tenth of [ln lo, ln hi).
TEST(Random, LogUniformFillsEachDecadeAlike) {
  std::mt19937_64 rng(5);
  int counts[10] = {};
  constexpr int kDraws = 100000;
  for (int k = 0; k < kDraws; ++k) {
    const double v = log_uniform(rng, 1e-5, 1e5);
    ASSERT_GE(v, 1e-5 * (1 - 1e-15));
    ASSERT_LT(v, 1e5);
    ++counts[std::min(9, static_cast<int>((std::log10(v) + 5) / 1.0))];
  }
  for (const int c : counts) EXPECT_NEAR(c, kDraws / 10, 600);  // 6 standard deviations (sqrt(9000) = 95)
}

}  // namespace
}  // namespace collide2d::tool
