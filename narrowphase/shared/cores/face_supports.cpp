// An ellipse's support along every face normal of a core at once (convex_core.h): the faces'
// normals and first vertices across the lanes of a vector, a square root and a division a lane; and
// the bound of every vertex cone of a polygon at once (arc_bound-inl.h). Google Highway picks the
// widest vectors the CPU has at the first call.
#include "narrowphase/shared/cores/convex_core.h"
#include "narrowphase/shared/lanes.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "narrowphase/shared/cores/face_supports.cpp"
#include "hwy/foreach_target.h"  // re-includes this file once per SIMD target
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace collide2d::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

#include "narrowphase/shared/cores/arc_bound-inl.h"

// The first N slots; the rest, slots of no face, zero.
template <std::size_t N>
void supports_over(const detail::Core& c, double a, double b, detail::FaceSupports& out) {
  const hn::CappedTag<double, N> d;
  const auto aa = hn::Set(d, a * a), bb = hn::Set(d, b * b), ab = hn::Set(d, a * b);
  const double* normals = c.n[0].data();  // x and y of each normal in turn
  for (std::size_t k = 0; k < N; k += hn::Lanes(d)) {
    hn::Vec<decltype(d)> nx, ny;
    hn::LoadInterleaved2(d, normals + 2 * k, nx, ny);
    const auto ax = hn::Mul(aa, nx), by = hn::Mul(bb, ny);
    const auto h = hn::Sqrt(hn::Add(hn::Mul(ax, nx), hn::Mul(by, ny)));
    const auto inverse = hn::Div(hn::Set(d, 1.0), h);
    const auto along = hn::Add(hn::Mul(nx, hn::LoadU(d, c.x.data() + k)), hn::Mul(ny, hn::LoadU(d, c.y.data() + k)));
    hn::StoreU(h, d, out.h.data() + k);
    hn::StoreU(hn::Neg(hn::Mul(ax, inverse)), d, out.qx.data() + k);
    hn::StoreU(hn::Neg(hn::Mul(by, inverse)), d, out.qy.data() + k);
    hn::StoreU(hn::Mul(hn::Mul(ab, ab), hn::Mul(inverse, hn::Mul(inverse, inverse))), d, out.rho.data() + k);
    hn::StoreU(hn::Neg(hn::Add(h, along)), d, out.s.data() + k);
  }
}

// A capsule's four slots (two faces and the segment's two directions) or a polygon's eight: the
// widest vectors are the slowest at square roots and divisions, which half of them would waste.
void face_supports(const detail::Core& c, double a, double b, detail::FaceSupports& out) {
  if (c.axes() > 4) return supports_over<kMaxPolygonVertices>(c, a, b, out);
  supports_over<4>(c, a, b, out);
  for (auto* slots : {&out.h, &out.rho, &out.qx, &out.qy, &out.s}) std::fill(slots->begin() + 4, slots->end(), 0.0);
}

std::uint32_t cones_within(const detail::Core& c, const detail::FaceSupports& along, double least_rho, double a,
                           double b, double s) {
  const hn::CappedTag<double, kMaxPolygonVertices> d;
  // Slot k of each array below holds face prev(k)'s value: the face whose normal starts k's cone.
  std::array<double, kMaxPolygonVertices> e0x, e0y, q0x, q0y, rho0, h0;
  for (int k = 0; k < kMaxPolygonVertices; ++k) {
    const int from = k == 0 ? c.count - 1 : k - 1;
    e0x[k] = c.n[from].x(), e0y[k] = c.n[from].y(), q0x[k] = along.qx[from], q0y[k] = along.qy[from];
    rho0[k] = along.rho[from], h0[k] = along.h[from];
  }
  const double* normals = c.n[0].data();  // x and y of each normal in turn
  std::uint32_t bits = 0;
  for (std::size_t k = 0; k < kMaxPolygonVertices; k += hn::Lanes(d)) {
    ArcLanes<hn::Vec<decltype(d)>> arc;
    hn::LoadInterleaved2(d, normals + 2 * k, arc.e1x, arc.e1y);
    arc.e0x = hn::LoadU(d, e0x.data() + k), arc.e0y = hn::LoadU(d, e0y.data() + k);
    arc.q0x = hn::LoadU(d, q0x.data() + k), arc.q0y = hn::LoadU(d, q0y.data() + k);
    arc.q1x = hn::LoadU(d, along.qx.data() + k), arc.q1y = hn::LoadU(d, along.qy.data() + k);
    arc.rho0 = hn::LoadU(d, rho0.data() + k), arc.rho1 = hn::LoadU(d, along.rho.data() + k);
    arc.h0 = hn::LoadU(d, h0.data() + k), arc.h1 = hn::LoadU(d, along.h.data() + k);
    arc.vx = hn::LoadU(d, c.x.data() + k), arc.vy = hn::LoadU(d, c.y.data() + k);
    const auto within = arc_within(d, arc, hn::Set(d, least_rho), hn::Set(d, a), hn::Set(d, b), hn::Set(d, s));
    std::uint8_t lanes[8] = {};
    hn::StoreMaskBits(d, within, lanes);
    bits |= static_cast<std::uint32_t>(lanes[0]) << k;
  }
  return bits & ((1u << c.count) - 1);
}

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d::detail {

HWY_EXPORT(face_supports);
HWY_EXPORT(cones_within);

void face_supports(const Core& c, double a, double b, FaceSupports& out) {
  HWY_DYNAMIC_DISPATCH(face_supports)(c, a, b, out);
}

std::uint32_t cones_within(const Core& c, const FaceSupports& along, double least_rho, double a, double b, double s) {
  return HWY_DYNAMIC_DISPATCH(cones_within)(c, along, least_rho, a, b, s);
}

}  // namespace collide2d::detail
#endif
