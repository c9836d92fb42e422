// Does not compile, by design: a kind with an entry but no rows in the pair table. The test
// registry_missing_row compiles it and expects the check of narrowphase/dispatch.h to refuse it,
// naming each pair without a row (RowCheck<Rect, Wedge>, ..., RowCheck<Wedge, Wedge>).
#include "narrowphase/pairs.h"

namespace wedge_test {

struct Wedge {
  collide2d::Vec2 center = collide2d::Vec2::Zero();
};
void validate(const Wedge&) {}
collide2d::Aabb aabb(const Wedge&) { return {}; }
collide2d::Vec2 support(const Wedge& w, const collide2d::Vec2&) { return w.center; }
bool contains(const Wedge&, const collide2d::Vec2&) { return false; }

}  // namespace wedge_test

namespace collide2d::detail {

template <>
struct Kind<wedge_test::Wedge> {
  static constexpr std::string_view word = "wedge";
  static constexpr std::uint32_t number = 7;
};

static_assert(
    every_pair_has_a_row<KindList<Rect, ConvexPolygon, Capsule, Segment, Circle, Ellipse, wedge_test::Wedge>>());

}  // namespace collide2d::detail
