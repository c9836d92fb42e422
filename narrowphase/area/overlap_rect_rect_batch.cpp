// The rectangle-pair areas of the IoU batches (narrowphase/area/batch.cpp) in vectors: the lane
// kernel of narrowphase/area/rect_rect_area-inl.h compiled once per SIMD target by Google Highway,
// the best the CPU offers picked at the first call, as narrowphase/batch/overlap_batch.cpp does.
#include "narrowphase/area/overlap_rect_rect.h"

#include "narrowphase/shared/lanes.h"

#include <cstddef>
#include <utility>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "narrowphase/area/overlap_rect_rect_batch.cpp"
#include "hwy/foreach_target.h"  // re-includes this file once per SIMD target
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace collide2d::HWY_NAMESPACE {

#include "narrowphase/area/rect_rect_area-inl.h"
#include "narrowphase/batch/batch_load-inl.h"

void rect_rect_area_chunk(detail::Chunk<8>& chunk, std::size_t count, double* out) {
  for (std::size_t i = 0; i < count; i += hn::Lanes(D())) {
    const auto lanes = load<detail::RectRectLanes<V>>(chunk.field, i, std::make_index_sequence<8>());
    hn::StoreU(rect_rect_area(D(), lanes), D(), out + i);
  }
}

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d::detail::areas {
namespace {
HWY_EXPORT(rect_rect_area_chunk);
}  // namespace

void rect_rect_areas(Chunk<8>& chunk, std::size_t count, double* out) {
  HWY_DYNAMIC_DISPATCH(rect_rect_area_chunk)(chunk, count, out);
}

}  // namespace collide2d::detail::areas
#endif
