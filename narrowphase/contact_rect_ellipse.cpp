// The contact of a rectangle A and an ellipse B: the global maximum of s(n) over the four quarter
// turns of directions between the rectangle's face normals, each settled exactly by the corner it
// supports rather than searched.
//
// On the quarter turn where the rectangle's support point is its corner c, s is
//   f(n) = n.(c_B - c) - h_B(n),
// the separation of the point c and the ellipse. Over every direction its maximum is their signed
// distance (Eberly's point–ellipse root, distance_point_ellipse), and its critical points are the
// normals of the ellipse through c, at most four, maxima and minima in turn around the circle: one
// maximum, or two when c lies inside the ellipse's evolute (the second, other_local_nearest, across
// the major axis). So the maximum of s over the quarter is the largest of its two ends (the face
// normals) and of those one or two maxima that lie inside it: no branch and bound, no local
// maximum that could pass for the global one, whatever the depth or the aspect. The generic
// search (deepest_direction.h) bisected arcs of such quarters with seven to ten support evaluations
// in deep overlaps, where s is convex near the face normals.
//
// Each point–ellipse root costs as much as a few support evaluations, so quarters are settled only
// where a cheaper bound leaves them open: first the best face normal (a face contact's maximum is a
// kink of s there), certified by disc_bound, which settles most pairs after one support
// evaluation; then the corner on the side where s rises from that face, certified the same way;
// then the other quarters in the order of their bounds (cheap_arc_bound: the ellipse's tangents at
// the quarter's ends, else arc_bound), while a bound exceeds the best value found.
#include "narrowphase/curved_contact.h"

#include "narrowphase/distance_point_ellipse.h"

