// An ellipse's support along every face normal of a core at once (convex_core.h): the faces'
// normals and first vertices across the lanes of a vector, a square root and a division a lane.
// Google Highway picks the widest vectors the CPU has at the first call.
#include "narrowphase/polygon/convex_core.h"

#include <cstddef>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "narrowphase/polygon/face_supports.cpp"
#include "hwy/foreach_target.h"  // re-includes this file once per SIMD target
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace collide2d::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

void face_supports(const detail::Core& c, double a, double b, detail::FaceSupports& out) {
  const hn::CappedTag<double, kMaxPolygonVertices> d;
  const auto aa = hn::Set(d, a * a), bb = hn::Set(d, b * b), ab = hn::Set(d, a * b);
  const double* normals = c.n[0].data();  // x and y of each normal in turn
  for (std::size_t k = 0; k < kMaxPolygonVertices; k += hn::Lanes(d)) {
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

}  // namespace collide2d::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace collide2d::detail {

HWY_EXPORT(face_supports);

void face_supports(const Core& c, double a, double b, FaceSupports& out) {
  HWY_DYNAMIC_DISPATCH(face_supports)(c, a, b, out);
}

}  // namespace collide2d::detail
#endif
