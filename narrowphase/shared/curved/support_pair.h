// Private: two convex, centrally symmetric solids seen through their exact support functions, in the
// frame of the longer one, generic over the scalar (the ellipse overlap test repeats itself in long
// double) and over the shapes (ellipses and circles are smooth; a rectangle's support point is a
// corner, constant on each quarter turn of directions between its face normals).
//
// For a unit direction n and a shape centred at the origin, h(n) is the support function, the support
// point is the offset from the centre, and rho is the radius of curvature there (0 at a corner).
// With delta = c_B - c_A, the separation of the pair along n (A towards B) is
//   s(n) = n.delta - h_A(n) - h_B(n)
// (h_B(-n) = h_B(n) by symmetry): the signed distance between the two supporting lines normal to n.
// The signed distance of the pair is max s over all n, apart and overlapping alike.
#pragma once

#include <collide2d/shapes.h>
#include "shapes/internal.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

namespace collide2d::detail {

template <class Real>
struct Support {
  V2<Real> offset;     // support point minus centre
  Real h = 0;          // support function value
  Real rho = 0;        // radius of curvature of the boundary at the support point
  Real rho_slope = 0;  // d rho / d phi for n turning counter-clockwise
};

template <class Real>
struct EllipseSupport {
  Rotation<Real> rot;  // in the pair's frame
  Real a = 1;
  Real b = 1;

  // n must be a unit vector.
  Support<Real> at(const V2<Real>& n) const { return at_extent(n, extent(n)); }
  // The same where h = extent(n) is known.
  Support<Real> at_extent(const V2<Real>& n, Real h) const {
    const V2<Real> l = rot.apply_inverse(n);
    const Real u = a * l[0];
    const Real v = b * l[1];
    const Real inv = 1 / h;
    const Real k = a * b * inv;  // at most max(a, b): (ab)^2 / h^3 without overflow
    const Real rho = k * k * inv;
    // rho = (ab)^2 / h^3, so rho' = -3 rho h' / h, and h' = perp(n).offset = (b^2 - a^2) l0 l1 / h.
    const Real turn = (b - a) * (b + a) * inv * l[0] * l[1];
    return {rot.apply(V2<Real>(a * u * inv, b * v * inv)), h, rho, -3 * rho * inv * turn};
  }
  // The curve is smooth: no side to choose.
  Support<Real> at(const V2<Real>& n, const V2<Real>&) const { return at(n); }
  // The support value h(n) alone, without the point.
  Real extent(const V2<Real>& n) const {
    using std::sqrt;
    const V2<Real> l = rot.apply_inverse(n);
    const Real u = a * l[0];
    const Real v = b * l[1];
    return sqrt(u * u + v * v);  // not hypot: that costs a quarter of a distance query
  }
  // The least radius of curvature over the directions from x to y (less than a half turn), given
  // its values there: rho = (ab)^2 / h^3 falls as h grows towards the major axis, so it is least at
  // an end unless the arc holds the major axis' direction, where it is b^2 / a.
  Real rho_floor(const V2<Real>& x, const V2<Real>& y, Real rho_x, Real rho_y) const {
    using std::min;
    const V2<Real> major = a >= b ? V2<Real>(rot.c, rot.s) : V2<Real>(-rot.s, rot.c);
    const auto holds = [&](const V2<Real>& m) { return cross(x, m) >= 0 && cross(m, y) >= 0; };
    if (holds(major) || holds(V2<Real>(-major))) return rho_min();
    return min(rho_x, rho_y);
  }
  // The least radius of curvature, at the ends of the major axis.
  Real rho_min() const { return std::min(a, b) * std::min(a, b) / std::max(a, b); }
  // Bounds of the radius of curvature over the directions within `turn` rad of n, from the support
  // offset at n: rho = (ab)^2 / h^3, and |h'| = |perp(n).offset| <= max(a, b) keeps h within
  // n.offset +- max(a, b) turn. The upper bound is infinite where h may reach 0.
  Real rho_within(const V2<Real>& offset, const V2<Real>& n, Real turn) const {
    const Real h = n.dot(offset) - std::max(a, b) * turn;
    return h > 0 ? rho_at(h) : std::numeric_limits<Real>::infinity();
  }
  Real rho_least_within(const V2<Real>& offset, const V2<Real>& n, Real turn) const {
    return std::max(rho_at(n.dot(offset) + std::max(a, b) * turn), rho_min());
  }
  // The radius of curvature (ab)^2 / h^3 where the support value is h, without overflow.
  Real rho_at(Real h) const {
    const Real k = a * b / h;
    return k * k / h;
  }
  // The radius of the largest disc inside the ellipse tangent at its support point `offset` for the
  // unit direction n. Its centre is where the inward normal there meets the major axis (the
  // medial axis: that point's two nearest boundary points are this one and its mirror image), at
  // distance b^2 / h(n) for semi-axes a >= b and h(n) = n.offset: b^2 / a at the ends of the major
  // axis, b on the flat sides. Shrunk by 16 u, so that rounding cannot make it larger than it is.
  Real inscribed_radius(const V2<Real>& offset, const V2<Real>& n) const {
    const Real minor = std::min(a, b);
    return minor * minor / n.dot(offset) * (1 - 16 * std::numeric_limits<Real>::epsilon());
  }
};

// A rectangle's support point is the corner on the side of `side`, a direction in the same quarter
// turn as n: on a face normal n itself cannot choose between the face's two corners, and a caller
// walking an arc of directions must keep the corner of that arc's interior.
template <class Real>
struct RectSupport {
  Rotation<Real> rot;  // in the pair's frame
  Real hx = 1;
  Real hy = 1;

