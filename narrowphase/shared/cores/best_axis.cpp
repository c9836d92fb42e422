// The separations of one core along every separating axis of another at once (convex_core.h): the
// axes' directions across the lanes of a vector, each of the other core's vertices broadcast, a
// running minimum and the first vertex at it, then the first axis beyond the caller's stop or else
// the first of the greatest. The same products, sums and minima as one axis at a time, so the
// result is the same to the bit; Google Highway picks the widest vectors the CPU has at the first
// call.
#include "narrowphase/shared/cores/convex_core.h"

#include <cstddef>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "narrowphase/shared/cores/best_axis.cpp"
#include "hwy/foreach_target.h"  // re-includes this file once per SIMD target
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace collide2d::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

template <std::size_t N>
detail::BestAxis best_axis(const double* axes_x, const double* axes_y, const double* offsets, const Vec2* y,
                           int y_count, double stop) {
  const hn::CappedTag<double, N> d;
  detail::BestAxis best;
  for (std::size_t k = 0; k < N; k += hn::Lanes(d)) {
    const auto ax = hn::LoadU(d, axes_x + k), ay = hn::LoadU(d, axes_y + k);
    auto least = hn::Add(hn::Mul(ax, hn::Set(d, y[0].x())), hn::Mul(ay, hn::Set(d, y[0].y())));
    auto vertex = hn::Zero(d);
    for (std::size_t j = 1; j < static_cast<std::size_t>(y_count); ++j) {
      const auto p = hn::Add(hn::Mul(ax, hn::Set(d, y[j].x())), hn::Mul(ay, hn::Set(d, y[j].y())));
      vertex = hn::IfThenElse(hn::Lt(p, least), hn::Set(d, static_cast<double>(j)), vertex);
      least = hn::Min(least, p);
    }
    const auto s = hn::Sub(least, hn::LoadU(d, offsets + k));
    const auto take = [&](intptr_t lane) {
      const auto i = static_cast<std::size_t>(lane);
      best = {hn::ExtractLane(s, i), static_cast<int>(k + i), static_cast<int>(hn::ExtractLane(vertex, i))};
    };
    const intptr_t beyond = hn::FindFirstTrue(d, hn::Gt(s, hn::Set(d, stop)));
    if (beyond >= 0) {
      take(beyond);
      break;
    }
    const auto top = hn::MaxOfLanes(d, s);
    if (hn::GetLane(top) > best.s) take(hn::FindFirstTrue(d, hn::Eq(s, top)));
  }
  return best;
}
detail::BestAxis best_of_four_axes(const double* ax, const double* ay, const double* ad, const Vec2* y, int y_count,
                                   double stop) {
  return best_axis<4>(ax, ay, ad, y, y_count, stop);
}
detail::BestAxis best_of_eight_axes(const double* ax, const double* ay, const double* ad, const Vec2* y, int y_count,
                                    double stop) {
  return best_axis<kMaxPolygonVertices>(ax, ay, ad, y, y_count, stop);
}

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d::detail {

HWY_EXPORT(best_of_four_axes);
HWY_EXPORT(best_of_eight_axes);

BestAxis best_axis(const AxisLanes<4>& ax, const AxisLanes<4>& ay, const AxisLanes<4>& ad, const Vec2* y, int y_count,
                   double stop) {
  return HWY_DYNAMIC_DISPATCH(best_of_four_axes)(ax.data(), ay.data(), ad.data(), y, y_count, stop);
}
BestAxis best_axis(const AxisLanes<kMaxPolygonVertices>& ax, const AxisLanes<kMaxPolygonVertices>& ay,
                   const AxisLanes<kMaxPolygonVertices>& ad, const Vec2* y, int y_count, double stop) {
  return HWY_DYNAMIC_DISPATCH(best_of_eight_axes)(ax.data(), ay.data(), ad.data(), y, y_count, stop);
}

}  // namespace collide2d::detail
#endif
