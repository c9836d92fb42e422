// The batched circle–ellipse contact (contact.h). The point–ellipse root is nearly all of a
// circle–ellipse contact's time, and one pair at a time it is a chain of two divisions and a square
// root per Newton step that the CPU cannot overlap; lanes of pairs stepping together fill that
// chain (Highway, as in overlap_batch.cpp).
#include "narrowphase/batch_chunk.h"
#include "narrowphase/contact.h"
#include "narrowphase/lanes.h"

#include <algorithm>
#include <cstddef>
#include <utility>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "narrowphase/contact_batch.cpp"
#include "hwy/foreach_target.h"  // re-includes this file once per SIMD target
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace collide2d::HWY_NAMESPACE {

#include "narrowphase/batch_load-inl.h"
#include "narrowphase/point_ellipse-inl.h"

using Lanes = detail::CircleEllipseLanes<V>;

void store(const detail::NearestOnEllipse<V, M>& n, detail::Chunk<7>& out, std::size_t i) {
  const D d;
  const V one = hn::Set(d, 1.0);
  const V fields[7] = {n.distance, n.qx, n.qy, n.nx, n.ny, hn::IfThenElseZero(n.inside, one), hn::IfThenElseZero(n.general, one)};
  for (std::size_t k = 0; k < 7; ++k) hn::StoreU(fields[k], d, out.field[k] + i);
}

// The nearest ellipse points of the chunk's first `count` circle centres, in whole vectors, into
// `out`: distance, the point, the normal, inside and general (1 or 0). (Two or four vectors
// stepping together gained nothing: the dividers, which the square root shares, are already the
// bottleneck.)
void nearest_chunk(const detail::Chunk<Lanes::kFields>& in, detail::Chunk<7>& out, std::size_t count) {
  const D d;
  for (std::size_t i = 0; i < count; i += hn::Lanes(d)) {
    const Lanes f = load<Lanes>(in.field, i, std::make_index_sequence<Lanes::kFields>());
    store(nearest_on_ellipse(d, f.px, f.py, f.a, f.b), out, i);
  }
}

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d {
namespace {

HWY_EXPORT(nearest_chunk);

}  // namespace

void contact_circle_ellipse(std::span<const Circle> circles, std::span<const Ellipse> ellipses,
                            std::span<const Orientation> ellipse_orientations, std::span<Contact> contacts) {
  detail::check_lengths("contact_circle_ellipse", {circles.size(), ellipses.size(), ellipse_orientations.size()},
                        contacts.size(), "contacts");
  const auto lanes_of = [&](std::size_t k) {
    return detail::circle_ellipse_lanes(circles[k], ellipses[k], ellipse_orientations[k]);
  };
  detail::Chunk<detail::CircleEllipseLanes<double>::kFields> in;
  detail::Chunk<7> out;
  for (std::size_t start = 0; start < contacts.size(); start += detail::kChunk) {
    const std::size_t count = std::min(detail::kChunk, contacts.size() - start);
    detail::fill_chunk(in, start, count, lanes_of);
    HWY_DYNAMIC_DISPATCH(nearest_chunk)(in, out, count);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t k = start + i;
      const auto lane = [&](std::size_t field) { return out.field[field][i]; };
      const Ellipse& e = ellipses[k];
      const PointEllipseResult r =
          lane(6) != 0 ? detail::point_ellipse_result({lane(0), lane(1), lane(2), lane(3), lane(4), lane(5) != 0, true})
                       : distance_point_ellipse(e.a, e.b, Vec2(in.field[0][i], in.field[1][i]));
      contacts[k] = detail::circle_ellipse_contact(circles[k], e, ellipse_orientations[k], r);
    }
  }
}

}  // namespace collide2d
#endif