  Support<Real> at(const V2<Real>& n, const V2<Real>& side) const {
    const V2<Real> l = rot.apply_inverse(side);
    const V2<Real> offset = rot.apply(V2<Real>(l[0] >= 0 ? hx : -hx, l[1] >= 0 ? hy : -hy));
    return {offset, n.dot(offset), Real(0)};
  }
  Real rho_floor(const V2<Real>&, const V2<Real>&, Real, Real) const { return 0; }
  // The support value h(n) alone.
  Real extent(const V2<Real>& n) const {
    using std::abs;
    const V2<Real> l = rot.apply_inverse(n);
    return abs(l[0]) * hx + abs(l[1]) * hy;
  }
  // The signed distance from q (relative to the centre) to the solid rectangle.
  Real signed_distance(const V2<Real>& q) const {
    using std::abs;
    using std::max;
    using std::sqrt;
    const V2<Real> l = rot.apply_inverse(q);
    const Real dx = abs(l[0]) - hx, dy = abs(l[1]) - hy;
    if (dx <= 0 && dy <= 0) return max(dx, dy);
    const Real ox = max(dx, Real(0)), oy = max(dy, Real(0));
    return sqrt(ox * ox + oy * oy);
  }
};

template <class Real>
struct Separation {
  Real s = 0;      // s(n)
  Real slope = 0;  // ds/dphi for n turning counter-clockwise
  Real bend = 0;   // -d2s/dphi2 = s + rho_A + rho_B, positive wherever s > 0 (s is concave there)
  V2<Real> gap;    // support point of B in -n minus support point of A in n
  V2<Real> offset_a;
  V2<Real> offset_b;  // B's support offset in direction +n (B's contact point is c_B - offset_b)
  Real rho_a = 0;
  Real rho_b = 0;
  Real rho_slope = 0;  // d(rho_A + rho_B) / d phi, so that d3s/dphi3 = -(slope + rho_slope)
};

template <class Real>
EllipseSupport<Real> support_in(const Ellipse& e, const Rotation<Real>& rot) {
  return {rot, static_cast<Real>(e.a), static_cast<Real>(e.b)};
}
template <class Real>
RectSupport<Real> support_in(const Rect& r, const Rotation<Real>& rot) {
  return {rot, static_cast<Real>(r.half_extents.x()), static_cast<Real>(r.half_extents.y())};
}
inline double longest(const Ellipse& e) { return std::max(e.a, e.b); }
inline double longest(const Rect& r) { return r.half_extents.maxCoeff(); }
// What a shape adds to the pair's scale: its reach, or for a rectangle its half sides summed, which
// bounds the sum of its coordinates' magnitudes.
inline double scale_reach(const Ellipse& e) { return longest(e); }
inline double scale_reach(const Rect& r) { return r.half_extents.sum(); }

// Everything here (directions, offsets, delta) is in the pair's frame: the axes of the longer shape,
// whose rotation is then exactly the identity. In world axes a needle's normal carries an absolute
// error of u, which its support function multiplies by its length: for a needle 1e20 long a gap of
// 0.5 beside it was lost. In its own axes the normal is exact and directions near it keep their
// relative precision; the shorter shape's rotation, composed from the two cosines and sines,
// carries the error u instead, times its own length.
template <class Real, class SA, class SB>
struct SupportPair {
  SA A;
  SB B;
  V2<Real> delta;        // c_B - c_A
  Real scale = 0;        // |delta| + the two shapes' reaches: rounding errors are a few u * scale
  Rotation<Real> frame;  // the pair's axes in world axes

