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
// Each point–ellipse root costs as much as a few support evaluations, so a quarter's root is taken
// only where its maximum can lie inside it and beat the best value found (quarter_bound). The four
// face normals come first, from B's support at the rectangle's two axes. Where the best of them
// shows the pair apart with B's support point over that face, delta lies in the face's Voronoi
// region of the Minkowski sum A + B and s there is the distance: no bound is needed. Elsewhere a
// quarter stays shut unless its corner lies in the solid ellipse, in the hull of its evolute, or
// delta in the Voronoi region of its arc, and unless the ellipse's tangents at the quarter's ends
// (and their discs of curvature) allow a larger s; the open ones are settled in the order of their
// bounds, and a maximum found in one may certify itself (disc_bound). With a tolerance, the roots
// stop early (quarter_maximum).
#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/curved/curved_contact.h"

#include "narrowphase/shared/ellipse/distance_point_ellipse.h"

#include <algorithm>
#include <optional>

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

// A quarter turn from the rectangle's face normal x counter-clockwise to the next, y = perp(x): its
// corner there (on the side of x + y: hx along x and hy along y where x is the rectangle's own x
// axis or its opposite, else the other way round), the corner relative to B's centre in B's axes,
// and an upper bound of s over the quarter (quarter_bound, below). The corner is RectSupport::at's
// to the bit, without its branches on the signs of x + y, which would run for all four quarters.
struct Quarter {
  V2<double> x, y;
  V2<double> corner;
  Vec2 local;
  double bound = -std::numeric_limits<double>::infinity();
  bool nearest = false;  // whether the corner's nearest point may be the quarter's maximum

  static Quarter of(const RectEllipse& p, const V2<double>& x, bool along_own_x) {
    Quarter q;
    q.x = x, q.y = perp(x);
    q.corner = along_own_x ? V2<double>(p.A.hx * q.x + p.A.hy * q.y) : V2<double>(p.A.hy * q.x + p.A.hx * q.y);
    q.local = p.B.rot.apply_inverse(V2<double>(q.corner - p.delta));
    return q;
  }
};

// The maximum of s inside the quarter, into `m` if s has one there (else the quarter's maximum is
// at an end); `evaluations` counts each point–ellipse root as one. Without q.nearest the nearest
// point, known to lie outside the quarter, is skipped. With a tolerance the nearest point's root
// stops early (nearest_in_range) and `within` says so, with a bound of the error of s in `error`.
bool quarter_maximum(const RectEllipse& p, const Quarter& q, const Tolerance<double>& tolerance, Direction<double>& m,
                     double& error, bool& within, int& evaluations) {
  const V2<double>&x = q.x, &y = q.y, &corner = q.corner;
  const Vec2& local = q.local;
  // With `margin` (a sine) to spare on both sides, as in_range wants; n as at_foot turns it.
  const auto inside = [&](const V2<double>& n, double margin) {
    return cross(x, n) >= margin && cross(n, y) >= margin;
  };
  const auto in_quarter = [&](const Vec2& normal, double margin) {
    return inside(-p.B.rot.apply(V2<double>(normal)), margin);
  };
  error = 0.0, within = false;
  if (q.nearest) {
    ++evaluations;
    const RangeFoot near = nearest_in_range(p.B.a, p.B.b, local, 0.0, tolerance.length, tolerance.angle, in_quarter);
    if (near.in_range) {
      m = at_foot(p, corner, near.foot.point, near.foot.normal, near.foot.signed_distance);
      error = near.error, within = near.early;
      return true;
    }
  }
  ++evaluations;
  const std::optional<CurveFoot> other = other_local_nearest(p.B.a, p.B.b, local);
  if (!other) return false;
  m = at_foot(p, corner, other->point, other->normal, other->signed_distance);
  return inside(m.n, 0.0);
}

// The four face normals of the rectangle, k = 0..3 counter-clockwise from its axis x, with B's
// support offsets along them and s there; quarter k runs from normal k to normal k + 1, where A's
// support point is the corner between those two faces.
struct Faces {
  V2<double> normal[5];
  V2<double> offset[5];  // B's, offset[k + 2] = -offset[k]
  double rho[5] = {};    // B's radius of curvature there
  double s[4] = {};

  static Faces of(const RectEllipse& p) {
    Faces f;
    const V2<double> x(p.A.rot.c, p.A.rot.s), y = perp(x);
    const double ex = p.B.extent(x), ey = p.B.extent(y);
    const Support<double> sx = p.B.at_extent(x, ex), sy = p.B.at_extent(y, ey);
    const V2<double> ox = sx.offset, oy = sy.offset;
    const double dx = p.delta.dot(x), dy = p.delta.dot(y);
    const V2<double> normals[4] = {x, y, -x, -y}, offsets[4] = {ox, oy, -ox, -oy};
    const double s[4] = {dx - p.A.hx - ex, dy - p.A.hy - ey, -dx - p.A.hx - ex, -dy - p.A.hy - ey};
    for (int k = 0; k < 5; ++k)
      f.normal[k] = normals[k % 4], f.offset[k] = offsets[k % 4], f.rho[k] = k % 2 ? sy.rho : sx.rho;
    std::copy(s, s + 4, f.s);
    return f;
  }
  int best() const { return static_cast<int>(std::max_element(s, s + 4) - s); }
};

