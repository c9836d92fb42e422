// Box2D as an independent check: for convex shapes the true distance lies between the distance of
// the circumscribed polygon approximations and that of the inscribed ones, and the bracket closes
// on collide2d's value as the polygons get finer. Sharp convex polygons Box2D has exactly: its
// float answers lie within their float error of ours; a capsule it has only as a rounded box that
// holds it, within a known reach.
#include <collide2d/chain.h>
#include <collide2d/query.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>
#include "bench/box2d_baseline.h"
#include "tools/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace collide2d {
namespace {

using baseline::Fit;

std::string describe_pair(const Shape& a, const Shape& b) {
  std::string out;
  for (const Shape* s : {&a, &b}) {
    out += std::string(shape_name(*s)) + " at " + std::to_string(center_of(*s).x()) + " " +
           std::to_string(center_of(*s).y()) + "; ";
  }
  return out;
}

std::vector<std::pair<Shape, Shape>> random_pairs(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const tool::Uniform u(0.0, 1.0);
  const auto ellipse = [&] {
    return Ellipse{tool::uniform_point(rng, 0, 4), 0.2 + u(rng), 0.05 + 0.5 * u(rng), 7 * u(rng)};
  };
  std::vector<std::pair<Shape, Shape>> out;
  for (int k = 0; k < n; ++k) {
    const Shape b = ellipse();
    switch (k % 3) {
      case 0:
        out.emplace_back(ellipse(), b);
        break;
      case 1: {
        const Vec2 c = tool::uniform_point(rng, 0, 4);
        const double height = 0.1 + u(rng);
        out.emplace_back(Rect{c, Vec2(0.1 + u(rng), height), 7 * u(rng)}, b);
        break;
      }
      default:
        out.emplace_back(Circle{tool::uniform_point(rng, 0, 4), 0.1 + u(rng)}, b);
        break;
    }
  }
  return out;
}

// The pair as Box2D polygons (ellipses as N-gons), coordinates taken from A's centre.
std::pair<baseline::Polygon, baseline::Polygon> box2d_pair(const Shape& a, const Shape& b, int sides, Fit fit) {
  const Vec2 origin = center_of(a);
  return {baseline::to_box2d(a, sides, fit, origin), baseline::to_box2d(b, sides, fit, origin)};
}

baseline::ShapePair box2d_shapes(const Shape& a, const Shape& b, int sides, Fit fit) {
  const auto [pa, pb] = box2d_pair(a, b, sides, fit);
  return baseline::to_box2d_shapes(pa, pb);
}

double box2d(const Shape& a, const Shape& b, int sides, Fit fit) {
  const auto [pa, pb] = box2d_pair(a, b, sides, fit);
  return baseline::box2d_distance(pa, pb);
}

// Box2D works in float: its distances carry errors of a few float ulps of the coordinates (here
// below 8, relative to the shared origin).
constexpr double kFloatTolerance = 2e-5;

TEST(Box2dBracket, OurDistanceLiesBetweenCircumscribedAndInscribed) {
  const auto pairs = random_pairs(3000, 11);
  int separated = 0;
  for (const int sides : {8, 32, 128}) {
    int k = 0;
    for (const auto& [a, b] : pairs) {
      const double d = distance(a, b).distance;
      const double outer = box2d(a, b, sides, Fit::circumscribed);
      const double inner = box2d(a, b, sides, Fit::inscribed);
      ASSERT_LE(outer, d + kFloatTolerance) << "pair " << k << " sides " << sides;
      ASSERT_GE(inner, d - kFloatTolerance) << "pair " << k << " sides " << sides;
      separated += d > 0 && sides == 8;
      ++k;
    }
  }
  EXPECT_GT(separated, 1000);
}

// The bracket width falls about as 1/N^2 (the sagitta of a side), and both ends approach our value.
TEST(Box2dBracket, BracketClosesOnOurDistance) {
  const auto pairs = random_pairs(600, 12);
  std::vector<double> widths[2];
  const int sides[2] = {8, 256};
  for (const auto& [a, b] : pairs) {
    const double d = distance(a, b).distance;
    if (d < 0.05) continue;  // keep pairs apart at every N, so the bracket is a pair of distances
    for (int i = 0; i < 2; ++i) {
      const double outer = box2d(a, b, sides[i], Fit::circumscribed);
      const double inner = box2d(a, b, sides[i], Fit::inscribed);
      widths[i].push_back(inner - outer);
      if (i == 1) {
        EXPECT_NEAR(outer, d, 1e-3 * std::max(1.0, d));
        EXPECT_NEAR(inner, d, 1e-3 * std::max(1.0, d));
      }
    }
  }
  ASSERT_GT(widths[0].size(), 200u);
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const double w8 = median(widths[0]), w256 = median(widths[1]);
  std::printf("[box2d bracket] %zu pairs: median width %.3e at N = 8, %.3e at N = 256 (ratio %.0f)\n", widths[0].size(),
              w8, w256, w8 / w256);
  EXPECT_GT(w8 / w256, 100.0);
}

// With radius-0 polygons, b2TestOverlap on the 8-gons agrees with the exact test wherever the
// bracket decides: circumscribed polygons apart means the shapes are apart, inscribed polygons
// overlapping means the shapes overlap.
TEST(Box2dBracket, OverlapOfPolygonsBracketsTheExactVerdict) {
  const auto pairs = random_pairs(3000, 13);
  int decided = 0;
  for (const auto& [a, b] : pairs) {
    const auto outer = box2d_shapes(a, b, 8, Fit::circumscribed);
    const auto inner = box2d_shapes(a, b, 8, Fit::inscribed);
    const bool exact = overlaps(a, b);
    if (!baseline::box2d_overlap(outer)) {  // apart, unless Box2D's float rounding decided it
      EXPECT_FALSE(exact && box2d(a, b, 8, Fit::circumscribed) > kFloatTolerance);
      ++decided;
    }
    if (baseline::box2d_overlap(inner)) {  // overlapping, unless the shapes are within rounding
      EXPECT_TRUE(exact || distance(a, b).distance < kFloatTolerance);
      ++decided;
    }
  }
  EXPECT_GT(decided, 2000);
}

// Contacts. The signed distance only grows when the shapes shrink (s(n) = n.delta - h_A - h_B), so
// Box2D's manifold on the circumscribed N-gons gives a separation at most ours, and on the
// inscribed ones at least ours (b2CollidePolygons: the polygons' exact depth by separating axes).
// Box2D 2.4.1 caps a polygon at b2_maxPolygonVertices = 8, so N runs from 5 to 8 here; the bracket
// narrows about as 1/N^2 ((8/5)^2 = 2.6). Box2D's normal is a polygon face's, off ours by up to
// half a side's turn (pi / N).
TEST(Box2dBracket, ContactDepthLiesBetweenCircumscribedAndInscribed) {
  const auto pairs = random_pairs(3000, 14);
  const int sides[2] = {5, 8};
  std::vector<double> widths[2], turns[2];
  int checked = 0;
  for (const auto& [a, b] : pairs) {
    const Contact c = contact(a, b);
    if (c.separation > -0.05) continue;  // deep enough that the inscribed polygons overlap too
    double width[2];
    bool both = true;
    for (int i = 0; i < 2; ++i) {
      const auto outer = baseline::box2d_contact(box2d_shapes(a, b, sides[i], Fit::circumscribed));
      const auto inner = baseline::box2d_contact(box2d_shapes(a, b, sides[i], Fit::inscribed));
      ASSERT_TRUE(outer) << "circumscribed polygons of an overlapping pair apart";
      ASSERT_LE(outer->separation, c.separation + kFloatTolerance) << "sides " << sides[i];
      if (!inner) {
        both = false;
        continue;
      }
      ASSERT_GE(inner->separation, c.separation - kFloatTolerance) << "sides " << sides[i];
      width[i] = inner->separation - outer->separation;
      turns[i].push_back(std::acos(std::clamp(outer->normal.dot(c.normal), -1.0, 1.0)));
    }
    if (!both) continue;
    for (int i = 0; i < 2; ++i) widths[i].push_back(width[i]);
    ++checked;
  }
  ASSERT_GT(checked, 300);
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  std::printf(
      "[box2d bracket] contacts of %d overlapping pairs: median depth bracket %.3e at N = 5, %.3e at N = 8 "
      "(ratio %.2f); median normal turn %.3e, %.3e rad\n",
      checked, median(widths[0]), median(widths[1]), median(widths[0]) / median(widths[1]), median(turns[0]),
      median(turns[1]));
  EXPECT_GT(median(widths[0]) / median(widths[1]), 2.0);
  EXPECT_LT(median(turns[1]), median(turns[0]));
}

// Times of impact. A polygon inscribed in a shape stays inscribed as both move (it turns with it),
// so the circumscribed polygons meet no later than the shapes, and the inscribed ones no earlier:
// on pairs scaled up 100 times (sizes 5 to 100, closing at 400 to 800 per step), Box2D's
// b2TimeOfImpact on circumscribed N-gons must not come after our time, and on inscribed ones not
// before it, beyond its own target over the closing speed along our normal, and its float rounding.
// Its target is a separation of 0.005 +- 0.00125 between polygons, but with a circle (a radius) the
// separation of the cores reaching the radii less 3 times 0.005: there it stops 0.015 +- 0.00125
// into the overlap, after touching. Translation only:
// Box2D's root finder "may miss some intermediate, non-tunneling collisions" when shapes turn.
TEST(Box2dBracket, TimeOfImpactLiesBetweenCircumscribedAndInscribed) {
  std::mt19937_64 rng(41);
  const tool::Uniform u(0.0, 1.0);
  std::vector<double> widths[2];  // N = 8 and 32
  int checked = 0;
  for (const auto& [a, b] : random_pairs(600, 42)) {
    const double scale = 100;
    const auto scaled = [&](const Shape& s, const Vec2& centre) {
      return std::visit(
          [&](auto x) -> Shape {
            x.center = centre;
            if constexpr (std::is_same_v<decltype(x), Circle>) x.radius *= scale;
            if constexpr (std::is_same_v<decltype(x), Ellipse>) x.a *= scale, x.b *= scale;
            if constexpr (std::is_same_v<decltype(x), Rect>) x.half_extents *= scale;
            return x;
          },
          s);
    };
    const double heading = 6.283185307179586 * u(rng);
    const Vec2 dir(std::cos(heading), std::sin(heading));
    const Shape sa = scaled(a, Vec2::Zero()), sb = scaled(b, (2 + 2 * u(rng)) * scale * dir);
    if (overlaps(sa, sb)) continue;
    const double across = u(rng) - 0.5, along = 4 + 4 * u(rng);
    const Motion mb{-along * scale * dir + across * scale * Vec2(-dir.y(), dir.x()), 0.0};
    const TimeOfImpact ours = time_of_impact(sa, {}, sb, mb);
    if (ours.status != ToiStatus::hit) continue;
    const double closing = std::abs(ours.normal.dot(mb.velocity));
    if (closing < 0.1 * mb.velocity.norm()) continue;  // grazing: Box2D's early stop is not bounded
    const double slack = (0.01625 + 4e-3) / closing;   // its target, and float ulps of coordinates ~400
    double t[2][2];                                    // [N = 8, 32][circumscribed, inscribed]
    for (int n = 0; n < 2; ++n) {
      for (int f = 0; f < 2; ++f) {
        b2TOIOutput out;
        baseline::box2d_time_of_impact(
            baseline::to_box2d_toi(sa, {}, sb, mb, n == 0 ? 8 : 32, f == 0 ? Fit::circumscribed : Fit::inscribed),
            &out);
        t[n][f] = out.state == b2TOIOutput::e_separated ? 1.0 : out.t;
      }
      EXPECT_LE(t[n][0], ours.t + slack) << "circumscribed, N index " << n;
      EXPECT_GE(t[n][1], ours.t - slack) << "inscribed, N index " << n;
      widths[n].push_back(t[n][1] - t[n][0]);
    }
    ++checked;
  }
  ASSERT_GT(checked, 200);
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  std::printf(
      "[box2d bracket] times of impact of %d pairs: median bracket %.3e at N = 8, %.3e at N = 32 (ratio %.1f)\n",
      checked, median(widths[0]), median(widths[1]), median(widths[0]) / median(widths[1]));
  EXPECT_GT(median(widths[0]) / median(widths[1]), 4.0);
}

// Sharp convex polygons of 3 to 8 vertices, 0.5 to 1.5 across (Box2D welds vertices closer than
// 0.0025), against polygons and circles.
std::vector<std::pair<Shape, Shape>> polygon_pairs(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const tool::Uniform u(0.0, 1.0);
  const auto polygon = [&] {
    const int count = 3 + static_cast<int>(u(rng) * 6);
    const double a = 0.5 + u(rng), b = a / (1 + u(rng));
    std::vector<Vec2> v;
    for (int k = 0; k < count; ++k) {
      const double t = 2 * std::numbers::pi * (k + 0.6 * u(rng)) / count;
      v.emplace_back(a * std::cos(t), b * std::sin(t));
    }
    const double angle = 7 * u(rng);
    return ConvexPolygon::of(v).at(tool::uniform_point(rng, 0, 3), angle);
  };
  std::vector<std::pair<Shape, Shape>> out;
  for (int k = 0; k < n; ++k) {
    const Shape a = polygon();
    out.emplace_back(a, k % 2 == 0 ? Shape(polygon()) : Shape(Circle{tool::uniform_point(rng, 0, 3), 0.2 + u(rng)}));
  }
  return out;
}

// Apart, b2Distance is our distance; overlapping, b2CollidePolygonAndCircle's depth is ours, and
// b2CollidePolygons' deepest manifold point is ours where Box2D takes the same reference face and
// the incident face's deepest vertex lies within its side planes; else shallower (Box2D clips it
// away), or deeper by up to 0.1 b2_linearSlop, the margin by which Box2D prefers A's face to B's.
TEST(Box2dBracket, PolygonsMatchBox2dWithinFloatError) {
  int apart = 0, overlapping = 0, deepest_kept = 0, polygon_pairs_overlapping = 0;
  double worst = 0;
  for (const auto& [a, b] : polygon_pairs(4000, 51)) {
    const auto [pa, pb] = box2d_pair(a, b, 8, Fit::inscribed);
    const Contact c = contact(a, b);
    if (c.separation > 0) {
      const double d = baseline::box2d_distance(pa, pb);
      worst = std::max(worst, std::abs(d - c.separation));
      ASSERT_NEAR(d, c.separation, kFloatTolerance) << describe_pair(a, b);
      ++apart;
      continue;
    }
    const auto box2d = baseline::box2d_contact(baseline::to_box2d_shapes(pa, pb));
    if (c.separation > -kFloatTolerance) continue;  // touching to Box2D's rounding: it may keep no point
    ASSERT_TRUE(box2d) << describe_pair(a, b);
    ++overlapping;
    ASSERT_GE(box2d->separation, c.separation - 0.1 * b2_linearSlop - kFloatTolerance) << describe_pair(a, b);
    if (std::holds_alternative<Circle>(b)) {
      worst = std::max(worst, std::abs(box2d->separation - c.separation));
      ASSERT_NEAR(box2d->separation, c.separation, kFloatTolerance) << describe_pair(a, b);
    } else {
      ++polygon_pairs_overlapping;
      deepest_kept += std::abs(box2d->separation - c.separation) <= kFloatTolerance;
    }
  }
  std::printf(
      "[box2d bracket] polygons: %d apart, %d overlapping, worst |difference| %.2e; polygon pairs' deepest "
      "point kept by Box2D in %d of %d\n",
      apart, overlapping, worst, deepest_kept, polygon_pairs_overlapping);
  EXPECT_GT(apart, 1000);
  EXPECT_GT(overlapping, 500);
  EXPECT_GT(deepest_kept, polygon_pairs_overlapping * 9 / 10);
}

// Box2D 2.4.1 has no capsule; its rounded box (bench/box2d_baseline.h) holds the capsule and lies
// within 0.42 w of it (w, the box's half width), so that against any shape Box2D's
// separation lies between ours less that for each capsule and ours, to float error: apart from a
// polygon, a circle or another capsule (b2Distance), overlapping a circle
// (b2CollidePolygonAndCircle).
TEST(Box2dBracket, CapsulesLieWithinBox2dsRoundedBoxes) {
  std::mt19937_64 rng(53);
  const tool::Uniform u(0.0, 1.0);
  const auto capsule = [&] {
    return Capsule{tool::uniform_point(rng, 0, 3), 0.1 + u(rng), 0.05 + 0.5 * u(rng), 7 * u(rng)};
  };
  const auto others = polygon_pairs(3000, 55);
  constexpr double kBoxReach = 0.42 * baseline::kCapsuleBoxHalfWidth;
  int apart = 0, overlapping = 0;
  for (int k = 0; k < 3000; ++k) {
    const Shape a = capsule();
    const Shape placed = k % 3 == 0   ? Shape(capsule())
                         : k % 3 == 1 ? others[k].first
                                      : Shape(Circle{tool::uniform_point(rng, 0, 3), 0.1 + 0.5 * u(rng)});
    const double slack = kBoxReach * (std::holds_alternative<Capsule>(placed) ? 2 : 1);
    const auto [pa, pb] = box2d_pair(a, placed, 8, Fit::inscribed);
    const Contact c = contact(a, placed);
    if (c.separation > 0) {
      const double d = baseline::box2d_distance(pa, pb);
      ASSERT_LE(d, c.separation + kFloatTolerance) << describe_pair(a, placed);
      ASSERT_GE(d, c.separation - slack - kFloatTolerance) << describe_pair(a, placed);
      ++apart;
    } else if (std::holds_alternative<Circle>(placed) && c.separation < -slack - kFloatTolerance) {
      const auto box2d = baseline::box2d_contact(baseline::to_box2d_shapes(pa, pb));
      ASSERT_TRUE(box2d) << describe_pair(a, placed);
      ASSERT_LE(box2d->separation, c.separation + kFloatTolerance) << describe_pair(a, placed);
      ASSERT_GE(box2d->separation, c.separation - slack - kFloatTolerance) << describe_pair(a, placed);
      ++overlapping;
    }
  }
  std::printf("[box2d bracket] capsules: %d apart, %d overlapping circles\n", apart, overlapping);
  EXPECT_GT(apart, 1000);
  EXPECT_GT(overlapping, 100);
}

// A segment is Box2D's two-sided b2EdgeShape, exactly: apart from a polygon or a circle, b2Distance
// is our distance; overlapping a circle, b2CollideEdgeAndCircle's depth is ours; overlapping a
// polygon, b2CollideEdgeAndPolygon's deepest point is ours where it pushes the polygon out on the
// same side and keeps that point (it takes the side of the polygon's centroid, which may be the
// deeper way out, and it may clip the deepest point away).
TEST(Box2dBracket, SegmentsMatchBox2dsEdgesWithinFloatError) {
  std::mt19937_64 rng(57);
  const tool::Uniform u(0.0, 1.0);
  const auto others = polygon_pairs(3000, 59);
  int apart = 0, overlapping = 0, polygons_overlapping = 0, deepest_kept = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec2 p = tool::uniform_point(rng, 0, 3);
    const Shape a = Segment::between(p, p + tool::uniform_point(rng, -2, 2));
    const Shape placed =
        k % 2 == 0 ? others[k].first : Shape(Circle{tool::uniform_point(rng, 0, 3), 0.1 + 0.5 * u(rng)});
    const auto [pa, pb] = box2d_pair(a, placed, 8, Fit::inscribed);
    const Contact c = contact(a, placed);
    if (c.separation > 0) {
      ASSERT_NEAR(baseline::box2d_distance(pa, pb), c.separation, kFloatTolerance) << describe_pair(a, placed);
      ++apart;
      continue;
    }
    if (c.separation > -kFloatTolerance) continue;  // touching to Box2D's rounding: it may keep no point
    const auto box2d = baseline::box2d_contact(baseline::to_box2d_shapes(pa, pb));
    ASSERT_TRUE(box2d) << describe_pair(a, placed);
    ++overlapping;
    if (std::holds_alternative<Circle>(placed)) {
      ASSERT_NEAR(box2d->separation, c.separation, kFloatTolerance) << describe_pair(a, placed);
    } else {
      ++polygons_overlapping;
      deepest_kept += std::abs(box2d->separation - c.separation) <= kFloatTolerance;
    }
  }
  std::printf(
      "[box2d bracket] segments: %d apart, %d overlapping; polygon pairs' deepest point kept by Box2D in %d of %d\n",
      apart, overlapping, deepest_kept, polygons_overlapping);
  EXPECT_GT(apart, 1000);
  EXPECT_GT(overlapping, 300);
  EXPECT_GT(deepest_kept, polygons_overlapping * 9 / 10);
}

