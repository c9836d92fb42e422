// The batched overlap tests (batch.h, and overlap_pairs.h for the World). Google Highway
// (libhwy-dev) compiles the lane-generic filters once per SIMD target and picks the best the CPU
// offers at the first call; a plain build then runs on any x86-64 (and on ARM) without -march flags.
// Highway rather than xsimd: its runtime dispatch is built in (xsimd 8 leaves it to the caller), and
// its operations are plain functions on vector types, so each kernel's template reads the same on
// one pair and on a vector of them (lanes.h).
//
// Work goes in chunks (batch_chunk.h): the vector kernel decides the chunk, and the uncertain pairs
// go to the exact fallback one by one.
#include <collide2d/batch.h>
#include "narrowphase/batch/overlap_pairs.h"

#include "narrowphase/batch/batch_chunk.h"
#include "narrowphase/overlap/overlap_rect_ellipse.h"
#include "narrowphase/shared/frames/rect_ellipse_frame.h"
#include "narrowphase/shared/frames/rect_pair_frame.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "narrowphase/batch/overlap_batch.cpp"
#include "hwy/foreach_target.h"  // re-includes this file once per SIMD target
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace collide2d::HWY_NAMESPACE {

#include "narrowphase/overlap/overlap_circle-inl.h"
#include "narrowphase/overlap/overlap_ellipse_ellipse-inl.h"
#include "narrowphase/overlap/overlap_rect_ellipse-inl.h"
#include "narrowphase/overlap/overlap_rect_rect-inl.h"

#include "narrowphase/overlap/disc_filter-inl.h"
#include "narrowphase/shared/cores/least_quadratic-inl.h"

#include "narrowphase/batch/batch_load-inl.h"

detail::LaneVerdicts<M> decide(const detail::RectEllipseLanes<V>& f) { return RectEllipseFilter<D>(D(), f).run(); }
// The kernels that decide every lane.
detail::LaneVerdicts<M> all_decided(const M& hit) { return {hn::Not(hit), hit}; }
detail::LaneVerdicts<M> decide(const detail::RectRectLanes<V>& f) { return all_decided(rect_rect_overlap(f)); }
detail::LaneVerdicts<M> decide(const detail::CircleCircleLanes<V>& f) {
  return all_decided(circle_circle_overlap(D(), f));
}
detail::LaneVerdicts<M> decide(const detail::RectCircleLanes<V>& f) { return all_decided(rect_circle_overlap(D(), f)); }
detail::LaneVerdicts<M> decide(const detail::CircleEllipseLanes<V>& f) {
  return CircleEllipseFilter<D, V>(D(), f).run();
}
detail::LaneVerdicts<M> decide(const detail::EllipseEllipseLanes<V>& f) { return ellipse_cubic_verdicts(D(), f); }

detail::LaneVerdicts<M> decide(const detail::CoreEllipseLanes<V>& f) { return core_ellipse_verdicts(D(), f); }
detail::LaneVerdicts<M> decide(const detail::SegmentEllipseLanes<V>& f) { return core_ellipse_verdicts(D(), f); }
detail::LaneVerdicts<M> decide(const detail::DiscEllipseLanes<V>& f) { return disc_verdicts(D(), f); }
detail::LaneVerdicts<M> decide(const detail::DiscPairLanes<V>& f) { return disc_verdicts(D(), f); }
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
      const detail::FilterVerdict verdict = bit(separated) ? detail::FilterVerdict::separated
                                            : bit(overlap) ? detail::FilterVerdict::overlap
                                                           : detail::FilterVerdict::uncertain;
      chunk.verdict[i + j] = static_cast<std::uint8_t>(verdict);
    }
  }
}

