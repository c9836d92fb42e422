// Pairs of core shapes (rectangles, convex polygons sharp and rounded, capsules, circles) settled on
// their convex cores (narrowphase/shared/cores/convex_core.h): overlap, distance and contact against
// the 50-digit reference's signed distance (a scan of the dual function, not separating axes) and
// against the construction's own gap, on near-tangent, deep, far-off and extreme-scale families
// and on the degenerate configurations of segments and faces.
#include "contact_testing.h"
#include "core_families.h"
#include "mp_reference.h"

#include <collide2d/kernels.h>

#include "narrowphase/contact/capsule_segment.h"
#include "narrowphase/shared/cores/convex_core.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

namespace collide2d {
namespace {

using testing::angle_between;
using testing::cases_of;
using testing::core_families;
using testing::CoreCase;
using testing::CoreFamily;
using testing::Form;

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

Orientation orientation_of(const Shape& s) { return Orientation::of(angle_of(s)); }

// The kernels under test for a pair: two cores, or a core and an ellipse (B); a polygon's, a
// capsule's or a segment's contact with a circle, its typed kernel.
struct Kernels {
  std::function<Contact(const ContactOptions&)> contact;
  std::function<DistanceResult()> distance;
  std::function<bool()> overlap;
};

template <class P>
Kernels kernels_on(const P& p) {
  return {[p](const ContactOptions& o) { return detail::core_contact(p, o); }, [p] { return detail::core_distance(p); },
          [p] { return detail::core_overlap(p); }};
}

// The cores' methods on a pair of core shapes, the cores as the queries take them
// (detail::core_pair()), or in eight slots for every kind where `eight_slots`. The kernels read the
// shapes' polygon outlines: they hold for as long as the shapes do.
Kernels core_kernels(const Shape& a, const Shape& b, bool eight_slots = false) {
  return std::visit(
      [eight_slots](const auto& x, const auto& y) -> Kernels {
        using X = std::decay_t<decltype(x)>;
        using Y = std::decay_t<decltype(y)>;
        if constexpr (std::is_same_v<X, Ellipse> || std::is_same_v<Y, Ellipse>) {
          throw std::logic_error("not a pair of core shapes");
        } else {
          if (!eight_slots) return kernels_on(detail::core_pair(x, orientation_of(x), y, orientation_of(y)));
          const detail::Placement at = detail::Placement::of(y.center, orientation_of(y), x.center, orientation_of(x));
          return kernels_on(detail::CorePairOf<detail::Core, detail::Core>{
              detail::core_of(x, {}), detail::core_of(y, at), detail::Rotation<double>::of(orientation_of(x)),
              x.center});
        }
      },
      a, b);
}

Kernels kernels_of(const Shape& a, const Shape& b) {
  if (const auto* e = std::get_if<Ellipse>(&b)) {
    const detail::CoreEllipse p = std::visit(
        [&](const auto& x) -> detail::CoreEllipse {
          if constexpr (std::is_same_v<std::decay_t<decltype(x)>, Ellipse>) {
            throw std::logic_error("two ellipses");
          } else {
            return detail::CoreEllipse::of(x, orientation_of(x), *e, Orientation::of(e->angle));
          }
        },
        a);
    return {[p](const ContactOptions& o) { return detail::core_ellipse_contact(p, o); },
            [p] { return detail::core_ellipse_distance(p); }, [p] { return detail::core_ellipse_overlap(p); }};
  }
  Kernels out = core_kernels(a, b);
  const auto* polygon = std::get_if<ConvexPolygon>(&a);
  const auto* circle = std::get_if<Circle>(&b);
  if (polygon && circle) {
    out.contact = [x = *polygon, y = *circle](const ContactOptions& o) {
      return contact_polygon_circle(x, orientation_of(x), y, o);
    };
  }
  if (const auto* capsule = std::get_if<Capsule>(&a); capsule && circle) {
    out.contact = [x = *capsule, y = *circle](const ContactOptions& o) {
      return contact_capsule_circle(x, orientation_of(x), y, o);
    };
  }
  if (const auto* capsule = std::get_if<Capsule>(&a)) {
    if (const auto* other = std::get_if<Capsule>(&b)) {
      out.contact = [x = *capsule, y = *other](const ContactOptions& o) {
        return contact_capsule_capsule(x, orientation_of(x), y, orientation_of(y), o);
      };
    }
    if (const auto* segment = std::get_if<Segment>(&b)) {
      out.contact = [x = *capsule, y = *segment](const ContactOptions& o) {
        return contact_capsule_segment(x, orientation_of(x), y, orientation_of(y), o);
      };
    }
  }
  if (const auto* segment = std::get_if<Segment>(&a); segment && circle) {
    out.contact = [x = *segment, y = *circle](const ContactOptions& o) {
      return contact_segment_circle(x, orientation_of(x), y, o);
    };
  }
  return out;
}

double ulps_of(const Vec2& p) { return 8 * kU * p.cwiseAbs().maxCoeff(); }

class CoreFamilies : public ::testing::TestWithParam<CoreFamily> {};

TEST_P(CoreFamilies, MatchReference) {
  const CoreFamily& f = GetParam();
  double worst_sep = 0, worst_known = 0, worst_points = 0, worst_normal = 0;
  int k = 0, normals = 0, apart = 0, overlapping = 0;
  for (const CoreCase& c : cases_of(f)) {
    const std::string what = f.name + " case " + std::to_string(k++);
    const Kernels kernels = kernels_of(c.a, c.b);
    const Contact got = kernels.contact({});
    const reference::SignedDistance ref = reference::signed_distance(c.a, c.b);
    const double ref_sep = static_cast<double>(ref.separation);
    const double size = std::max(reach_of(c.a), reach_of(c.b));
    const double scale = std::max(size, (center_of(c.b) - center_of(c.a)).norm());
    const double err = std::abs(got.separation - ref_sep) / scale;
    worst_sep = std::max(worst_sep, err);
    EXPECT_LE(err, 8 * kU) << what << " separation " << got.separation << " reference " << ref_sep;
    if (c.delta >= 0) {
      // Apart or touching by construction: the gap is the distance, to the rounding of B's centre.
      const double rho = 16 * kU * (center_of(c.b).cwiseAbs().maxCoeff() + 4 * size);
      worst_known = std::max(worst_known, (std::abs(got.separation - c.delta) - rho) / scale);
      EXPECT_LE(std::abs(got.separation - c.delta), rho + 8 * kU * scale) << what << " nominal gap " << c.delta;
    }

    const Vec2 ref_normal(static_cast<double>(ref.normal.x), static_cast<double>(ref.normal.y));
    const bool unique = ref.runner_up < ref.separation - 1e-9 * scale;
    const double curvature = static_cast<double>(ref.curvature);
    if (unique && std::abs(ref_sep) > 1e-9 * size && 64 * kU * scale / curvature <= 1e-10) {
      const double turn = angle_between(got.normal, ref_normal);
      worst_normal = std::max(worst_normal, turn);
      ++normals;
      EXPECT_LE(turn, 1e-10) << what << " normal " << got.normal.transpose() << " reference " << ref_normal.transpose();
    }

    // The contact's points separation * normal apart; every point of the manifold on its shape, its
    // two points |separation| apart. Where the two shapes' best faces tie to 1e-9 of the scale, the
    // manifold is on A's face, whose normal and separations differ from the maximum's by as much.
    const auto off = [&](const Shape& s, const Vec2& q) {
      return static_cast<double>(reference::distance_to(s, reference::to_mp(q))) - ulps_of(q);
    };
    // (Overlapping with the deepest vertex beyond the reference face's ends, a point within them
    // stands in: its points are farther apart along the normal than the separation.)
    const Vec2 main = got.point_b - got.point_a;
    const double main_ulps = ulps_of(got.point_a) + ulps_of(got.point_b);
    const double main_along = (main - main.dot(got.normal) * got.normal).norm() - main_ulps;
    worst_points =
        std::max({worst_points, main_along / scale, off(c.a, got.point_a) / scale, off(c.b, got.point_b) / scale});
    EXPECT_LE(main_along, 16 * kU * scale) << what << " point_b - point_a not along the normal";
    EXPECT_GE(main.dot(got.normal), got.separation - main_ulps - 16 * kU * scale)
        << what << " points deeper than the pair";
    EXPECT_LE(off(c.a, got.point_a), 16 * kU * scale) << what << " point_a is off A";
    EXPECT_LE(off(c.b, got.point_b), 16 * kU * scale) << what << " point_b is off B";
    for (const ContactPoint& m : got.points()) {
      const double ulps = ulps_of(m.point_a) + ulps_of(m.point_b);
      EXPECT_LE(std::abs((m.point_b - m.point_a).norm() - std::abs(m.separation)) - ulps, 16 * kU * scale)
          << what << " manifold point's separation";
      EXPECT_LE(off(c.a, m.point_a), 16 * kU * scale) << what << " manifold point_a is off A";
      EXPECT_LE(off(c.b, m.point_b), 16 * kU * scale) << what << " manifold point_b is off B";
      EXPECT_GE(m.separation, got.separation - 1e-9 * (reach_of(c.a) + reach_of(c.b)) - 16 * kU * scale)
          << what << " a point deeper than the pair";
    }

    // The verdict and the distance, wherever the reference is clear of rounding.
    const DistanceResult d = kernels.distance();
    if (std::abs(ref_sep) > 16 * kU * scale) {
      EXPECT_EQ(kernels.overlap(), ref_sep < 0) << what << " verdict, reference " << ref_sep;
      EXPECT_EQ(d.overlapping, ref_sep < 0) << what << " distance's verdict";
      (ref_sep < 0 ? overlapping : apart)++;
    }
    if (d.overlapping) {
      // A point of both, to rounding; where two slivers cross in a region thinner than the rounding
      // of their edges' crossing points, within the overlap's depth of each.
      const double bound = std::max(64 * kU * scale, std::abs(ref_sep));
      EXPECT_LE(off(c.a, d.point_a), bound) << what << " witness off A, reference " << ref_sep;
      EXPECT_LE(off(c.b, d.point_a), bound) << what << " witness off B, reference " << ref_sep;
    } else {
      EXPECT_LE(std::abs(d.distance - std::max(ref_sep, 0.0)), 8 * kU * scale) << what << " distance";
      EXPECT_LE(std::abs((d.point_b - d.point_a).norm() - d.distance) - ulps_of(d.point_a) - ulps_of(d.point_b),
                16 * kU * scale)
          << what << " closest points";
    }
  }
  std::printf(
      "[cores] %-28s worst separation %.1f u  known gap %.1f u  points %.1f u  normal %.1e rad (%d)  apart %d "
      "overlapping %d\n",
      f.name.c_str(), worst_sep / kU, worst_known / kU, worst_points / kU, worst_normal, normals, apart, overlapping);
}

Contact contact_of(const Shape& a, const Shape& b, const ContactOptions& options = {}) {
  return core_kernels(a, b).contact(options);
}

// Two capsules on one line: their cores' only separating directions are the line itself (an end of
// each) and its normal, which a segment's faces alone would miss.
TEST(CorePairs, CapsulesInLine) {
  const Capsule a{Vec2(0, 0), 1.0, 0.5, 0.0};
  for (const double gap : {0.5, 1e-9, 0.0, -1e-9, -0.5}) {
    const Capsule b{Vec2(3 + gap, 0), 1.0, 0.5, 0.0};
    const Contact c = contact_of(a, b);
    EXPECT_NEAR(c.separation, gap, 4 * kU * 4) << gap;
    EXPECT_EQ(c.normal, Vec2(1, 0)) << gap;
    EXPECT_EQ(core_kernels(a, b).overlap(), gap <= 0) << gap;
    const DistanceResult d = core_kernels(a, b).distance();
    EXPECT_NEAR(d.distance, std::max(gap, 0.0), 4 * kU * 4) << gap;
  }
  // Cores overlapping along the line: the way out is sideways, by the two radii.
  const Contact side = contact_of(a, Capsule{Vec2(1.5, 0), 1.0, 0.5, 0.0});
  EXPECT_EQ(side.separation, -1.0);
  EXPECT_EQ(std::abs(side.normal.y()), 1.0);
  // Crossing at right angles, 0.25 from A's centre: B's way out is past A's nearer end, 1.75 (past
  // the far end 2.25, across A's core 2).
  const Contact crossing = contact_of(a, Capsule{Vec2(0.25, 0), 1.0, 0.5, std::numbers::pi / 2});
  EXPECT_NEAR(crossing.separation, -1.75, 4 * kU * 4);
  EXPECT_NEAR(crossing.normal.x(), 1.0, 4 * kU);
}

// A box resting on a wider box, gap 1e-9 either way: two points, the upper box's bottom corners,
// on the lower box's top face (face 2 of a rectangle in these pairs, the 4-gon of
// ConvexPolygon::box), with the same ids whatever the gap and a slide along the face.
TEST(CorePairs, BoxRestingOnABox) {
  const Rect floor{Vec2(0, 0), Vec2(2, 1), 0.0};
  for (const double gap : {1e-9, 0.0, -1e-9}) {
    for (const double slide : {-0.3, 0.0, 0.7}) {
      const ConvexPolygon crate = ConvexPolygon::box(0.5, 0.5).at(Vec2(slide, 1.5 + gap));
      const Contact c = contact_of(floor, crate);
      EXPECT_NEAR(c.separation, gap, 8 * kU * 2) << gap << " " << slide;
      EXPECT_EQ(c.normal, Vec2(0, 1));
      ASSERT_EQ(c.manifold_size, 2) << gap << " " << slide;
      EXPECT_EQ(c.manifold[0].id, feature_id(FeatureKind::face_of_a, 2, 0));
      EXPECT_EQ(c.manifold[1].id, feature_id(FeatureKind::face_of_a, 2, 1));
      for (const ContactPoint& m : c.points()) {
        EXPECT_NEAR(m.point_a.y(), 1.0, 8 * kU * 2);
        EXPECT_NEAR(m.point_b.y(), 1.0 + gap, 8 * kU * 2);
        EXPECT_NEAR(std::abs(m.point_a.x() - slide), 0.5, 8 * kU * 2);
      }
      // The pair the other way round: the faces tie, and A's, the crate's bottom face 0, is the
      // reference; the floor's longer face is cut to its ends.
      const Contact back = contact_of(crate, floor);
      EXPECT_EQ(back.normal, Vec2(0, -1));
      ASSERT_EQ(back.manifold_size, 2);
      const std::uint32_t ids[] = {back.manifold[0].id, back.manifold[1].id};
      EXPECT_EQ(std::min(ids[0], ids[1]), feature_id(FeatureKind::face_of_a, 0, 8));
      EXPECT_EQ(std::max(ids[0], ids[1]), feature_id(FeatureKind::face_of_a, 0, 9));
    }
  }
  // Overhanging the floor's end: the crate's outer corner is cut to the face's end, where the face
  // (from vertex 2 at +x to vertex 3) starts (id 8).
  const Contact over = contact_of(floor, ConvexPolygon::box(0.5, 0.5).at(Vec2(2.2, 1.5)));
  ASSERT_EQ(over.manifold_size, 2);
  EXPECT_EQ(over.manifold[1].id, feature_id(FeatureKind::face_of_a, 2, 8));
  EXPECT_EQ(over.manifold[1].point_a, Vec2(2, 1));
}

// A rounded core far from an ellipse (offsets to 1e40 of its size), and against a needle ellipse
// of aspect 1e28 across its long axis: the scaled frame's quadratic is then huge, and with it its
// rounding, which must not decide the radius's reach.
TEST(CorePairs, RoundedCoresFarFromAnEllipseOrAcrossANeedle) {
  const Ellipse e{Vec2(-8, -8), 8, 8, -8};
  for (double offset = 1e3; offset <= 1e40; offset *= 10) {
    for (const Shape& a : {Shape(Capsule{Vec2(-offset, 4.375), 4.375, 4.375, 4.375}),
                           Shape(ConvexPolygon::regular(5, 2.0, 3.0).at(Vec2(offset, -offset), 0.3))}) {
      const double gap = static_cast<double>(reference::signed_distance(a, e).separation);
      ASSERT_GT(gap, 0.0);
      EXPECT_FALSE(overlaps(a, e)) << offset;
      EXPECT_FALSE(distance(a, e).overlapping) << offset;
    }
  }
  const Ellipse needle{Vec2(0, 0), 1e-28, 1.0, 0.0};
  for (const double x : {-2.0, -1e-3, 1e-3, 2.0}) {
    const Capsule across{Vec2(x, 0.5), 0.25, 0.5, 1.5707963267948966};
    const double gap = static_cast<double>(reference::signed_distance(across, needle).separation);
    EXPECT_EQ(overlaps(across, needle), gap < 0) << x << " reference " << gap;
    EXPECT_EQ(distance(across, needle).overlapping, gap < 0) << x;
  }
}

// A triangle's tip exactly on a face, a capsule of radius 1e-9 of its length flat on a face, a
// capsule of length 1e-9 of its radius against a circle: known separations.
TEST(CorePairs, KnownSeparations) {
  const Rect floor{Vec2(0, 0), Vec2(2, 1), 0.0};
  const std::vector<Vec2> wedge = {{0, 0}, {1, 2}, {-1, 2}};
  const ConvexPolygon tip = ConvexPolygon::of(wedge).at(Vec2(0.25, 1));
  EXPECT_EQ(contact_of(floor, tip).separation, 0.0);
  EXPECT_TRUE(core_kernels(floor, tip).overlap());
  EXPECT_TRUE(core_kernels(floor, tip).distance().overlapping);
  const ConvexPolygon lifted = ConvexPolygon::of(wedge).at(Vec2(0.25, 1 + 1e-12));
  EXPECT_NEAR(contact_of(floor, lifted).separation, 1e-12, 4 * kU * 2);
  EXPECT_FALSE(core_kernels(floor, lifted).overlap());

  const Capsule needle{Vec2(0.5, 1 + 1e-9 + 1e-3), 1.0, 1e-9, 0.0};
  const Contact lying = contact_of(floor, needle);
  EXPECT_NEAR(lying.separation, 1e-3, 8 * kU * 2);
  EXPECT_EQ(lying.manifold_size, 2);

  const Capsule bead{Vec2(3, 0), 1e-9, 1.0, 0.7};
  const Circle ball{Vec2(0, 0), 1.5};
  const Contact c = contact_of(bead, ball);
  // The core's nearest end is 1e-9 nearer than the centre, along cos 0.7.
  EXPECT_NEAR(c.separation, 3 - 1e-9 * std::cos(0.7) - 2.5, 8 * kU * 3);
}

// The polygon–circle, capsule–circle and segment–circle kernels (the centre's Voronoi regions)
// against the cores' contact (separating axes, then the nearest of every vertex–edge pair): the same
// separation, normal, points and feature, on every polygon–, capsule– and segment–circle family; with the contact
// limited, the same contact or both beyond the limit, each by a lower bound of the separation (the
// two may find different ones).
TEST(CorePairs, CircleKernelsAreTheCoresContact) {
  int compared = 0;
  for (const CoreFamily& f : core_families()) {
    const bool cored = is_one_of(testing::kPolygonKinds, f.a) || is_one_of(testing::kCapsuleKinds, f.a);
    if (f.b != Form::circle || !(cored || f.a == Form::segment)) {
      continue;
    }
    for (const CoreCase& c : cases_of(f)) {
      const auto& y = std::get<Circle>(c.b);
      for (const double limit : {HUGE_VAL, 0.0}) {
        const ContactOptions o{.max_separation = limit};
        const Contact got = std::visit(
            [&](const auto& x) -> Contact {
              using X = std::decay_t<decltype(x)>;
              if constexpr (std::is_same_v<X, ConvexPolygon>) return contact_polygon_circle(x, orientation_of(x), y, o);
              if constexpr (std::is_same_v<X, Capsule>) return contact_capsule_circle(x, orientation_of(x), y, o);
              if constexpr (std::is_same_v<X, Segment>) return contact_segment_circle(x, orientation_of(x), y, o);
              throw std::logic_error("not a polygon, a capsule or a segment");
            },
            c.a);
        const Contact want = core_kernels(c.a, c.b).contact(o);
        ASSERT_EQ(got.manifold_size, want.manifold_size) << f.name;
        if (want.empty()) {
          const double separation = core_kernels(c.a, c.b).contact({}).separation;
          const double rounding = 64 * kU * (reach_of(c.a) + reach_of(c.b) + (center_of(c.b) - center_of(c.a)).norm());
          for (const double bound : {got.separation, want.separation}) {
            EXPECT_GT(bound, limit) << f.name;
            EXPECT_LE(bound, separation + rounding) << f.name;
          }
          continue;
        }
        ASSERT_EQ(got.separation, want.separation) << f.name << " " << compared;
        EXPECT_EQ(got.normal, want.normal) << f.name;
        EXPECT_EQ(got.point_a, want.point_a) << f.name;
        EXPECT_EQ(got.point_b, want.point_b) << f.name;
        EXPECT_EQ(got.manifold[0].id, want.manifold[0].id) << f.name;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 200);
}

// The capsule–capsule and capsule–segment kernel's own contact (the two segments' features found
// directly) against the cores' contact (separating axes, then the nearest vertex–edge pair): the
// same features (every manifold point's id) and, to rounding, the same separation, normal and
// points, on every family of two capsules or of a capsule and a segment, the contact limited or
// not. The kernel leaves ties to the cores: parallel faces (the parallel families) and ends on a
// face's end (the face families, where a stub's whole face is its ends); it decides the rest.
Contact capsule_direct(const Shape& a, const Shape& b, const ContactOptions& o) {
  const auto& x = std::get<Capsule>(a);
  if (const auto* y = std::get_if<Capsule>(&b))
    return detail::capsule_segment_direct(x, orientation_of(x), *y, orientation_of(*y), o, false);
  const auto& y = std::get<Segment>(b);
  return detail::capsule_segment_direct(x, orientation_of(x), y, orientation_of(y), o, false);
}

TEST(CorePairs, CapsuleKernelIsTheCoresContact) {
  int compared = 0, left = 0, left_off_ties = 0;
  for (const CoreFamily& f : core_families()) {
    const bool a_capsule = is_one_of(testing::kCapsuleKinds, f.a), b_capsule = is_one_of(testing::kCapsuleKinds, f.b);
    if (!((a_capsule && (b_capsule || f.b == Form::segment)) || (f.a == Form::segment && b_capsule))) continue;
    const bool ties = f.touch != testing::Touch::any;
    int k = 0;
    for (const CoreCase& c : cases_of(f)) {
      const std::string what = f.name + " case " + std::to_string(k++);
      const bool swap = f.a == Form::segment;
      const Shape &a = swap ? c.b : c.a, &b = swap ? c.a : c.b;
      const Kernels cores = core_kernels(a, b);
      const double scale = std::max({reach_of(a), reach_of(b), (center_of(b) - center_of(a)).norm()});
      for (const double limit : {HUGE_VAL, 0.0}) {
        const Contact got = capsule_direct(a, b, {.max_separation = limit}),
                      want = cores.contact({.max_separation = limit});
        if (got.manifold_size < 0) {
          ++left;
          left_off_ties += ties ? 0 : 1;
          continue;
        }
        if (got.empty() != want.empty()) {
          // Only a pair at the limit, to rounding, may fall either side of it.
          EXPECT_LE(std::abs(cores.contact({}).separation - limit), 8 * kU * scale) << what << " limit " << limit;
          continue;
        }
        if (want.empty()) continue;
        EXPECT_LE(std::abs(got.separation - want.separation), 8 * kU * scale) << what;
        EXPECT_LE((got.normal - want.normal).norm(), 64 * kU) << what;
        // Points far from the origin carry the rounding of their own coordinates.
        const auto same_point = [&](const Vec2& x, const Vec2& y) {
          return (x - y).norm() <= 16 * kU * scale + ulps_of(y);
        };
        EXPECT_TRUE(same_point(got.point_a, want.point_a)) << what;
        EXPECT_TRUE(same_point(got.point_b, want.point_b)) << what;
        ASSERT_EQ(got.manifold_size, want.manifold_size) << what;
        for (int m = 0; m < got.manifold_size; ++m) {
          EXPECT_EQ(got.manifold[m].id, want.manifold[m].id) << what << " point " << m;
          EXPECT_TRUE(same_point(got.manifold[m].point_a, want.manifold[m].point_a)) << what << " point " << m;
          EXPECT_TRUE(same_point(got.manifold[m].point_b, want.manifold[m].point_b)) << what << " point " << m;
          EXPECT_LE(std::abs(got.manifold[m].separation - want.manifold[m].separation), 8 * kU * scale) << what;
        }
        ++compared;
      }
    }
  }
  std::printf(
      "[capsule kernel] decided and compared %d, left to the cores %d (%d outside the parallel and face families)\n",
      compared, left, left_off_ties);
  EXPECT_GT(compared, 1000);
  EXPECT_LE(left_off_ties, compared / 100);
}

// The same contact to the bit: every field and every manifold point.
void expect_same(const Contact& got, const Contact& want, const std::string& what) {
  EXPECT_EQ(got.separation, want.separation) << what;
  EXPECT_EQ(got.normal, want.normal) << what;
  EXPECT_EQ(got.point_a, want.point_a) << what;
  EXPECT_EQ(got.point_b, want.point_b) << what;
  ASSERT_EQ(got.manifold_size, want.manifold_size) << what;
  for (int k = 0; k < got.manifold_size; ++k) {
    EXPECT_EQ(got.manifold[k].point_a, want.manifold[k].point_a) << what << " point " << k;
    EXPECT_EQ(got.manifold[k].point_b, want.manifold[k].point_b) << what << " point " << k;
    EXPECT_EQ(got.manifold[k].separation, want.manifold[k].separation) << what << " point " << k;
    EXPECT_EQ(got.manifold[k].id, want.manifold[k].id) << what << " point " << k;
  }
}

// The cores as the queries take them against eight slots for every core: a capsule's or a segment's
// core in two slots, and a rectangle's or a polygon's read in its own frame (A's). The same contact
// (with and without a limit), distance and verdict on every family of two core shapes.
TEST(CorePairs, QueriesCoresAreTheEightSlotCores) {
  int compared = 0;
  for (const CoreFamily& f : core_families()) {
    if (f.a == Form::ellipse || f.b == Form::ellipse) continue;
    int k = 0;
    for (const CoreCase& c : cases_of(f)) {
      const std::string what = f.name + " case " + std::to_string(k++);
      const Kernels two = core_kernels(c.a, c.b), eight = core_kernels(c.a, c.b, true);
      for (const double limit : {HUGE_VAL, 0.0}) {
        expect_same(two.contact({.max_separation = limit}), eight.contact({.max_separation = limit}), what);
      }
      const DistanceResult d2 = two.distance(), d8 = eight.distance();
      EXPECT_EQ(d2.overlapping, d8.overlapping) << what;
      EXPECT_EQ(d2.distance, d8.distance) << what;
      EXPECT_EQ(d2.point_a, d8.point_a) << what;
      EXPECT_EQ(d2.point_b, d8.point_b) << what;
      EXPECT_EQ(two.overlap(), eight.overlap()) << what;
      ++compared;
    }
  }
  EXPECT_GT(compared, 500);
}

INSTANTIATE_TEST_SUITE_P(Families, CoreFamilies, ::testing::ValuesIn(testing::core_families()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace collide2d
