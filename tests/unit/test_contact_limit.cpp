// ContactOptions::max_separation: a pair within the limit gets, to the bit, the contact the query
// without a limit computes; a pair beyond it an empty manifold whose separation is a lower bound
// of the full one and passes the limit. On every pair kind's hard-case families and on random
// pairs whose boxes overlap (as a broad phase hands them over), at limits from deep overlap to far
// apart, and at each pair's own separation.
#include "hard_cases.h"
#include "tools/random.h"

#include <collide2d/kernels.h>
#include <collide2d/query.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace collide2d::testing {
namespace {

bool same_bits(const Contact& x, const Contact& y) {
  if (x.separation != y.separation || x.normal != y.normal || x.point_a != y.point_a || x.point_b != y.point_b ||
      x.manifold_size != y.manifold_size || x.evaluations != y.evaluations)
    return false;
  for (int k = 0; k < x.manifold_size; ++k) {
    const ContactPoint &p = x.manifold[static_cast<std::size_t>(k)], &q = y.manifold[static_cast<std::size_t>(k)];
    if (p.point_a != q.point_a || p.point_b != q.point_b || p.separation != q.separation || p.id != q.id) return false;
  }
  return true;
}

struct Tally {
  int within = 0;
  int beyond = 0;
};

// The limited contact of (a, b) against the full one `full`, with a failure message naming the pair.
void check_limit(const Shape& a, const Shape& b, const Contact& full, double limit, Tally& tally) {
  const Contact c = contact(a, b, {.max_separation = limit});
  const std::string pair = describe(a) + " ; " + describe(b) + " limit " + std::to_string(limit);
  if (c.empty()) {
    ++tally.beyond;
    EXPECT_GT(full.separation, limit) << pair;
    EXPECT_GT(c.separation, limit) << pair;
    // A lower bound, up to the rounding of the two computations.
    const double scale = half_size(a) + half_size(b) + (aabb(a).min - aabb(b).min).norm();
    EXPECT_LE(c.separation, full.separation + 1e-12 * scale) << pair;
  } else {
    ++tally.within;
    EXPECT_TRUE(same_bits(c, full)) << pair << ": " << c.separation << " against " << full.separation;
  }
}

void check_limits(const Shape& a, const Shape& b, double size, Tally& tally) {
  const Contact full = contact(a, b);
  for (const double limit : {-0.5 * size, -1e-3 * size, 0.0, 1e-9 * size, 1e-3 * size, 0.5 * size})
    check_limit(a, b, full, limit, tally);
  // At the pair's own separation the limit keeps it; just below, either answer is right.
  check_limit(a, b, full, full.separation, tally);
  check_limit(a, b, full, std::nextafter(full.separation, -HUGE_VAL), tally);
  EXPECT_FALSE(contact(a, b, {.max_separation = full.separation}).empty());
}

TEST(ContactLimit, HardCaseFamiliesOfEveryPair) {
  const Kind kinds[] = {Kind::rect, Kind::circle, Kind::ellipse};
  Tally tally;
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      for (const Family& f : standard_families(kinds[i], kinds[j])) {
        for (const Case& c : family_cases(f)) check_limits(c.a, c.b, half_size(c.a) + half_size(c.b), tally);
      }
    }
  }
  // Both answers occur: the check above is not vacuous.
  EXPECT_GT(tally.within, 1000);
  EXPECT_GT(tally.beyond, 1000);
}

Shape random_shape(std::mt19937_64& rng, int kind) {
  const tool::Uniform unit(0, 1);
  const auto size = [&] { return 0.05 * std::pow(20.0, unit(rng)); };
  const double y = 4 * unit(rng) - 2;
  const Vec2 centre(4 * unit(rng) - 2, y);
  const double angle = 6.3 * unit(rng);
  if (kind == 0) {
    const double height = size();
    return Rect{centre, Vec2(size(), height), angle};
  }
  if (kind == 1) return Circle{centre, size()};
  const double a = size();
  return Ellipse{centre, a, a / std::pow(100.0, unit(rng)), angle};
}

TEST(ContactLimit, CandidatePairsOfEveryPair) {
  std::mt19937_64 rng(31);
  Tally tally;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int found = 0; found < 2000;) {
        const Shape a = random_shape(rng, i), b = random_shape(rng, j);
        if (!intersects(aabb(a), aabb(b))) continue;
        ++found;
        check_limits(a, b, half_size(a) + half_size(b), tally);
      }
    }
  }
  EXPECT_GT(tally.within, 10000);
  EXPECT_GT(tally.beyond, 10000);
}

TEST(ContactLimit, NanIsRefused) {
  const Shape a = Circle{{0, 0}, 1}, b = Ellipse{{3, 0}, 1, 0.5, 0};
  try {
    contact(a, b, {.max_separation = std::nan("")});
    ADD_FAILURE() << "a NaN limit was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "contact max_separation must not be NaN");
  }
  // Infinite limits are limits: +inf keeps every pair, -inf none.
  EXPECT_FALSE(contact(a, b, {.max_separation = HUGE_VAL}).empty());
  EXPECT_TRUE(contact(a, b, {.max_separation = -HUGE_VAL}).empty());
}

}  // namespace
}  // namespace collide2d::testing
