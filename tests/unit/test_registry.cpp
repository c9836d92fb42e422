// The registry of kinds and the table of pairs (shapes/kinds.h, narrowphase/pairs.h): the numbers the
// formats keep for ever, and a kind added through them alone. The half-plane below is a kind of this
// test's own: its entry, its geometry and its rows, in this file only. The list of kinds with it
// dispatches every query, the library's kinds as the library does and the half-plane's pairs by its
// rows, checked against answers known in closed form.
#include <collide2d/query.h>

#include "narrowphase/pairs.h"
#include "shapes/kinds.h"
#include "tools/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <variant>

namespace registry_test {

using namespace collide2d;

// The points p with normal.p <= offset: a floor, a wall, the sea. normal is a unit vector.
struct HalfPlane {
  Vec2 normal = Vec2::UnitY();
  double offset = 0.0;
};

// Its geometry, as every kind has (detail::ShapeKind).
void validate(const HalfPlane& h) {
  if (!h.normal.allFinite() || std::abs(h.normal.norm() - 1.0) > 1e-12 || !std::isfinite(h.offset))
    throw InvalidShape("half-plane normal must be a finite unit vector and its offset finite");
}
Aabb aabb(const HalfPlane&) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return {Vec2::Constant(-kInf), Vec2::Constant(kInf)};
}
// The point on its line nearest the origin, along its normal; no point of it is farther along a
// direction that is not the normal.
Vec2 support(const HalfPlane& h, const Vec2&) { return h.offset * h.normal; }
bool contains(const HalfPlane& h, const Vec2& p) { return h.normal.dot(p) <= h.offset; }

using Shape7 = std::variant<Circle, Ellipse, Rect, Capsule, ConvexPolygon, Segment, HalfPlane>;

}  // namespace registry_test

namespace collide2d::detail {

using registry_test::HalfPlane;

template <>
struct Kind<HalfPlane> {
  static constexpr std::string_view word = "halfplane";
  static constexpr std::uint32_t number = 6;
  static std::array<double, 3> key(const HalfPlane& h) { return {h.normal.x(), h.normal.y(), h.offset}; }
};

using KindsWithHalfPlane = KindList<Rect, ConvexPolygon, Capsule, Segment, Circle, Ellipse, HalfPlane>;

// Any kind against the half-plane: the kind's point deepest towards it is its support point along
// -normal; the separation that point's height over the line, the normal from the shape to the
// half-plane -normal.
struct OnHalfPlane : NoBoundary {
  static constexpr bool batched = false;
  template <class X>
  static Vec2 deepest(const X& x, const HalfPlane& h) {
    return support(x, Vec2(-h.normal));
  }
  template <class X>
  static double height(const X& x, const HalfPlane& h) {
    return h.normal.dot(deepest(x, h)) - h.offset;
  }
  template <class X>
  static bool overlap(const X& x, const HalfPlane& h) {
    return height(x, h) <= 0.0;
  }
  template <class X>
  static bool posed_overlap(const X& x, const Orientation&, const HalfPlane& h, const Orientation&) {
    return overlap(x, h);
  }
  template <class X>
  static DistanceResult distance(const X& x, const HalfPlane& h) {
    const Vec2 p = deepest(x, h);
    const double s = height(x, h);
    return s <= 0.0 ? DistanceResult::touching(p) : DistanceResult::apart(s, p, Vec2(p - s * h.normal));
  }
  template <class X>
  static Contact contact(const X& x, const Orientation&, const HalfPlane& h, const Orientation&, const ContactOptions&,
                         bool) {
    const Vec2 p = deepest(x, h);
    const double s = height(x, h);
    return Contact::of(s, -h.normal, p, Vec2(p - s * h.normal));
  }
};

template <>
struct Pair<Rect, HalfPlane> : OnHalfPlane {};
template <>
struct Pair<ConvexPolygon, HalfPlane> : OnHalfPlane {};
template <>
struct Pair<Capsule, HalfPlane> : OnHalfPlane {};
template <>
struct Pair<Segment, HalfPlane> : OnHalfPlane {};
template <>
struct Pair<Circle, HalfPlane> : OnHalfPlane {};
template <>
struct Pair<Ellipse, HalfPlane> : OnHalfPlane {};
template <>
struct Pair<HalfPlane, HalfPlane> : Unsupported {};

static_assert(every_pair_has_a_row<KindsWithHalfPlane>());
static_assert(KindsWithHalfPlane::numbers_distinct());

}  // namespace collide2d::detail

