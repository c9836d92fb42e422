// Private: a convex solid's boundary as a closed loop of edges and arcs, for the area kernels.
//
// Every arc is the image of a unit-circle arc under an affine map, p = c + M u with |u| = 1 (M a
// rotation times diag(a, b): a circle's M is r I), run counter-clockwise from u0 to u1. Points are
// relative to an origin near the pair (the first shape's centre), so that far from the world's
// origin the geometry keeps the digits of its own size.
#pragma once

#include <collide2d/shapes.h>

#include "shapes/internal.h"

#include <Eigen/Core>

#include <array>

namespace collide2d::detail::areas {

// The pieces and crossings below have no default member values, so that a boundary's room for a
// rounded octagon's 16 pieces is not written for a curve that uses one: each piece is set whole
// where it is made. They are generic over the scalar: in double for every query, and in
// double-double where iou_distance() takes two near-identical shapes again.
template <class Real>
struct ArcOf {
  V2<Real> c;
  Eigen::Matrix<Real, 2, 2> m;
  Eigen::Matrix<Real, 2, 2> inverse;  // of m
  Real det;                           // of m: a b, or r^2
  V2<Real> u0;
  V2<Real> u1;
  bool full;  // the whole ellipse, from u0 round to u0
  bool circular;

  V2<Real> point(const V2<Real>& u) const { return c + m * u; }
  // The unit vector of a point on (or near) the curve.
  V2<Real> unit(const V2<Real>& p) const;
  // The counter-clockwise tangent at u (not unit).
  V2<Real> tangent(const V2<Real>& u) const { return m * V2<Real>(-u.y(), u.x()); }
};

// A point where a piece starts or ends, with its unit vector when the piece is an arc.
template <class Real>
struct EndOf {
  V2<Real> p;
  V2<Real> u;  // UnitX on an edge
};

// Piece k runs from start to the next piece's start, straight or along its arc.
template <class Real>
struct PieceOf {
  EndOf<Real> start;
  EndOf<Real> end;
  bool curved;
  ArcOf<Real> arc;  // on an edge, unset
};

// At most a rounded octagon's 8 edges and 8 arcs.
inline constexpr int kMaxPieces = 2 * kMaxPolygonVertices;

template <class Real>
struct BoundaryOf {
  std::array<PieceOf<Real>, kMaxPieces> pieces;  // the first `count` set
  int count = 0;
  bool polygonal = true;  // edges only
};

using Arc = ArcOf<double>;
using End = EndOf<double>;
using Piece = PieceOf<double>;
using Boundary = BoundaryOf<double>;

// The boundary of a solid shape (not a segment), relative to `origin`: in double-double, the
// shape's offset from the origin is exact and its rotation within 2^-102.
template <class Real = double>
BoundaryOf<Real> boundary_of(const Shape& s, const Vec2& origin);

// A monotone stand-in for the counter-clockwise angle from u0 to u (both unit), in [0, 4): the
// position of a point along an arc, cheaper than the angle and ordered as it is.
double turn_key(const Vec2& u0, const Vec2& u);

}  // namespace collide2d::detail::areas
