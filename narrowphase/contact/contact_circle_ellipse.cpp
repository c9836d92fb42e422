#include <collide2d/kernels.h>

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/ellipse/distance_point_ellipse.h"
#include "narrowphase/shared/lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace collide2d {
namespace detail {
#include "narrowphase/shared/ellipse/point_ellipse-inl.h"
}  // namespace detail

namespace {

// The contact to ContactOptions::tolerance: Newton's steps on the secular equation as
// distance_point_ellipse takes them, stopped at the first after which SecularRoot::width bounds
// the root near enough. With the root within t (1 + w) and |g| <= reach (point_ellipse-inl.h), the
// normal turns by at most w / 2 up to the root (its angle moves at most 1 / (2t) per unit of t), and
// the distance |t - 1| e1 |g| by at most e1 reach w (t + |t - 1|) (|g| falls at most as fast as
// 1 / t). The circle's point moves with the normal, by its radius times the turn; the ellipse's is
// the circle's moved by the separation along the normal, so that their difference stays
// separation * normal. The sign must be certain, so that the verdict stays the exact one. Nullopt
// for the axis cases, which distance_point_ellipse settles in closed form.
std::optional<Contact> contact_within_tolerance(const detail::CirclePosedEllipseLanes<double>& f, double px, double py,
                                                const ContactOptions& options) {
  const detail::Scalar d;
  const auto q = detail::Quadrant<double, bool>::of(d, px, py, f.a, f.b);
  if (!q.general) return std::nullopt;
  const double tolerance = options.tolerance, angle = tolerance / std::max(f.r, q.e0);
  const double rounding = 16 * std::numeric_limits<double>::epsilon() * (std::abs(px) + std::abs(py) + q.e0 + f.r);
  detail::SecularRoot<detail::Scalar, double> root(d, q.r0, q.z0, q.z1);
  for (bool running = true; running;) {
    running = root.step();
    const double w = running ? root.width() : 0.0, turn = w / 2;
    if (!(turn <= angle)) continue;
    detail::ContactLanes<double> c = detail::circle_ellipse_contact(f, detail::nearest_at_root(d, q, root.t(), px, py));
    const double t = root.t();
    const double error = q.e1 * root.reach() * w * (t + std::abs(t - 1)) + rounding;
    const double s = std::abs(c.separation);
    if (running && !(s > error && f.r * turn + error + (s + error) * turn <= tolerance && error <= tolerance)) continue;
    c.bx = c.ax + c.separation * c.nx;
    c.by = c.ay + c.separation * c.ny;
    return c.contact();
  }
  return std::nullopt;
}

}  // namespace

// The signed distance of the circle's centre to the ellipse (Eberly's secular equation, inside and
// out: distance_point_ellipse.h) less the radius: point_ellipse-inl.h, which the batch runs on
// vectors with the same operations. With a tolerance, contact_within_tolerance.
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b, const ContactOptions& options) {
  return contact_circle_ellipse(a, b, Orientation::of(b.angle), options);
}

Contact contact_circle_ellipse(const Circle& a, const Ellipse& b, const Orientation& b_orientation,
                               const ContactOptions& options) {
  const detail::CirclePosedEllipseLanes<double> f = detail::circle_posed_ellipse_lanes(a, b, b_orientation);
  double px, py;
  detail::circle_centre_in_ellipse_frame(f, px, py);
  const Vec2 p(px, py);
  if (detail::has_limit(options)) {
    const double floor = distance_floor(b.a, b.b, p) - a.radius;
    if (detail::beyond_limit(floor, std::abs(px) + std::abs(py) + b.a + b.b + a.radius, options))
      return Contact::beyond(floor);
  }
  if (options.tolerance > 0) {
    if (const std::optional<Contact> c = contact_within_tolerance(f, px, py, options)) return *c;
  }
  const PointEllipseResult r = distance_point_ellipse(b.a, b.b, p);
  return detail::circle_ellipse_contact(f, detail::nearest_on_ellipse(r)).contact();
}

}  // namespace collide2d
