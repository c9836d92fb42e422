// Private: what the methods on a convex core and an ellipse share (core_ellipse.cpp): the faces'
// separations, the global maximum of the separation, and the overlap verdict that the overlap test
// and the distance both take. The methods themselves live with their queries:
// overlap/overlap_core_ellipse.cpp, distance/distance_core_ellipse.cpp and
// contact/contact_core_ellipse.cpp.
#pragma once

#include "narrowphase/shared/cores/convex_core.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace collide2d::detail {

// A local maximum of the separation of the two cores (A's radius left out), in the ellipse's frame:
// its value s, its direction u (from A to the ellipse), A's point there and the ellipse's; where its
// root stopped within a tolerance (RootTolerance), a bound of the error of s (0: exact).
struct Peak {
  double s = -std::numeric_limits<double>::infinity();
  Vec2 u = Vec2::UnitX();
  Vec2 on_a = Vec2::Zero(), on_e = Vec2::Zero();
  double error = 0.0;
};

// The largest face normal's separation, a lower bound of the signed distance; the ellipse's support
// along each face normal (FaceSupports) and its least radius of curvature, min(a, b)^2 / max(a, b).
struct Faces {
  Peak best;
  int face = -1;                                                // best's
  double runner_up = -std::numeric_limits<double>::infinity();  // the largest separation of the other faces
  FaceSupports along;
  double least_rho = 0.0;

  Vec2 q(int i) const { return {along.qx[i], along.qy[i]}; }
};
Faces best_face(const CoreEllipse& p);

// The pair's scale: what the rounding of its separations is a few u of.
inline double scale(const CoreEllipse& p) {
  return p.core.discs.reach + std::max(p.a, p.b) + p.core.v[0].cwiseAbs().maxCoeff();
}

// ContactOptions::tolerance as the vertices' point–ellipse roots take it
// (distance_point_ellipse_within): `length` on the separation and the points, `angle` on the normal;
// a length of 0 takes every root to the last bit.
struct RootTolerance {
  double length = 0.0, angle = 0.0;
};

// The global maximum of the separation of A's core and the ellipse, from the best face's, and the
// point–ellipse roots it took.
struct Deepest {
  Peak peak;
  int roots = 0;
};
Deepest deepest(const CoreEllipse& p, const Faces& faces, const RootTolerance& tolerance = {});

// Whether the solids overlap: the one verdict of the overlap test and the distance, so that they
// agree to the bit, with what it found on the way.
struct CoreEllipseVerdict {
  bool overlapping = false;
  // The point of A's core least in the ellipse's quadratic, in the ellipse's frame, and whether it
  // certainly lies in the ellipse.
  Vec2 least_point = Vec2::Zero();
  bool least_inside = false;
  std::optional<Faces> faces;  // where the quadratic did not decide
  Peak deepest;                // where the faces did not decide (else its s is -infinity)
};
CoreEllipseVerdict verdict(const CoreEllipse& p);
// The deepest peak, unless the verdict found it, from the faces it found or else from new ones.
Peak deepest_after(const CoreEllipse& p, const CoreEllipseVerdict& v);

}  // namespace collide2d::detail
