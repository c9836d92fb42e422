// A convex polygon and a circle: the centre against the polygon's faces in its frame (E. Catto,
// Box2D's b2CollidePolygonAndCircle), on the core kernel the core shapes share (core_circle.h).
#include "narrowphase/contact/core_circle.h"

#include <array>

namespace collide2d {

Contact contact_polygon_circle(const ConvexPolygon& a, const Orientation& a_orientation, const Circle& b,
                               const ContactOptions& options) {
  const PolygonOutline& o = *a.outline;
  return detail::core_circle(a,
                             detail::CoreView<kMaxPolygonVertices>{o.vertices.data(), o.normals.data(),
                                                                   o.offsets.data(), o.count, o.radius, o.reach},
                             a_orientation, b, options);
}

Contact contact_polygon_circle(const ConvexPolygon& a, const Circle& b, const ContactOptions& options) {
  return contact_polygon_circle(a, Orientation::of(a.angle), b, options);
}

}  // namespace collide2d
