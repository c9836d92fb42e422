// The user-facing narrow phase: one entry point per query over every pair of shapes, either order.
//
//   bool overlaps(a, b, options)   solid shapes share a point (touching counts); nothing else computed
//   DistanceResult distance(a, b)  distance 0 and a witness when overlapping, else closest points
//
// Both validate their shapes first and throw InvalidShape (naming the field) on NaN, infinity or a
// non-positive size. Pairs are dispatched at compile time (std::visit) to the typed kernels below,
// each written once for the order rect < circle < ellipse and swapped for the other order:
//
//   pair              overlap                                  distance
//   rect–rect         separating axes (overlap_rect_rect)      vertex–box minimum (distance_rect_rect)
//   rect–circle       clamp in the box frame                   same clamp
//   rect–ellipse      options.rect_ellipse (overlap_rect_...)  Minkowski regions + point–ellipse
//   circle–circle     centre distance                          centre distance
//   circle–ellipse    point–ellipse distance                   point–ellipse distance
//   ellipse–ellipse   not yet: throws UnsupportedPair          not yet: throws UnsupportedPair
#pragma once

#include "narrowphase/distance_result.h"
#include "narrowphase/overlap_rect_ellipse.h"

#include <stdexcept>

namespace collide2d {

struct OverlapOptions {
  RectEllipseMethod rect_ellipse = RectEllipseMethod::minkowski;
};

// Thrown for a pair of shapes that has no kernel yet.
class UnsupportedPair : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

bool overlaps(const Shape& a, const Shape& b, const OverlapOptions& options = {});
DistanceResult distance(const Shape& a, const Shape& b);

}  // namespace collide2d
