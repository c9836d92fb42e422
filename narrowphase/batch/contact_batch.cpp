// The batched contacts (batch.h). Circle–ellipse: the point–ellipse root is nearly all of its time,
// and one pair at a time it is a chain of divisions and a square root per Newton step that the CPU
// cannot overlap; lanes of pairs stepping together, and several vectors of them side by side, fill
// that chain (Highway, as in overlap_batch.cpp). Rectangle–circle: a closed form whose cases
// (corner, face, inside) branch one pair at a time, every case computed and selected per lane.
#include <collide2d/kernels.h>
#include "narrowphase/batch/batch_chunk.h"
#include "narrowphase/shared/lanes.h"

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
#include "narrowphase/contact/contact_rect_circle-inl.h"
#include "narrowphase/shared/ellipse/point_ellipse-inl.h"

using In = detail::CirclePosedEllipseLanes<V>;
using Out = detail::ContactLanes<V>;

// The contacts into `out` at i, and each lane's `general` mask into its verdict byte (false: the
// one-off kernel takes the pair).
void store(const Out& contacts, const M& general, detail::Chunk<Out::kFields>& out, std::size_t i) {
  const D d;
  const auto fields = contacts.fields();
  for (std::size_t k = 0; k < Out::kFields; ++k) hn::StoreU(fields[k], d, out.field[k] + i);
  std::uint8_t bits[detail::kMaxLanes / 8 + 1] = {};
  hn::StoreMaskBits(d, general, bits);
  for (std::size_t j = 0; j < hn::Lanes(d); ++j) out.verdict[i + j] = bits[j / 8] >> (j % 8) & 1;
}

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
  void store_into(detail::Chunk<Out::kFields>& out, std::size_t i) const {
    store(circle_ellipse_contact(f, nearest_at_root(D(), q, root.t(), px, py)), q.general, out, i);
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
  (v[K].store_into(out, i + K * n), ...);
}

// The contacts of the chunk's first `count` pairs, in whole vectors. A Newton step is a chain of
// divisions and a square root whose latency leaves the dividers idle most of the time: kTogether
// vectors step side by side to fill them; a fourth adds nothing.
void circle_ellipse_chunk(const detail::Chunk<In::kFields>& in, detail::Chunk<Out::kFields>& out, std::size_t count) {
  constexpr std::size_t kTogether = 3;
  const std::size_t n = hn::Lanes(D());
  std::size_t i = 0;
  for (; i + (kTogether - 1) * n < count; i += kTogether * n)
    side_by_side(in, out, i, std::make_index_sequence<kTogether>());
  for (; i < count; i += n) side_by_side(in, out, i, std::index_sequence<0>());
}

// The rectangle–circle contacts of the chunk's first `count` pairs, in whole vectors.
void rect_circle_chunk(const detail::Chunk<detail::RectCirclePosedLanes<double>::kFields>& in,
                       detail::Chunk<Out::kFields>& out, std::size_t count) {
  using Lanes = detail::RectCirclePosedLanes<V>;
  const D d;
  for (std::size_t i = 0; i < count; i += hn::Lanes(d)) {
    const Lanes f = load<Lanes>(in.field, i, std::make_index_sequence<Lanes::kFields>());
    M general;
    const RectCircleFeature<V> e = rect_circle_feature(d, f, general);
    store(rect_circle_contact(f, e), general, out, i);
  }
}

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d {
namespace {

HWY_EXPORT(circle_ellipse_chunk);
HWY_EXPORT(rect_circle_chunk);

// The vector kernels for this CPU.
void run_circle_ellipse(const detail::Chunk<detail::CirclePosedEllipseLanes<double>::kFields>& in,
                        detail::Chunk<detail::ContactLanes<double>::kFields>& out, std::size_t count) {
  HWY_DYNAMIC_DISPATCH(circle_ellipse_chunk)(in, out, count);
}
void run_rect_circle(const detail::Chunk<detail::RectCirclePosedLanes<double>::kFields>& in,
                     detail::Chunk<detail::ContactLanes<double>::kFields>& out, std::size_t count) {
  HWY_DYNAMIC_DISPATCH(rect_circle_chunk)(in, out, count);
}

// Runs a batch chunk by chunk: lanes_of(k) fills pair k's lanes, chunk(in, out, count) runs the
// vector kernel, and one_off(k) takes the pairs it leaves.
template <class In, class LanesOf, class RunChunk, class OneOff>
void contact_batch(std::span<Contact> contacts, LanesOf lanes_of, RunChunk chunk, OneOff one_off) {
  using Out = detail::ContactLanes<double>;
  detail::Chunk<In::kFields> in;
  detail::Chunk<Out::kFields> out;
  static_assert(in.kPairs == out.kPairs);
  for (std::size_t start = 0; start < contacts.size(); start += in.kPairs) {
    const std::size_t count = std::min(in.kPairs, contacts.size() - start);
    detail::fill_chunk(in, start, count, lanes_of);
    chunk(in, out, count);
    for (std::size_t i = 0; i < count; ++i) {
      if (!out.verdict[i]) {
        contacts[start + i] = one_off(start + i);
        continue;
      }
      const auto lane = [&](std::size_t field) { return out.field[field][i]; };
      contacts[start + i] =
          Contact::of(lane(0), Vec2(lane(1), lane(2)), Vec2(lane(3), lane(4)), Vec2(lane(5), lane(6)));
    }
  }
}

}  // namespace

void contact_circle_ellipse(std::span<const Circle> circles, std::span<const Ellipse> ellipses,
                            std::span<const Orientation> ellipse_orientations, std::span<Contact> contacts) {
  detail::check_lengths("contact_circle_ellipse",
                        std::array{circles.size(), ellipses.size(), ellipse_orientations.size()}, contacts.size(),
                        "contacts");
  contact_batch<detail::CirclePosedEllipseLanes<double>>(
      contacts,
      [&](std::size_t k) {
        return detail::circle_posed_ellipse_lanes(circles[k], ellipses[k], ellipse_orientations[k]);
      },
      run_circle_ellipse,
      [&](std::size_t k) { return contact_circle_ellipse(circles[k], ellipses[k], ellipse_orientations[k]); });
}

void contact_rect_circle(std::span<const Rect> rects, std::span<const Orientation> rect_orientations,
                         std::span<const Circle> circles, std::span<Contact> contacts) {
  detail::check_lengths("contact_rect_circle", std::array{rects.size(), rect_orientations.size(), circles.size()},
                        contacts.size(), "contacts");
  contact_batch<detail::RectCirclePosedLanes<double>>(
      contacts,
      [&](std::size_t k) { return detail::rect_circle_posed_lanes(rects[k], rect_orientations[k], circles[k]); },
      run_rect_circle, [&](std::size_t k) { return contact_rect_circle(rects[k], rect_orientations[k], circles[k]); });
}

}  // namespace collide2d
#endif
