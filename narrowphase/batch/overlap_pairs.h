// Private: the batched overlap tests (overlap_batch.h) over pairs given by reference rather than as
// lists of copies: pair(k) returns pair k as a PairRef. The World passes its bodies by index this
// way, so that a batch entry is two indices and no shape is copied; the public functions are this
// over their lists. A template, so that pair(k) inlines: a call through a function pointer would
// cost as much as a rectangle pair's whole test.
#pragma once

#include <collide2d/shapes.h>
#include "narrowphase/batch/batch_chunk.h"
#include "narrowphase/batch/lanes.h"
#include "narrowphase/frames/rect_ellipse_frame.h"
#include "narrowphase/frames/rect_pair_frame.h"
#include "narrowphase/kernel_order.h"
#include "narrowphase/overlap/overlap_ellipse_ellipse.h"
#include "narrowphase/overlap/overlap_rect_ellipse.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
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
  return rect_ellipse_lanes(rect_ellipse_frame<double>(p.a, {ro.c, ro.s}, p.b, {eo.c, eo.s}));
}
inline RectRectLanes<double> lanes_of(const PairRef<Rect, Rect>& p) {
  return key(p.b) < key(p.a) ? rect_rect_lanes(p.b, p.b_orientation, p.a, p.a_orientation)
                             : rect_rect_lanes(p.a, p.a_orientation, p.b, p.b_orientation);
}
inline CircleCircleLanes<double> lanes_of(const PairRef<Circle, Circle>& p) {
  return key(p.b) < key(p.a) ? circle_circle_lanes(p.b, p.a) : circle_circle_lanes(p.a, p.b);
}
inline RectCircleLanes<double> lanes_of(const PairRef<Rect, Circle>& p) {
  return rect_circle_lanes(p.a, p.a_orientation, p.b);
}
inline CircleEllipseLanes<double> lanes_of(const PairRef<Circle, Ellipse>& p) {
  return circle_ellipse_lanes(p.a, p.b, p.b_orientation);
}
inline EllipseEllipseLanes<double> lanes_of(const PairRef<Ellipse, Ellipse>& p) {
  return key(p.b) < key(p.a) ? ellipse_ellipse_lanes(p.b, p.b_orientation, p.a, p.a_orientation)
                             : ellipse_ellipse_lanes(p.a, p.a_orientation, p.b, p.b_orientation);
}

// The verdict of a pair the vector kernel left uncertain.
inline bool exact(const PairRef<Rect, Ellipse>& p) { return minkowski_fallback(p.a, p.b); }
inline bool exact(const PairRef<Circle, Ellipse>& p) { return circle_ellipse_exact(lanes_of(p)); }
// The one-off kernel whole (its algebraic test is again uncertain, then its certain cases and GJK).
inline bool exact(const PairRef<Ellipse, Ellipse>& p) {
  return key(p.b) < key(p.a) ? overlap_ellipse_ellipse(p.b, p.b_orientation, p.a, p.a_orientation)
                             : overlap_ellipse_ellipse(p.a, p.a_orientation, p.b, p.b_orientation);
}
template <class A, class B>
bool exact(const PairRef<A, B>&) {
  throw std::logic_error("a kernel that decides every pair left one uncertain");
}

// The vector kernel of a pair kind on the chunk's first `count` pairs (overlap_batch.cpp: the best
// SIMD target the CPU has).
template <class A, class B>
struct Kinds {};
void decide(Chunk<8>& chunk, std::size_t count, Kinds<Rect, Ellipse>);
void decide(Chunk<8>& chunk, std::size_t count, Kinds<Rect, Rect>);
void decide(Chunk<4>& chunk, std::size_t count, Kinds<Circle, Circle>);
void decide(Chunk<5>& chunk, std::size_t count, Kinds<Rect, Circle>);
void decide(Chunk<5>& chunk, std::size_t count, Kinds<Circle, Ellipse>);
void decide(Chunk<10>& chunk, std::size_t count, Kinds<Ellipse, Ellipse>);

// overlapping[k] for the pairs k < overlapping.size(), A before B in kernel order (rectangle,
// circle, ellipse). In chunks: each pair's lanes from scalar code, the
// chunk's verdicts from the vector kernel, each pair it left uncertain from the exact fallback.
template <class A, class B, class Pair>
void overlap_pairs(Pair pair, std::span<std::uint8_t> overlapping) {
  using Lanes = decltype(lanes_of(std::declval<PairRef<A, B>>()));
  Chunk<Lanes::kFields> chunk;
  for (std::size_t start = 0; start < overlapping.size(); start += kChunk) {
    const std::size_t count = std::min(kChunk, overlapping.size() - start);
    fill_chunk(chunk, start, count, [&](std::size_t k) { return lanes_of(pair(k)); });
    decide(chunk, count, Kinds<A, B>());
    for (std::size_t i = 0; i < count; ++i) {
      const auto verdict = static_cast<FilterVerdict>(chunk.verdict[i]);
      const bool hit = verdict == FilterVerdict::uncertain ? exact(pair(start + i)) : verdict == FilterVerdict::overlap;
      overlapping[start + i] = hit ? 1 : 0;
    }
  }
}

}  // namespace collide2d::detail
