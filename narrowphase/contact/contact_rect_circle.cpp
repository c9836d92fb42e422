#include <collide2d/kernels.h>
#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/frames/box_local.h"
#include "narrowphase/frames/unit_vector.h"
#include "shapes/internal.h"

#include <cmath>

namespace collide2d {
namespace {

double sign_of(double x) { return x < 0 ? -1.0 : 1.0; }

}  // namespace

// In the rectangle's frame, with p the circle's centre: outside the box, the signed distance is
// the distance from p to the box minus the radius, along the face normal where only one coordinate
// is clamped (exact, not rounded through p - q) and from the corner otherwise; inside (or on the
// boundary), p leaves through the nearer face, at depth (half extent - |p|) plus the radius. Where
// two faces are equally near, either is a maximiser; the x face is reported.
Contact contact_rect_circle(const Rect& a, const Circle& b, const ContactOptions& options) {
  return contact_rect_circle(a, Orientation::of(a.angle), b, options);
}

Contact contact_rect_circle(const Rect& a, const Orientation& a_orientation, const Circle& b,
                            const ContactOptions& options) {
  const detail::Rotation<double> rot{a_orientation.c, a_orientation.s};
  const Vec2 p = rot.apply_inverse(Vec2(b.center - a.center));
  const Vec2& h = a.half_extents;
  const Vec2 q = detail::clamp_to_box(p, h);
  const bool out_x = q.x() != p.x(), out_y = q.y() != p.y();
  Vec2 n;
  Vec2 on_a = q;
  double d;
  if (out_x && out_y) {
    const detail::LengthAndDirection from_corner = detail::length_and_direction(p - q);
    d = from_corner.length;
    n = from_corner.direction;
  } else if (out_x || out_y) {
    const int k = out_x ? 0 : 1;
    n = Vec2::Zero();
    n[k] = sign_of(p[k]);
    d = std::abs(p[k]) - h[k];
  } else {
    const Vec2 room = h - p.cwiseAbs();
    const int k = room.x() <= room.y() ? 0 : 1;
    n = Vec2::Zero();
    n[k] = sign_of(p[k]);
    on_a[k] = n[k] * h[k];
    d = -room[k];
  }
  const Vec2 normal = rot.apply(n);
  return detail::within_limit(
      Contact::of(d - b.radius, normal, a.center + rot.apply(on_a), b.center - b.radius * normal), options);
}

}  // namespace collide2d
