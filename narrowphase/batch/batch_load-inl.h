// Private: the vector types of the batched kernels, and loading a chunk's lanes (batch_chunk.h)
// into them. Included inside the per-target namespace of a Highway file, once per target (no
// #pragma once).
#if defined(COLLIDE2D_BATCH_LOAD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_BATCH_LOAD_INL_H_
#undef COLLIDE2D_BATCH_LOAD_INL_H_
#else
#define COLLIDE2D_BATCH_LOAD_INL_H_
#endif

namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<double>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

// The lanes i ... i + Lanes(D()) - 1 of the chunk's fields.
template <class Lanes, std::size_t kStride, std::size_t... I>
Lanes load(const double (&field)[sizeof...(I)][kStride], std::size_t i, std::index_sequence<I...>) {
  if constexpr (requires { Lanes::of(std::array<V, sizeof...(I)>{}); }) {
    return Lanes::of({hn::LoadU(D(), field[I] + i)...});
  } else {
    return Lanes{hn::LoadU(D(), field[I] + i)...};
  }
}

#endif  // COLLIDE2D_BATCH_LOAD_INL_H_