namespace registry_test {
namespace {

using detail::KindsWithHalfPlane;

Shape7 widen(const Shape& s) {
  return std::visit([](const auto& x) { return Shape7(x); }, s);
}

// The formats keep each kind's number for ever: a replay written before reads the same.
TEST(Registry, NumbersAreTheFormatsOwn) {
  EXPECT_EQ(detail::kind_number(Circle{}), 0u);
  EXPECT_EQ(detail::kind_number(Ellipse{}), 1u);
  EXPECT_EQ(detail::kind_number(Rect{}), 2u);
  EXPECT_EQ(detail::kind_number(Capsule{}), 3u);
  EXPECT_EQ(detail::kind_number(ConvexPolygon{}), 4u);
  EXPECT_EQ(detail::kind_number(Segment{}), 5u);
  EXPECT_EQ(detail::Kinds::words("chain"), "circle, ellipse, rect, capsule, polygon, segment or chain");
}

// The list with the half-plane dispatches the library's pairs as the library does, to the bit.
TEST(Registry, AnotherListDispatchesTheLibrarysPairsAlike) {
  std::mt19937_64 rng(7);
  const tool::Uniform size(0.2, 2), turn(-3, 3);
  const auto random_shape = [&](int kind) -> Shape {
    const Vec2 c = tool::uniform_point(rng, -3, 3);
    switch (kind) {
      case 0:
        return Circle{c, size(rng)};
      case 1:
        return Ellipse{c, size(rng), size(rng), turn(rng)};
      case 2:
        return Rect{c, tool::uniform_point(rng, 0.2, 2), turn(rng)};
      case 3:
        return Capsule{c, size(rng), size(rng), turn(rng)};
      case 4:
        return ConvexPolygon::regular(5, size(rng), 0.1).at(c, turn(rng));
      default:
        return Segment{c, tool::uniform_point(rng, 0.2, 2), turn(rng)};
    }
  };
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    const Shape a = random_shape(i % 6), b = random_shape(i / 6 % 6);
    if (std::holds_alternative<Segment>(a) && std::holds_alternative<Segment>(b)) continue;
    const Shape7 wa = widen(a), wb = widen(b);
    ASSERT_EQ(detail::overlap_of<KindsWithHalfPlane>(wa, wb), overlaps(a, b));
    const DistanceResult d = detail::distance_of<KindsWithHalfPlane>(wa, wb), e = distance(a, b);
    ASSERT_EQ(d.distance, e.distance);
    ASSERT_EQ(d.point_a, e.point_a);
    const Orientation oa = Orientation::of(angle_of(a)), ob = Orientation::of(angle_of(b));
    const Contact c = detail::contact_of<KindsWithHalfPlane>(wa, oa, wb, ob, {}), k = contact(a, b);
    ASSERT_EQ(c.separation, k.separation);
    ASSERT_EQ(c.normal, k.normal);
    ++compared;
  }
  EXPECT_GT(compared, 1900);
}

// Each kind at height 2 above the floor y <= -1, its lowest point known in closed form: the
// separation, the overlap, the distance and the normal, in either order.
TEST(Registry, TheHalfPlaneMeetsEveryKindByItsRows) {
  const HalfPlane floor{Vec2::UnitY(), -1.0};
  const double t = 0.4, c = std::cos(t), s = std::sin(t);
  struct Case {
    Shape shape;
    double lowest;  // the shape's least y
  };
  const Case cases[] = {
      {Circle{Vec2(0.3, 2), 0.5}, 1.5},
      {Ellipse{Vec2(0.3, 2), 1.5, 0.5, t}, 2 - std::hypot(1.5 * s, 0.5 * c)},
      {Rect{Vec2(0.3, 2), Vec2(1.5, 0.5), t}, 2 - (1.5 * s + 0.5 * c)},
      {Capsule{Vec2(0.3, 2), 1.5, 0.5, t}, 2 - 1.5 * s - 0.5},
      {ConvexPolygon::box(1.5, 0.5).at(Vec2(0.3, 2), t), 2 - (1.5 * s + 0.5 * c)},
      {Segment{Vec2(0.3, 2), Vec2(-1.5, 0), t}, 2 - 1.5 * s},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(shape_name(k.shape));
    for (const double lift : {-3.0, -2.0, -0.5, 0.0, 1.0}) {
      const Shape moved = std::visit(
          [&](auto x) -> Shape {
            x.center.y() += lift;
            return x;
          },
          k.shape);
      const double height = k.lowest + lift - (-1.0);
      const Shape7 x = widen(moved), h = floor;
      EXPECT_EQ(detail::overlap_of<KindsWithHalfPlane>(x, h), height <= 1e-12);
      EXPECT_EQ(detail::overlap_of<KindsWithHalfPlane>(h, x), detail::overlap_of<KindsWithHalfPlane>(x, h));
      const Contact ahead = detail::contact_of<KindsWithHalfPlane>(x, {}, h, {}, {});
      EXPECT_NEAR(ahead.separation, height, 1e-12);
      EXPECT_EQ(ahead.normal, Vec2(0, -1));
      const Contact back = detail::contact_of<KindsWithHalfPlane>(h, {}, x, {}, {});
      EXPECT_EQ(back.separation, ahead.separation);
      EXPECT_EQ(back.normal, Vec2(0, 1));
      EXPECT_EQ(back.point_a, ahead.point_b);
      const DistanceResult d = detail::distance_of<KindsWithHalfPlane>(x, h);
      EXPECT_NEAR(d.distance, std::max(height, 0.0), 1e-12);
    }
  }
}

// A row the table marks unsupported refuses each query.
TEST(Registry, AnUnsupportedRowRefuses) {
  const Shape7 a = HalfPlane{}, b = HalfPlane{Vec2::UnitX(), 2.0};
  EXPECT_THROW(detail::overlap_of<KindsWithHalfPlane>(a, b), UnsupportedPair);
  EXPECT_THROW(detail::distance_of<KindsWithHalfPlane>(a, b), UnsupportedPair);
  EXPECT_THROW(detail::boundary_of<KindsWithHalfPlane>(a, Shape7(Circle{})), UnsupportedPair);
}

}  // namespace
}  // namespace registry_test
