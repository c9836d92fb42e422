/// @file
/// The typed kernels, for callers who know their shapes' kinds or keep their orientations: a broad
/// phase of their own, a solver, a game's own loop. They are what query.h dispatches to, and what
/// the World runs.
///
/// Contract: the shapes must be valid (validate() in shapes.h); the kernels do not check. Each takes
/// its pair in kernel order, as its name says: a rectangle, a polygon, a capsule, a segment, a
/// circle, an ellipse; two shapes of one kind in either order (the dispatch of query.h fixes one, so
/// that it is symmetric bit for bit). A kernel that takes Orientations skips the sines and cosines:
/// each must be Orientation::of(angle) of its shape, and the result is the plain kernel's bit for
/// bit. docs/algorithms/README.md gives each pair's kernels and their methods, docs/accuracy.md the
/// bounds the tests assert.
#pragma once

#include <collide2d/query.h>
#include <collide2d/shapes.h>

namespace collide2d {

/// overlaps(a, b) with each shape's kept orientation: the same verdict bit for bit, with no
/// validation and no sines and cosines (but in the ellipse pair's double-double fallback, for a pair
/// within about 1e-14 of touching).
bool overlaps(const Shape& a, const Orientation& a_orientation, const Shape& b, const Orientation& b_orientation);
/// contact(a, b, options) with each shape's kept orientation: the same contact bit for bit, with no
/// validation and no sines and cosines.
Contact contact(const Shape& a, const Orientation& a_orientation, const Shape& b, const Orientation& b_orientation,
                const ContactOptions& options = {});

/// Overlap of two rectangles by separating axes (their four face normals), in A's frame.
bool overlap_rect_rect(const Rect& a, const Rect& b);
bool overlap_rect_rect(const Rect& a, const Orientation& a_orientation, const Rect& b,
                       const Orientation& b_orientation);
/// Overlap of a rectangle and a circle: the centre clamped to the box, in the box's frame.
bool overlap_rect_circle(const Rect& r, const Circle& c);
bool overlap_rect_circle(const Rect& r, const Orientation& r_orientation, const Circle& c);
/// Overlap of a rectangle and an ellipse: the ellipse centre against the Minkowski sum, decided in
/// double where its margins clear their rounding bounds, else in double-double.
bool overlap_rect_ellipse(const Rect& r, const Ellipse& e);
bool overlap_rect_ellipse(const Rect& r, const Orientation& r_orientation, const Ellipse& e,
                          const Orientation& e_orientation);
/// Overlap of two circles: the centres' distance against the radii.
bool overlap_circle_circle(const Circle& a, const Circle& b);
/// Overlap of a circle and an ellipse: the centre's distance to the ellipse against the radius.
bool overlap_circle_ellipse(const Circle& c, const Ellipse& e);
bool overlap_circle_ellipse(const Circle& c, const Ellipse& e, const Orientation& e_orientation);
/// Overlap of two ellipses: the pencil's characteristic cubic where its signs clear their error
/// bounds, else GJK on the exact support functions, in double-double near touching.
bool overlap_ellipse_ellipse(const Ellipse& a, const Ellipse& b);
bool overlap_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                             const Orientation& b_orientation);

/// Distances with closest points (DistanceResult), one kernel per pair.
DistanceResult distance_rect_rect(const Rect& a, const Rect& b);
DistanceResult distance_rect_circle(const Rect& r, const Circle& c);
DistanceResult distance_rect_ellipse(const Rect& r, const Ellipse& e);
DistanceResult distance_circle_circle(const Circle& a, const Circle& b);
DistanceResult distance_circle_ellipse(const Circle& c, const Ellipse& e);
DistanceResult distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b);
DistanceResult distance_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                                        const Orientation& b_orientation);
/// The gap between two ellipse curves (boundary_distance() in query.h).
DistanceResult boundary_distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b);
/// The gap between two circles' curves: on the line of centres, for one nested in the other.
DistanceResult boundary_distance_circle_circle(const Circle& a, const Circle& b);

/// Contacts (Contact in query.h), one kernel per pair. Each honours options.max_separation; the
/// other options only where ContactOptions says.
Contact contact_rect_rect(const Rect& a, const Rect& b, const ContactOptions& options = {});
Contact contact_rect_rect(const Rect& a, const Orientation& a_orientation, const Rect& b,
                          const Orientation& b_orientation, const ContactOptions& options = {});
Contact contact_rect_circle(const Rect& a, const Circle& b, const ContactOptions& options = {});
Contact contact_rect_circle(const Rect& a, const Orientation& a_orientation, const Circle& b,
                            const ContactOptions& options = {});
Contact contact_rect_ellipse(const Rect& a, const Ellipse& b, const ContactOptions& options = {});
Contact contact_rect_ellipse(const Rect& a, const Orientation& a_orientation, const Ellipse& b,
                             const Orientation& b_orientation, const ContactOptions& options = {});
/// A convex polygon and a circle: the centre against the polygon's faces in its frame (E. Catto,
/// Box2D's b2CollidePolygonAndCircle), the separation exact apart as well.
Contact contact_polygon_circle(const ConvexPolygon& a, const Circle& b, const ContactOptions& options = {});
Contact contact_polygon_circle(const ConvexPolygon& a, const Orientation& a_orientation, const Circle& b,
                               const ContactOptions& options = {});
/// A capsule and a circle: the same, on the capsule's segment (two faces, one each way).
Contact contact_capsule_circle(const Capsule& a, const Circle& b, const ContactOptions& options = {});
Contact contact_capsule_circle(const Capsule& a, const Orientation& a_orientation, const Circle& b,
                               const ContactOptions& options = {});
/// Two capsules: their segments' nearest features apart, the deepest of their four faces where the
/// segments meet, and Box2D's manifold on that face (b2ClipPolygons); the convex cores' contact
/// where features tie (segments parallel or in line).
Contact contact_capsule_capsule(const Capsule& a, const Capsule& b, const ContactOptions& options = {});
Contact contact_capsule_capsule(const Capsule& a, const Orientation& a_orientation, const Capsule& b,
                                const Orientation& b_orientation, const ContactOptions& options = {});
/// A capsule and a segment: the same, the segment a capsule of radius 0.
Contact contact_capsule_segment(const Capsule& a, const Segment& b, const ContactOptions& options = {});
Contact contact_capsule_segment(const Capsule& a, const Orientation& a_orientation, const Segment& b,
                                const Orientation& b_orientation, const ContactOptions& options = {});
/// A segment and a circle: the same as a capsule and a circle, on the segment.
Contact contact_segment_circle(const Segment& a, const Circle& b, const ContactOptions& options = {});
Contact contact_segment_circle(const Segment& a, const Orientation& a_orientation, const Circle& b,
                               const ContactOptions& options = {});
Contact contact_circle_circle(const Circle& a, const Circle& b);
Contact contact_circle_circle(const Circle& a, const Circle& b, const ContactOptions& options);
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b, const ContactOptions& options = {});
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b, const Orientation& b_orientation,
                               const ContactOptions& options = {});
Contact contact_ellipse_ellipse(const Ellipse& a, const Ellipse& b, const ContactOptions& options = {});
Contact contact_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                                const Orientation& b_orientation, const ContactOptions& options = {});

}  // namespace collide2d
