// The user-facing narrow phase: one entry point per query over every pair of shapes, either order.
//
//   bool overlaps(a, b, options)            solid shapes share a point (touching counts); nothing else
//   bool overlaps(shape, box, options)      the same for a shape and an axis-aligned box
//   DistanceResult distance(a, b, options)  distance 0 and a witness when overlapping, else closest points
//   Contact contact(a, b, options)          signed distance (minus the penetration depth when overlapping),
//                                           normal, deepest or closest points, and a manifold
//                                           (narrowphase/contact.h)
//   DistanceResult boundary_distance(a, b, options)
//                                           circles and ellipses: the gap between the boundary curves
//                                           (0 and a common point when they meet), e.g. of nested shapes
//
// All validate their shapes first and throw InvalidShape (naming the field) on NaN, infinity or a
// non-positive size. Pairs are dispatched at compile time (std::visit) to the typed kernels below,
// each written once for the order rect < circle < ellipse and swapped for the other order:
//
//   pair              overlap                                  distance
//   rect–rect         separating axes (overlap_rect_rect)      vertex–box minimum (distance_rect_rect)
//   rect–circle       clamp in the box frame                   same clamp
//   rect–ellipse      options.rect_ellipse (overlap_rect_...)  Minkowski regions + point–ellipse
//   circle–circle     centre distance                          centre distance
//   circle–ellipse    point–ellipse distance                   point–ellipse distance
//   ellipse–ellipse   GJK on exact supports (overlap_ellipse_  options.ellipse (distance_ellipse_ellipse)
//                     ellipse), long double when undecided
//
// Boundary distance: circle–circle in closed form; circle–ellipse as ellipse–ellipse with a = b;
// rectangles throw UnsupportedPair.
// Contact: circle–circle and rect–circle in closed form; rect–rect by separating axes and Box2D's
// face clipping; circle–ellipse by the point–ellipse distance of the centre less the radius;
// rect–ellipse and ellipse–ellipse by the global maximum of the separation over all directions
// (rect–ellipse: each quarter turn between the rectangle's face normals settled in closed form,
// narrowphase/contact_rect_ellipse.cpp; two ellipses: narrowphase/deepest_direction.h).
#pragma once

#include <collide2d/contact.h>
#include "narrowphase/distance/distance_ellipse_ellipse.h"
#include <collide2d/distance_result.h>
#include "narrowphase/overlap/overlap_rect_ellipse.h"

#include <stdexcept>

namespace collide2d {

struct OverlapOptions {
  RectEllipseMethod rect_ellipse = RectEllipseMethod::minkowski;
};

struct DistanceOptions {
  EllipseDistanceMethod ellipse = EllipseDistanceMethod::robust;
};

// Thrown for a query that is not defined for the pair (the boundary distance of a rectangle).
class UnsupportedPair : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

bool overlaps(const Shape& a, const Shape& b, const OverlapOptions& options = {});
// The same verdict, bit for bit, with the default options, for callers that validated both shapes
// when they posed them and keep each one's Orientation::of(angle_of(shape)) (the World): no
// validation, and no cosines and sines (but in the ellipse pair's long-double fallback, a pair
// within about 1e-14 of touching, which takes them from the angles).
bool overlaps(const Shape& a, const Orientation& a_orientation, const Shape& b, const Orientation& b_orientation);
// Whether the solid shape meets the closed axis-aligned box, which may have no width or height (a
// segment or a point): the part of the box within the shape's own box, as a rectangle of angle 0,
// for the rectangle kernels; exact up to the rounding of that part's centre and half sizes, which
// is the rounding of the shape's coordinates. Validates both (InvalidShape).
bool overlaps(const Shape& shape, const Aabb& box, const OverlapOptions& options = {});
DistanceResult distance(const Shape& a, const Shape& b, const DistanceOptions& options = {});
DistanceResult boundary_distance(const Shape& a, const Shape& b, const DistanceOptions& options = {});
Contact contact(const Shape& a, const Shape& b, const ContactOptions& options = {});
// The same contact, bit for bit, for callers that validated both shapes when they posed them and
// keep each one's Orientation::of(angle_of(shape)) (the World, a time of impact): no validation, no
// cosines and sines.
Contact contact(const Shape& a, const Orientation& a_orientation, const Shape& b, const Orientation& b_orientation,
                const ContactOptions& options = {});

}  // namespace collide2d