// Whether a point (in B's axes) may lie in the solid ellipse, or in the hull of its evolute, each
// grown by the margin. The first after squeezing the major axis to the minor, which moves no
// point further from the ellipse.
struct NearEllipse {
  double scale_x = 1, scale_y = 1, reach = 0, a = 0, b = 0, evolute = 0;

  static NearEllipse of(const RectEllipse& p) {
    NearEllipse e;
    const bool wide = p.B.a >= p.B.b;
    (wide ? e.scale_x : e.scale_y) = wide ? p.B.b / p.B.a : p.B.a / p.B.b;
    e.reach = std::min(p.B.a, p.B.b) + p.margin();
    e.a = p.B.a, e.b = p.B.b;
    e.evolute = std::abs((p.B.a - p.B.b) * (p.B.a + p.B.b)) + p.margin() * (p.B.a + p.B.b);
    return e;
  }
  bool in_solid(const V2<double>& q) const {
    const double u = q[0] * scale_x, v = q[1] * scale_y;
    return u * u + v * v <= reach * reach;
  }
  bool in_hull(const V2<double>& q) const { return a * std::abs(q[0]) + b * std::abs(q[1]) < evolute; }
};

// Quarter k with its bound: an upper bound of s over it, +infinity where delta lies in the Voronoi
// region of its arc (below), or -infinity where its maximum lies at an end (a face normal, which
// Faces weighed). Inside the quarter s is the corner's f_k(n) = n.(delta - c_k) - h_B(n).
// - B contains the disc of radius r tangent at each end's support point o, r the least radius of
//   curvature over the quarter (deepest_direction.h says why): f_k(n) <= n.g - r |n - e|^2 / 2
//   with g = delta - c_k - o and e that end, a sinusoid whose maximum over the quarter lies where
//   g + r e points, if into the quarter, else at an end. (r = 0, the tangent alone, left open the
//   quarters of most corners inside the ellipse: 0.8 roots more per overlapping pair.)
// - The critical points of f_k are the normals of the ellipse through c_k (the top of the file).
//   Where c_k lies outside the solid ellipse and outside the convex hull of its evolute (the rhombus
//   a |x| + b |y| < |a^2 - b^2|), there are two, and f_k has one maximum, the corner's distance
//   d_k > 0. The quarter then holds a maximum only where d_k's direction lies in it: delta lies in
//   the Voronoi region of the arc of c_k + B between the two faces' segments, beyond both segments'
//   ends, g_x.y > 0 and g_y.x > 0 with x, y the quarter's ends. A wrong call at that region's edge
//   costs no more than the rounding (the arc meets the segment there, and the two separations
//   agree); the point is taken as outside the solid and the hull only when it is more than the
//   margin, 64 u of the scale, away from them, far above the rounding of its coordinates.
Quarter quarter_bound(const RectEllipse& p, const Faces& f, const NearEllipse& near, int k) {
  Quarter q = Quarter::of(p, f.normal[k], k % 2 == 0);
  const V2<double>&x = q.x, &y = q.y;
  const V2<double> gx = p.delta - q.corner - f.offset[k], gy = p.delta - q.corner - f.offset[k + 1];
  // In the arc's Voronoi region the pair is apart at that corner and its quarter holds the maximum,
  // unless the corner lies in the solid: no bound is worth its square root there.
  q.nearest = gx.dot(y) > 0 && gy.dot(x) > 0;
  if (q.nearest) {
    q.bound = std::numeric_limits<double>::infinity();
    return q;
  }
  q.nearest = near.in_solid(q.local);
  if (!q.nearest && !near.in_hull(q.local)) return q;
  const double r = p.B.rho_floor(x, y, f.rho[k], f.rho[k + 1]);
  const auto along = [&](const V2<double>& g, const V2<double>& end, const V2<double>& other) {
    const V2<double> w = g + r * end;
    if (w.dot(x) > 0 && w.dot(y) > 0) {
      const V2<double> n = w / w.norm();
      return n.dot(g) - r * (n - end).squaredNorm() / 2;
    }
    return std::max(end.dot(g), other.dot(g) - r);
  };
  q.bound = std::min(along(gx, x, y), along(gy, y, x));
  return q;
}

