#include "narrowphase/area/crossings.h"

#include "narrowphase/area/conic_roots.h"
#include "shapes/internal.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace collide2d::detail::areas {
namespace {

// The position of a point of the piece (t on an edge, u on an arc), if the piece owns it.
bool owns(const Piece& piece, double t, const Vec2& u, Place& place) {
  if (!piece.curved) {
    place.key = t;
    place.u = Vec2::UnitX();
    return t >= 0 && t < 1;
  }
  place.u = u;
  place.key = turn_key(piece.arc.u0, u);
  return piece.arc.full || place.key < turn_key(piece.arc.u0, piece.arc.u1);
}

Vec2 tangent(const Piece& piece, const Place& place) {
  return piece.curved ? piece.arc.tangent(place.u) : Vec2(piece.end.p - piece.start.p);
}

class Collector {
 public:
  Collector(const Boundary& a, const Boundary& b, Crossings& out) : a_(a), b_(b), out_(out) {}

  // A crossing at p, at t or u on A's piece i and on B's piece j.
  void add(const Vec2& p, int i, double ta, const Vec2& ua, int j, double tb, const Vec2& ub) {
    Crossing x;
    x.p = p;
    x.a.piece = i;
    x.b.piece = j;
    if (out_.count == kMaxCrossings || !owns(a_.pieces[i], ta, ua, x.a) || !owns(b_.pieces[j], tb, ub, x.b)) return;
    const Vec2 ta_dir = tangent(a_.pieces[i], x.a), tb_dir = tangent(b_.pieces[j], x.b);
    x.entering = cross(tb_dir, ta_dir) / std::sqrt(ta_dir.squaredNorm() * tb_dir.squaredNorm());
    out_.list[out_.count++] = x;
  }