  template <class X, class Y>
  static SupportPair of(const X& a, const Y& b) {
    return of(a, Rotation<Real>::of(a.angle), b, Rotation<Real>::of(b.angle));
  }
  // With each shape's orientation (the cosine and sine of its angle) kept by the caller.
  template <class X, class Y>
  static SupportPair of(const X& a, const Rotation<Real>& ra, const Y& b, const Rotation<Real>& rb) {
    const V2<Real> d(static_cast<Real>(b.center.x()) - static_cast<Real>(a.center.x()),
                     static_cast<Real>(b.center.y()) - static_cast<Real>(a.center.y()));
    const bool a_longer = longest(a) >= longest(b);
    const Rotation<Real> frame = a_longer ? ra : rb;
    // Equal angles give the identity exactly (composing would leave c^2 + s^2, off 1 by an ulp).
    const auto in_frame = [&](const Rotation<Real>& r) {
      return a.angle == b.angle ? Rotation<Real>{} : r.relative_to(frame);
    };
    return {support_in(a, a_longer ? Rotation<Real>{} : in_frame(ra)),
            support_in(b, a_longer ? in_frame(rb) : Rotation<Real>{}), frame.apply_inverse(d),
            d.norm() + static_cast<Real>(scale_reach(a) + scale_reach(b)), frame};
  }

  V2<Real> to_world(const V2<Real>& v) const { return frame.apply(v); }
  V2<Real> from_world(const V2<Real>& v) const { return frame.apply_inverse(v); }

  // The tolerance below which a sign computed here is not trusted.
  Real margin() const { return 64 * std::numeric_limits<Real>::epsilon() * scale; }

  // s along the unit direction n, with each rectangle's corner taken on the side of `side`.
  Separation<Real> separation(const V2<Real>& n, const V2<Real>& side) const {
    return combine(n, A.at(n, side), B.at(n, side));
  }
  Separation<Real> separation(const V2<Real>& n) const { return separation(n, n); }
  // s along n with the corners of two sides of a rectangle's face normal n (the arcs before and
  // after it): the curved shape's support is evaluated once for both.
  std::array<Separation<Real>, 2> separations(const V2<Real>& n, const V2<Real>& before, const V2<Real>& after) const {
    if constexpr (std::is_same_v<SA, RectSupport<Real>>) {
      static_assert(!std::is_same_v<SB, RectSupport<Real>>, "two rectangles have their own kernels");
      return separations(n, before, after, B.at(n, n));
    } else if constexpr (std::is_same_v<SB, RectSupport<Real>>) {
      return separations(n, before, after, A.at(n, n));
    } else {
      const Separation<Real> e = separation(n);
      return {e, e};
    }
  }
  // The same for a rectangle and a curve whose support at n is known.
  std::array<Separation<Real>, 2> separations(const V2<Real>& n, const V2<Real>& before, const V2<Real>& after,
                                              const Support<Real>& curved) const {
    if constexpr (std::is_same_v<SA, RectSupport<Real>>) {
      return {combine(n, A.at(n, before), curved), combine(n, A.at(n, after), curved)};
    } else {
      return {combine(n, curved, B.at(n, before)), combine(n, curved, B.at(n, after))};
    }
  }
  // s along -n, from e along n: both shapes are centrally symmetric, so their support points (a
  // rectangle's corner on the opposite side) are those for n negated, bit for bit, and no support
  // is evaluated.
  Separation<Real> opposite(const V2<Real>& n, const Separation<Real>& e) const {
    const V2<Real> gap = delta + e.offset_a + e.offset_b;
    const Real s = -n.dot(gap);
    return {s, -perp(n).dot(gap), s + e.rho_a + e.rho_b, gap, -e.offset_a, -e.offset_b, e.rho_a, e.rho_b, e.rho_slope};
  }

 private:
  Separation<Real> combine(const V2<Real>& n, const Support<Real>& sa, const Support<Real>& sb) const {
    const V2<Real> gap = delta - sa.offset - sb.offset;
    const Real s = n.dot(gap);
    return {s,      perp(n).dot(gap), s + sa.rho + sb.rho,        gap, sa.offset, sb.offset,
            sa.rho, sb.rho,           sa.rho_slope + sb.rho_slope};
  }
};

}  // namespace collide2d::detail