namespace collide2d {
namespace detail {
namespace {

using RectEllipse = SupportPair<double, RectSupport<double>, EllipseSupport<double>>;

// The separation along the direction of a normal of the ellipse through the corner (its foot on
// the curve, the point–ellipse solvers' output in the ellipse's frame): A's point is the corner, B's
// the foot, s the corner's signed distance along that normal, and s' = 0 (a critical point).
Direction<double> at_foot(const RectEllipse& p, const V2<double>& corner, const Vec2& point, const Vec2& normal,
                          double s) {
  const V2<double> n = -p.B.rot.apply(V2<double>(normal));
  const V2<double> off_b = -p.B.rot.apply(V2<double>(point));
  const double inv = 1 / n.dot(off_b);
  const double k = p.B.a * p.B.b * inv;
  const double rho = k * k * inv;  // (ab)^2 / h^3, as EllipseSupport::at
  const double rho_slope = -3 * rho * inv * perp(n).dot(off_b);
  return {n, Separation<double>{s, 0.0, s + rho, p.delta - corner - off_b, corner, off_b, 0.0, rho, rho_slope}};
}

// The maximum of s inside the quarter turn from x counter-clockwise to y (a right angle), where the
// rectangle's corner is the one on the side of x + y, into `m` if s has one there (else the
// quarter's maximum is at an end); `evaluations` counts each point–ellipse root as one.
bool quarter_maximum(const RectEllipse& p, const V2<double>& x, const V2<double>& y, Direction<double>& m,
                     int& evaluations) {
  const V2<double> corner = p.A.at(V2<double>(x + y), V2<double>(x + y)).offset;
  const Vec2 local = p.B.rot.apply_inverse(V2<double>(corner - p.delta));
  const auto inside = [&] { return cross(x, m.n) >= 0 && cross(m.n, y) >= 0; };
  ++evaluations;
  const PointEllipseResult nearest = distance_point_ellipse(p.B.a, p.B.b, local);
  m = at_foot(p, corner, nearest.closest, nearest.normal, nearest.inside ? -nearest.distance : nearest.distance);
  if (inside()) return true;
  ++evaluations;
  const std::optional<CurveFoot> other = other_local_nearest(p.B.a, p.B.b, local);
  if (!other) return false;
  m = at_foot(p, corner, other->point, other->normal, other->signed_distance);
  return inside();
}

// The contact, from the global maximum of s; ca and cb are the centres.
Contact rect_ellipse_contact(const RectEllipse& p, const Vec2& ca, const Vec2& cb) {
  const double margin = climb_margin(p);
  const double flat = margin / 2;
  // The best face normal f, turned towards B, and s there with the corners before and after it.
  double extent;
  const V2<double> axis = best_face(p, &extent);
  const V2<double> f = p.delta.dot(axis) >= 0 ? axis : V2<double>(-axis);
  const Support<double> at_f = p.B.at_extent(f, extent);
  // A face contact: the ellipse's support point lies over the face, s has a kink at f, and the
  // middle of the face is A's point.
  {
    const V2<double> middle = p.A.extent(f) * f;
    const V2<double> gap = p.delta - middle - at_f.offset;
    const double s = f.dot(gap), slope = perp(f).dot(gap);
    if (std::abs(slope) <= p.A.extent(perp(f)) + flat) {
      const Separation<double> e{s, slope, s + at_f.rho, gap, middle, at_f.offset, 0.0, at_f.rho, at_f.rho_slope};
      // Built here, as curved_contact would, without the Deepest it takes.
      if (disc_bound(p, f, e) <= s + margin) return face_contact(p, cb, f, at_f.offset, s, 1);
    }
  }
  int evaluations = 1;
  const V2<double> axes[5] = {f, perp(f), -f, -perp(f), f};
  // s at the four face normals, seen from the quarter before (ends[k][0]) and after (ends[k][1]),
  // and the maxima inside the quarters.
  Direction<double> ends[4][2], inner[4];
  const Direction<double>* best = &ends[0][0];
  const auto consider = [&](const Direction<double>& m) {
    if (m.at.s > best->at.s) best = &m;
  };
  const auto set_ends = [&](int k, const std::array<Separation<double>, 2>& e) {
    ends[k][0] = {axes[k], e[0]};
    ends[k][1] = {axes[k], e[1]};
  };
  set_ends(0, p.separations(f, axes[3] + f, f + axes[1], at_f));
  consider(ends[0][1]);
  bool settled[4] = {};
  // Where s rises from f into a quarter, the maximum is most often at that quarter's corner, and
  // disc_bound certifies it without the other face normal.
  const bool rising_after = ends[0][1].at.slope > flat, rising_before = ends[0][0].at.slope < -flat;
  if (rising_after != rising_before) {
    const int k = rising_after ? 0 : 3;
    settled[k] = true;
    if (quarter_maximum(p, axes[k], axes[k + 1], inner[k], evaluations)) {
      consider(inner[k]);
      if (disc_bound(p, inner[k].n, inner[k].at) <= inner[k].at.s + margin) {
        return curved_contact(p, ca, cb, Deepest<double>{*best, evaluations});
      }
    }
  }
  // The last two face normals from the points of the first two (SupportPair::opposite).
  set_ends(1, p.separations(axes[1], f + axes[1], axes[1] + axes[2]));
  ++evaluations;
  set_ends(2, {p.opposite(f, ends[0][0].at), p.opposite(f, ends[0][1].at)});
  set_ends(3, {p.opposite(axes[1], ends[1][0].at), p.opposite(axes[1], ends[1][1].at)});
  for (int k = 1; k < 4; ++k) consider(ends[k][0]), consider(ends[k][1]);
  double bound[4];
  for (int k = 0; k < 4; ++k) {
    const Direction<double>&x = ends[k][1], &y = ends[(k + 1) % 4][0];
    bound[k] = settled[k] ? -std::numeric_limits<double>::infinity() : cheap_arc_bound(p, x, y, best->at.s + margin);
  }
  for (;;) {
    const int k = static_cast<int>(std::max_element(bound, bound + 4) - bound);
    if (!(bound[k] > best->at.s + margin)) return curved_contact(p, ca, cb, Deepest<double>{*best, evaluations});
    bound[k] = -std::numeric_limits<double>::infinity();
    if (quarter_maximum(p, axes[k], axes[k + 1], inner[k], evaluations)) consider(inner[k]);
  }
}

}  // namespace
}  // namespace detail

Contact contact_rect_ellipse(const Rect& a, const Ellipse& b, const ContactOptions& options) {
  return contact_rect_ellipse(a, Orientation::of(a.angle), b, Orientation::of(b.angle), options);
}

// options.guess is not needed: the quarters are settled in closed form, from no starting direction.
Contact contact_rect_ellipse(const Rect& a, const Orientation& a_orientation, const Ellipse& b,
                             const Orientation& b_orientation, const ContactOptions&) {
  const detail::RectEllipse p =
      detail::RectEllipse::of(a, {a_orientation.c, a_orientation.s}, b, {b_orientation.c, b_orientation.s});
  return detail::rect_ellipse_contact(p, a.center, b.center);
}

}  // namespace collide2d
