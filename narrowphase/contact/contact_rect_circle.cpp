#include <collide2d/kernels.h>
#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/frames/unit_vector.h"
#include "narrowphase/shared/lanes.h"

namespace collide2d {
namespace detail {
#include "narrowphase/contact/contact_rect_circle-inl.h"
}  // namespace detail

// In the rectangle's frame, with p the circle's centre: outside the box, the signed distance is
// the distance from p to the box minus the radius, along the face normal where only one coordinate
// is clamped (exact, not rounded through p - q) and from the corner otherwise; inside (or on the
// boundary), p leaves through the nearer face, at depth (half extent - |p|) plus the radius. Where
// two faces are equally near, either is a maximiser; the x face is reported. Written over lanes
// (contact_rect_circle-inl.h) for the batch.
Contact contact_rect_circle(const Rect& a, const Circle& b, const ContactOptions& options) {
  return contact_rect_circle(a, Orientation::of(a.angle), b, options);
}

Contact contact_rect_circle(const Rect& a, const Orientation& a_orientation, const Circle& b,
                            const ContactOptions& options) {
  const detail::RectCirclePosedLanes<double> f = detail::rect_circle_posed_lanes(a, a_orientation, b);
  bool general;
  detail::RectCircleFeature<double> e = detail::rect_circle_feature(detail::Scalar(), f, general);
  if (!general) {
    const detail::LengthAndDirection corner = detail::length_and_direction(Vec2(e.px - e.on_x, e.py - e.on_y));
    e.nx = corner.direction.x(), e.ny = corner.direction.y(), e.d = corner.length;
  }
  return detail::limited(options, [&] { return detail::rect_circle_contact(f, e).contact(); });
}

}  // namespace collide2d
