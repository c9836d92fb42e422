// Private: pairs as lanes. The lane-generic kernels (the *-inl.h files) are written with the names
// Highway gives its operations; the overloads below give the same names to double values and bool
// masks (one pair, a lane of width one), found by ordinary lookup, while Highway's own are found on
// its vector types by argument-dependent lookup. One template then serves the one-off kernel and
// the batch (overlap_batch.cpp), with the same IEEE operations in the same order. The inputs of
// each kernel, one field per lane, are plain structs here, shared by both.
#pragma once

#include <collide2d/kernels.h>
#include <collide2d/shapes.h>
#include "narrowphase/shared/ellipse/distance_point_ellipse.h"
#include "shapes/internal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace collide2d::detail {

struct Scalar {};
inline double Set(Scalar, double x) { return x; }
inline double Abs(double x) { return std::abs(x); }
inline double Max(double x, double y) { return std::max(x, y); }
inline double Min(double x, double y) { return std::min(x, y); }
inline double Sqrt(double x) { return std::sqrt(x); }
inline double Neg(double x) { return -x; }
inline bool And(bool x, bool y) { return x && y; }
inline bool Or(bool x, bool y) { return x || y; }
inline bool AndNot(bool not_x, bool y) { return !not_x && y; }
inline double CopySign(double magnitude, double sign) { return std::copysign(magnitude, sign); }
inline double IfThenElse(bool m, double yes, double no) { return m ? yes : no; }
inline bool AllTrue(Scalar, bool m) { return m; }
inline bool AllFalse(Scalar, bool m) { return !m; }
inline bool Not(bool m) { return !m; }

// Per lane: certainly separated, certainly overlapping, or neither (uncertain: the exact fallback).
template <class M>
struct LaneVerdicts {
  M separated;
  M overlap;
};

// The nearest point of an ellipse's curve to a point (point_ellipse-inl.h), in the ellipse's frame.
template <class V, class M>
struct NearestOnEllipse {
  V distance;  // from the point to the curve
  V qx, qy;    // the nearest point
  V nx, ny;    // the curve's outward unit normal there
  M inside;    // the point lies in the closed solid
};

inline PointEllipseResult point_ellipse_result(const NearestOnEllipse<double, bool>& n) {
  return {n.distance, Vec2(n.qx, n.qy), Vec2(n.nx, n.ny), n.inside};
}
inline NearestOnEllipse<double, bool> nearest_on_ellipse(const PointEllipseResult& r) {
  return {r.distance, r.closest.x(), r.closest.y(), r.normal.x(), r.normal.y(), r.inside};
}

// A circle and a posed ellipse as the contact takes them: both centres, the ellipse's orientation
// and semi-axes, the radius.
template <class V>
struct CirclePosedEllipseLanes {
  V cx, cy;  // circle centre
  V ex, ey;  // ellipse centre
  V c, s;    // ellipse orientation
  V a, b;    // semi-axes
  V r;       // radius

  static constexpr std::size_t kFields = 9;
  std::array<V, kFields> fields() const { return {cx, cy, ex, ey, c, s, a, b, r}; }  // in declaration order
};

// A single-point contact (Contact's separation, normal, point_a, point_b).
template <class V>
struct ContactLanes {
  V separation;
  V nx, ny;
  V ax, ay;
  V bx, by;

  static constexpr std::size_t kFields = 7;
  std::array<V, kFields> fields() const { return {separation, nx, ny, ax, ay, bx, by}; }  // in declaration order
  Contact contact() const { return Contact::of(separation, Vec2(nx, ny), Vec2(ax, ay), Vec2(bx, by)); }
};

// A rectangle–ellipse pair in the rectangle's frame (RectEllipseFrame's fields).
template <class V>
struct RectEllipseLanes {
  V x0, x1;  // ellipse centre
  V e0, e1;  // rectangle half extents
  V c, s;    // ellipse a-axis direction
  V a, b;    // ellipse semi-axes

  static constexpr std::size_t kFields = 8;
  std::array<V, kFields> fields() const { return {x0, x1, e0, e1, c, s, a, b}; }  // in declaration order
};

// A rectangle pair: B seen from A's frame (RectPairFrame), and both rectangles' half extents.
template <class V>
struct RectRectLanes {
  V tx, ty;  // B's centre
  V c, s;    // B's orientation
  V ax, ay;  // A's half extents
  V bx, by;  // B's half extents

  static constexpr std::size_t kFields = 8;
  std::array<V, kFields> fields() const { return {tx, ty, c, s, ax, ay, bx, by}; }  // in declaration order
};

// Two circles: B's centre less A's, and the radii.
template <class V>
struct CircleCircleLanes {
  V dx, dy;
  V ra, rb;

  static constexpr std::size_t kFields = 4;
  std::array<V, kFields> fields() const { return {dx, dy, ra, rb}; }
};

// A rectangle and a circle: the circle's centre in the rectangle's frame, the rectangle's half
// extents, the radius.
template <class V>
struct RectCircleLanes {
  V px, py;
  V hx, hy;
  V r;

  static constexpr std::size_t kFields = 5;
  std::array<V, kFields> fields() const { return {px, py, hx, hy, r}; }
};

// A posed rectangle and a circle as the contact takes them: the rectangle's centre, orientation and
// half extents, the circle's centre and radius.
template <class V>
struct RectCirclePosedLanes {
  V rx, ry;  // rectangle centre
  V c, s;    // its orientation
  V hx, hy;  // its half extents
  V cx, cy;  // circle centre
  V r;       // radius

  static constexpr std::size_t kFields = 9;
  std::array<V, kFields> fields() const { return {rx, ry, c, s, hx, hy, cx, cy, r}; }  // in declaration order
};