 private:
  const Boundary& a_;
  const Boundary& b_;
  Crossings& out_;
};

void edge_edge(const Piece& p, int i, const Piece& q, int j, Collector& out) {
  const Vec2 e = p.end.p - p.start.p, g = q.end.p - q.start.p, w = q.start.p - p.start.p;
  const double den = cross(e, g);
  if (den == 0) return;
  const double s = cross(w, g) / den, t = cross(w, e) / den;
  out.add(p.start.p + s * e, i, s, Vec2::UnitX(), j, t, Vec2::UnitX());
}

// The edge's parameters where it meets the arc's whole curve, and the curve's unit vectors there:
// from the foot of the curve's centre on the edge's line in the curve's unit frame, so that an edge
// far longer than a small arc keeps the arc's digits (the quadratic's constant term would cancel).
template <class Add>
void edge_curve(const Piece& edge, const Arc& arc, Add add) {
  const Vec2 e = edge.end.p - edge.start.p;
  const Vec2 p0 = arc.inverse * (edge.start.p - arc.c), d = arc.inverse * e;
  const double dd = d.squaredNorm(), foot = -p0.dot(d) / dd;
  const double reach = (p0 + foot * d).norm(), rest = (1 - reach) * (1 + reach);
  if (!(rest >= 0) || dd == 0) return;
  const double half = std::sqrt(rest / dd);
  for (const double s : {foot - half, foot + half}) add(edge.start.p + s * e, s, arc.unit(edge.start.p + s * e));
}

void edge_arc(const Piece& edge, int i, const Piece& arc, int j, Collector& out) {
  edge_curve(edge, arc.arc, [&](const Vec2& p, double s, const Vec2& u) { out.add(p, i, s, Vec2::UnitX(), j, 0, u); });
}

void arc_edge(const Piece& arc, int i, const Piece& edge, int j, Collector& out) {
  edge_curve(edge, arc.arc, [&](const Vec2& p, double s, const Vec2& u) { out.add(p, i, 0, u, j, s, Vec2::UnitX()); });
}

// Two circles meet on the line of their centres at distance l from the smaller one's centre, and
// h off it: l = (d^2 + r1^2 - r2^2) / 2d, h^2 = r1^2 - l^2 (r1 the smaller radius), with d^2 - r2^2 as
// (d - r2)(d + r2), so that the smaller circle keeps its digits beside a larger one.
template <class Add>
void circle_circle(const Arc& small, const Arc& large, Add add) {
  const Vec2 d = large.c - small.c;
  const double r1 = small.m(0, 0), r2 = large.m(0, 0), dist = d.norm();
  if (dist == 0) return;
  const double l = ((dist - r2) * (dist + r2) + r1 * r1) / (2 * dist), h2 = (r1 - l) * (r1 + l);
  if (!(h2 >= 0)) return;
  const Vec2 along = d / dist, across = std::sqrt(h2) * Vec2(-along.y(), along.x());
  for (const double side : {-1.0, 1.0}) add(small.c + l * along + side * across);
}

void arc_arc(const Piece& p, int i, const Piece& q, int j, Collector& out) {
  // The smaller curve is the unit circle the other is solved on: the larger one's terms stay near
  // its size there, where in the larger one's frame the smaller one's would cancel.
  const bool swap = q.arc.m.cwiseAbs().maxCoeff() < p.arc.m.cwiseAbs().maxCoeff();
  const Arc &on = swap ? q.arc : p.arc, &other = swap ? p.arc : q.arc;
  if (on.circular && other.circular)
    return circle_circle(on, other, [&](const Vec2& x) { out.add(x, i, 0, p.arc.unit(x), j, 0, q.arc.unit(x)); });
  UnitCircleRoots roots = unit_circle_meets(other.inverse * on.m, other.inverse * (on.c - other.c));
  for (int k = 0; k < roots.count; ++k) {
    const Vec2 x = on.point(roots.u[k]), v = other.unit(x);
    if (swap)
      out.add(x, i, 0, v, j, 0, roots.u[k]);
    else
      out.add(x, i, 0, roots.u[k], j, 0, v);
  }
}

using DD = DoubleDouble;

// A piece's curve function at p, zero on the curve, and its gradient: the edge's cross product
// with p, or |M^-1 (p - c)|^2 - 1 on an arc.
struct Level {
  DD value;
  V2<DD> gradient;
};

Level level(const PieceOf<DD>& piece, const V2<DD>& p) {
  if (!piece.curved) {
    const V2<DD> e = piece.end.p - piece.start.p;
    return {cross(e, V2<DD>(p - piece.start.p)), perp(e)};
  }
  const V2<DD> w = piece.arc.inverse * (p - piece.arc.c);
  return {w.squaredNorm() - 1, DD(2) * (piece.arc.inverse.transpose() * w)};
}

// Newton's steps stop one after the first below this fraction of the point's distance from the
// origin: the iteration converges quadratically, so that the point is then off by the rounding of
// the curve functions across the curves and by that over the sine of the crossing angle along
// them; kMaxSteps bound them. A point that wandered beyond kReach of that distance from the double
// crossing is another crossing, or none.
constexpr double kSettled = 0x1p-40;
constexpr double kReach = 0x1p-8;
constexpr int kMaxSteps = 8;

// The larger coordinate's magnitude: the scale the steps are measured against.
double magnitude(const V2<DD>& v) { return std::max(std::abs(v.x().hi), std::abs(v.y().hi)); }

// Newton's step at p for the two pieces' curve equations; none where their gradients are parallel.
std::optional<V2<DD>> newton_step(const PieceOf<DD>& pa, const PieceOf<DD>& pb, const V2<DD>& p) {
  const Level f = level(pa, p), g = level(pb, p);
  const DD det = cross(f.gradient, g.gradient);
  if (det.hi == 0) return std::nullopt;
  return V2<DD>(g.value * f.gradient.y() - f.value * g.gradient.y(),
                f.value * g.gradient.x() - g.value * f.gradient.x()) /
         det;
}

}  // namespace

bool refined(const BoundaryOf<DD>& a, const BoundaryOf<DD>& b, const Crossing& x, ExtendedCrossing& out) {
  const PieceOf<DD>&pa = a.pieces[x.a.piece], &pb = b.pieces[x.b.piece];
  const V2<DD> start(x.p.x(), x.p.y());
  V2<DD> p = start;
  const double size = magnitude(start);
  bool small = false, settled = false;
  for (int k = 0; k < kMaxSteps && !settled; ++k) {
    const std::optional<V2<DD>> step = newton_step(pa, pb, p);
    if (!step) return false;
    p += *step;
    settled = small;
    small = magnitude(*step) <= kSettled * size;
  }
  if (!settled || !(magnitude(p - start) <= kReach * size)) return false;
  const V2<DD> unit_x = V2<DD>::UnitX();
  out.a = {p, pa.curved ? pa.arc.unit(p) : unit_x};
  out.b = {p, pb.curved ? pb.arc.unit(p) : unit_x};
  return true;
}

Crossings crossings_of(const Boundary& a, const Boundary& b) {
  Crossings out;
  Collector collect(a, b, out);
  for (int i = 0; i < a.count; ++i) {
    const Piece& p = a.pieces[i];
    for (int j = 0; j < b.count; ++j) {
      const Piece& q = b.pieces[j];
      if (!p.curved && !q.curved) edge_edge(p, i, q, j, collect);
      if (!p.curved && q.curved) edge_arc(p, i, q, j, collect);
      if (p.curved && !q.curved) arc_edge(p, i, q, j, collect);
      if (p.curved && q.curved) arc_arc(p, i, q, j, collect);
    }
  }
  return out;
}

}  // namespace collide2d::detail::areas
