// Private: the batched overlap tests (batch.h) over pairs given by reference rather than as
// lists of copies: pair(k) returns pair k as a PairRef. The World passes its bodies by index this
// way, so that a batch entry is two indices and no shape is copied; the public functions are this
// over their lists. A template, so that pair(k) inlines: a call through a function pointer would
// cost as much as a rectangle pair's whole test.
#pragma once

#include <collide2d/shapes.h>
#include "narrowphase/batch/batch_chunk.h"
#include "narrowphase/overlap/overlap_ellipse_ellipse.h"
#include "narrowphase/overlap/overlap_rect_ellipse.h"
#include "narrowphase/pairs.h"
#include "narrowphase/shared/cores/convex_core.h"
#include "narrowphase/shared/frames/rect_ellipse_frame.h"
#include "narrowphase/shared/frames/rect_pair_frame.h"
#include "narrowphase/shared/lanes.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>

namespace collide2d::detail {

template <class A, class B>
struct PairRef {
  const A& a;
  const Orientation& a_orientation;  // a circle's is not read
  const B& b;
  const Orientation& b_orientation;
};

// Pair k's lanes (the one-off kernel's inputs and rounding), two shapes of one kind in the
// dispatcher's key order.
inline RectEllipseLanes<double> lanes_of(const PairRef<Rect, Ellipse>& p) {
  const Orientation &ro = p.a_orientation, &eo = p.b_orientation;
  return rect_ellipse_lanes(rect_ellipse_frame<double>(p.a, Rotation<double>::of(ro), p.b, Rotation<double>::of(eo)));
}
inline RectRectLanes<double> lanes_of(const PairRef<Rect, Rect>& p) {
  return precedes(p.b, p.a) ? rect_rect_lanes(p.b, p.b_orientation, p.a, p.a_orientation)
                            : rect_rect_lanes(p.a, p.a_orientation, p.b, p.b_orientation);
}
inline CircleCircleLanes<double> lanes_of(const PairRef<Circle, Circle>& p) {
  return precedes(p.b, p.a) ? circle_circle_lanes(p.b, p.a) : circle_circle_lanes(p.a, p.b);
}
inline RectCircleLanes<double> lanes_of(const PairRef<Rect, Circle>& p) {
  return rect_circle_lanes(p.a, p.a_orientation, p.b);
}
inline CircleEllipseLanes<double> lanes_of(const PairRef<Circle, Ellipse>& p) {
  return circle_ellipse_lanes(p.a, p.b, p.b_orientation);
}
inline EllipseEllipseLanes<double> lanes_of(const PairRef<Ellipse, Ellipse>& p) {
  return precedes(p.b, p.a) ? ellipse_ellipse_lanes(p.b, p.b_orientation, p.a, p.a_orientation)
                            : ellipse_ellipse_lanes(p.a, p.a_orientation, p.b, p.b_orientation);
}

// A core shape's core placed in the frame of an ellipse of semi-axes a, b posed at `frame_center` and
// `frame`.
template <class A, std::size_t N = std::tuple_size_v<std::decay_t<decltype(slots_of(std::declval<A>()))>>>
CoreEllipseLanes<double, N> core_ellipse_lanes(const A& shape, const Orientation& o, const Vec2& frame_center,
                                               const Orientation& frame, double a, double b) {
  const Placement at = Placement::of(shape.center, o, frame_center, frame);
  const auto& slots = slots_of(shape);
  CoreEllipseLanes<double, N> f;  // every field set below: no zero fill first
  f.ox = at.offset.x(), f.oy = at.offset.y(), f.c = at.rot.c, f.s = at.rot.s;
  for (std::size_t i = 0; i < N; ++i) f.vx[i] = slots[i].x(), f.vy[i] = slots[i].y();
  f.count = count_of(shape), f.radius = radius_of(shape), f.a = a, f.b = b;
  return f;
}
template <class A>
auto lanes_of(const PairRef<A, Ellipse>& p) {
  return core_ellipse_lanes(p.a, p.a_orientation, p.b.center, p.b_orientation, p.b.a, p.b.b);
}
// A circle is the ellipse of two equal semi-axes: its quadratic is the squared distance over r^2,
// and its bounds on a rounded core's reach (quadratic_verdicts) meet.
template <class A>
requires on_cores<A, Circle>
auto lanes_of(const PairRef<A, Circle>& p) {
  return core_ellipse_lanes(p.a, p.a_orientation, p.b.center, Orientation{}, p.b.radius, p.b.radius);
}

// Pair k's disc lanes (disc_filter-inl.h, convex_core.h's disc_lanes) for a core shape A, two
// shapes of one kind in the dispatcher's key order.
template <class A, class B>
auto disc_lanes_of(const PairRef<A, B>& p) {
  if constexpr (std::is_same_v<A, B>) {
    if (precedes(p.b, p.a)) return disc_lanes(p.b, p.b_orientation, p.a, p.a_orientation);
  }
  return disc_lanes(p.a, p.a_orientation, p.b, p.b_orientation);
}

// The verdict of a pair the vector kernel left uncertain.
inline bool exact(const PairRef<Rect, Ellipse>& p) { return minkowski_fallback(p.a, p.b); }
inline bool exact(const PairRef<Circle, Ellipse>& p) { return circle_ellipse_exact(lanes_of(p)); }
// The one-off kernel whole (its algebraic test is again uncertain, then its certain cases and GJK).
inline bool exact(const PairRef<Ellipse, Ellipse>& p) {
  return precedes(p.b, p.a) ? overlap_ellipse_ellipse(p.b, p.b_orientation, p.a, p.a_orientation)
                            : overlap_ellipse_ellipse(p.a, p.a_orientation, p.b, p.b_orientation);
}
// A core shape against an ellipse: the one-off test whole.
template <class A>
bool exact(const PairRef<A, Ellipse>& p) {
  return core_ellipse_overlap(CoreEllipse::of(p.a, p.a_orientation, p.b, p.b_orientation));
}
// Two core shapes, or a core shape and a circle: the one-off test whole, in the dispatcher's order.
template <class A, class B>
requires(on_cores<A, B> && !std::is_same_v<B, Ellipse>) bool exact(const PairRef<A, B>& p) {
  if constexpr (std::is_same_v<A, B>) {
    if (precedes(p.b, p.a)) return core_overlap(core_pair(p.b, p.b_orientation, p.a, p.a_orientation));
  }
  return core_overlap(core_pair(p.a, p.a_orientation, p.b, p.b_orientation));
}
template <class A, class B>
bool exact(const PairRef<A, B>&) {
  throw std::logic_error("a kernel that decides every pair left one uncertain");
}

// The vector kernel of a kind of lanes on the chunk's first `count` pairs (overlap_batch.cpp: the
// best SIMD target the CPU has). Kernels are named by their lanes, so that pair kinds whose lanes
// are one kind (a polygon against an ellipse or a circle) share one.
template <class Lanes>
struct KernelOf {};
void decide(Chunk<8>& chunk, std::size_t count, KernelOf<RectEllipseLanes<double>>);
void decide(Chunk<8>& chunk, std::size_t count, KernelOf<RectRectLanes<double>>);
void decide(Chunk<4>& chunk, std::size_t count, KernelOf<CircleCircleLanes<double>>);
void decide(Chunk<5>& chunk, std::size_t count, KernelOf<RectCircleLanes<double>>);
void decide(Chunk<5>& chunk, std::size_t count, KernelOf<CircleEllipseLanes<double>>);
void decide(Chunk<10>& chunk, std::size_t count, KernelOf<EllipseEllipseLanes<double>>);
void decide(Chunk<PolygonEllipseLanes<double>::kFields>& chunk, std::size_t count,
            KernelOf<PolygonEllipseLanes<double>>);
void decide(Chunk<SegmentEllipseLanes<double>::kFields>& chunk, std::size_t count,
            KernelOf<SegmentEllipseLanes<double>>);
void decide(Chunk<DiscEllipseLanes<double>::kFields>& chunk, std::size_t count, KernelOf<DiscEllipseLanes<double>>);
void decide(Chunk<DiscPairLanes<double>::kFields>& chunk, std::size_t count, KernelOf<DiscPairLanes<double>>);

// The verdict the vector kernel left in a chunk's slot, or else the exact fallback's.
template <class Ref>
bool verdict_or_exact(std::uint8_t slot, const Ref& pair) {
  const auto verdict = static_cast<FilterVerdict>(slot);
  return verdict == FilterVerdict::uncertain ? exact(pair) : verdict == FilterVerdict::overlap;
}

// overlapping[at(i)] for i < n: in chunks, each pair's lanes from scalar code, the chunk's verdicts
// from the kind's vector kernel, each pair it left uncertain from the exact fallback; the exact
// test alone where the kind has no vector kernel of its own.
template <class A, class B, class Pair, class At>
void settle(Pair pair, std::size_t n, At at, std::span<std::uint8_t> overlapping) {
  if constexpr (requires(const PairRef<A, B>& p) { lanes_of(p); }) {
    using Lanes = decltype(lanes_of(std::declval<PairRef<A, B>>()));
    Chunk<Lanes::kFields> chunk;
    for (std::size_t start = 0; start < n; start += chunk.kPairs) {
      const std::size_t count = std::min(chunk.kPairs, n - start);
      fill_chunk(chunk, start, count, [&](std::size_t i) { return lanes_of(pair(at(i))); });
      decide(chunk, count, KernelOf<Lanes>());
      for (std::size_t i = 0; i < count; ++i) {
        overlapping[at(start + i)] = verdict_or_exact(chunk.verdict[i], pair(at(start + i))) ? 1 : 0;
      }
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) overlapping[at(i)] = exact(pair(at(i))) ? 1 : 0;
  }
}

// overlapping[k] for the pairs k < overlapping.size(), A before B in rank order (shapes/kinds.h).
// A pair on convex cores first meets the disc test (a few fields a pair, no vertex read), and only
// the pairs it leaves go on.
template <class A, class B, class Pair>
void overlap_pairs(Pair pair, std::span<std::uint8_t> overlapping) {
  if constexpr (on_cores<A, B>) {
    using Lanes = decltype(disc_lanes_of(std::declval<PairRef<A, B>>()));
    Chunk<Lanes::kFields> discs;
    std::array<std::size_t, discs.kPairs> open;
    for (std::size_t start = 0; start < overlapping.size(); start += discs.kPairs) {
      const std::size_t count = std::min(discs.kPairs, overlapping.size() - start);
      fill_chunk(discs, start, count, [&](std::size_t k) { return disc_lanes_of(pair(k)); });
      decide(discs, count, KernelOf<Lanes>());
      std::size_t n = 0;
      for (std::size_t i = 0; i < count; ++i) {
        const auto verdict = static_cast<FilterVerdict>(discs.verdict[i]);
        if (verdict == FilterVerdict::uncertain) open[n++] = start + i;
        overlapping[start + i] = verdict == FilterVerdict::overlap ? 1 : 0;
      }
      settle<A, B>(
          pair, n, [&](std::size_t i) { return open[i]; }, overlapping);
    }
  } else {
    settle<A, B>(
        pair, overlapping.size(), [](std::size_t k) { return k; }, overlapping);
  }
}

// The batched overlap tests of a pair of kinds with a batch (pairs.h), A before B in rank order, on
// lists: each list as long as the results (a circle's orientations aside), then overlap_pairs.
// Throws std::invalid_argument, naming the lengths, before anything is written. Instantiated in
// overlap_batch.cpp for every batched pair, so that the tests, the benchmarks and the Python module
// run the code the library compiled.
template <class A, class B>
void overlap_batch(std::span<const A> a, std::span<const Orientation> a_orientations, std::span<const B> b,
                   std::span<const Orientation> b_orientations, std::span<std::uint8_t> overlapping);

}  // namespace collide2d::detail
