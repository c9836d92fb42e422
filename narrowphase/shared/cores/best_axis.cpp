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

// The axes' directions from `load(d, k, ax, ay)`, lanes k on; the other core's least projection on
// them and its first vertex there from `least_of(d, ax, ay, least, vertex)`.
template <std::size_t N, class Load, class Least>
detail::BestAxis best_axis(Load load, Least least_of, const double* offsets, double stop) {
  const hn::CappedTag<double, N> d;
  detail::BestAxis best;
  for (std::size_t k = 0; k < N; k += hn::Lanes(d)) {
    hn::Vec<decltype(d)> ax, ay, least, vertex;
    load(d, k, ax, ay);
    least_of(d, ax, ay, least, vertex);
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
// The `count` points y, one at a time.
inline auto least_of_points(const Vec2* y, int count) {
  return [y, count](auto d, auto ax, auto ay, auto& least, auto& vertex) {
    least = hn::Add(hn::Mul(ax, hn::Set(d, y[0].x())), hn::Mul(ay, hn::Set(d, y[0].y())));
    vertex = hn::Zero(d);
    for (std::size_t j = 1; j < static_cast<std::size_t>(count); ++j) {
      const auto p = hn::Add(hn::Mul(ax, hn::Set(d, y[j].x())), hn::Mul(ay, hn::Set(d, y[j].y())));
      vertex = hn::IfThenElse(hn::Lt(p, least), hn::Set(d, static_cast<double>(j)), vertex);
      least = hn::Min(least, p);
    }
  };
}
// A rectangle of half extents (hx, hy) about the origin, its vertices (-hx, -hy), (hx, -hy),
// (hx, hy) and (-hx, hy): their projections -s, d, s and -d for the sums s and d of ax hx and
// ay hy (rounding is symmetric, so the same bits), the least -max(|s|, |d|) at the first vertex
// that has it.
inline auto least_of_rect(double hx, double hy) {
  return [hx, hy](auto d, auto ax, auto ay, auto& least, auto& vertex) {
    const auto a = hn::Mul(ax, hn::Set(d, hx)), b = hn::Mul(ay, hn::Set(d, hy));
    const auto s = hn::Add(a, b), t = hn::Sub(a, b), m = hn::Max(hn::Abs(s), hn::Abs(t));
    least = hn::Neg(m);
    const auto at = [d](double j) { return hn::Set(d, j); };
    vertex = hn::IfThenElse(hn::Eq(s, m), at(0),
                            hn::IfThenElse(hn::Eq(t, least), at(1), hn::IfThenElse(hn::Eq(s, least), at(2), at(3))));
  };
}
// The directions' coordinates apart.
inline auto load_apart(const double* ax, const double* ay) {
  return [ax, ay](auto d, std::size_t k, auto& x, auto& y) { x = hn::LoadU(d, ax + k), y = hn::LoadU(d, ay + k); };
}
template <std::size_t N>
detail::BestAxis best_of_axes(const double* ax, const double* ay, const double* ad, const Vec2* y, int y_count,
                              double stop) {
  return best_axis<N>(load_apart(ax, ay), least_of_points(y, y_count), ad, stop);
}
detail::BestAxis best_of_four_axes(const double* ax, const double* ay, const double* ad, const Vec2* y, int y_count,
                                   double stop) {
  return best_of_axes<4>(ax, ay, ad, y, y_count, stop);
}
detail::BestAxis best_of_eight_axes(const double* ax, const double* ay, const double* ad, const Vec2* y, int y_count,
                                    double stop) {
  return best_of_axes<kMaxPolygonVertices>(ax, ay, ad, y, y_count, stop);
}
// The directions as points, x and y in turn: a polygon outline's normals, read in place.
detail::BestAxis best_of_eight_normals(const Vec2* normals, const double* ad, const Vec2* y, int y_count, double stop) {
  const auto load = [normals](auto d, std::size_t k, auto& x, auto& y) {
    hn::LoadInterleaved2(d, normals[k].data(), x, y);
  };
  return best_axis<kMaxPolygonVertices>(load, least_of_points(y, y_count), ad, stop);
}
// Against a rectangle of half extents (hx, hy).
detail::BestAxis best_of_eight_axes_on_rect(const double* ax, const double* ay, const double* ad, double hx, double hy,
                                            double stop) {
  return best_axis<kMaxPolygonVertices>(load_apart(ax, ay), least_of_rect(hx, hy), ad, stop);
}

// The least (or greatest, `most`) of the eight slots c and the first slot at it.
template <class D>
void extreme_of(D d, const double* c, bool most, double& value, int& slot) {
  auto m = hn::LoadU(d, c);
  for (std::size_t k = hn::Lanes(d); k < kMaxPolygonVertices; k += hn::Lanes(d)) {
    m = most ? hn::Max(m, hn::LoadU(d, c + k)) : hn::Min(m, hn::LoadU(d, c + k));
  }
  const auto e = most ? hn::MaxOfLanes(d, m) : hn::MinOfLanes(d, m);
  value = hn::GetLane(e);
  for (std::size_t k = 0;; k += hn::Lanes(d)) {
    const intptr_t at = hn::FindFirstTrue(d, hn::Eq(hn::LoadU(d, c + k), e));
    if (at >= 0) return void(slot = static_cast<int>(k) + static_cast<int>(at));
  }
}
void core_extremes(const detail::Core& c, detail::Extremes* out) {
  const hn::CappedTag<double, kMaxPolygonVertices> d;
  for (int k = 0; k < 2; ++k) {
    const double* along = k == 0 ? c.x.data() : c.y.data();
    extreme_of(d, along, false, out[k].least, out[k].at_least);
    extreme_of(d, along, true, out[k].most, out[k].at_most);
  }
}

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d::detail {

HWY_EXPORT(best_of_four_axes);
HWY_EXPORT(best_of_eight_axes);
HWY_EXPORT(best_of_eight_normals);
HWY_EXPORT(core_extremes);
HWY_EXPORT(best_of_eight_axes_on_rect);

BestAxis best_axis(const AxisLanes<4>& ax, const AxisLanes<4>& ay, const AxisLanes<4>& ad, const Vec2* y, int y_count,
                   double stop) {
  return HWY_DYNAMIC_DISPATCH(best_of_four_axes)(ax.data(), ay.data(), ad.data(), y, y_count, stop);
}
BestAxis best_axis(const AxisLanes<kMaxPolygonVertices>& ax, const AxisLanes<kMaxPolygonVertices>& ay,
                   const AxisLanes<kMaxPolygonVertices>& ad, const Vec2* y, int y_count, double stop) {
  return HWY_DYNAMIC_DISPATCH(best_of_eight_axes)(ax.data(), ay.data(), ad.data(), y, y_count, stop);
}
BestAxis best_axis(const std::array<Vec2, kMaxPolygonVertices>& normals, const AxisLanes<kMaxPolygonVertices>& ad,
                   const Vec2* y, int y_count, double stop) {
  return HWY_DYNAMIC_DISPATCH(best_of_eight_normals)(normals.data(), ad.data(), y, y_count, stop);
}
BestAxis best_axis(const AxisLanes<kMaxPolygonVertices>& ax, const AxisLanes<kMaxPolygonVertices>& ay,
                   const AxisLanes<kMaxPolygonVertices>& ad, const Vec2& half_extents, double stop) {
  return HWY_DYNAMIC_DISPATCH(best_of_eight_axes_on_rect)(ax.data(), ay.data(), ad.data(), half_extents.x(),
                                                          half_extents.y(), stop);
}
std::array<Extremes, 2> coordinate_extremes_in_lanes(const Core& c) {
  std::array<Extremes, 2> out;
  HWY_DYNAMIC_DISPATCH(core_extremes)(c, out.data());
  return out;
}

}  // namespace collide2d::detail
#endif