inline RectCirclePosedLanes<double> rect_circle_posed_lanes(const Rect& r, const Orientation& ro, const Circle& c) {
  return {r.center.x(),       r.center.y(), ro.c,         ro.s,    r.half_extents.x(),
          r.half_extents.y(), c.center.x(), c.center.y(), c.radius};
}

// A circle and an ellipse: the circle's centre in the ellipse's frame, the semi-axes, the radius.
template <class V>
struct CircleEllipseLanes {
  V px, py;
  V a, b;
  V r;

  static constexpr std::size_t kFields = 5;
  std::array<V, kFields> fields() const { return {px, py, a, b, r}; }
};

// A core shape against an ellipse as the disc test takes it (disc_filter-inl.h): the shape's centre
// in the ellipse's frame, its reach and inner radius, the semi-axes.
template <class V>
struct DiscEllipseLanes {
  V ox, oy;
  V reach, inner;
  V a, b;

  static constexpr std::size_t kFields = 6;
  std::array<V, kFields> fields() const { return {ox, oy, reach, inner, a, b}; }
};

// Two core shapes, or a core shape and a circle, as the disc test takes them: B's centre in A's
// frame, and each shape's reach and inner radius (a circle's radius both).
template <class V>
struct DiscPairLanes {
  V dx, dy;
  V a_reach, a_inner;
  V b_reach, b_inner;

  static constexpr std::size_t kFields = 6;
  std::array<V, kFields> fields() const { return {dx, dy, a_reach, a_inner, b_reach, b_inner}; }
};

// A core shape's core (convex_core.h) against an ellipse, as the batched overlap takes it: the core's
// placement in the ellipse's frame, its N vertex slots in its own frame (every slot set, those past
// the count repeating the first; 2 for a segment), their count, its radius and the semi-axes.
template <class V, std::size_t N = kMaxPolygonVertices>
struct CoreEllipseLanes {
  V ox, oy;  // the placement's offset
  V c, s;    // and rotation
  std::array<V, N> vx, vy;
  V count;
  V radius;
  V a, b;

  static constexpr std::size_t kFields = 8 + 2 * N;
  std::array<V, kFields> fields() const {  // in declaration order
    std::array<V, kFields> out;            // every slot set below: no zero fill first
    out[0] = ox, out[1] = oy, out[2] = c, out[3] = s;
    std::copy(vx.begin(), vx.end(), out.begin() + 4);
    std::copy(vy.begin(), vy.end(), out.begin() + 4 + N);
    out[kFields - 4] = count, out[kFields - 3] = radius, out[kFields - 2] = a, out[kFields - 1] = b;
    return out;
  }
  // The lanes of fields() (the batch's loads: the arrays rule out brace-initialising the fields).
  static CoreEllipseLanes of(const std::array<V, kFields>& in) {
    CoreEllipseLanes f;
    f.ox = in[0], f.oy = in[1], f.c = in[2], f.s = in[3];
    std::copy_n(in.begin() + 4, N, f.vx.begin());
    std::copy_n(in.begin() + 4 + N, N, f.vy.begin());
    f.count = in[kFields - 4], f.radius = in[kFields - 3], f.a = in[kFields - 2], f.b = in[kFields - 1];
    return f;
  }
};
template <class V>
using PolygonEllipseLanes = CoreEllipseLanes<V, kMaxPolygonVertices>;
template <class V>
using SegmentEllipseLanes = CoreEllipseLanes<V, 2>;

// Two ellipses as the algebraic test takes them (overlap_ellipse_ellipse-inl.h): B's centre less A's in world
// axes, each orientation, each pair of semi-axes.
template <class V>
struct EllipseEllipseLanes {
  V dx, dy;
  V ca, sa;  // A's orientation
  V cb, sb;  // B's orientation
  V aa, ab;  // A's semi-axes
  V ba, bb;  // B's semi-axes

  static constexpr std::size_t kFields = 10;
  std::array<V, kFields> fields() const { return {dx, dy, ca, sa, cb, sb, aa, ab, ba, bb}; }  // in declaration order
};

inline EllipseEllipseLanes<double> ellipse_ellipse_lanes(const Ellipse& a, const Orientation& oa, const Ellipse& b,
                                                         const Orientation& ob) {
  const Vec2 d = b.center - a.center;
  return {d.x(), d.y(), oa.c, oa.s, ob.c, ob.s, a.a, a.b, b.a, b.b};
}

inline CircleCircleLanes<double> circle_circle_lanes(const Circle& a, const Circle& b) {
  const Vec2 d = b.center - a.center;
  return {d.x(), d.y(), a.radius, b.radius};
}
inline RectCircleLanes<double> rect_circle_lanes(const Rect& r, const Orientation& ro, const Circle& c) {
  const Vec2 p = Rotation<double>::of(ro).apply_inverse(Vec2(c.center - r.center));
  return {p.x(), p.y(), r.half_extents.x(), r.half_extents.y(), c.radius};
}
inline CircleEllipseLanes<double> circle_ellipse_lanes(const Circle& c, const Ellipse& e, const Orientation& eo) {
  const Vec2 p = Rotation<double>::of(eo).apply_inverse(Vec2(c.center - e.center));
  return {p.x(), p.y(), e.a, e.b, c.radius};
}
// The verdict for a circle–ellipse lane the filter left uncertain: the point–ellipse root
// (overlap_circle_ellipse.cpp).
bool circle_ellipse_exact(const CircleEllipseLanes<double>& f);
inline CirclePosedEllipseLanes<double> circle_posed_ellipse_lanes(const Circle& c, const Ellipse& e,
                                                                  const Orientation& eo) {
  return {c.center.x(), c.center.y(), e.center.x(), e.center.y(), eo.c, eo.s, e.a, e.b, c.radius};
}

}  // namespace collide2d::detail
