#include <collide2d/query.h>

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/pairs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>

namespace collide2d {
namespace {

using detail::Pair;

// Calls kernel(x, y, swapped) with the pair in rank order (dispatch.h).
template <class Kernel>
auto in_kernel_order(const Shape& a, const Shape& b, Kernel kernel) {
  return detail::in_rank_order<detail::Kinds>(a, b, kernel);
}

// Validates, runs kernel(x, y) in rank order and swaps the result back.
template <class Kernel>
auto ordered_result(const Shape& a, const Shape& b, Kernel kernel) {
  validate(a);
  validate(b);
  return in_kernel_order(a, b, [&kernel](const auto& x, const auto& y, bool swapped) {
    const auto r = kernel(x, y);
    return swapped ? r.swapped() : r;
  });
}

template <class X, class Y>
using Row = Pair<std::decay_t<X>, std::decay_t<Y>>;

}  // namespace

// Nested circles: the gap lies on the line of centres, on the side away from the larger circle's
// centre (any side when the centres coincide).
DistanceResult detail::Pair<Circle, Circle>::boundary(const Circle& a, const Circle& b) {
  const Vec2 delta = b.center - a.center;
  const double d = delta.norm();
  if (d >= a.radius + b.radius) return distance_circle_circle(a, b);
  const Vec2 u = d > 0 ? Vec2(delta / d) : Vec2::UnitX();
  if (d <= std::abs(a.radius - b.radius)) {
    const Vec2 away = a.radius >= b.radius ? u : Vec2(-u);
    const Vec2 pa = a.center + a.radius * away;
    const Vec2 pb = b.center + b.radius * away;
    const double gap = std::abs(a.radius - b.radius) - d;
    return gap > 0 ? DistanceResult::apart(gap, pa, pb) : DistanceResult::touching(pa);
  }
  const double along = (d * d + a.radius * a.radius - b.radius * b.radius) / (2 * d);
  const double across = std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
  return DistanceResult::touching(a.center + along * u + across * Vec2(-u.y(), u.x()));
}
void detail::validate(const ContactOptions& options) {
  if (!options.guess.allFinite()) throw std::invalid_argument("contact guess must be finite");
  if (std::isnan(options.max_separation)) throw std::invalid_argument("contact max_separation must not be NaN");
}

bool overlaps(const Shape& a, const Shape& b) {
  validate(a);
  validate(b);
  return in_kernel_order(
      a, b, [](const auto& x, const auto& y, bool) { return Row<decltype(x), decltype(y)>::overlap(x, y); });
}

bool overlaps(const Shape& a, const Orientation& a_orientation, const Shape& b, const Orientation& b_orientation) {
  return in_kernel_order(a, b, [&](const auto& x, const auto& y, bool swapped) {
    using R = Row<decltype(x), decltype(y)>;
    return swapped ? R::posed_overlap(x, b_orientation, y, a_orientation)
                   : R::posed_overlap(x, a_orientation, y, b_orientation);
  });
}

bool overlaps(const Shape& shape, const Aabb& box) {
  validate(shape);
  validate(box);
  // Only the part of the box within the shape's own box matters, and cutting it out is exact (min
  // and max): the rectangle made from that part then rounds like the shape's coordinates, not like
  // the box's (a box 6e37 wide, its edge at 0, would take in a circle 0.125 beyond it).
  const Aabb own = aabb(shape);
  const Aabb part{box.min.cwiseMax(own.min), box.max.cwiseMin(own.max)};
  if ((part.min.array() > part.max.array()).any()) return false;
  // A part with no width is still a rectangle for the kernels, which skip validation.
  const Rect r{0.5 * (part.min + part.max), 0.5 * (part.max - part.min), 0.0};
  return std::visit([&](const auto& x) { return Row<Rect, decltype(x)>::overlap(r, x); }, shape);
}

DistanceResult distance(const Shape& a, const Shape& b) {
  return ordered_result(a, b,
                        [](const auto& x, const auto& y) { return Row<decltype(x), decltype(y)>::distance(x, y); });
}

DistanceResult boundary_distance(const Shape& a, const Shape& b) {
  return ordered_result(a, b,
                        [](const auto& x, const auto& y) { return Row<decltype(x), decltype(y)>::boundary(x, y); });
}

Contact contact(const Shape& a, const Shape& b, const ContactOptions& options) {
  validate(a);
  validate(b);
  detail::validate(options);
  return contact(a, Orientation::of(angle_of(a)), b, Orientation::of(angle_of(b)), options);
}

Contact contact(const Shape& a, const Orientation& a_orientation, const Shape& b, const Orientation& b_orientation,
                const ContactOptions& options) {
  return in_kernel_order(a, b, [&](const auto& x, const auto& y, bool swapped) {
    using R = Row<decltype(x), decltype(y)>;
    if (!swapped) return R::contact(x, a_orientation, y, b_orientation, options, false);
    ContactOptions reversed = options;
    reversed.guess = -options.guess;
    return R::contact(x, b_orientation, y, a_orientation, reversed, true).swapped();
  });
}

}  // namespace collide2d
