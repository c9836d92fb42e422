// Test helpers for the World's unit tests (tests/unit/test_world*.cpp): random shapes, worlds and
// filters, and the checks of its frame-by-frame lists against a scan of every pair and the 50-digit
// reference.
#pragma once

#include <collide2d/world.h>

#include "mp_reference.h"
#include "tools/random.h"
#include "world_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <ostream>
#include <random>
#include <string>
#include <vector>

namespace collide2d {

// gtest prints handles as index:generation.
inline void PrintTo(const BodyId& id, std::ostream* os) { *os << id.index << ':' << id.generation; }

namespace testing {

using Rng = std::mt19937_64;

// began and ended are what `now` gained and lost since `previous`.
template <class Pair>
void expect_changes(const std::vector<Pair>& previous, const std::vector<Pair>& now, const std::vector<Pair>& began,
                    const std::vector<Pair>& ended, const std::string& what) {
  std::vector<Pair> gained, lost;
  std::set_difference(now.begin(), now.end(), previous.begin(), previous.end(), std::back_inserter(gained));
  std::set_difference(previous.begin(), previous.end(), now.begin(), now.end(), std::back_inserter(lost));
  ASSERT_EQ(began, gained) << what;
  ASSERT_EQ(ended, lost) << what;
}

using tool::uniform;
using tool::uniform_point;

inline Shape random_shape(Rng& rng, double spread) {
  const double y = uniform(rng, 0, spread);
  const double x = uniform(rng, 0, spread);
  const Vec2 c(x, y);
  const double size = uniform(rng, 0.1, 1.0);
  switch (static_cast<int>(uniform(rng, 0, 3))) {
    case 0:
      return Circle{c, size};
    case 1:
      return Ellipse{c, size, size * uniform(rng, 0.05, 1.0), uniform(rng, 0, 6.3)};
    default:
      return Rect{c, Vec2(size, size * uniform(rng, 0.1, 1.0)), uniform(rng, 0, 6.3)};
  }
}

// The World's pairs against a scan of every pair (reference::all_pairs); the proximity pairs' distances
// are the narrow phase's (expect_sample_matches_reference checks that narrow phase itself).
inline void expect_matches_all_pairs(const World& world, double margin, const std::string& what) {
  const reference::AllPairs expected = reference::all_pairs(world, margin);
  ASSERT_EQ(world.overlapping(), expected.overlapping) << what;
  ASSERT_EQ(world.sensing(), expected.sensing) << what;
  std::vector<ShapePair> reported;
  for (const Proximity& p : world.proximity()) {
    reported.push_back({p.a, p.b, p.shape_a, p.shape_b});
    ASSERT_EQ(p.result.distance, distance(world.shape(p.shape_a), world.shape(p.shape_b)).distance);
  }
  ASSERT_EQ(reported, expected.near) << what;
}

// The pair of two bodies of one shape each.
inline ShapePair solo_pair(const World& world, BodyId x, BodyId y) {
  return {x, y, world.shapes(x)[0], world.shapes(y)[0]};
}

inline bool has(const std::vector<ShapePair>& sorted, const ShapePair& p) {
  return std::binary_search(sorted.begin(), sorted.end(), p);
}

// Independently of the World's own aabb() and overlaps(): the pairs whose exact boxes (50 digits,
// rounded outward), grown by margin / 2, meet must include every overlapping and proximity pair;
// and a sample of them, half from the World's overlapping pairs, is checked against the 50-digit
// reference: the verdict, and with a margin, the distance and membership of the proximity list.
inline void expect_sample_matches_reference(const World& world, double margin, Rng& rng, const std::string& what) {
  const std::vector<ShapePair> near = reference::exact_box_pairs(world, margin / 2);
  for (const ShapePair& p : world.overlapping()) ASSERT_TRUE(has(near, p)) << what << ": exact boxes apart";
  for (const Proximity& p : world.proximity())
    ASSERT_TRUE(has(near, {p.a, p.b, p.shape_a, p.shape_b})) << what << ": exact boxes apart";
  const auto pick = [&rng](const std::vector<ShapePair>& from) { return from[tool::uniform_index(rng, from.size())]; };
  for (int k = 0; k < 12; ++k) {
    const ShapePair p = k % 2 == 0 && !world.overlapping().empty() ? pick(world.overlapping()) : pick(near);
    const Shape& a = world.shape(p.shape_a);
    const Shape& b = world.shape(p.shape_b);
    ASSERT_EQ(has(world.overlapping(), p), reference::overlap(a, b)) << what << ": " << p.a.index << "-" << p.b.index;
    if (margin == 0 || has(world.overlapping(), p)) continue;
    const double d = static_cast<double>(reference::distance(a, b));
    const auto reported = std::find_if(world.proximity().begin(), world.proximity().end(), [&p](const Proximity& q) {
      return q.shape_a == p.shape_a && q.shape_b == p.shape_b;
    });
    // Within rounding of the margin either answer is right.
    const double scale = 20.0, tolerance = 8 * std::numeric_limits<double>::epsilon() * scale;
    if (std::abs(d - margin) > tolerance) ASSERT_EQ(reported != world.proximity().end(), d <= margin) << what;
    if (reported != world.proximity().end()) ASSERT_NEAR(reported->result.distance, d, tolerance) << what;
  }
}

inline World random_world(Rng& rng, int n) {
  World world;
  for (int k = 0; k < n; ++k) world.add(random_shape(rng, 10.0));
  return world;
}

inline Filter random_filter(Rng& rng) {
  const int groups[] = {0, 0, 0, 1, -1};
  return {.category = std::uint64_t{1} << static_cast<int>(uniform(rng, 0, 3)),
          .mask = static_cast<std::uint64_t>(uniform(rng, 0, 8)),
          .group = groups[static_cast<int>(uniform(rng, 0, 5))]};
}

}  // namespace testing
}  // namespace collide2d
