#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/ellipse/distance_point_ellipse.h"
#include "narrowphase/polygon/convex_core.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide2d::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

// The ellipse's support value along unit n.
double extent(const CoreEllipse& p, const Vec2& n) {
  return std::sqrt(p.a * p.a * n.x() * n.x() + p.b * p.b * n.y() * n.y());
}

// A local maximum of the separation of the two cores (A's radius left out), in the ellipse's frame:
// its value s, its direction u (from A to the ellipse), A's point there and the ellipse's.
struct Peak {
  double s = -kInf;
  Vec2 u = Vec2::UnitX();
  Vec2 on_a = Vec2::Zero(), on_e = Vec2::Zero();
};

// Face i's normal: the ellipse's support point along -n over the face, at s = n.(q - v).
Peak face_peak(const CoreEllipse& p, int i) {
  const Vec2& n = p.core.n[i];
  const double h = extent(p, n);
  const Vec2 q(-p.a * p.a * n.x() / h, -p.b * p.b * n.y() / h);
  const double s = n.dot(q - p.core.v[i]);
  return {s, n, Vec2(q - s * n), q};
}

// Whether u lies in the cone of directions where vertex k is A's support point: from the normal of
// the face that ends at k to the normal of the face that starts there (a half turn at a segment's
// end; every direction at a point).
bool in_cone(const Core& c, int k, const Vec2& u) {
  if (c.count == 1) return true;
  const Vec2& before = c.n[k == 0 ? c.count - 1 : k - 1];
  return cross(before, u) >= 0.0 && cross(u, c.n[k]) >= 0.0;
}

// The maxima of the separation over vertex k's cone that lie inside it, into `best`; each root
// counted in `roots`.
void vertex_peaks(const CoreEllipse& p, int k, Peak& best, int& roots) {
  const Vec2& v = p.core.v[k];
  const auto consider = [&](double s, const Vec2& normal, const Vec2& foot) {
    const Vec2 u = -normal;  // from the vertex towards the ellipse, the ellipse's inward normal
    if (s > best.s && in_cone(p.core, k, u)) best = {s, u, v, foot};
  };
  ++roots;
  const PointEllipseResult near = distance_point_ellipse(p.a, p.b, v);
  consider(near.inside ? -near.distance : near.distance, near.normal, near.closest);
  ++roots;
  if (const std::optional<CurveFoot> other = other_local_nearest(p.a, p.b, v)) {
    consider(other->signed_distance, other->normal, other->point);
  }
}

// The largest face normal's separation, a lower bound of the signed distance.
Peak best_face(const CoreEllipse& p) {
  Peak best;
  for (int i = 0; i < p.core.faces(); ++i) {
    const Peak f = face_peak(p, i);
    if (f.s > best.s) best = f;
  }
  return best;
}

// The global maximum of the separation of A's core and the ellipse, from the best face's, and the
// roots it took.
Peak deepest(const CoreEllipse& p, Peak best, int& roots) {
  for (int k = 0; k < p.core.count; ++k) vertex_peaks(p, k, best, roots);
  return best;
}

// The point of A's core least in the ellipse's quadratic (x/a)^2 + (y/b)^2, and that value: in
// the frame scaled to make the ellipse the unit disc, the core's point nearest the origin (a convex
// polygon there too); 0 where the core holds the centre strictly inside (on an edge, that edge's
// nearest point says so; and a core that rounding has collapsed, far from the ellipse, holds
// nothing).
struct Least {
  Vec2 point = Vec2::Zero();
  double q = kInf;
  double bound = 0.0;  // of q's rounding: 16 u of the largest squared scaled vertex
};
Least least_quadratic(const CoreEllipse& p) {
  const Core& c = p.core;
  const auto scaled = [&](const Vec2& v) { return Vec2(v.x() / p.a, v.y() / p.b); };
  Least out;
  bool holds = c.count >= 3;
  const int edges = c.count == 2 ? 1 : c.count;
  for (int i = 0; i < edges; ++i) {
    const Vec2 w0 = scaled(c.v[i]), w1 = scaled(c.v[(i + 1) % c.count]);
    const Vec2 e = w1 - w0;
    holds = holds && cross(e, Vec2(-w0)) > 0.0;
    const double length = e.squaredNorm();
    const double t = length > 0.0 ? std::clamp(-w0.dot(e) / length, 0.0, 1.0) : 0.0;
    const Vec2 w = t == 1.0 ? w1 : Vec2(w0 + t * e);
    const double q = w.squaredNorm();
    if (q < out.q) out = {Vec2(w.x() * p.a, w.y() * p.b), q};
  }
  if (c.count == 1) out = {c.v[0], scaled(c.v[0]).squaredNorm()};
  if (holds) out = {Vec2::Zero(), 0.0};
  for (int k = 0; k < c.count; ++k) out.bound = std::max(out.bound, scaled(c.v[k]).squaredNorm());
  out.bound *= 8 * std::numeric_limits<double>::epsilon();
  return out;
}

}  // namespace

Contact core_ellipse_contact(const CoreEllipse& p, const ContactOptions& options) {
  const double r = p.core.radius;
  const Peak faces = best_face(p);
  const double scale = p.core.reach + std::max(p.a, p.b) + p.core.v[0].cwiseAbs().maxCoeff();
  if (beyond_limit(faces.s - r, scale, options)) return Contact::beyond(faces.s - r);
  return limited(options, [&] {
    int roots = 0;
    const Peak d = deepest(p, faces, roots);
    const Vec2 u = p.world_direction(d.u);
    Contact c = Contact::of(d.s - r, u, p.world_point(Vec2(d.on_a + r * d.u)), p.world_point(d.on_e));
    c.evaluations = roots;
    return c;
  });
}

namespace {

// Overlapping where the core's least ellipse quadratic is below 1 by more than its rounding (that
// point is a witness: the scaled frame stretches a needle's short axis, and with it the rounding of
// a long edge's nearest point, which the bound follows); else where the signed distance is within
// the radius (a vertex or face point of the core inside the ellipse is a witness, or the ellipse's
// nearest point within the radius of a rounded core), unless a cheaper bound shows them apart. The
// one verdict of the overlap test and the distance, so that they agree to the bit; the deepest peak
// into `d` where it was needed.
bool overlapping(const CoreEllipse& p, const Least& least, Peak& d) {
  if (least.q <= 1.0 - least.bound) return true;
  // Certainly apart: a sharp core beyond the quadratic's rounding, or a face normal's separation (a
  // lower bound of the signed distance) beyond the radius.
  if (p.core.radius == 0.0 && least.q > 1.0 + least.bound) return false;
  const Peak faces = best_face(p);
  if (faces.s > p.core.radius) return false;
  int roots = 0;
  d = deepest(p, faces, roots);
  return d.s <= p.core.radius;
}

}  // namespace

bool core_ellipse_overlap(const CoreEllipse& p) {
  Peak d;
  return overlapping(p, least_quadratic(p), d);
}

DistanceResult core_ellipse_distance(const CoreEllipse& p) {
  const Least least = least_quadratic(p);
  Peak d;
  if (overlapping(p, least, d)) {
    const Vec2& witness = d.s == -kInf ? least.point : d.s <= 0.0 ? d.on_a : d.on_e;
    return DistanceResult::touching(p.world_point(witness));
  }
  if (d.s == -kInf) {
    int roots = 0;
    d = deepest(p, best_face(p), roots);
  }
  const double r = p.core.radius;
  return DistanceResult::apart(d.s - r, p.world_point(Vec2(d.on_a + r * d.u)), p.world_point(d.on_e));
}

}  // namespace collide2d::detail
