/// @file
/// Batched kernels, for callers with pair lists of their own (a broad phase of their own, a game's
/// candidate list): pair i is the i-th shape of the first list with the i-th of the second.
///
/// Each result is bit for bit the one-off kernel's (kernels.h), two shapes of one kind first put in
/// the order of query.h. The certain cases run 2 to 8 pairs at a time in SIMD lanes (Google
/// Highway, chosen at run time for the CPU: SSE4, AVX2, AVX-512, NEON, ...); the few pairs within
/// their rounding bounds of touching are finished one by one by the exact fallback.
///
/// Contract, as for kernels.h: valid shapes, and each orientation Orientation::of(angle) of its
/// shape; nothing is validated. Lists of different lengths throw std::invalid_argument, naming the
/// lengths, before anything is written.
#pragma once

#include <collide2d/query.h>
#include <collide2d/shapes.h>

#include <cstdint>
#include <span>

namespace collide2d {

/// overlapping[i] = 1 when pair i's solids share a point, else 0.
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
void overlap_ellipse_ellipse(std::span<const Ellipse> a, std::span<const Orientation> a_orientations,
                             std::span<const Ellipse> b, std::span<const Orientation> b_orientations,
                             std::span<std::uint8_t> overlapping);
/// The same for the pairs on convex cores: a polygon or a capsule with an ellipse or a circle, and
/// two polygons.
void overlap_polygon_ellipse(std::span<const ConvexPolygon> polygons, std::span<const Orientation> polygon_orientations,
                             std::span<const Ellipse> ellipses, std::span<const Orientation> ellipse_orientations,
                             std::span<std::uint8_t> overlapping);
void overlap_capsule_ellipse(std::span<const Capsule> capsules, std::span<const Orientation> capsule_orientations,
                             std::span<const Ellipse> ellipses, std::span<const Orientation> ellipse_orientations,
                             std::span<std::uint8_t> overlapping);
void overlap_polygon_circle(std::span<const ConvexPolygon> polygons, std::span<const Orientation> polygon_orientations,
                            std::span<const Circle> circles, std::span<std::uint8_t> overlapping);
void overlap_capsule_circle(std::span<const Capsule> capsules, std::span<const Orientation> capsule_orientations,
                            std::span<const Circle> circles, std::span<std::uint8_t> overlapping);
void overlap_polygon_polygon(std::span<const ConvexPolygon> a, std::span<const Orientation> a_orientations,
                             std::span<const ConvexPolygon> b, std::span<const Orientation> b_orientations,
                             std::span<std::uint8_t> overlapping);

/// contacts[i] = contact_circle_ellipse(circles[i], ellipses[i], ellipse_orientations[i]).
/// Bit for bit: the point-ellipse roots of several vectors of pairs step side by side, each lane stopping
/// where the one-off root stops.
void contact_circle_ellipse(std::span<const Circle> circles, std::span<const Ellipse> ellipses,
                            std::span<const Orientation> ellipse_orientations, std::span<Contact> contacts);
/// contacts[i] = contact_rect_circle(rects[i], rect_orientations[i], circles[i]).
/// Bit for bit: every case of the closed form computed per lane and the pair's own kept.
void contact_rect_circle(std::span<const Rect> rects, std::span<const Orientation> rect_orientations,
                         std::span<const Circle> circles, std::span<Contact> contacts);

}  // namespace collide2d