// Box2D's b2ChainShape on the same chains: a floor in line, a hill and a valley bending 0.05 rad at
// each vertex, and a box, a circle, a hexagon and an ellipse's inscribed 8-gon (Box2D's own
// shapes, exactly, so that the two libraries see the same solids) posed along each, upright on the
// segment under them and sunk 0.02 into it. At every pose both give the body a contact, and the
// deepest over the chain's segments agrees within Box2D's float error (separation and normal)
// wherever the body's lowest point is not on a vertex. On a vertex the rules differ: at a hill's
// (convex) the neighbour owns the corner and gives the least way out of the solid corner, along its
// own normal, where Box2D's segment gives its own, deeper; in a valley (concave) both segments
// keep their contacts and the deeper is the segment's own, where Box2D keeps the neighbour's.
TEST(Box2dBracket, ChainsMatchBox2dsChainsWithinFloatError) {
  std::vector<Vec2> octagon;
  for (int k = 0; k < 8; ++k)
    octagon.emplace_back(0.6 * std::cos(k * std::numbers::pi / 4), 0.3 * std::sin(k * std::numbers::pi / 4));
  const Shape bodies[] = {Rect{Vec2::Zero(), Vec2(0.5, 0.25), 0.0}, Circle{Vec2::Zero(), 0.4},
                          ConvexPolygon::regular(6, 0.5), ConvexPolygon::of(octagon)};
  int poses = 0, matched = 0, off_vertex_mismatches = 0;
  double worst_matched = 0;
  for (const double bend : {0.0, 0.05, -0.05}) {
    std::vector<Vec2> points{Vec2(20, 0)};
    for (int k = 0; k < 42; ++k) points.push_back(points.back() + Vec2(-std::cos(k * bend), -std::sin(k * bend)));
    const std::vector<ChainSegment> ours = chain_segments(points, false);
    const std::vector<baseline::Box2dShape> theirs = baseline::to_box2d_chain(points, Vec2::Zero());
    for (const Shape& local : bodies) {
      for (double s = 5.0; s < 35.0; s += 0.0625) {
        const int k = static_cast<int>(s);
        const Vec2 e = (points[k + 2] - points[k + 1]).normalized(), n(e.y(), -e.x());
        const double angle = std::atan2(e.y(), e.x());
        const Shape turned = placed(local, {Vec2::Zero(), angle}, Orientation::of(angle));
        const double below = -n.dot(support(turned, -n));
        const Vec2 on = points[k + 1] + (s - k) * (points[k + 2] - points[k + 1]);
        const Shape body = placed(local, {on + (below - 0.02) * n, angle}, Orientation::of(angle));
        const baseline::Box2dShape shape =
            baseline::to_box2d_shape(baseline::to_box2d(body, 8, Fit::inscribed, Vec2::Zero()));
        std::optional<Contact> deepest;
        std::optional<baseline::Box2dContact> box2d;
        for (std::size_t j = 0; j < ours.size(); ++j) {
          const Contact c = contact(ours[j], body);
          if (!c.empty() && c.separation <= 0 && (!deepest || c.separation < deepest->separation)) deepest = c;
          const auto b = baseline::box2d_contact(baseline::ShapePair{{theirs[j], shape}});
          if (b && (!box2d || b->separation < box2d->separation)) box2d = b;
        }
        ASSERT_TRUE(deepest) << shape_name(body) << " at " << s << " bend " << bend;
        ASSERT_TRUE(box2d) << shape_name(body) << " at " << s << " bend " << bend;
        ++poses;
        const double gap = std::abs(box2d->separation - deepest->separation);
        if (gap <= kFloatTolerance && (box2d->normal - deepest->normal).norm() <= 1e-4) {
          ++matched;
          worst_matched = std::max(worst_matched, gap);
        } else if (s != std::floor(s)) {
          ++off_vertex_mismatches;
        }
      }
    }
  }
  std::printf("[box2d bracket] chains: deepest contact matched at %d of %d poses (worst |difference| %.2e)\n", matched,
              poses, worst_matched);
  EXPECT_EQ(off_vertex_mismatches, 0);
  EXPECT_GT(matched, poses * 9 / 10);
}

}  // namespace
}  // namespace collide2d
