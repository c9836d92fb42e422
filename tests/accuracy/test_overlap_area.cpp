// The overlap area and centroid of every pair of solid kinds against the 50-digit reference of
// area_reference.h (crossings by a search on bounded slopes, Green's theorem by quadrature), on
// generic, nested, disjoint, near-tangent, near-identical, far-off and extreme-scale families;
// symmetry to the bit; and the answer zero exactly where the exact overlap test says the solids are
// apart.
#include "area_reference.h"
#include "core_families.h"
#include "hard_cases.h"
#include "narrowphase/baselines/ellipse_overlap_area.h"
#include "narrowphase/baselines/rotated_box_iou.h"

#include <collide2d/area.h>
#include <collide2d/query.h>
#include <collide2d/ray_cast.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace collide2d {
namespace {

using testing::Form;
using testing::random_shape;

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr Form kSolids[] = {Form::rect, Form::polygon, Form::rounded, Form::capsule, Form::circle, Form::ellipse};

// The scale of a pair: the larger of the two shapes' bounding-box areas, and its side.
struct Scale {
  double area = 0;
  double size = 0;
};
Scale scale_of(const Shape& a, const Shape& b) {
  Scale s;
  for (const Shape* x : {&a, &b}) {
    const Aabb box = aabb(*x);
    const Vec2 side = box.max - box.min;
    s.area = std::max(s.area, side.x() * side.y());
    s.size = std::max(s.size, side.maxCoeff());
  }
  return s;
}

// The error of the area in units of eps times the scale's area, and of the first moment (area
// times centroid) in units of eps times the scale's area and its size or, far from the origin, the
// magnitude of the coordinates that the centroid is rounded to.
struct Errors {
  double area = 0;
  double moment = 0;
};
Errors errors_of(const Shape& a, const Shape& b) {
  const OverlapArea got = overlap_area(a, b);
  const reference::AreaReference want = reference::overlap_area(a, b);
  const Scale s = scale_of(a, b);
  Errors e;
  e.area = std::abs(static_cast<double>(want.area - got.area)) / (kEps * s.area);
  if (want.area > 0 && got.area > 0) {
    const Vec2 c = center_of(a);  // moments about A's centre, where both are exact to their rounding
    const double mx =
        static_cast<double>(want.area * (want.centroid.x - c.x())) - got.area * (got.centroid.x() - c.x());
    const double my =
        static_cast<double>(want.area * (want.centroid.y - c.y())) - got.area * (got.centroid.y() - c.y());
    e.moment = std::hypot(mx, my) / (kEps * s.area * std::max(s.size, got.centroid.cwiseAbs().maxCoeff()));
  }
  return e;
}

// The bound every family meets, in the units of Errors.
constexpr double kBound = 2;

// The errors of the pair, expected within the bound.
Errors expect_close(const Shape& a, const Shape& b, const std::string& what) {
  const Errors e = errors_of(a, b);
  EXPECT_LE(e.area, kBound) << what;
  EXPECT_LE(e.moment, kBound) << what;
  return e;
}

void keep_worst(Errors& worst, const Errors& e) {
  worst.area = std::max(worst.area, e.area);
  worst.moment = std::max(worst.moment, e.moment);
}

std::string pair_name(Form a, Form b) { return std::string(testing::name_of(a)) + "-" + testing::name_of(b); }

TEST(OverlapArea, GenericPairsOfEveryKind) {
  std::mt19937_64 rng(56);
  std::uniform_real_distribution<double> offset(-1.2, 1.2);
  for (const Form fa : kSolids) {
    for (const Form fb : kSolids) {
      Errors worst;
      for (int k = 0; k < 12; ++k) {
        const Shape a = random_shape(fa, 1.0, 4.0, rng);
        const Shape b = moved_to(random_shape(fb, 1.0, 4.0, rng), Vec2(offset(rng), offset(rng)));
        keep_worst(worst, expect_close(a, b, pair_name(fa, fb)));
      }
      std::printf("%-18s area %5.2f eps  moment %5.2f eps\n", pair_name(fa, fb).c_str(), worst.area, worst.moment);
    }
  }
}

bool solid(Form f) { return f != Form::segment; }

// The near-tangent, deep, sliver, far-off, small, large, face and parallel families of the core
// tests (core_families.h), each overlapping case against the reference.
TEST(OverlapArea, CoreFamilies) {
  for (const testing::CoreFamily& f : testing::core_families()) {
    if (!solid(f.a) || !solid(f.b)) continue;
    Errors worst;
    for (const testing::CoreCase& c : testing::cases_of(f)) {
      if (c.delta >= 0) continue;
      keep_worst(worst, expect_close(c.a, c.b, f.name + " depth " + std::to_string(-c.delta)));
    }
    std::printf("%-30s area %5.2f eps  moment %5.2f eps\n", f.name.c_str(), worst.area, worst.moment);
  }
}

// Zero exactly where the exact overlap test (query.h) finds the solids apart, and more than zero
// where it finds them overlapping, on every pair whose gap or depth (contact()'s separation: a
// family's nominal one is a needle's only to the rounding of its support point) is at least 1e-9 of
// the size.
TEST(OverlapArea, ZeroExactlyWhereApart) {
  int checked = 0;
  for (const testing::CoreFamily& f : testing::core_families()) {
    if (!solid(f.a) || !solid(f.b)) continue;
    for (const testing::CoreCase& c : testing::cases_of(f)) {
      if (std::abs(contact(c.a, c.b).separation) < 1e-9 * f.size) continue;
      EXPECT_EQ(overlap_area(c.a, c.b).area > 0, overlaps(c.a, c.b)) << f.name << " gap " << c.delta;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

// The same shape nudged by 1e-3 ... 1e-13 of its size along a random direction (IoU near 1).
TEST(OverlapArea, NearIdenticalShapes) {
  std::mt19937_64 rng(57);
  std::uniform_real_distribution<double> turn(0, 2 * std::numbers::pi);
  for (const Form f : kSolids) {
    Errors worst;
    for (const double nudge : {1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13}) {
      const Shape a = random_shape(f, 1.0, 4.0, rng);
      const double t = turn(rng);
      const Shape b = moved_to(a, center_of(a) + nudge * Vec2(std::cos(t), std::sin(t)));
      keep_worst(worst, expect_close(a, b, std::string(testing::name_of(f)) + " nudged by " + std::to_string(nudge)));
    }
    std::printf("%-18s area %5.2f eps  moment %5.2f eps\n", testing::name_of(f), worst.area, worst.moment);
  }
}

// Rectangles at equal angles, a right angle apart and sharing an edge: against the reference, and
// where the construction gives the answer exactly (axis-aligned, dyadic), against that.
TEST(OverlapArea, RotatedBoxes) {
  std::mt19937_64 rng(58);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 24; ++k) {
    const double angle = 2 * std::numbers::pi * unit(rng);
    const Rect a{Vec2(unit(rng), unit(rng)), Vec2(0.5 + unit(rng), 0.5 + unit(rng)), angle};
    const Vec2 shift(unit(rng) - 0.5, unit(rng) - 0.5);
    const double turns[] = {0.0, std::numbers::pi / 2, std::numbers::pi, -std::numbers::pi / 2};
    const Rect b{a.center + shift, Vec2(0.5 + unit(rng), 0.5 + unit(rng)), angle + turns[k % 4]};
    expect_close(a, b, "boxes " + std::to_string(k));
  }
  // Axis-aligned dyadic boxes: the overlap is the box of the larger lows and the smaller highs.
  for (int k = 0; k < 200; ++k) {
    const auto dyadic = [&] { return std::ldexp(std::floor(unit(rng) * 64), -5) - 1; };
    const Vec2 c1(dyadic(), dyadic()), c2(dyadic(), dyadic()), h1(0.25 + dyadic() / 4 + 0.25, 0.5),
        h2(0.75, 0.25 + dyadic() / 4 + 0.25);
    const Vec2 lo = (c1 - h1).cwiseMax(c2 - h2), hi = (c1 + h1).cwiseMin(c2 + h2), side = (hi - lo).cwiseMax(0.0);
    const OverlapArea got = overlap_area(Rect{c1, h1, 0}, Rect{c2, h2, 0});
    EXPECT_NEAR(got.area, side.x() * side.y(), 2 * kEps) << k;
    if (got.area > 0) EXPECT_LE((got.centroid - (lo + hi) / 2).norm() * got.area, 2 * kEps) << k;
  }
}

// The shape grown by k about its centre (a polygon's about the origin of its outline, inside it).
Shape scaled(const Shape& s, double k) {
  return std::visit(
      [k](auto x) -> Shape {
        using T = decltype(x);
        if constexpr (std::is_same_v<T, Circle>) x.radius *= k;
        if constexpr (std::is_same_v<T, Ellipse>) x.a *= k, x.b *= k;
        if constexpr (std::is_same_v<T, Rect>) x.half_extents *= k;
        if constexpr (std::is_same_v<T, Capsule>) x.half_length *= k, x.radius *= k;
        if constexpr (std::is_same_v<T, ConvexPolygon>) {
          std::vector<Vec2> v(x.vertices().begin(), x.vertices().end());
          for (Vec2& p : v) p *= k;
          return ConvexPolygon::of(v, x.radius() * k).at(x.center, x.angle);
        }
        return x;
      },
      s);
}

// The shape turned by t about its centre.
Shape turned(const Shape& s, double t) {
  return std::visit(
      [t](auto x) -> Shape {
        if constexpr (requires { x.angle; }) x.angle += t;
        return x;
      },
      s);
}

// A rectangle or a polygon without rounding.
bool sharp(const Shape& s) {
  const auto* p = std::get_if<ConvexPolygon>(&s);
  return std::holds_alternative<Rect>(s) || (p && p->outline->radius == 0);
}

// Slivers: overlaps of at least 1e-6 of the scale and at most 1e-2 (above it the scale's bound of
// CoreFamilies gives the area to 200 eps of itself), on the core families' overlapping cases and the
// overlapping cases of the hard families of circles, ellipses and rectangles up to aspect 1e3: the
// area within 1e-12 of itself. Curved pairs get there in double: their crossings, a few eps of the
// scale off, move a sliver's area by that relative to the chord's length, which is still 1e-3 of the
// size where the area is 1e-6 of the scale. Two sharp polygons overlapping by less than 2^-7 of the
// larger area are clipped again in double-double and come out rounded to nearest.
struct SliverErrors {
  double curved = 0;         // relative
  double sharp = 0;          // relative
  double sharp_rounded = 0;  // eps of the area, below 2^-7 of the larger area
  int count = 0;
  int rounded = 0;  // of them below 2^-7
};

void check_sliver(const Shape& a, const Shape& b, const std::string& what, SliverErrors& worst) {
  const double scale = scale_of(a, b).area, got = overlap_area(a, b).area;
  if (got < 0.5e-6 * scale || got > 1e-2 * scale) return;
  const double want = static_cast<double>(reference::overlap_area(a, b).area);
  if (want < 1e-6 * scale) return;
  const double relative = std::abs(got - want) / want;
  EXPECT_LE(relative, 1e-12) << what;
  ++worst.count;
  if (!sharp(a) || !sharp(b)) {
    worst.curved = std::max(worst.curved, relative);
    return;
  }
  worst.sharp = std::max(worst.sharp, relative);
  if (want < 0x1p-7 * std::max(area(a), area(b))) {
    EXPECT_LE(relative / kEps, 0.5) << what;
    worst.sharp_rounded = std::max(worst.sharp_rounded, relative / kEps);
    ++worst.rounded;
  }
}

TEST(OverlapArea, SliversKeepTheirDigits) {
  SliverErrors worst;
  for (const testing::CoreFamily& f : testing::core_families()) {
    for (const testing::CoreCase& c : testing::cases_of(f)) {
      if (c.delta < 0 && solid(f.a) && solid(f.b))
        check_sliver(c.a, c.b, f.name + " depth " + std::to_string(-c.delta), worst);
    }
  }
  using testing::Kind;
  const std::pair<Kind, Kind> kinds[] = {{Kind::circle, Kind::circle},   {Kind::circle, Kind::ellipse},
                                         {Kind::ellipse, Kind::ellipse}, {Kind::rect, Kind::circle},
                                         {Kind::rect, Kind::ellipse},    {Kind::rect, Kind::rect}};
  for (const auto& [ka, kb] : kinds) {
    for (const testing::Family& f : testing::standard_families(ka, kb)) {
      if (f.aspect_max > 1e3) continue;
      for (const testing::Case& c : testing::family_cases(f)) {
        if (overlaps(c.a, c.b)) check_sliver(c.a, c.b, f.name, worst);
      }
    }
  }
  std::printf("%d slivers: curved %.3g, sharp %.3g relative; %d sharp below 2^-7 %.2f eps\n", worst.count, worst.curved,
              worst.sharp, worst.rounded, worst.sharp_rounded);
  EXPECT_GT(worst.count, 1000);
  EXPECT_GT(worst.rounded, 50);
}

// The reference's |A delta B| / |A u B|, from its overlap and the two areas.
double reference_distance(const Shape& a, const Shape& b) {
  const reference::Real both = reference::area(a) + reference::area(b), shared = reference::overlap_area(a, b).area;
  return static_cast<double>((both - 2 * shared) / (both - shared));
}

// A distance's error in units in its last place, or in those of 1e-12 below it.
double ulps_of_distance(double got, double want) {
  const double at = std::max(want, 1e-12);
  return std::abs(got - want) / (std::nextafter(at, 2.0) - at);
}

// The same shape moved, turned, grown and all three by 0.6 ... 1e-12 of its size: iou_distance
// within a few units in its own last place wherever it is at least 1e-12 (a circle turned is the
// same circle), and within as many of 1e-12 below. A shape shrunk by as much as it is moved touches
// the other from inside, where two crossings closer than double resolves may be ones the curves do
// not make, or miss a lens they do: there iou_distance is within a few eps.
TEST(OverlapArea, IouDistanceOfNearIdenticalShapes) {
  std::mt19937_64 rng(62);
  std::uniform_real_distribution<double> turn(0, 2 * std::numbers::pi);
  for (const Form f : kSolids) {
    double worst = 0, worst_inside = 0;
    for (const double nudge : {0.6, 0.3, 0.1, 0.03, 1e-2, 3e-3, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-12}) {
      for (int k = 0; k < 2; ++k) {
        const Shape a = random_shape(f, 1.0, 4.0, rng);
        const double t = turn(rng);
        const Shape moved = moved_to(a, center_of(a) + nudge * Vec2(std::cos(t), std::sin(t)));
        for (const Shape& b :
             {moved, scaled(a, 1 + nudge), turned(a, nudge), turned(scaled(moved, 1 + nudge / 2), -nudge)}) {
          const double error = ulps_of_distance(iou_distance(a, b), reference_distance(a, b));
          EXPECT_LE(error, 3) << testing::name_of(f) << " nudged by " << nudge;
          worst = std::max(worst, error);
        }
        const Shape inside = scaled(moved, 1 - nudge);
        const double got = iou_distance(a, inside), want = reference_distance(a, inside);
        EXPECT_LE(std::abs(got - want), 2 * kEps) << testing::name_of(f) << " inside, nudged by " << nudge;
        worst_inside = std::max(worst_inside, ulps_of_distance(got, want));
      }
    }
    std::printf("%-10s worst %.3g ulps; touching inside %.3g ulps\n", testing::name_of(f), worst, worst_inside);
    // Circles of the test's radius 1 touch to the last bit, where a lens below double's resolution
    // is missed.
    EXPECT_LE(worst_inside, f == Form::circle ? 64 : 3) << testing::name_of(f);
  }
}

TEST(OverlapArea, IouDistanceOfEqualAndApartShapes) {
  std::mt19937_64 rng(63);
  for (const Form f : kSolids) {
    const Shape a = random_shape(f, 1.0, 4.0, rng);
    EXPECT_EQ(iou_distance(a, a), 0.0) << testing::name_of(f);
    EXPECT_EQ(iou_distance(a, moved_to(a, center_of(a) + Vec2(20, 0))), 1.0) << testing::name_of(f);
  }
}

// The worst relative error of a value against the reference's, in units of eps.
struct Worst {
  double ours = 0;
  double rival = 0;
  void keep(double want, double got_ours, double got_rival) {
    ours = std::max(ours, std::abs(got_ours - want) / (kEps * want));
    rival = std::max(rival, std::abs(got_rival - want) / (kEps * want));
  }
};

double reference_iou(const Shape& a, const Shape& b) {
  const reference::Real shared = reference::overlap_area(a, b).area;
  return static_cast<double>(shared / (reference::area(a) + reference::area(b) - shared));
}

// Rotated boxes, ours beside the rival written from detectron2's method
// (narrowphase/baselines/rotated_box_iou.h), against the reference: the IoU of generic pairs and of slivers (faces
// overlapping by 1e-3 ... 1e-9 of the size, the angles equal or 1e-9 apart), and the distance
// 1 - IoU of the same box moved, turned or grown by 1e-3 ... 1e-12. Ours is asserted; the rival's
// is what the docs quote beside it.
TEST(OverlapArea, RotatedBoxesBesideTheRival) {
  std::mt19937_64 rng(64);
  std::uniform_real_distribution<double> unit(0, 1);
  const auto box = [&] {
    return Rect{Vec2(unit(rng), unit(rng)), Vec2(0.3 + unit(rng), 0.3 + unit(rng)), 6 * unit(rng)};
  };
  Worst generic, slivers, distances;
  for (int k = 0; k < 60; ++k) {
    const Rect a = box(), b = box();
    generic.keep(reference_iou(a, b), iou(a, b), baselines::rotated_box_iou(a, b));
  }
  for (const double depth : {1e-3, 1e-5, 1e-7, 1e-9}) {
    for (const double turn : {0.0, 1e-9}) {
      const Rect a = box();
      const Vec2 h(0.3 + unit(rng), 0.3 + unit(rng));
      const Orientation o = Orientation::of(a.angle);
      const Vec2 local(a.half_extents.x() + h.x() - depth, 0.2 * unit(rng));
      const Vec2 along(o.c * local.x() - o.s * local.y(), o.s * local.x() + o.c * local.y());
      const Rect b{a.center + along, h, a.angle + turn};
      slivers.keep(reference_iou(a, b), iou(a, b), baselines::rotated_box_iou(a, b));
    }
  }
  // IoU itself within 2 eps where edges nearly coincide: near-identical boxes, and boxes a right
  // angle apart or at one angle with a face of each on one line.
  double near_parallel = 0;
  const auto keep_near_parallel = [&](const Rect& a, const Shape& b) {
    near_parallel = std::max(near_parallel, std::abs(iou(a, b) - reference_iou(a, b)) / kEps);
  };
  for (const double nudge : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const Rect a = box();
    for (const Shape& b : {moved_to(a, a.center + Vec2(nudge, -nudge)), scaled(a, 1 + nudge), turned(a, nudge)}) {
      const Rect& r = std::get<Rect>(b);
      distances.keep(reference_distance(a, b), iou_distance(a, b), 1 - baselines::rotated_box_iou(a, r));
      keep_near_parallel(a, b);
    }
  }
  for (const double turn : {std::numbers::pi / 2, std::numbers::pi, -std::numbers::pi / 2, 0.0}) {
    const Rect a = box();
    const Orientation o = Orientation::of(a.angle);
    const double across = a.half_extents.y() + 0.5;  // B's lower face on A's upper face's line
    const Vec2 up(-o.s * across, o.c * across);
    keep_near_parallel(a, Rect{a.center + up + Vec2(0.3 * o.c, 0.3 * o.s), Vec2(0.5, 0.5), a.angle + turn});
    keep_near_parallel(a, Rect{a.center + 0.5 * up, Vec2(0.7, 0.4), a.angle + turn});
  }
  EXPECT_LE(near_parallel, 2);
  std::printf("IoU, edges nearly parallel  ours %8.3g eps\n", near_parallel);
  EXPECT_LE(generic.ours, 8);
  EXPECT_LE(slivers.ours, 256);
  EXPECT_LE(distances.ours, 2);
  std::printf("generic IoU      ours %8.3g eps  rival %8.3g eps\n", generic.ours, generic.rival);
  std::printf("sliver IoU       ours %8.3g eps  rival %8.3g eps\n", slivers.ours, slivers.rival);
  std::printf("1 - IoU, nudged  ours %8.3g eps  rival %8.3g eps\n", distances.ours, distances.rival);
}

// Two ellipses, ours beside the rival that follows Hughes and Chraibi
// (narrowphase/baselines/ellipse_overlap_area.h), against the reference: the area's error in eps of
// the scale on generic pairs, on the same ellipse moved by 1e-3 ... 1e-12, and on the hard-case
// families of two ellipses (near-tangent, aspect to 1e4, far, small, large, nested, concentric,
// mirrored, at the evolute's cusps, thin rings). Ours is asserted;
// the rival's is what the docs quote beside it.
TEST(OverlapArea, EllipsesBesideTheRival) {
  struct Family {
    std::string name;
    std::vector<std::pair<Ellipse, Ellipse>> pairs;
  };
  std::vector<Family> families{{"generic", {}}, {"nudged", {}}};
  std::mt19937_64 rng(65);
  std::uniform_real_distribution<double> offset(-1.2, 1.2), turn(0, 2 * std::numbers::pi);
  for (int k = 0; k < 24; ++k) {
    const Shape a = random_shape(Form::ellipse, 1.0, 4.0, rng), b = random_shape(Form::ellipse, 1.0, 4.0, rng);
    families[0].pairs.emplace_back(std::get<Ellipse>(a),
                                   std::get<Ellipse>(moved_to(b, Vec2(offset(rng), offset(rng)))));
  }
  for (const double nudge : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const Ellipse a = std::get<Ellipse>(random_shape(Form::ellipse, 1.0, 4.0, rng));
    const double t = turn(rng);
    families[1].pairs.emplace_back(a,
                                   std::get<Ellipse>(moved_to(a, a.center + nudge * Vec2(std::cos(t), std::sin(t)))));
  }
  // The hard-case families of two ellipses (hard_cases.h): the first 3 overlapping pairs of each, up
  // to aspect 1e4 (beyond it the reference's search for crossings takes minutes a pair).
  for (const testing::Family& f : testing::standard_families(testing::Kind::ellipse, testing::Kind::ellipse)) {
    if (f.aspect_max > 1e4) continue;
    Family family{f.name, {}};
    for (const testing::Case& c : testing::family_cases(f)) {
      if (family.pairs.size() == 3) break;
      if (overlaps(c.a, c.b)) family.pairs.emplace_back(std::get<Ellipse>(c.a), std::get<Ellipse>(c.b));
    }
    families.push_back(family);
  }
  for (const Family& family : families) {
    double ours = 0, rival = 0;
    for (const auto& [a, b] : family.pairs) {
      const double want = static_cast<double>(reference::overlap_area(a, b).area), unit = kEps * scale_of(a, b).area;
      ours = std::max(ours, std::abs(overlap_area(a, b).area - want) / unit);
      rival = std::max(rival, std::abs(baselines::ellipse_overlap_area(a, b) - want) / unit);
    }
    EXPECT_LE(ours, kBound) << family.name;
    std::printf("%-26s ours %6.2f eps  rival %9.3g eps\n", family.name.c_str(), ours, rival);
  }
}

// The area of each kind against the reference's quadrature over its boundary.
TEST(OverlapArea, AreaOfEachKind) {
  std::mt19937_64 rng(61);
  for (const Form f : kSolids) {
    for (int k = 0; k < 4; ++k) {
      const Shape s = random_shape(f, 1.0, 4.0, rng);
      const double want = static_cast<double>(reference::area(s));
      EXPECT_NEAR(area(s), want, 2 * kEps * want) << testing::name_of(f);
    }
  }
}

// B inside A: the overlap is B. B grown about a point inside A: the overlap never shrinks (to the
// rounding of the scale) and never exceeds either shape.
TEST(OverlapArea, NestedAndMonotone) {
  std::mt19937_64 rng(59);
  for (const Form fa : kSolids) {
    for (const Form fb : kSolids) {
      const Shape a = random_shape(fa, 1.0, 2.0, rng);
      const Shape b = moved_to(random_shape(fb, 1.0, 2.0, rng), center_of(a));
      const OverlapArea inner = overlap_area(a, scaled(b, 1e-3));
      EXPECT_NEAR(inner.area, area(scaled(b, 1e-3)), 2 * kEps * inner.area) << pair_name(fa, fb);
      EXPECT_EQ(inner.crossings, 0);
      const Shape off = moved_to(b, center_of(a) + Vec2(0.2, -0.1));
      double last = 0;
      for (double k = 0.05; k < 4; k *= 1.1) {
        const Shape grown = scaled(off, k);
        const double now = overlap_area(a, grown).area;
        EXPECT_GE(now, last - 4 * kEps * scale_of(a, grown).area) << pair_name(fa, fb) << " grown by " << k;
        EXPECT_LE(now, std::min(area(a), area(grown)) + 4 * kEps * scale_of(a, grown).area)
            << pair_name(fa, fb) << " grown by " << k;
        last = now;
      }
    }
  }
}

// Solids that touch share no open region: area 0 at A's centre, and no crossing.
TEST(OverlapArea, TouchingSharesNothing) {
  const std::pair<Shape, Shape> touching[] = {
      {Rect{Vec2(0, 0), Vec2(1, 1), 0}, Rect{Vec2(2, 0.5), Vec2(1, 1), 0}},
      {Circle{Vec2(0, 0), 1}, Circle{Vec2(2, 0), 1}},
      {Rect{Vec2(0, 0), Vec2(1, 1), 0}, Capsule{Vec2(0, 1.5), 2, 0.5, 0}},
  };
  for (const auto& [a, b] : touching) {
    const OverlapArea o = overlap_area(a, b);
    EXPECT_EQ(o.area, 0.0);
    EXPECT_EQ(o.crossings, 0);
    EXPECT_EQ(o.centroid, center_of(a));
  }
}

// B shrunk from A about a point of A's boundary lies inside A and touches it there, where the two
// boundaries meet at a tangency that double rounds to no crossing, to one, or to a grazing pair:
// the overlap is B, both ways round.
TEST(OverlapArea, TouchingFromInsideGivesTheInnerShape) {
  std::mt19937_64 rng(64);
  std::uniform_real_distribution<double> turn(0, 2 * std::numbers::pi);
  int count = 0;
  for (const Form f : kSolids) {
    for (int k = 0; k < 40; ++k) {
      const Shape a = random_shape(f, 1.0, 2.0, rng);
      const double t = turn(rng);
      const Vec2 out(std::cos(t), std::sin(t)), far = center_of(a) + 10 * out;
      const Vec2 touch = ray_cast(a, far, -out, 20)->point;
      for (const double s : {0.7, 0.3, 1e-2}) {
        const Shape inner = moved_to(scaled(a, s), touch + s * (center_of(a) - touch));
        const double tolerance = 2 * kEps * scale_of(a, inner).area;
        EXPECT_NEAR(overlap_area(a, inner).area, area(inner), tolerance) << testing::name_of(f) << " shrunk by " << s;
        EXPECT_NEAR(overlap_area(inner, a).area, area(inner), tolerance) << testing::name_of(f) << " shrunk by " << s;
        ++count;
      }
    }
  }
  EXPECT_EQ(count, 720);
}

// Bad input: a clear error naming the problem.
TEST(OverlapArea, RefusesBadShapes) {
  EXPECT_THROW(overlap_area(Circle{{0, 0}, std::nan("")}, Circle{}), InvalidShape);
  EXPECT_THROW(overlap_area(Circle{}, Ellipse{{0, 0}, -1, 1, 0}), InvalidShape);
  EXPECT_THROW(iou(Circle{}, Rect{{std::numeric_limits<double>::infinity(), 0}, {1, 1}, 0}), InvalidShape);
  EXPECT_THROW(iou_distance(Rect{}, Segment{}), InvalidShape);
  try {
    area(Segment{});
    ADD_FAILURE() << "a segment has an area";
  } catch (const InvalidShape& e) {
    EXPECT_NE(std::string(e.what()).find("segment"), std::string::npos) << e.what();
  }
}

// Swapping A and B gives the same area, centroid and IoU distance to the bit, and the chord reversed.
TEST(OverlapArea, SymmetricToTheBit) {
  std::mt19937_64 rng(60);
  std::uniform_real_distribution<double> offset(-1.2, 1.2);
  for (const Form fa : kSolids) {
    for (const Form fb : kSolids) {
      for (int k = 0; k < 20; ++k) {
        const Shape a = random_shape(fa, 1.0, 4.0, rng);
        const Shape b = moved_to(random_shape(fb, 1.0, 4.0, rng), Vec2(offset(rng), offset(rng)));
        const OverlapArea ab = overlap_area(a, b), ba = overlap_area(b, a);
        EXPECT_EQ(ab.area, ba.area) << pair_name(fa, fb);
        EXPECT_EQ(ab.crossings, ba.crossings);
        if (ab.area > 0) EXPECT_EQ(ab.centroid, ba.centroid);
        if (ab.crossings == 2) EXPECT_EQ(ab.chord[0], ba.chord[1]);
        EXPECT_EQ(iou_distance(a, b), iou_distance(b, a)) << pair_name(fa, fb);
      }
    }
  }
}

}  // namespace
}  // namespace collide2d
