// The batched overlap tests (overlap_batch.h). Google Highway (libhwy-dev) compiles the lane-generic
// filters once per SIMD target and picks the best the CPU offers at the first call; a plain build
// then runs on any x86-64 (and on ARM) without -march flags. Highway rather than xsimd: its runtime
// dispatch is built in (xsimd 8 leaves it to the caller), and its operations are plain functions on
// vector types, so each kernel's template reads the same on one pair and on a vector of them
// (lanes.h).
//
// Work goes in chunks (batch_chunk.h): the vector kernel decides the chunk, and the uncertain pairs
// go to the exact fallback one by one.
#include "narrowphase/overlap_batch.h"
#include "narrowphase/overlap_pairs.h"

#include "narrowphase/batch_chunk.h"
#include "narrowphase/kernel_order.h"
#include "narrowphase/overlap_rect_ellipse.h"
#include "narrowphase/rect_ellipse_frame.h"
#include "narrowphase/rect_pair_frame.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "narrowphase/overlap_batch.cpp"
#include "hwy/foreach_target.h"  // re-includes this file once per SIMD target
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace collide2d::HWY_NAMESPACE {

#include "narrowphase/circle_overlap-inl.h"
#include "narrowphase/rect_ellipse_filter-inl.h"
#include "narrowphase/rect_rect_overlap-inl.h"

#include "narrowphase/batch_load-inl.h"

detail::LaneVerdicts<M> decide(const detail::RectEllipseLanes<V>& f) { return RectEllipseFilter<D>(D(), f).run(); }
// The kernels that decide every lane.
detail::LaneVerdicts<M> all_decided(const M& hit) { return {hn::Not(hit), hit}; }
detail::LaneVerdicts<M> decide(const detail::RectRectLanes<V>& f) { return all_decided(rect_rect_overlap(f)); }
detail::LaneVerdicts<M> decide(const detail::CircleCircleLanes<V>& f) { return all_decided(circle_circle_overlap(D(), f)); }
detail::LaneVerdicts<M> decide(const detail::RectCircleLanes<V>& f) { return all_decided(rect_circle_overlap(D(), f)); }
detail::LaneVerdicts<M> decide(const detail::CircleEllipseLanes<V>& f) { return CircleEllipseFilter<D, V>(D(), f).run(); }

// The kernel on the chunk's first `count` pairs, in whole vectors.
template <template <class> class Lanes>
void decide_chunk(detail::Chunk<Lanes<double>::kFields>& chunk, std::size_t count) {
  constexpr std::size_t kFields = Lanes<double>::kFields;
  const std::size_t lanes = hn::Lanes(D());
  for (std::size_t i = 0; i < count; i += lanes) {
    const auto v = decide(load<Lanes<V>>(chunk.field, i, std::make_index_sequence<kFields>()));
    std::uint8_t separated[detail::kMaxLanes / 8 + 1] = {}, overlap[detail::kMaxLanes / 8 + 1] = {};
    hn::StoreMaskBits(D(), v.separated, separated);
    hn::StoreMaskBits(D(), v.overlap, overlap);
    for (std::size_t j = 0; j < lanes; ++j) {
      const auto bit = [j](const std::uint8_t* bits) { return (bits[j / 8] >> (j % 8) & 1) != 0; };
      const FilterVerdict verdict =
          bit(separated) ? FilterVerdict::separated : bit(overlap) ? FilterVerdict::overlap : FilterVerdict::uncertain;
      chunk.verdict[i + j] = static_cast<std::uint8_t>(verdict);
    }
  }
}

void rect_ellipse_chunk(detail::Chunk<8>& chunk, std::size_t count) { decide_chunk<detail::RectEllipseLanes>(chunk, count); }
void rect_rect_chunk(detail::Chunk<8>& chunk, std::size_t count) { decide_chunk<detail::RectRectLanes>(chunk, count); }
void circle_circle_chunk(detail::Chunk<4>& chunk, std::size_t count) { decide_chunk<detail::CircleCircleLanes>(chunk, count); }
void rect_circle_chunk(detail::Chunk<5>& chunk, std::size_t count) { decide_chunk<detail::RectCircleLanes>(chunk, count); }
void circle_ellipse_chunk(detail::Chunk<5>& chunk, std::size_t count) { decide_chunk<detail::CircleEllipseLanes>(chunk, count); }

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d {

void detail::check_lengths(const char* what, std::initializer_list<std::size_t> in, std::size_t out, const char* results) {
  if (std::all_of(in.begin(), in.end(), [out](std::size_t n) { return n == out; })) return;
  std::string lengths;
  for (const std::size_t n : in) lengths += std::to_string(n) + ", ";
  lengths.resize(lengths.size() - 2);
  throw std::invalid_argument(std::string(what) + ": the lists differ in length (" + lengths + " pairs in, " +
                              std::to_string(out) + " " + results + " out)");
}

namespace {

HWY_EXPORT(rect_ellipse_chunk);
HWY_EXPORT(rect_rect_chunk);
HWY_EXPORT(circle_circle_chunk);
HWY_EXPORT(rect_circle_chunk);
HWY_EXPORT(circle_ellipse_chunk);

// Pair k's lanes (the one-off kernel's inputs and rounding), two shapes of one kind in the
// dispatcher's key order.
detail::RectEllipseLanes<double> lanes_of(const detail::PairRef<Rect, Ellipse>& p) {
  const Orientation &ro = p.a_orientation, &eo = p.b_orientation;
  return detail::rect_ellipse_lanes(detail::rect_ellipse_frame<double>(p.a, {ro.c, ro.s}, p.b, {eo.c, eo.s}));
}
detail::RectRectLanes<double> lanes_of(const detail::PairRef<Rect, Rect>& p) {
  return detail::key(p.b) < detail::key(p.a) ? detail::rect_rect_lanes(p.b, p.b_orientation, p.a, p.a_orientation)
                                             : detail::rect_rect_lanes(p.a, p.a_orientation, p.b, p.b_orientation);
}
detail::CircleCircleLanes<double> lanes_of(const detail::PairRef<Circle, Circle>& p) {
  return detail::key(p.b) < detail::key(p.a) ? detail::circle_circle_lanes(p.b, p.a) : detail::circle_circle_lanes(p.a, p.b);
}
detail::RectCircleLanes<double> lanes_of(const detail::PairRef<Rect, Circle>& p) {
  return detail::rect_circle_lanes(p.a, p.a_orientation, p.b);
}
detail::CircleEllipseLanes<double> lanes_of(const detail::PairRef<Circle, Ellipse>& p) {
  return detail::circle_ellipse_lanes(p.a, p.b, p.b_orientation);
}

// The verdict of a pair the vector kernel left uncertain.
bool exact(const detail::PairRef<Rect, Ellipse>& p) { return detail::minkowski_fallback(p.a, p.b); }
bool exact(const detail::PairRef<Circle, Ellipse>& p) { return detail::circle_ellipse_exact(lanes_of(p)); }
template <class A, class B>
bool exact(const detail::PairRef<A, B>&) {
  throw std::logic_error("a kernel that decides every pair left one uncertain");
}

// The vector kernel of a pair kind on the chunk's first `count` pairs.
template <class A, class B>
struct Kinds {};
void decide(detail::Chunk<8>& chunk, std::size_t count, Kinds<Rect, Ellipse>) {
  HWY_DYNAMIC_DISPATCH(rect_ellipse_chunk)(chunk, count);
}
void decide(detail::Chunk<8>& chunk, std::size_t count, Kinds<Rect, Rect>) {
  HWY_DYNAMIC_DISPATCH(rect_rect_chunk)(chunk, count);
}
void decide(detail::Chunk<4>& chunk, std::size_t count, Kinds<Circle, Circle>) {
  HWY_DYNAMIC_DISPATCH(circle_circle_chunk)(chunk, count);
}
void decide(detail::Chunk<5>& chunk, std::size_t count, Kinds<Rect, Circle>) {
  HWY_DYNAMIC_DISPATCH(rect_circle_chunk)(chunk, count);
}
void decide(detail::Chunk<5>& chunk, std::size_t count, Kinds<Circle, Ellipse>) {
  HWY_DYNAMIC_DISPATCH(circle_ellipse_chunk)(chunk, count);
}

// The public functions' lists as a pair source; a circle's orientations may be left empty.
template <class A, class B>
struct Lists {
  std::span<const A> a;
  std::span<const Orientation> a_orientations;
  std::span<const B> b;
  std::span<const Orientation> b_orientations;

  static detail::PairRef<A, B> pair(const void* context, std::size_t k) {
    static const Orientation unturned;
    const Lists& l = *static_cast<const Lists*>(context);
    return {l.a[k], l.a_orientations.empty() ? unturned : l.a_orientations[k], l.b[k],
            l.b_orientations.empty() ? unturned : l.b_orientations[k]};
  }
  void run(std::span<std::uint8_t> overlapping) const { detail::overlap_pairs<A, B>({this, &Lists::pair}, overlapping); }
};

}  // namespace

// The batch in chunks: each pair's lanes from scalar code (the one-off kernel's rounding), the
// chunk's verdicts from the vector kernel, and each pair it left uncertain from the exact fallback.
template <class A, class B>
void detail::overlap_pairs(const PairSource<A, B>& pairs, std::span<std::uint8_t> overlapping) {
  using Lanes = decltype(lanes_of(std::declval<PairRef<A, B>>()));
  const auto pair = [&](std::size_t k) { return pairs.pair(pairs.context, k); };
  detail::Chunk<Lanes::kFields> chunk;
  for (std::size_t start = 0; start < overlapping.size(); start += detail::kChunk) {
    const std::size_t count = std::min(detail::kChunk, overlapping.size() - start);
    detail::fill_chunk(chunk, start, count, [&](std::size_t k) { return lanes_of(pair(k)); });
    decide(chunk, count, Kinds<A, B>());
    for (std::size_t i = 0; i < count; ++i) {
      const auto verdict = static_cast<FilterVerdict>(chunk.verdict[i]);
      const bool hit = verdict == FilterVerdict::uncertain ? exact(pair(start + i)) : verdict == FilterVerdict::overlap;
      overlapping[start + i] = hit ? 1 : 0;
    }
  }
}

template void detail::overlap_pairs<Rect, Ellipse>(const PairSource<Rect, Ellipse>&, std::span<std::uint8_t>);
template void detail::overlap_pairs<Rect, Rect>(const PairSource<Rect, Rect>&, std::span<std::uint8_t>);
template void detail::overlap_pairs<Circle, Circle>(const PairSource<Circle, Circle>&, std::span<std::uint8_t>);
template void detail::overlap_pairs<Rect, Circle>(const PairSource<Rect, Circle>&, std::span<std::uint8_t>);
template void detail::overlap_pairs<Circle, Ellipse>(const PairSource<Circle, Ellipse>&, std::span<std::uint8_t>);

void overlap_rect_ellipse(std::span<const Rect> rects, std::span<const Orientation> rect_orientations,
                          std::span<const Ellipse> ellipses, std::span<const Orientation> ellipse_orientations,
                          std::span<std::uint8_t> overlapping) {
  detail::check_lengths("overlap_rect_ellipse", {rects.size(), rect_orientations.size(), ellipses.size(), ellipse_orientations.size()},
                        overlapping.size());
  Lists<Rect, Ellipse>{rects, rect_orientations, ellipses, ellipse_orientations}.run(overlapping);
}

void overlap_rect_rect(std::span<const Rect> a, std::span<const Orientation> a_orientations, std::span<const Rect> b,
                       std::span<const Orientation> b_orientations, std::span<std::uint8_t> overlapping) {
  detail::check_lengths("overlap_rect_rect", {a.size(), a_orientations.size(), b.size(), b_orientations.size()}, overlapping.size());
  Lists<Rect, Rect>{a, a_orientations, b, b_orientations}.run(overlapping);
}

void overlap_circle_circle(std::span<const Circle> a, std::span<const Circle> b, std::span<std::uint8_t> overlapping) {
  detail::check_lengths("overlap_circle_circle", {a.size(), b.size()}, overlapping.size());
  Lists<Circle, Circle>{a, {}, b, {}}.run(overlapping);
}

void overlap_rect_circle(std::span<const Rect> rects, std::span<const Orientation> rect_orientations,
                         std::span<const Circle> circles, std::span<std::uint8_t> overlapping) {
  detail::check_lengths("overlap_rect_circle", {rects.size(), rect_orientations.size(), circles.size()}, overlapping.size());
  Lists<Rect, Circle>{rects, rect_orientations, circles, {}}.run(overlapping);
}

void overlap_circle_ellipse(std::span<const Circle> circles, std::span<const Ellipse> ellipses,
                            std::span<const Orientation> ellipse_orientations, std::span<std::uint8_t> overlapping) {
  detail::check_lengths("overlap_circle_ellipse", {circles.size(), ellipses.size(), ellipse_orientations.size()},
                        overlapping.size());
  Lists<Circle, Ellipse>{circles, {}, ellipses, ellipse_orientations}.run(overlapping);
}

}  // namespace collide2d
#endif
