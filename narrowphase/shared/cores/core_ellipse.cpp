#include "narrowphase/shared/cores/core_ellipse.h"

#include "narrowphase/shared/ellipse/distance_point_ellipse.h"
#include "narrowphase/shared/lanes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace collide2d::detail {
#include "narrowphase/shared/cores/arc_bound-inl.h"
#include "narrowphase/shared/cores/least_quadratic-inl.h"

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Whether u lies in the cone of directions where vertex k is A's support point, from the normal of
// the face that ends at k to the normal of the face that starts there (a half turn at a segment's
// end; every direction at a point), with `margin` to spare on both sides (a sine; a negative margin
// widens the cone). For a direction within `turn` rad of u, a margin of turn makes it certainly
// inside, and failing a margin of -turn certainly outside.
bool in_cone(const Core& c, int k, const Vec2& u, double margin = 0.0) {
  return c.count == 1 || (cross(c.n[c.prev(k)], u) >= margin && cross(u, c.n[k]) >= margin);
}

// The maxima of the separation over vertex k's cone that lie inside it, into `best`; each root
// counted in `roots`. Where the nearest foot's normal lies in the cone it is the greatest
// separation over every direction, and the other foot's cannot pass it. With a tolerance the
// nearest foot's root stops early (nearest_in_range).
void vertex_peaks(const CoreEllipse& p, int k, const RootTolerance& tolerance, Peak& best, int& roots) {
  const Vec2& v = p.core.v[k];
  // u, from the vertex towards the ellipse, is the ellipse's inward normal.
  const auto in_cone_of = [&](const Vec2& normal, double margin) { return in_cone(p.core, k, Vec2(-normal), margin); };
  const auto consider = [&](const CurveFoot& f, double error) {
    if (f.signed_distance > best.s) best = {f.signed_distance, -f.normal, v, f.point, error};
  };
  ++roots;
  const RangeFoot near = nearest_in_range(p.a, p.b, v, p.core.radius, tolerance.length, tolerance.angle, in_cone_of);
  if (near.in_range) return consider(near.foot, near.error);
  ++roots;
  const std::optional<CurveFoot> other = other_local_nearest(p.a, p.b, v);
  if (other && in_cone_of(other->normal, 0.0)) consider(*other, 0.0);
}

// Whether the separation of the point v and the ellipse stays at most s over the arc from the
// normal slot `from` to `to`, whose ends' separations are at most s (arc_bound-inl.h).
bool arc_within(const CoreEllipse& p, const Faces& faces, const Vec2& v, int from, int to, double s) {
  const Core& c = p.core;
  const Vec2 &e0 = c.n[from], &e1 = c.n[to];
  const FaceSupports& along = faces.along;
  const ArcLanes<double> arc{e0.x(),       e0.y(),       e1.x(),          e1.y(),        along.qx[from], along.qy[from],
                             along.qx[to], along.qy[to], along.rho[from], along.rho[to], along.h[from],  along.h[to],
                             v.x(),        v.y()};
  return arc_within(Scalar{}, arc, faces.least_rho, p.a, p.b, s);
}

// A core's kind, by its count: its vertex cones' shapes. Each kind has its own code for the cones,
// so that a polygon's carries no segment's or point's branches.
enum class CoreKind { point, segment, polygon };

// Whether the separation over vertex k's cone stays at most s, at least every face's (arc_within).
// A segment's end takes its half turn as two quarter turns about the segment's direction there
// (the normals' slots 2 and 3), whose separation is checked first.
template <CoreKind kind>
bool cone_within(const CoreEllipse& p, const Faces& faces, int k, double s) {
  const Core& c = p.core;
  const Vec2& v = c.v[k];
  if constexpr (kind == CoreKind::point) return v.norm() - std::min(p.a, p.b) <= s;
  const int before = c.prev(k);
  if constexpr (kind == CoreKind::polygon) return arc_within(p, faces, v, before, k, s);
  const int mid = k == 1 ? 2 : 3;
  return -faces.along.h[mid] - c.n[mid].dot(v) <= s && arc_within(p, faces, v, before, mid, s) &&
         arc_within(p, faces, v, mid, k, s);
}

