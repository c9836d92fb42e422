// Random numbers that are the same on every platform, for the scenes and workloads the tools, the
// benchmarks and the tests generate. std::mt19937_64 is specified to the bit; the standard
// distributions are not (libstdc++, libc++ and Microsoft's library map its numbers differently).
#pragma once

#include <cmath>
#include <random>

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

}  // namespace collide2d::tool