// No contact where s along the direction from a quarter's corner to B's centre, a lower bound of
// the separation, passes the caller's limit: tried for the quarter whose arc's Voronoi region holds
// delta, as the pairs apart at a corner have it, and whose faces' s fell short.
std::optional<Contact> corner_beyond(const RectEllipse& p, const Quarter& q, const ContactOptions& options) {
  if (!has_limit(options) || !q.nearest || q.bound != std::numeric_limits<double>::infinity()) return std::nullopt;
  const V2<double> toward = p.delta - q.corner;
  const V2<double> n = toward / toward.norm();
  const double s = p.delta.dot(n) - p.A.extent(n) - p.B.extent(n);
  if (!beyond_limit(s, p.scale, options)) return std::nullopt;
  return Contact::beyond(s);
}

// The contact, from the global maximum of s; ca and cb are the centres. Each face's s, and each
// quarter's maximum, is a lower bound of the separation: the search ends when one passes the
// caller's limit.
Contact rect_ellipse_contact(const RectEllipse& p, const Vec2& ca, const Vec2& cb, const ContactOptions& options) {
  // The larger reach_of, only where a tolerance needs it (an overflow to infinity only stiffens the angle).
  const double size =
      options.tolerance > 0 ? std::max({std::sqrt(p.A.hx * p.A.hx + p.A.hy * p.A.hy), p.B.a, p.B.b}) : 1.0;
  const Tolerance<double> tolerance{options.tolerance, options.tolerance / size};
  const Faces faces = Faces::of(p);
  const int face = faces.best();
  const V2<double>& f = faces.normal[face];
  const double s = faces.s[face];
  const double margin = climb_margin(p);
  if (beyond_limit(s, p.scale, options)) return Contact::beyond(s);
  // Apart, with B's support point over the face: delta is in the face's Voronoi region of the
  // Minkowski sum, and s is the distance.
  if (s >= 0 && std::abs(perp(f).dot(p.delta - faces.offset[face])) <= p.A.extent(perp(f)) + margin / 2) {
    return limited(options, [&] { return face_contact(p, cb, f, faces.offset[face], s, 1); });
  }
  Quarter quarters[4];
  const NearEllipse near = NearEllipse::of(p);
  for (int k = 0; k < 4; ++k) {
    quarters[k] = quarter_bound(p, faces, near, k);
    if (const std::optional<Contact> none = corner_beyond(p, quarters[k], options)) return *none;
  }
  int evaluations = 1;
  Direction<double> inner[4];
  const Direction<double>* best = nullptr;
  double top = s;       // the best value found
  double floor = top;   // a lower bound of the separation at its direction
  bool within = false;  // whether it came from a root stopped within the tolerance
  // The quarters in the order of their bounds while one exceeds the best value found; a maximum
  // found inside one may certify itself (disc_bound, which wants an exact root) before the next
  // root is taken.
  const auto lower = [](const Quarter& a, const Quarter& b) { return a.bound < b.bound; };
  for (bool certified = false; !certified;) {
    Quarter& q = *std::max_element(quarters, quarters + 4, lower);
    if (!(q.bound > floor + margin)) break;
    q.bound = -std::numeric_limits<double>::infinity();
    Direction<double>& m = inner[&q - quarters];
    double error = 0.0;
    bool early = false;
    if (quarter_maximum(p, q, tolerance, m, error, early, evaluations) && m.at.s > top) {
      if (beyond_limit(m.at.s, p.scale, options)) return Contact::beyond(m.at.s);
      best = &m;
      top = m.at.s, floor = top - error, within = early;
      certified = std::max_element(quarters, quarters + 4, lower)->bound <= floor + margin ||
                  (!within && disc_bound(p, m.n, m.at) <= top + margin);
    }
  }
  return limited(options, [&] {
    if (best == nullptr) return face_contact(p, cb, f, faces.offset[face], s, evaluations);
    // A root stopped within the tolerance keeps the corner, and the foot is the corner moved by s.
    return curved_contact(p, ca, cb, Deepest<double>{*best, evaluations, within ? Kept::a : Kept::none});
  });
}

}  // namespace
}  // namespace detail

Contact contact_rect_ellipse(const Rect& a, const Ellipse& b, const ContactOptions& options) {
  return contact_rect_ellipse(a, Orientation::of(a.angle), b, Orientation::of(b.angle), options);
}

// options.guess is not needed: the quarters are settled in closed form, from no starting direction.
Contact contact_rect_ellipse(const Rect& a, const Orientation& a_orientation, const Ellipse& b,
                             const Orientation& b_orientation, const ContactOptions& options) {
  const detail::RectEllipse p = detail::RectEllipse::of(a, detail::Rotation<double>::of(a_orientation), b,
                                                        detail::Rotation<double>::of(b_orientation));
  return detail::rect_ellipse_contact(p, a.center, b.center, options);
}

}  // namespace collide2d
