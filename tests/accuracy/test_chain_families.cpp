// Hard cases for chains against the 50-digit reference: a shape of every moving kind (an ellipse of
// aspect 1e4 among them) grazing the vertex of a hill along a direction inside the vertex's cone, at
// the origin and 1e6 away, at gaps of 1e-3, 1e-9 and 0 of its size and 1e-9 deep; and a capsule and
// a box lying on a floor, exactly along it. Apart, the vertex is the nearest point of both segments,
// so the chain's contact is the segment's exact one: its separation matches the reference's signed
// distance at the segments' own scale. Sunk, the contact is the least way out of the hill's corner,
// no deeper than the way the shape was sunk. Its normal lies in the cone, and at least one of the
// two segments gives it.
#include "core_families.h"
#include "mp_reference.h"
#include "tools/random.h"

#include <collide2d/chain.h>
#include <collide2d/world.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <variant>
#include <vector>

namespace collide2d {
namespace {

using testing::Form;

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

Vec2 right_of(const Vec2& d) { return Vec2(d.y(), -d.x()); }
Vec2 turned(const Vec2& v, double angle) {
  return Vec2(std::cos(angle) * v.x() - std::sin(angle) * v.y(), std::sin(angle) * v.x() + std::cos(angle) * v.y());
}
double cross(const Vec2& p, const Vec2& q) { return p.x() * q.y() - p.y() * q.x(); }

// The shape moved so that its support point along -u lies at `at`.
Shape touching(Shape shape, const Vec2& u, const Vec2& at) {
  const Vec2 shift = at - support(shape, Vec2(-u));
  std::visit([&](auto& x) { x.center += shift; }, shape);
  return shape;
}

struct Hill {
  std::vector<ChainSegment> segments;  // the two that meet at the vertex, in the chain's order
  Vec2 vertex, n1, n2;                 // the vertex and the two segments' normals
};

// A hill turning 0.5 rad to the left at its vertex, segments 2 long, the vertex at `at`.
Hill hill(const Vec2& at) {
  const Vec2 e1(-1, 0), e2 = turned(e1, 0.5);
  const std::vector<Vec2> points{at - 4 * e1, at - 2 * e1, at, at + 2 * e2, at + 4 * e2};
  const std::vector<ChainSegment> segments = chain_segments(points, false);
  // The normals of the segments as rounded, 1e-10 off the ideal at 1e6 from the origin.
  return {segments, at, right_of(segments[0].segment.end.normalized()), right_of(segments[1].segment.end.normalized())};
}

TEST(ChainFamilies, GrazingAConvexVertex) {
  std::mt19937_64 rng(71);
  const tool::Uniform u01(0.0, 1.0);
  const auto random_kind = [&](int kind) -> Shape {
    switch (kind) {
      case 0:
        return testing::random_shape(Form::rect, 1.0, 4.0, rng);
      case 1:
        return testing::random_shape(Form::polygon, 1.0, 4.0, rng);
      case 2:
        return testing::random_shape(Form::capsule, 1.0, 4.0, rng);
      case 3:
        return Circle{Vec2::Zero(), 0.25 + u01(rng)};
      default:
        return Ellipse{Vec2::Zero(), 1.0, 1e-4, 7 * u01(rng)};
    }
  };
  double worst = 0;
  int cases = 0;
  for (const double offset : {0.0, 1e6}) {
    const Hill h = hill(Vec2(offset, 0.75 * offset));
    for (int kind = 0; kind < 5; ++kind) {
      for (const double gap : {1e-3, 1e-9, 0.0, -1e-9}) {
        for (int k = 0; k < 6; ++k) {
          const double angle = 7 * u01(rng);
          const Shape local = placed(random_kind(kind), {Vec2::Zero(), angle}, Orientation::of(angle));
          // A direction inside the cone, away from its edges by a tenth of its width.
          const double t = 0.1 + 0.8 * u01(rng);
          const Vec2 u =
              (std::cos(0.5 * t) * h.n1 + std::sin(0.5 * t) * turned(h.n1, std::acos(-1.0) / 2)).normalized();
          const Shape body = touching(local, u, h.vertex + gap * u);
          const std::string what = std::string(shape_name(body)) + " offset " + std::to_string(offset) + " gap " +
                                   std::to_string(gap) + " case " + std::to_string(k);
          int given = 0;
          for (const ChainSegment& s : h.segments) {
            const Contact c = contact(s, body);
            if (c.empty()) continue;
            ++given;
            // The rounding of the body's placement, at its centre's magnitude.
            const double rho = 16 * kU * (center_of(body).cwiseAbs().maxCoeff() + 4 * reach_of(body));
            if (gap > 0) {
              const double reference = static_cast<double>(reference::signed_distance(s.segment, body).separation);
              const double scale = reach_of(body) + 2.0;
              worst = std::max(worst, std::abs(c.separation - reference) / scale);
              EXPECT_LE(std::abs(c.separation - reference), 16 * kU * scale) << what;
              EXPECT_LE(std::abs(c.separation - gap), rho + 16 * kU * scale) << what;
            } else {
              // Touching, or sunk along u: the least way out of the hill's corner is no deeper.
              EXPECT_GE(c.separation, gap - rho) << what;
              EXPECT_LE(c.separation, rho) << what;
            }
            EXPECT_GE(cross(h.n1, c.normal), -1e-12) << what;
            EXPECT_GE(cross(c.normal, h.n2), -1e-12) << what;
          }
          EXPECT_GE(given, 1) << what;
          ++cases;
        }
      }
    }
  }
  std::printf("[chain families] %d grazing cases, worst |separation - reference| %.2g u of the scale\n", cases,
              worst / kU);
}

// A capsule and a box lying on a floor of two segments, exactly along it, apart by a gap or sunk
// into it, across the vertex between the segments: each segment under the shape gives the floor's
// normal, a manifold of two points along its part, and the gap.
TEST(ChainFamilies, LyingAlongAFloor) {
  const std::vector<Vec2> points{{4, 0}, {2, 0}, {0, 0}, {-2, 0}, {-4, 0}};
  const std::vector<ChainSegment> floor = chain_segments(points, false);
  for (const double gap : {0.25, 0x1p-30, 0.0, -0x1p-10}) {
    for (const double x : {1.0, 0.25, -0.5}) {
      for (const Shape& body : {Shape(Capsule{Vec2(x, 0.25 + gap), 0.75, 0.25, 0.0}),
                                Shape(Rect{Vec2(x, 0.25 + gap), Vec2(0.75, 0.25), 0.0})}) {
        const std::string what =
            std::string(shape_name(body)) + " at " + std::to_string(x) + " gap " + std::to_string(gap);
        int under = 0;
        for (const ChainSegment& s : floor) {
          const Contact c = contact(s, body);
          if (c.empty()) continue;
          ++under;
          EXPECT_EQ(c.separation, gap) << what;
          EXPECT_EQ(c.normal, Vec2(0, 1)) << what;
          EXPECT_EQ(c.manifold_size, 2) << what;
        }
        EXPECT_EQ(under, x - 0.75 < 0.0 && x + 0.75 > 0.0 ? 2 : 1) << what;
      }
    }
  }
}

}  // namespace
}  // namespace collide2d
