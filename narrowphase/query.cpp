#include <collide2d/query.h>

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/pairs.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace collide2d {

using detail::Kinds;

void detail::validate(const ContactOptions& options) {
  if (!options.guess.allFinite()) throw std::invalid_argument("contact guess must be finite");
  if (std::isnan(options.max_separation)) throw std::invalid_argument("contact max_separation must not be NaN");
  if (!(options.tolerance >= 0 && std::isfinite(options.tolerance)))
    throw std::invalid_argument("contact tolerance must be finite and not negative (got " +
                                std::to_string(options.tolerance) + ")");
}

bool overlaps(const Shape& a, const Shape& b) {
  validate(a);
  validate(b);
  return detail::overlap_of<Kinds>(a, b);
}

bool overlaps(const Shape& a, const Orientation& a_orientation, const Shape& b, const Orientation& b_orientation) {
  return detail::posed_overlap_of<Kinds>(a, a_orientation, b, b_orientation);
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
  return std::visit([&](const auto& x) { return detail::Pair<Rect, std::decay_t<decltype(x)>>::overlap(r, x); }, shape);
}

DistanceResult distance(const Shape& a, const Shape& b) {
  validate(a);
  validate(b);
  return detail::distance_of<Kinds>(a, b);
}

DistanceResult boundary_distance(const Shape& a, const Shape& b) {
  validate(a);
  validate(b);
  return detail::boundary_of<Kinds>(a, b);
}

Contact contact(const Shape& a, const Shape& b, const ContactOptions& options) {
  validate(a);
  validate(b);
  detail::validate(options);
  return contact(a, Orientation::of(angle_of(a)), b, Orientation::of(angle_of(b)), options);
}

Contact contact(const Shape& a, const Orientation& a_orientation, const Shape& b, const Orientation& b_orientation,
                const ContactOptions& options) {
  return detail::contact_of<Kinds>(a, a_orientation, b, b_orientation, options);
}

}  // namespace collide2d
