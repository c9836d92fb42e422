// Green's theorem over the overlap's boundary, which is the part of each rectangle's boundary inside
// the other. Each rectangle's edges are clipped to the other in the other's frame, where that one
// is the box |x| <= h.x, |y| <= h.y and clipping a line to it is four slabs (Liang and Barsky, "A
// new concept and method for line clipping", 1984). An edge through m along the unit u, clipped to
// the lengths s0 ... s1 from m, adds cross(m + s0 u, m + s1 u) = (s1 - s0) cross(m, u) to twice the
// area about the frame's centre: no crossing point is formed and no polygon assembled, and the two
// reciprocals of the relative rotation's cosine and sine serve every slab of both rectangles. The
// cross product is the same in either frame; moving the origin of A's clipped edges from B's centre
// to A's adds cross(B's centre, their sum). Rectangles turned a whole number of right angles from
// each other overlap in a box.
#include "narrowphase/area/overlap_rect_rect.h"

#include "shapes/internal.h"

#include <algorithm>
#include <cmath>

namespace collide2d::detail::areas {
namespace {

// A rectangle seen from the frame of another: its centre, its first axis there (cos, sin), the
// reciprocals of those two, and its half extents.
struct Posed {
  Vec2 c;
  Vec2 u;
  Vec2 inverse;
  Vec2 h;
};

struct Clipped {
  double twice_area = 0;    // about the frame's centre
  Vec2 sum = Vec2::Zero();  // of the clipped edges' vectors
};

// The lengths along the edge through m with unit direction u (1 / u given) of its part inside the
// slabs |x| <= box.x, |y| <= box.y, from the edge's half length back to its half length forward.
double inside_length(const Vec2& m, const Vec2& inverse, double half, const Vec2& box) {
  const double x0 = (-box.x() - m.x()) * inverse.x(), x1 = (box.x() - m.x()) * inverse.x();
  const double y0 = (-box.y() - m.y()) * inverse.y(), y1 = (box.y() - m.y()) * inverse.y();
  const double s0 = std::max(std::max(-half, std::min(x0, x1)), std::min(y0, y1));
  const double s1 = std::min(std::min(half, std::max(x0, x1)), std::max(y0, y1));
  return std::max(s0, s1) - s0;  // 0 where the part is empty
}

// The parts inside the box |x| <= box.x, |y| <= box.y of the edges of the rectangle `r`, turned
// parallel to neither axis. Edge k runs through its midpoint m along its unit direction: u, v, -u,
// -v, v = perp(u); the part of length w adds w cross(m, direction), which for these midpoints is
// +-cross(c, u) or +-cross(c, v) plus the half extent across.
Clipped clip_edges(const Posed& r, const Vec2& box) {
  const Vec2 u = r.u, v(-u.y(), u.x());
  const Vec2 iu = r.inverse, iv(-iu.y(), iu.x());  // 1 / v = (1 / -u.y, 1 / u.x)
  const double hx = r.h.x(), hy = r.h.y();
  const double w0 = inside_length(r.c - hy * v, iu, hx, box), w2 = inside_length(r.c + hy * v, -iu, hx, box);
  const double w1 = inside_length(r.c + hx * u, iv, hy, box), w3 = inside_length(r.c - hx * u, -iv, hy, box);
  const double cu = cross(r.c, u), cv = cross(r.c, v);
  return {w0 * (cu + hy) + w2 * (hy - cu) + w1 * (cv + hx) + w3 * (hx - cv), (w0 - w2) * u + (w1 - w3) * v};
}

// Below this a rotation is taken for a whole number of right angles: what that moves is under
// 2^-60 of the area, far inside the rounding of the rest.
constexpr double kAligned = 0x1p-60;

// The overlap of two boxes, B's centre at c and half extents e in A's frame.
double boxes(const Vec2& ha, const Vec2& c, const Vec2& e) {
  const Vec2 lo = (-ha).cwiseMax(c - e), hi = ha.cwiseMin(c + e);
  return std::max(hi.x() - lo.x(), 0.0) * std::max(hi.y() - lo.y(), 0.0);
}

}  // namespace

double rect_rect_area(const Rect& a, const Rect& b) {
  const auto ra = Rotation<double>::of(a.angle), rb = Rotation<double>::of(b.angle);
  const auto rel = rb.relative_to(ra);
  const Vec2 c = ra.apply_inverse(Vec2(b.center - a.center));  // B's centre in A's frame
  const Vec2 ha = a.half_extents, hb = b.half_extents;
  if (std::abs(rel.s) <= kAligned) return boxes(ha, c, hb);
  if (std::abs(rel.c) <= kAligned) return boxes(ha, c, Vec2(hb.y(), hb.x()));
  const Vec2 u(rel.c, rel.s), inverse(1 / rel.c, 1 / rel.s);
  const Clipped b_in_a = clip_edges({c, u, inverse, hb}, ha);
  const Vec2 a_centre = -rel.apply_inverse(c);  // A's centre in B's frame
  const Clipped a_in_b = clip_edges({a_centre, Vec2(rel.c, -rel.s), Vec2(inverse.x(), -inverse.y()), ha}, hb);
  // a_in_b's sum is in B's axes: cross() is the same in A's once both vectors turn.
  return (b_in_a.twice_area + a_in_b.twice_area + cross(c, rel.apply(a_in_b.sum))) / 2;
}

}  // namespace collide2d::detail::areas
