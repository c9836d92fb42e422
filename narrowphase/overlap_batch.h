// Batched overlap tests, for callers with their own pair lists (a broad phase of their own, a
// game's candidate list): pair i is (the i-th shape of the first list, the i-th of the second), and
// overlapping[i] is set to 1 when the solids share a point, to 0 otherwise.
//
// Each verdict is bit for bit the one-off kernel's given the same kept orientations (the posed
// overlap_rect_ellipse in overlap_rect_ellipse.h). The certain cases are decided 2 to 8 pairs at a
// time with SIMD instructions (Google Highway, chosen at run time for the CPU: SSE4, AVX2, AVX-512,
// NEON, ...); the few pairs whose margins lie within their rounding bounds are finished one by one
// by the exact fallback.
//
// Like the posed one-off kernels, these neither validate the shapes nor take sines and cosines:
// each orientation must be Orientation::of(angle) of its shape, and the shapes must be valid
// (validate() in shapes.h), as the World keeps them. Lists of different lengths throw
// std::invalid_argument, naming the lengths, before anything is written.
#pragma once

#include "shapes/shapes.h"

#include <cstdint>
#include <span>

namespace collide2d {

void overlap_rect_ellipse(std::span<const Rect> rects, std::span<const Orientation> rect_orientations,
                          std::span<const Ellipse> ellipses, std::span<const Orientation> ellipse_orientations,
                          std::span<std::uint8_t> overlapping);

}  // namespace collide2d
