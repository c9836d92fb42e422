// Private: the contact of a pair with a curved shape, from the global maximum of its separation.
#pragma once

#include <collide2d/kernels.h>
#include "narrowphase/shared/curved/deepest_direction.h"

#include <cmath>
#include <limits>

namespace collide2d::detail {

// Whether n is exactly one of the rectangle's face normals (the climb and the search start from
// them, and a face contact's maximum stays there): the rectangle's support point is then the one
// that jumps, and no probing is needed to tell.
inline bool on_face_normal(const RectSupport<double>& r, const V2<double>& n) {
  const V2<double> x(r.rot.c, r.rot.s);
  return cross(x, n) == 0 || x.dot(n) == 0;
}
inline bool on_face_normal(const EllipseSupport<double>&, const V2<double>&) { return false; }

// The contact along A's face normal n (in the pair's frame) at separation s: B's support point,
// offset_b from its centre cb, is kept, and A's is that point moved back by s along the normal.
template <class SA, class SB>
Contact face_contact(const SupportPair<double, SA, SB>& p, const Vec2& cb, const V2<double>& n,
                     const V2<double>& offset_b, double s, int evaluations) {
  const Vec2 normal = p.to_world(n), pb = cb - p.to_world(offset_b);
  Contact c = Contact::of(s, normal, Vec2(pb - s * normal), pb);
  c.evaluations = evaluations;
  return c;
}

// The deepest points are the two support points where s'(n) vanishes to rounding. Elsewhere n is a
// kink of s (a rectangle's face normal, where its support set is the whole face), or a maximum
// sharper than a double angle resolves (a needle's flat side, s'' ~ a^2 / b, where its support
// point may sit anywhere along the side, tip included; see at_maximum). Either way one shape's
// support point jumps as n turns by a hair (1e-6 rad, wider than any such kink) and the other's
// barely moves: the steadier point is kept, and its partner is that point moved by the separation
// along the normal. A contact within a tolerance keeps the point within_tolerance chose.
template <class SA, class SB>
Contact curved_contact(const SupportPair<double, SA, SB>& p, const Vec2& ca, const Vec2& cb, const Deepest<double>& d) {
  const Separation<double>& e = d.at;
  if (on_face_normal(p.A, d.n)) return face_contact(p, cb, d.n, e.offset_b, e.s, d.evaluations);
  const Vec2 normal = p.to_world(d.n);
  const Vec2 off_a = p.to_world(e.offset_a), off_b = p.to_world(e.offset_b);
  Vec2 pa = ca + off_a, pb = cb - off_b;
  // The rounding of s' (three square roots, left to the pairs that need it).
  const auto rounding = [&] {
    return 4 * std::numeric_limits<double>::epsilon() * (p.delta.norm() + off_a.norm() + off_b.norm());
  };
  if (d.kept == Kept::a || on_face_normal(p.B, d.n)) {
    pb = pa + e.s * normal;
  } else if (d.kept == Kept::b) {
    pa = pb - e.s * normal;
  } else if (e.slope != 0 && !(std::abs(e.slope) <= rounding())) {  // 0: a root, its norms spared
    const V2<double> hair = 1e-6 * perp(d.n);
    const V2<double> before = (d.n - hair).normalized(), after = (d.n + hair).normalized();
    const Separation<double> x = p.separation(before, before), y = p.separation(after, after);
    if ((y.offset_b - x.offset_b).norm() <= (y.offset_a - x.offset_a).norm()) {
      pa = pb - e.s * normal;
    } else {
      pb = pa + e.s * normal;
    }
  }
  Contact c = Contact::of(e.s, normal, pa, pb);
  c.evaluations = d.evaluations;
  return c;
}

// ContactOptions::tolerance for the pair, whose larger shape's reach is `size`.
template <class SA, class SB>
Tolerance<double> tolerance_of(const SupportPair<double, SA, SB>& p, double size, const ContactOptions& options) {
  return {options.tolerance, options.tolerance / size, p.A.rho_min() + p.B.rho_min()};
}

}  // namespace collide2d::detail
