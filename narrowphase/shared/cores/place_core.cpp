// An eight-slot core placed in another shape's frame (convex_core.h), every slot at once: the
// vertices' and normals' coordinates across the lanes of a vector, turned and moved with the
// products and sums of Placement::point() and direction(), then each face's axis from them as
// one at a time. The same operations, so the same bits; Google Highway picks the widest vectors
// the CPU has at the first call.
#include "narrowphase/shared/cores/convex_core.h"

#include <cstddef>
#include <limits>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "narrowphase/shared/cores/place_core.cpp"
#include "hwy/foreach_target.h"  // re-includes this file once per SIMD target
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace collide2d::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

void place_slots(const Vec2* vertices, const Vec2* normals, int normal_count, int faces, const detail::Placement& at,
                 detail::Core& c) {
  const hn::CappedTag<double, kMaxPolygonVertices> d;
  using V = hn::Vec<decltype(d)>;
  const bool moves = at.moves();
  const auto cos = hn::Set(d, at.rot.c), sin = hn::Set(d, at.rot.s);
  // Rotation::apply()'s products and sums; in place where the placement is the identity, which
  // keeps a zero's sign.
  const auto turn = [&](V& x, V& y) {
    if (!moves) return;
    const V tx = hn::Sub(hn::Mul(cos, x), hn::Mul(sin, y));
    y = hn::Add(hn::Mul(sin, x), hn::Mul(cos, y));
    x = tx;
  };
  const auto ox = hn::Set(d, at.offset.x()), oy = hn::Set(d, at.offset.y());
  const auto zero = hn::Zero(d), no_offset = hn::Set(d, std::numeric_limits<double>::infinity());
  const auto slot = hn::Iota(d, 0.0);
  auto largest = zero;
  for (std::size_t k = 0; k < kMaxPolygonVertices; k += hn::Lanes(d)) {
    V x, y, mx, my;
    hn::LoadInterleaved2(d, vertices[k].data(), x, y);
    hn::LoadInterleaved2(d, normals[k].data(), mx, my);
    turn(x, y);
    if (moves) x = hn::Add(ox, x), y = hn::Add(oy, y);
    turn(mx, my);
    const auto at_k = hn::Add(slot, hn::Set(d, static_cast<double>(k)));
    const auto given = hn::Lt(at_k, hn::Set(d, static_cast<double>(normal_count)));
    const auto face = hn::Lt(at_k, hn::Set(d, static_cast<double>(faces)));
    mx = hn::IfThenElse(given, mx, zero), my = hn::IfThenElse(given, my, zero);
    largest = hn::Max(largest, hn::Max(hn::Abs(x), hn::Abs(y)));
    hn::StoreU(x, d, c.x.data() + k), hn::StoreU(y, d, c.y.data() + k);
    hn::StoreInterleaved2(x, y, d, c.v[k].data());
    hn::StoreInterleaved2(mx, my, d, c.n[k].data());
    hn::StoreU(hn::IfThenElse(face, mx, zero), d, c.ax.data() + k);
    hn::StoreU(hn::IfThenElse(face, my, zero), d, c.ay.data() + k);
    const auto along = hn::Add(hn::Mul(mx, x), hn::Mul(my, y));  // n.v, as plane_of's
    hn::StoreU(hn::IfThenElse(face, along, no_offset), d, c.ad.data() + k);
  }
  c.largest = hn::GetLane(hn::MaxOfLanes(d, largest));
}

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d::detail {

HWY_EXPORT(place_slots);

void place_slots(const std::array<Vec2, kMaxPolygonVertices>& vertices,
                 const std::array<Vec2, kMaxPolygonVertices>& normals, int normal_count, int faces, const Placement& at,
                 Core& c) {
  HWY_DYNAMIC_DISPATCH(place_slots)(vertices.data(), normals.data(), normal_count, faces, at, c);
}

}  // namespace collide2d::detail
#endif
