// Random numbers that are the same on every platform, for the scenes and workloads the tools, the
// benchmarks and the tests generate. std::mt19937_64 is specified to the bit; the standard
// distributions are not (libstdc++, libc++ and Microsoft's library map its numbers differently).
#pragma once

#include <collide2d/shapes.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string_view>

namespace collide2d::tool {

// A double in [lo, hi), mapped as libstdc++'s std::uniform_real_distribution<double> maps it (the
// generator's 64 bits scaled to [0, 1) and kept below 1, then to the range), so that what was made
// with that library stays the same.
template <class Generator = std::mt19937_64>  // 64 bits a call
double uniform(Generator& rng, double lo, double hi) {
  double u = static_cast<double>(rng()) * 0x1p-64;
  if (u >= 1.0) u = std::nextafter(1.0, 0.0);
  return u * (hi - lo) + lo;
}

// A point whose coordinates are uniform() in [lo, hi) each. It draws y before x: the order GCC
// gives two draws written as the arguments of one call, so that the cases seeded that way keep
// their inputs.
template <class Generator = std::mt19937_64>
Vec2 uniform_point(Generator& rng, double lo, double hi) {
  const double y = uniform(rng, lo, hi);
  return Vec2(uniform(rng, lo, hi), y);
}

// The unit vector at `angle`, from collide2d's own cosine and sine (Orientation::of), not the C
// library's: the same bits everywhere.
inline Vec2 direction(double angle) {
  const Orientation o = Orientation::of(angle);
  return {o.c, o.s};
}

// ln 2 in two parts, the first with its low bits zero so that k ln 2 is exact for the exponents the
// functions below meet (Cody and Waite, "Software Manual for the Elementary Functions").
inline constexpr double kLn2High = 0x1.62e42fee00000p-1, kLn2Low = 0x1.a39ef35793c76p-33;

// e^x and ln x for the generators, in plain double operations, so that what they make is the same
// with every C library (whose exp, log and pow differ in the last bit). Within a few ulps; not for
// the library's results, which use none.
inline double exponential(double x) {
  // x = k ln 2 + r with |r| <= ln 2 / 2; e^r by its Taylor series to r^20 / 20!.
  const double k = std::round(x / 0x1.62e42fefa39efp-1);
  const double r = (x - k * kLn2High) - k * kLn2Low;
  double sum = 1.0;
  for (int n = 20; n >= 1; --n) sum = 1.0 + sum * r / n;
  return std::ldexp(sum, static_cast<int>(k));
}

inline double logarithm(double x) {  // x > 0
  // x = m 2^e with m in [sqrt(1/2), sqrt(2)); ln m = 2 atanh(s), s = (m - 1) / (m + 1), |s| < 0.172,
  // by its series to s^41.
  int e = 0;
  double m = std::frexp(x, &e);
  if (m < 0x1.6a09e667f3bcdp-1) {
    m *= 2;
    --e;
  }
  const double s = (m - 1) / (m + 1), s2 = s * s;
  double sum = 0.0;
  for (int n = 41; n >= 3; n -= 2) sum = (sum + 1.0 / n) * s2;
  return e * kLn2High + (e * kLn2Low + 2 * s * (1 + sum));
}

// A number whose logarithm is uniform in [ln lo, ln hi), 0 < lo < hi.
template <class Generator = std::mt19937_64>
double log_uniform(Generator& rng, double lo, double hi) {
  return exponential(uniform(rng, logarithm(lo), logarithm(hi)));
}

// A seed made from a name, the same on every platform (std::hash is not): 64-bit FNV-1a.
inline std::uint64_t seed_of(std::string_view name) {
  std::uint64_t h = 0xcbf29ce484222325u;
  for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3u;
  return h;
}

// uniform() as an object, where code keeps a range and draws from it many times.
class Uniform {
 public:
  Uniform(double lo, double hi) : lo_(lo), hi_(hi) {}
  template <class Generator>
  double operator()(Generator& rng) const {
    return uniform(rng, lo_, hi_);
  }

 private:
  double lo_, hi_;
};

// An index in [0, n), n > 0, mapped as libstdc++'s std::uniform_int_distribution maps a 64-bit
// generator: Lemire's "Fast Random Integer Generation in an Interval" (the high word of the
// generator's number times n, drawing again where the low word falls in the biased sliver). The
// 128-bit product is formed from 32-bit halves, so that no compiler extension is needed.
template <class Generator = std::mt19937_64>
std::size_t uniform_index(Generator& rng, std::size_t n) {
  const std::uint64_t range = n;
  const auto product = [range](std::uint64_t x, std::uint64_t& low) {
    const std::uint64_t x0 = x & 0xffffffffu, x1 = x >> 32, r0 = range & 0xffffffffu, r1 = range >> 32;
    const std::uint64_t p00 = x0 * r0, p01 = x0 * r1, p10 = x1 * r0, p11 = x1 * r1;
    const std::uint64_t middle = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    low = (middle << 32) | (p00 & 0xffffffffu);
    return p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32);
  };
  std::uint64_t low = 0;
  std::uint64_t high = product(rng(), low);
  if (low < range) {
    const std::uint64_t threshold = (0 - range) % range;
    while (low < threshold) high = product(rng(), low);
  }
  return static_cast<std::size_t>(high);
}

}  // namespace collide2d::tool