void rect_ellipse_chunk(detail::Chunk<8>& chunk, std::size_t count) {
  decide_chunk<detail::RectEllipseLanes>(chunk, count);
}
void rect_rect_chunk(detail::Chunk<8>& chunk, std::size_t count) { decide_chunk<detail::RectRectLanes>(chunk, count); }
void circle_circle_chunk(detail::Chunk<4>& chunk, std::size_t count) {
  decide_chunk<detail::CircleCircleLanes>(chunk, count);
}
void rect_circle_chunk(detail::Chunk<5>& chunk, std::size_t count) {
  decide_chunk<detail::RectCircleLanes>(chunk, count);
}
void circle_ellipse_chunk(detail::Chunk<5>& chunk, std::size_t count) {
  decide_chunk<detail::CircleEllipseLanes>(chunk, count);
}
void ellipse_ellipse_chunk(detail::Chunk<10>& chunk, std::size_t count) {
  decide_chunk<detail::EllipseEllipseLanes>(chunk, count);
}

void core_ellipse_chunk(detail::Chunk<detail::PolygonEllipseLanes<double>::kFields>& chunk, std::size_t count) {
  decide_chunk<detail::PolygonEllipseLanes>(chunk, count);
}

void segment_ellipse_chunk(detail::Chunk<detail::SegmentEllipseLanes<double>::kFields>& chunk, std::size_t count) {
  decide_chunk<detail::SegmentEllipseLanes>(chunk, count);
}
void disc_ellipse_chunk(detail::Chunk<detail::DiscEllipseLanes<double>::kFields>& chunk, std::size_t count) {
  decide_chunk<detail::DiscEllipseLanes>(chunk, count);
}
void disc_pair_chunk(detail::Chunk<detail::DiscPairLanes<double>::kFields>& chunk, std::size_t count) {
  decide_chunk<detail::DiscPairLanes>(chunk, count);
}

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d {

void detail::check_lengths(const char* what, std::span<const std::size_t> in, std::size_t out, const char* results) {
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
HWY_EXPORT(ellipse_ellipse_chunk);
HWY_EXPORT(core_ellipse_chunk);
HWY_EXPORT(segment_ellipse_chunk);
HWY_EXPORT(disc_ellipse_chunk);
HWY_EXPORT(disc_pair_chunk);

}  // namespace

void detail::decide(Chunk<8>& chunk, std::size_t count, KernelOf<RectEllipseLanes<double>>) {
  HWY_DYNAMIC_DISPATCH(rect_ellipse_chunk)(chunk, count);
}
void detail::decide(Chunk<8>& chunk, std::size_t count, KernelOf<RectRectLanes<double>>) {
  HWY_DYNAMIC_DISPATCH(rect_rect_chunk)(chunk, count);
}
void detail::decide(Chunk<4>& chunk, std::size_t count, KernelOf<CircleCircleLanes<double>>) {
  HWY_DYNAMIC_DISPATCH(circle_circle_chunk)(chunk, count);
}
void detail::decide(Chunk<5>& chunk, std::size_t count, KernelOf<RectCircleLanes<double>>) {
  HWY_DYNAMIC_DISPATCH(rect_circle_chunk)(chunk, count);
}
void detail::decide(Chunk<5>& chunk, std::size_t count, KernelOf<CircleEllipseLanes<double>>) {
  HWY_DYNAMIC_DISPATCH(circle_ellipse_chunk)(chunk, count);
}
void detail::decide(Chunk<10>& chunk, std::size_t count, KernelOf<EllipseEllipseLanes<double>>) {
  HWY_DYNAMIC_DISPATCH(ellipse_ellipse_chunk)(chunk, count);
}
void detail::decide(Chunk<PolygonEllipseLanes<double>::kFields>& chunk, std::size_t count,
                    KernelOf<PolygonEllipseLanes<double>>) {
  HWY_DYNAMIC_DISPATCH(core_ellipse_chunk)(chunk, count);
}
void detail::decide(Chunk<SegmentEllipseLanes<double>::kFields>& chunk, std::size_t count,
                    KernelOf<SegmentEllipseLanes<double>>) {
  HWY_DYNAMIC_DISPATCH(segment_ellipse_chunk)(chunk, count);
}
void detail::decide(Chunk<DiscEllipseLanes<double>::kFields>& chunk, std::size_t count,
                    KernelOf<DiscEllipseLanes<double>>) {
  HWY_DYNAMIC_DISPATCH(disc_ellipse_chunk)(chunk, count);
}
void detail::decide(Chunk<DiscPairLanes<double>::kFields>& chunk, std::size_t count, KernelOf<DiscPairLanes<double>>) {
  HWY_DYNAMIC_DISPATCH(disc_pair_chunk)(chunk, count);
}

namespace {

// Shape k's orientation from its list; a circle's is not read, and its list may be empty.
template <class S>
const Orientation& orientation_at(std::span<const Orientation> list, std::size_t k) {
  static const Orientation unturned;
  if constexpr (std::is_same_v<S, Circle>) {
    return unturned;
  } else {
    return list[k];
  }
}

// The name of the pair's batch in messages: "overlap_rect_ellipse".
template <class A, class B>
inline constexpr auto kBatchName = [] {
  std::array<char, 48> out{};
  std::size_t n = 0;
  for (const std::string_view part :
       {std::string_view("overlap_"), detail::Kind<A>::word, std::string_view("_"), detail::Kind<B>::word}) {
    for (const char c : part) out[n++] = c;
  }
  return out;
}();

template <class S>
using List = std::span<const S>;
using Turns = std::span<const Orientation>;
using Verdicts = std::span<std::uint8_t>;

// The lists as pairs. A function of internal linkage, so that overlap_pairs' instance for its lambda
// is local too and GCC inlines the filling of the chunks into it; for the lambda of an externally
// visible function it calls the filling out of line.
template <class A, class B>
void overlap_lists(List<A> a, Turns a_orientations, List<B> b, Turns b_orientations, Verdicts overlapping) {
  detail::overlap_pairs<A, B>(
      [&](std::size_t k) {
        return detail::PairRef<A, B>{a[k], orientation_at<A>(a_orientations, k), b[k],
                                     orientation_at<B>(b_orientations, k)};
      },
      overlapping);
}

}  // namespace

template <class A, class B>
void detail::overlap_batch(std::span<const A> a, std::span<const Orientation> a_orientations, std::span<const B> b,
                           std::span<const Orientation> b_orientations, std::span<std::uint8_t> overlapping) {
  static_assert(detail::Pair<A, B>::batched, "the table of pairs (pairs.h) gives this pair no batch");
  constexpr bool a_turns = !std::is_same_v<A, Circle>, b_turns = !std::is_same_v<B, Circle>;
  std::array<std::size_t, 4> lengths{};
  std::size_t n = 0;
  lengths[n++] = a.size();
  if (a_turns) lengths[n++] = a_orientations.size();
  lengths[n++] = b.size();
  if (b_turns) lengths[n++] = b_orientations.size();
  detail::check_lengths(kBatchName<A, B>.data(), std::span(lengths.data(), n), overlapping.size());
  overlap_lists<A, B>(a, a_orientations, b, b_orientations, overlapping);
}

// Every batched pair's, compiled here with the library's flags. The tests run each pair of the
// table's batched list (tests/unit/test_overlap_batch.cpp), so that one missing here fails to link.
static_assert(std::tuple_size_v<detail::BatchedPairs<detail::Kinds>> == 11, "a batched pair to instantiate below");
template void detail::overlap_batch<Rect, Ellipse>(List<Rect>, Turns, List<Ellipse>, Turns, Verdicts);
template void detail::overlap_batch<Rect, Rect>(List<Rect>, Turns, List<Rect>, Turns, Verdicts);
template void detail::overlap_batch<Circle, Circle>(List<Circle>, Turns, List<Circle>, Turns, Verdicts);
template void detail::overlap_batch<Rect, Circle>(List<Rect>, Turns, List<Circle>, Turns, Verdicts);
template void detail::overlap_batch<Circle, Ellipse>(List<Circle>, Turns, List<Ellipse>, Turns, Verdicts);
template void detail::overlap_batch<Ellipse, Ellipse>(List<Ellipse>, Turns, List<Ellipse>, Turns, Verdicts);
template void detail::overlap_batch<ConvexPolygon, Ellipse>(List<ConvexPolygon>, Turns, List<Ellipse>, Turns, Verdicts);
template void detail::overlap_batch<Capsule, Ellipse>(List<Capsule>, Turns, List<Ellipse>, Turns, Verdicts);
template void detail::overlap_batch<ConvexPolygon, Circle>(List<ConvexPolygon>, Turns, List<Circle>, Turns, Verdicts);
template void detail::overlap_batch<Capsule, Circle>(List<Capsule>, Turns, List<Circle>, Turns, Verdicts);
template void detail::overlap_batch<ConvexPolygon, ConvexPolygon>(List<ConvexPolygon>, Turns, List<ConvexPolygon>,
                                                                  Turns, Verdicts);

// The public functions: each the generic form (overlap_pairs.h) of its pair.
void overlap_rect_ellipse(std::span<const Rect> rects, std::span<const Orientation> rect_orientations,
                          std::span<const Ellipse> ellipses, std::span<const Orientation> ellipse_orientations,
                          std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<Rect, Ellipse>(rects, rect_orientations, ellipses, ellipse_orientations, overlapping);
}

void overlap_rect_rect(std::span<const Rect> a, std::span<const Orientation> a_orientations, std::span<const Rect> b,
                       std::span<const Orientation> b_orientations, std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<Rect, Rect>(a, a_orientations, b, b_orientations, overlapping);
}

void overlap_circle_circle(std::span<const Circle> a, std::span<const Circle> b, std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<Circle, Circle>(a, {}, b, {}, overlapping);
}

void overlap_rect_circle(std::span<const Rect> rects, std::span<const Orientation> rect_orientations,
                         std::span<const Circle> circles, std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<Rect, Circle>(rects, rect_orientations, circles, {}, overlapping);
}

void overlap_circle_ellipse(std::span<const Circle> circles, std::span<const Ellipse> ellipses,
                            std::span<const Orientation> ellipse_orientations, std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<Circle, Ellipse>(circles, {}, ellipses, ellipse_orientations, overlapping);
}

void overlap_ellipse_ellipse(std::span<const Ellipse> a, std::span<const Orientation> a_orientations,
                             std::span<const Ellipse> b, std::span<const Orientation> b_orientations,
                             std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<Ellipse, Ellipse>(a, a_orientations, b, b_orientations, overlapping);
}

void overlap_polygon_ellipse(std::span<const ConvexPolygon> polygons, std::span<const Orientation> polygon_orientations,
                             std::span<const Ellipse> ellipses, std::span<const Orientation> ellipse_orientations,
                             std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<ConvexPolygon, Ellipse>(polygons, polygon_orientations, ellipses, ellipse_orientations,
                                                overlapping);
}

void overlap_capsule_ellipse(std::span<const Capsule> capsules, std::span<const Orientation> capsule_orientations,
                             std::span<const Ellipse> ellipses, std::span<const Orientation> ellipse_orientations,
                             std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<Capsule, Ellipse>(capsules, capsule_orientations, ellipses, ellipse_orientations, overlapping);
}

void overlap_polygon_circle(std::span<const ConvexPolygon> polygons, std::span<const Orientation> polygon_orientations,
                            std::span<const Circle> circles, std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<ConvexPolygon, Circle>(polygons, polygon_orientations, circles, {}, overlapping);
}

void overlap_capsule_circle(std::span<const Capsule> capsules, std::span<const Orientation> capsule_orientations,
                            std::span<const Circle> circles, std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<Capsule, Circle>(capsules, capsule_orientations, circles, {}, overlapping);
}

void overlap_polygon_polygon(std::span<const ConvexPolygon> a, std::span<const Orientation> a_orientations,
                             std::span<const ConvexPolygon> b, std::span<const Orientation> b_orientations,
                             std::span<std::uint8_t> overlapping) {
  detail::overlap_batch<ConvexPolygon, ConvexPolygon>(a, a_orientations, b, b_orientations, overlapping);
}

}  // namespace collide2d
#endif
