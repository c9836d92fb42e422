#include "narrowphase/time_of_impact.h"

#include "narrowphase/query.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>

namespace collide2d {
namespace {

// How fast a shape's support function h(n) changes as the shape turns, per radian: the distance
// from the centre of the normal line at the support point, |p x n|, at its largest. For an ellipse
// the point (a cos u, b sin u) gives (a^2 - b^2) |sin u cos u| / sqrt(b^2 cos^2 u + a^2 sin^2 u),
// largest at tan^2 u = b / a, where it is a - b; a rectangle's corner (hx, hy) supports the
// directions between its two faces' normals, where |hx n_y - hy n_x| is largest at a face normal:
// the longer half side. Both are less than the farthest point, the bound of plain conservative
// advancement, and a circle's is 0.
double turning_reach(const Shape& s) {
  if (const auto* e = std::get_if<Ellipse>(&s)) return std::abs(e->a - e->b);
  if (const auto* r = std::get_if<Rect>(&s)) return r->half_extents.maxCoeff();
  return 0.0;
}

[[noreturn]] void reject(const char* which, const char* field, double value, const char* rule) {
  std::ostringstream msg;
  msg.precision(17);
  msg << which << ' ' << field << ' ' << rule << " (got " << value << ')';
  throw InvalidShape(msg.str());
}

// The motion must be finite and keep the centre within the supported range over the step.
void validate(const Shape& s, const Motion& m, const char* which) {
  validate(s);
  for (int k = 0; k < 2; ++k) {
    const char* field = k == 0 ? "velocity x" : "velocity y";
    const double v = m.velocity[k];
    if (!std::isfinite(v)) reject(which, field, v, "must be finite");
    if (std::abs(center_of(s)[k] + v) > kMaxMagnitude) reject(which, field, v, "carries the centre beyond +-1e50");
  }
  if (!std::isfinite(m.angular_velocity)) reject(which, "angular velocity", m.angular_velocity, "must be finite");
}

TimeOfImpact result(ToiStatus status, double t, const Contact& c, int iterations) {
  return {status, t, c.normal, Vec2((c.point_a + c.point_b) / 2), iterations};
}

}  // namespace

Shape at_time(const Shape& s, const Motion& m, double t) {
  return std::visit(
      [&](auto shape) -> Shape {
        shape.center += t * m.velocity;
        if constexpr (!std::is_same_v<decltype(shape), Circle>) shape.angle += t * m.angular_velocity;
        return shape;
      },
      s);
}

TimeOfImpact time_of_impact(const Shape& a, const Motion& a_motion, const Shape& b, const Motion& b_motion,
                            const ToiOptions& options) {
  validate(a, a_motion, "A");
  validate(b, b_motion, "B");
  if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance)) {
    reject("time of impact", "tolerance", options.tolerance, "must be finite and not negative");
  }
  // Poses along the step are rounded to their coordinates' ulps, and a separation below that cannot
  // be kept: a step aimed closer could land on a rounded pose that overlaps (a bullet 1e6 from the
  // origin, with a tolerance of 1e-12, did). The tolerance is at least 8 u of the coordinates.
  const double coordinates = center_of(a).cwiseAbs().maxCoeff() + a_motion.velocity.cwiseAbs().maxCoeff() +
                             center_of(b).cwiseAbs().maxCoeff() + b_motion.velocity.cwiseAbs().maxCoeff();
  const double tolerance = std::max(options.tolerance > 0 ? options.tolerance : 1e-9 * (reach_of(a) + reach_of(b)),
                                    8 * std::numeric_limits<double>::epsilon() * coordinates);
  const Vec2 v = b_motion.velocity - a_motion.velocity;
  const double spin = std::abs(a_motion.angular_velocity) * turning_reach(a) +
                      std::abs(b_motion.angular_velocity) * turning_reach(b);
  // Shapes stay valid over the step (validate above), and only a turning one needs its cosine and
  // sine again.
  const Orientation a_start = Orientation::of(angle_of(a)), b_start = Orientation::of(angle_of(b));
  const auto orientation = [](const Shape& s, const Motion& m, const Orientation& start) {
    return m.angular_velocity == 0 ? start : Orientation::of(angle_of(s));
  };
  double t = 0.0;
  ContactOptions warm;  // each step's climb starts from the last normal, near the next one
  for (int k = 1;; ++k) {
    const Shape at_a = at_time(a, a_motion, t), at_b = at_time(b, b_motion, t);
    const Contact c = contact(at_a, orientation(at_a, a_motion, a_start), at_b, orientation(at_b, b_motion, b_start), warm);
    warm.guess = c.normal;
    if (k == 1 && c.separation <= 0) return result(ToiStatus::overlapping, 0.0, c, k);
    if (c.separation <= tolerance) return result(ToiStatus::hit, t, c, k);
    const double closing = spin - c.normal.dot(v);  // the fastest the separation can fall
    const double step = closing > 0 ? (c.separation - tolerance / 2) / closing : INFINITY;
    if (!(t + step < 1.0)) return result(ToiStatus::miss, 1.0, c, k);
    if (k == options.max_iterations) return result(ToiStatus::stalled, t, c, k);
    t += step;
  }
}

std::optional<CastHit> shape_cast(const Shape& shape, const Vec2& translation, const Shape& target,
                                  const ToiOptions& options) {
  const TimeOfImpact r = time_of_impact(target, {}, shape, {translation, 0.0}, options);
  if (r.status == ToiStatus::miss) return std::nullopt;
  return CastHit{r.t, r.point, r.normal};
}

}  // namespace collide2d
