#include <collide2d/query.h>

#include <collide2d/kernels.h>
#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/contact/contact_rect_rect.h"
#include "narrowphase/kernel_order.h"
#include "narrowphase/overlap/overlap_ellipse_ellipse.h"
#include "narrowphase/shared/cores/convex_core.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>

namespace collide2d {
namespace {

using detail::on_cores;
using detail::precedes;  // the order in which kernels take their shapes (kernel_order.h)
using detail::rank;

bool overlap_kernel(const Rect& a, const Rect& b) { return overlap_rect_rect(a, b); }
bool overlap_kernel(const Rect& a, const Circle& b) { return overlap_rect_circle(a, b); }
bool overlap_kernel(const Rect& a, const Ellipse& b) { return overlap_rect_ellipse(a, b); }
bool overlap_kernel(const Circle& a, const Circle& b) { return overlap_circle_circle(a, b); }
bool overlap_kernel(const Circle& a, const Ellipse& b) { return overlap_circle_ellipse(a, b); }
bool overlap_kernel(const Ellipse& a, const Ellipse& b) { return overlap_ellipse_ellipse(a, b); }

using O = Orientation;
bool posed_overlap(const Rect& a, const O& oa, const Rect& b, const O& ob) { return overlap_rect_rect(a, oa, b, ob); }
bool posed_overlap(const Rect& a, const O& oa, const Circle& b, const O&) { return overlap_rect_circle(a, oa, b); }
bool posed_overlap(const Rect& a, const O& oa, const Ellipse& b, const O& ob) {
  return overlap_rect_ellipse(a, oa, b, ob);
}
bool posed_overlap(const Circle& a, const O&, const Circle& b, const O&) { return overlap_circle_circle(a, b); }
bool posed_overlap(const Circle& a, const O&, const Ellipse& b, const O& ob) {
  return overlap_circle_ellipse(a, b, ob);
}
bool posed_overlap(const Ellipse& a, const O& oa, const Ellipse& b, const O& ob) {
  return overlap_ellipse_ellipse(a, oa, b, ob);
}

DistanceResult distance_kernel(const Rect& a, const Rect& b) { return distance_rect_rect(a, b); }
DistanceResult distance_kernel(const Rect& a, const Circle& b) { return distance_rect_circle(a, b); }
DistanceResult distance_kernel(const Rect& a, const Ellipse& b) { return distance_rect_ellipse(a, b); }
DistanceResult distance_kernel(const Circle& a, const Circle& b) { return distance_circle_circle(a, b); }
DistanceResult distance_kernel(const Circle& a, const Ellipse& b) { return distance_circle_ellipse(a, b); }
DistanceResult distance_kernel(const Ellipse& a, const Ellipse& b) { return distance_ellipse_ellipse(a, b); }

// `prefer_b`: the kernel's B is the caller's A, whose face a rectangle pair's manifold prefers.
Contact contact_kernel(const Rect& a, const O& oa, const Rect& b, const O& ob, const ContactOptions& o, bool prefer_b) {
  return detail::contact_rect_rect(a, oa, b, ob, o,
                                   prefer_b ? detail::PreferredFace::of_b : detail::PreferredFace::of_a);
}
Contact contact_kernel(const Rect& a, const O& oa, const Circle& b, const O&, const ContactOptions& o, bool) {
  return contact_rect_circle(a, oa, b, o);
}
Contact contact_kernel(const Rect& a, const O& oa, const Ellipse& b, const O& ob, const ContactOptions& o, bool) {
  return contact_rect_ellipse(a, oa, b, ob, o);
}
Contact contact_kernel(const Circle& a, const O&, const Circle& b, const O&, const ContactOptions& o, bool) {
  return contact_circle_circle(a, b, o);
}
Contact contact_kernel(const Circle& a, const O&, const Ellipse& b, const O& ob, const ContactOptions& o, bool) {
  return contact_circle_ellipse(a, b, ob, o);
}
Contact contact_kernel(const Ellipse& a, const O& oa, const Ellipse& b, const O& ob, const ContactOptions& o, bool) {
  return contact_ellipse_ellipse(a, oa, b, ob, o);
}

// The pairs with a polygon, a capsule or a segment (on_cores, kernel_order.h), in kernel order: a
// flat shape (rectangle, polygon, capsule, segment) first, settled on convex cores
// (narrowphase/shared/cores/convex_core.h).
template <class T>
Orientation orientation_of(const T& x) {
  if constexpr (std::is_same_v<T, Circle>) {
    return {};
  } else {
    return Orientation::of(x.angle);
  }
}

// The pair's cores, or A's core against the ellipse B, for `run` to settle.
template <class X, class Y, class Run>
auto on_core_pair(const X& a, const O& oa, const Y& b, const O& ob, Run run) {
  if constexpr (std::is_same_v<Y, Ellipse>) {
    return run(detail::CoreEllipse::of(a, oa, b, ob));
  } else {
    return run(detail::CorePair::of(a, oa, b, ob));
  }
}

struct CoreOverlap {
  bool operator()(const detail::CorePair& p) const { return detail::core_overlap(p); }
  bool operator()(const detail::CoreEllipse& p) const { return detail::core_ellipse_overlap(p); }
};
struct CoreDistance {
  DistanceResult operator()(const detail::CorePair& p) const { return detail::core_distance(p); }
  DistanceResult operator()(const detail::CoreEllipse& p) const { return detail::core_ellipse_distance(p); }
};
struct CoreContact {
  const ContactOptions& options;
  Contact operator()(const detail::CorePair& p) const { return detail::core_contact(p, options); }
  Contact operator()(const detail::CoreEllipse& p) const { return detail::core_ellipse_contact(p, options); }
};

// The discs about the two centres first: they settle most pairs before any core is built.
template <class X, class Y>
requires(on_cores<X> || on_cores<Y>) bool posed_overlap(const X& a, const O& oa, const Y& b, const O& ob) {
  const std::optional<bool> discs = detail::disc_verdict(detail::disc_lanes(a, oa, b, ob));
  return discs ? *discs : on_core_pair(a, oa, b, ob, CoreOverlap{});
}
template <class X, class Y>
requires(on_cores<X> || on_cores<Y>) bool overlap_kernel(const X& a, const Y& b) {
  return posed_overlap(a, orientation_of(a), b, orientation_of(b));
}
template <class X, class Y>
requires(on_cores<X> || on_cores<Y>) DistanceResult distance_kernel(const X& a, const Y& b) {
  return on_core_pair(a, orientation_of(a), b, orientation_of(b), CoreDistance{});
}
// A tie of two polygons' faces keeps the kernel's A's (the pair in kernel order), whichever the
// caller gave first.
template <class X, class Y>
requires(on_cores<X> || on_cores<Y>) Contact
    contact_kernel(const X& a, const O& oa, const Y& b, const O& ob, const ContactOptions& o, bool) {
  return on_core_pair(a, oa, b, ob, CoreContact{o});
}

Contact contact_kernel(const ConvexPolygon& a, const O& oa, const Circle& b, const O&, const ContactOptions& o, bool) {
  return contact_polygon_circle(a, oa, b, o);
}
Contact contact_kernel(const Capsule& a, const O& oa, const Circle& b, const O&, const ContactOptions& o, bool) {
  return contact_capsule_circle(a, oa, b, o);
}
Contact contact_kernel(const Segment& a, const O& oa, const Circle& b, const O&, const ContactOptions& o, bool) {
  return contact_segment_circle(a, oa, b, o);
}

Ellipse as_ellipse(const Circle& c) { return {c.center, c.radius, c.radius, 0.0}; }

// Nested circles: the gap lies on the line of centres, on the side away from the larger circle's
// centre (any side when the centres coincide).
DistanceResult boundary_kernel(const Circle& a, const Circle& b) {
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
DistanceResult boundary_kernel(const Circle& a, const Ellipse& b) {
  return boundary_distance_ellipse_ellipse(as_ellipse(a), b);
}
DistanceResult boundary_kernel(const Ellipse& a, const Ellipse& b) { return boundary_distance_ellipse_ellipse(a, b); }
template <class X, class Y>
requires(std::is_same_v<X, Rect> || on_cores<X>) DistanceResult boundary_kernel(const X&, const Y&) {
  throw UnsupportedPair(
      "the boundary distance covers circles and ellipses, not rectangles, polygons, capsules or segments");
}

// Calls kernel(x, y, swapped) with the pair in kernel order: by rank across kinds, by key within one.
template <class Kernel>
auto in_kernel_order(const Shape& a, const Shape& b, Kernel kernel) {
  return std::visit(
      [&kernel](const auto& x, const auto& y) {
        using X = std::decay_t<decltype(x)>;
        using Y = std::decay_t<decltype(y)>;
        if constexpr (rank<X>() < rank<Y>()) {
          return kernel(x, y, false);
        } else if constexpr (rank<X>() > rank<Y>()) {
          return kernel(y, x, true);
        } else {
          return precedes(y, x) ? kernel(y, x, true) : kernel(x, y, false);
        }
      },
      a, b);
}

// Validates, runs kernel(x, y) in kernel order and swaps the result back.
template <class Kernel>
auto ordered_result(const Shape& a, const Shape& b, Kernel kernel) {
  validate(a);
  validate(b);
  return in_kernel_order(a, b, [&kernel](const auto& x, const auto& y, bool swapped) {
    const auto r = kernel(x, y);
    return swapped ? r.swapped() : r;
  });
}

}  // namespace

void detail::validate(const ContactOptions& options) {
  if (!options.guess.allFinite()) throw std::invalid_argument("contact guess must be finite");
  if (std::isnan(options.max_separation)) throw std::invalid_argument("contact max_separation must not be NaN");
}

bool overlaps(const Shape& a, const Shape& b) {
  validate(a);
  validate(b);
  return in_kernel_order(a, b, [](const auto& x, const auto& y, bool) { return overlap_kernel(x, y); });
}

bool overlaps(const Shape& a, const Orientation& a_orientation, const Shape& b, const Orientation& b_orientation) {
  return in_kernel_order(a, b, [&](const auto& x, const auto& y, bool swapped) {
    return swapped ? posed_overlap(x, b_orientation, y, a_orientation)
                   : posed_overlap(x, a_orientation, y, b_orientation);
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
  return std::visit([&](const auto& x) { return overlap_kernel(r, x); }, shape);
}

DistanceResult distance(const Shape& a, const Shape& b) {
  return ordered_result(a, b, [](const auto& x, const auto& y) { return distance_kernel(x, y); });
}

DistanceResult boundary_distance(const Shape& a, const Shape& b) {
  return ordered_result(a, b, [](const auto& x, const auto& y) { return boundary_kernel(x, y); });
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
    if (!swapped) return contact_kernel(x, a_orientation, y, b_orientation, options, false);
    ContactOptions reversed = options;
    reversed.guess = -options.guess;
    return contact_kernel(x, b_orientation, y, a_orientation, reversed, true).swapped();
  });
}

}  // namespace collide2d