// The global maximum of the separation of A's core and the ellipse, from the best face's, and the
// roots it took: a vertex whose cone cannot beat the best so far takes none. Apart, the separation
// falls away on either side of its greatest (the directions along which it is at least c > 0 make
// an arc), so that where one face's separation is positive and passes every other face's, each
// beyond their rounding, the greatest lies between that face's neighbours: in the cones of its two
// ends. (Faces tied to rounding, as a needle's long sides, may have a far higher peak between
// them.) There, where the ellipse's support point along the face lies over the face, the face's
// point across from it is as far from the ellipse as the face's separation, a lower bound of the
// distance: the face is the greatest. Beyond a segment's end, that end is: as the distance from a
// convex set is convex along a line, the segment's nearest point is the line's nearest, across from
// the support point, clamped to the segment.
template <CoreKind kind>
Peak deepest_of(const CoreEllipse& p, const Faces& faces, const RootTolerance& tolerance, int& roots) {
  const Core& c = p.core;
  const double rounding = 64 * std::numeric_limits<double>::epsilon() * scale(p);
  const bool leads = faces.best.s > rounding && faces.best.s - faces.runner_up > rounding;
  Peak best = faces.best;
  if (leads) {
    const int f = faces.face, side = along_face(c.n[f], c.v[f], c.v[c.next(f)], faces.q(f));
    if (side == 0) return best;
    if constexpr (kind == CoreKind::segment) {
      vertex_peaks(p, side < 0 ? f : c.next(f), tolerance, best, roots);
      return best;
    }
  }
  // A polygon's every vertex open: every cone's bound at once, at the face's separation. A bound
  // that holds there holds at every later best, which only grows; one that fails is taken again
  // only once the best has grown.
  const bool at_once = kind == CoreKind::polygon && !leads;
  const double first = best.s;
  const std::uint32_t settled = at_once ? cones_within(c, faces.along, faces.least_rho, p.a, p.b, first) : 0;
  for (int k = 0; k < c.count; ++k) {
    const bool end_of_best = k == faces.face || k == c.next(faces.face);
    if (!leads || end_of_best) {
      const bool retake = !at_once || best.s > first;
      const bool within = (settled >> k & 1) || (retake && cone_within<kind>(p, faces, k, best.s - best.error));
      if (!within) vertex_peaks(p, k, tolerance, best, roots);
    }
  }
  return best;
}

// The point of A's core least in the ellipse's quadratic (least_quadratic-inl.h), in the scaled
// frame, and that value (0 where the core holds the centre strictly inside; on an edge, that edge's
// nearest point says so; and a core that rounding has collapsed, far from the ellipse, holds
// nothing).
LeastQuadratic<double> least_quadratic(const CoreEllipse& p) {
  const Core& c = p.core;
  const double count = c.count;
  return least_quadratic(Scalar{}, scaled_core(Scalar{}, c.x, c.y, p.a, p.b), count, c.count == 2 ? 1 : c.count);
}

}  // namespace

Faces best_face(const CoreEllipse& p) {
  const Core& c = p.core;
  Faces out;
  face_supports(c, p.a, p.b, out.along);
  double best = -kInf, runner_up = -kInf;
  int face = -1;
  for (int i = 0; i < c.faces(); ++i) {
    const double s = out.along.s[i];
    runner_up = std::max(runner_up, std::min(best, s));
    face = s > best ? i : face;
    best = std::max(best, s);
  }
  out.face = face, out.runner_up = runner_up;
  if (face >= 0) {
    const Vec2 &n = c.n[face], q = out.q(face);
    out.best = {best, n, Vec2(q - best * n), q};
  }
  const double minor = std::min(p.a, p.b);
  out.least_rho = minor * minor / std::max(p.a, p.b);
  return out;
}

Deepest deepest(const CoreEllipse& p, const Faces& faces, const RootTolerance& tolerance) {
  int roots = 0;  // a local, not the result's: the peaks' loop keeps it in a register
  switch (p.core.count) {
    case 1:
      return {deepest_of<CoreKind::point>(p, faces, tolerance, roots), roots};
    case 2:
      return {deepest_of<CoreKind::segment>(p, faces, tolerance, roots), roots};
    default:
      return {deepest_of<CoreKind::polygon>(p, faces, tolerance, roots), roots};
  }
}

// Overlapping where the core's least ellipse quadratic is below 1 by more than its rounding (that
// point is a witness: the scaled frame stretches a needle's short axis, and with it the rounding of
// a long edge's nearest point, which the bound follows) or a rounded core's radius certainly reaches
// the ellipse; apart where it certainly does not (quadratic_verdicts); else where the signed
// distance is within the radius (a vertex or face point of the core inside the ellipse is a
// witness, or the ellipse's nearest point within the radius of a rounded core), unless a face
// normal's separation (a lower bound of the signed distance) shows them apart. The one verdict of
// the overlap test and the distance, so that they agree to the bit; the faces' separations into
// the verdict where they were needed.
CoreEllipseVerdict verdict(const CoreEllipse& p) {
  const LeastQuadratic<double> least = least_quadratic(p);
  CoreEllipseVerdict v;
  v.least_point = Vec2(least.wx * p.a, least.wy * p.b);
  v.least_inside = !(least.q > 1.0 - least.bound);
  const LaneVerdicts<bool> certain = quadratic_verdicts(Scalar{}, least, p.core.x, p.core.y, p.core.radius, p.a, p.b);
  if (certain.overlap || certain.separated) {
    v.overlapping = certain.overlap;
    return v;
  }
  v.faces = best_face(p);
  if (v.faces->best.s > p.core.radius) return v;
  v.deepest = deepest(p, *v.faces).peak;
  v.overlapping = v.deepest.s <= p.core.radius;
  return v;
}

Peak deepest_after(const CoreEllipse& p, const CoreEllipseVerdict& v) {
  if (v.deepest.s != -kInf) return v.deepest;
  return deepest(p, v.faces ? *v.faces : best_face(p)).peak;
}

}  // namespace collide2d::detail
