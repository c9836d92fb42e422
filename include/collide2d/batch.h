// Batched overlap tests, for callers with their own pair lists (a broad phase of their own, a
// game's candidate list): pair i is (the i-th shape of the first list, the i-th of the second), and
// overlapping[i] is set to 1 when the solids share a point, to 0 otherwise.
//
// Each verdict is bit for bit overlaps(a, a_orientation, b, b_orientation)'s (query.h): the typed
// kernel's, with two shapes of one kind first put in the fixed order that makes the verdict the
// same either way round (a rectangle 1e35 from a small one can otherwise round to the other
// verdict). The certain cases are decided 2 to 8 pairs at a time with SIMD instructions (Google
// Highway, chosen at run time for the CPU: SSE4, AVX2, AVX-512, NEON, ...); the few pairs whose
// margins lie within their rounding bounds are finished one by one by the exact fallback.
//
// Like the posed one-off kernels, these neither validate the shapes nor take sines and cosines:
// each orientation must be Orientation::of(angle) of its shape, and the shapes must be valid
// (validate() in shapes.h), as the World keeps them. Lists of different lengths throw
// std::invalid_argument, naming the lengths, before anything is written.
#pragma once

#include <collide2d/shapes.h>

#include <cstdint>
#include <span>
#include <type_traits>

namespace collide2d {

void overlap_rect_ellipse(std::span<const Rect> rects, std::span<const Orientation> rect_orientations,
                          std::span<const Ellipse> ellipses, std::span<const Orientation> ellipse_orientations,
                          std::span<std::uint8_t> overlapping);
void overlap_rect_rect(std::span<const Rect> a, std::span<const Orientation> a_orientations, std::span<const Rect> b,
                       std::span<const Orientation> b_orientations, std::span<std::uint8_t> overlapping);
void overlap_circle_circle(std::span<const Circle> a, std::span<const Circle> b, std::span<std::uint8_t> overlapping);
void overlap_rect_circle(std::span<const Rect> rects, std::span<const Orientation> rect_orientations,
                         std::span<const Circle> circles, std::span<std::uint8_t> overlapping);
void overlap_circle_ellipse(std::span<const Circle> circles, std::span<const Ellipse> ellipses,
                            std::span<const Orientation> ellipse_orientations, std::span<std::uint8_t> overlapping);
// Ellipse pairs: the algebraic test (overlap_ellipse_ellipse.h) on vectors, the pairs near touching
// by the one-off kernel.
void overlap_ellipse_ellipse(std::span<const Ellipse> a, std::span<const Orientation> a_orientations,
                             std::span<const Ellipse> b, std::span<const Orientation> b_orientations,
                             std::span<std::uint8_t> overlapping);

// Any of the above by the kinds of the lists, A before B in kernel order (rectangle, circle,
// ellipse), for generic callers; a circle's orientations are not read.
template <class A, class B>
void overlap_batch(std::span<const A> a, std::span<const Orientation> a_orientations, std::span<const B> b,
                   std::span<const Orientation> b_orientations, std::span<std::uint8_t> overlapping) {
  if constexpr (std::is_same_v<A, Rect> && std::is_same_v<B, Rect>) {
    overlap_rect_rect(a, a_orientations, b, b_orientations, overlapping);
  } else if constexpr (std::is_same_v<A, Rect> && std::is_same_v<B, Circle>) {
    overlap_rect_circle(a, a_orientations, b, overlapping);
  } else if constexpr (std::is_same_v<A, Rect> && std::is_same_v<B, Ellipse>) {
    overlap_rect_ellipse(a, a_orientations, b, b_orientations, overlapping);
  } else if constexpr (std::is_same_v<A, Circle> && std::is_same_v<B, Circle>) {
    overlap_circle_circle(a, b, overlapping);
  } else if constexpr (std::is_same_v<A, Circle> && std::is_same_v<B, Ellipse>) {
    overlap_circle_ellipse(a, b, b_orientations, overlapping);
  } else {
    static_assert(std::is_same_v<A, Ellipse> && std::is_same_v<B, Ellipse>, "no batch for this pair kind or order");
    overlap_ellipse_ellipse(a, a_orientations, b, b_orientations, overlapping);
  }
}

}  // namespace collide2d
