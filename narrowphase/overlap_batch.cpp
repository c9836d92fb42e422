// The batched overlap tests (overlap_batch.h). Google Highway (libhwy-dev) compiles the lane-generic
// filters once per SIMD target and picks the best the CPU offers at the first call; a plain build
// then runs on any x86-64 (and on ARM) without -march flags. Highway rather than xsimd: its runtime
// dispatch is built in (xsimd 8 leaves it to the caller), and its operations are plain functions on
// vector types, so the filter's template reads the same on one pair and on a vector of them
// (scalar_lane.h).
//
// Work goes in chunks of 256 pairs: the scalar code builds each pair's frame (the same rounding as
// the one-off kernel), the vector filter decides the chunk, and the uncertain pairs go to the
// exact fallback one by one.
#include "narrowphase/overlap_batch.h"

#include "narrowphase/overlap_rect_ellipse.h"
#include "narrowphase/rect_ellipse_frame.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "narrowphase/overlap_batch.cpp"
#include "hwy/foreach_target.h"  // re-includes this file once per SIMD target
#include "hwy/highway.h"

#ifndef COLLIDE2D_OVERLAP_BATCH_CHUNK
#define COLLIDE2D_OVERLAP_BATCH_CHUNK
namespace collide2d::detail {

inline constexpr std::size_t kChunk = 256;
// The widest vector of doubles any target has: chunks are padded to a multiple of it.
inline constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);
static_assert(kChunk % kMaxLanes == 0);

// A chunk of rectangle–ellipse pairs in the rectangle's frame, one array per field, and the
// filter's verdict (a FilterVerdict) for each.
struct RectEllipseChunk {
  double x0[kChunk], x1[kChunk], e0[kChunk], e1[kChunk], c[kChunk], s[kChunk], a[kChunk], b[kChunk];
  std::uint8_t verdict[kChunk];
};

}  // namespace collide2d::detail
#endif

HWY_BEFORE_NAMESPACE();
namespace collide2d::HWY_NAMESPACE {

#include "narrowphase/rect_ellipse_filter-inl.h"

// The filter on the chunk's first `count` pairs (a multiple of every target's lane count).
void rect_ellipse_filter(detail::RectEllipseChunk& chunk, std::size_t count) {
  namespace hn = hwy::HWY_NAMESPACE;
  using D = hn::ScalableTag<double>;
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  for (std::size_t i = 0; i < count; i += lanes) {
    const RectEllipseLanes<hn::Vec<D>> f{hn::LoadU(d, chunk.x0 + i), hn::LoadU(d, chunk.x1 + i),
                                         hn::LoadU(d, chunk.e0 + i), hn::LoadU(d, chunk.e1 + i),
                                         hn::LoadU(d, chunk.c + i),  hn::LoadU(d, chunk.s + i),
                                         hn::LoadU(d, chunk.a + i),  hn::LoadU(d, chunk.b + i)};
    const auto v = RectEllipseFilter<D>(d, f).run();
    std::uint8_t separated[detail::kMaxLanes / 8 + 1] = {}, overlap[detail::kMaxLanes / 8 + 1] = {};
    hn::StoreMaskBits(d, v.separated, separated);
    hn::StoreMaskBits(d, v.overlap, overlap);
    for (std::size_t j = 0; j < lanes; ++j) {
      const auto bit = [j](const std::uint8_t* bits) { return (bits[j / 8] >> (j % 8) & 1) != 0; };
      const FilterVerdict verdict =
          bit(separated) ? FilterVerdict::separated : bit(overlap) ? FilterVerdict::overlap : FilterVerdict::uncertain;
      chunk.verdict[i + j] = static_cast<std::uint8_t>(verdict);
    }
  }
}

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d {
namespace {

HWY_EXPORT(rect_ellipse_filter);

void check_lengths(const char* what, std::size_t first, std::size_t second, std::size_t third, std::size_t fourth,
                   std::size_t out) {
  if (first == second && first == third && first == fourth && first == out) return;
  throw std::invalid_argument(std::string(what) + ": the lists differ in length (" + std::to_string(first) + ", " +
                              std::to_string(second) + ", " + std::to_string(third) + ", " + std::to_string(fourth) +
                              " pairs in, " + std::to_string(out) + " verdicts out)");
}

}  // namespace

void overlap_rect_ellipse(std::span<const Rect> rects, std::span<const Orientation> rect_orientations,
                          std::span<const Ellipse> ellipses, std::span<const Orientation> ellipse_orientations,
                          std::span<std::uint8_t> overlapping) {
  check_lengths("overlap_rect_ellipse", rects.size(), rect_orientations.size(), ellipses.size(),
                ellipse_orientations.size(), overlapping.size());
  detail::RectEllipseChunk chunk;
  for (std::size_t start = 0; start < rects.size(); start += detail::kChunk) {
    const std::size_t count = std::min(detail::kChunk, rects.size() - start);
    const std::size_t padded = (count + detail::kMaxLanes - 1) / detail::kMaxLanes * detail::kMaxLanes;
    for (std::size_t i = 0; i < padded; ++i) {
      const std::size_t k = start + std::min(i, count - 1);  // the padding repeats the last pair
      const Orientation& ro = rect_orientations[k];
      const Orientation& eo = ellipse_orientations[k];
      const detail::RectEllipseFrame<double> f =
          detail::rect_ellipse_frame<double>(rects[k], {ro.c, ro.s}, ellipses[k], {eo.c, eo.s});
      chunk.x0[i] = f.x[0];
      chunk.x1[i] = f.x[1];
      chunk.e0[i] = f.e[0];
      chunk.e1[i] = f.e[1];
      chunk.c[i] = f.c;
      chunk.s[i] = f.s;
      chunk.a[i] = f.a;
      chunk.b[i] = f.b;
    }
    HWY_DYNAMIC_DISPATCH(rect_ellipse_filter)(chunk, padded);
    for (std::size_t i = 0; i < count; ++i) {
      const auto verdict = static_cast<FilterVerdict>(chunk.verdict[i]);
      const bool hit = verdict == FilterVerdict::uncertain ? detail::minkowski_fallback(rects[start + i], ellipses[start + i])
                                                           : verdict == FilterVerdict::overlap;
      overlapping[start + i] = hit ? 1 : 0;
    }
  }
}

}  // namespace collide2d
#endif
