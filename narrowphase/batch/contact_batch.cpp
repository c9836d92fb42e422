// The batched circle–ellipse contact (contact.h). The point–ellipse root is nearly all of a
// circle–ellipse contact's time, and one pair at a time it is a chain of divisions and a square
// root per Newton step that the CPU cannot overlap; lanes of pairs stepping together, and several
// vectors of them side by side, fill that chain (Highway, as in overlap_batch.cpp).
#include <collide2d/kernels.h>
#include "narrowphase/batch/batch_chunk.h"
#include "narrowphase/batch/lanes.h"

#include <algorithm>
#include <cstddef>
#include <utility>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "narrowphase/batch/contact_batch.cpp"
#include "hwy/foreach_target.h"  // re-includes this file once per SIMD target
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace collide2d::HWY_NAMESPACE {

#include "narrowphase/batch/batch_load-inl.h"
#include "narrowphase/ellipse/point_ellipse-inl.h"

using In = detail::CirclePosedEllipseLanes<V>;
using Out = detail::ContactLanes<V>;

// One vector of pairs on its way: the centres in the ellipses' frames and the root in progress.
struct Vectors {
  In f;
  V px, py;
  Quadrant<V, M> q;
  SecularRoot<D, V> root;

  Vectors(const detail::Chunk<In::kFields>& in, std::size_t i)
      : f(load<In>(in.field, i, std::make_index_sequence<In::kFields>())),
        q((circle_centre_in_ellipse_frame(f, px, py), Quadrant<V, M>::of(D(), px, py, f.a, f.b))),
        root(D(), q.r0, q.z0, q.z1) {}

  // The contacts into `out` at i, and whether each lane's root holds (general) or the pair is an
  // axis case into its verdict bytes.
  void store(detail::Chunk<Out::kFields>& out, std::size_t i) const {
    const D d;
    const auto nearest = nearest_at_root(d, q, root.t(), px, py);
    const auto fields = circle_ellipse_contact(f, nearest).fields();
    for (std::size_t k = 0; k < Out::kFields; ++k) hn::StoreU(fields[k], d, out.field[k] + i);
    std::uint8_t general[detail::kMaxLanes / 8 + 1] = {};
    hn::StoreMaskBits(d, q.general, general);
    for (std::size_t j = 0; j < hn::Lanes(d); ++j) out.verdict[i + j] = general[j / 8] >> (j % 8) & 1;
  }
};

// The vectors of pairs at i, i + n, ... (n lanes each) stepping side by side until every lane has
// stopped, each where the one-off root stops. A vector whose lanes have all stopped steps no more,
// rather than waiting for the slowest lane of the group.
template <std::size_t... K>
void side_by_side(const detail::Chunk<In::kFields>& in, detail::Chunk<Out::kFields>& out, std::size_t i,
                  std::index_sequence<K...>) {
  const std::size_t n = hn::Lanes(D());
  Vectors v[] = {Vectors(in, i + K * n)...};
  bool running[] = {(static_cast<void>(K), true)...};
  while ((static_cast<int>(running[K] && (running[K] = v[K].root.step())) |
          ...)) {  // |, not ||: each vector running steps
  }
  (v[K].store(out, i + K * n), ...);
}

// The contacts of the chunk's first `count` pairs, in whole vectors. A Newton step is a chain of
// divisions and a square root, about 55 cycles, that leaves the dividers idle most of the time:
// kTogether vectors step side by side to fill them; a fourth adds nothing.
void contact_chunk(const detail::Chunk<In::kFields>& in, detail::Chunk<Out::kFields>& out, std::size_t count) {
  constexpr std::size_t kTogether = 3;
  const std::size_t n = hn::Lanes(D());
  std::size_t i = 0;
  for (; i + (kTogether - 1) * n < count; i += kTogether * n)
    side_by_side(in, out, i, std::make_index_sequence<kTogether>());
  for (; i < count; i += n) side_by_side(in, out, i, std::index_sequence<0>());
}

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d {
namespace {

HWY_EXPORT(contact_chunk);

}  // namespace

void contact_circle_ellipse(std::span<const Circle> circles, std::span<const Ellipse> ellipses,
                            std::span<const Orientation> ellipse_orientations, std::span<Contact> contacts) {
  detail::check_lengths("contact_circle_ellipse", {circles.size(), ellipses.size(), ellipse_orientations.size()},
                        contacts.size(), "contacts");
  const auto lanes_of = [&](std::size_t k) {
    return detail::circle_posed_ellipse_lanes(circles[k], ellipses[k], ellipse_orientations[k]);
  };
  detail::Chunk<detail::CirclePosedEllipseLanes<double>::kFields> in;
  detail::Chunk<detail::ContactLanes<double>::kFields> out;
  for (std::size_t start = 0; start < contacts.size(); start += detail::kChunk) {
    const std::size_t count = std::min(detail::kChunk, contacts.size() - start);
    detail::fill_chunk(in, start, count, lanes_of);
    HWY_DYNAMIC_DISPATCH(contact_chunk)(in, out, count);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t k = start + i;
      const auto lane = [&](std::size_t field) { return out.field[field][i]; };
      contacts[k] =
          out.verdict[i]
              ? detail::ContactLanes<double>{lane(0), lane(1), lane(2), lane(3), lane(4), lane(5), lane(6)}.contact()
              : contact_circle_ellipse(circles[k], ellipses[k], ellipse_orientations[k]);
    }
  }
}

}  // namespace collide2d
#endif
