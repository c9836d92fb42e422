#include "narrowphase/contact/contact_rect_rect.h"
#include <collide2d/kernels.h>
#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/frames/rect_pair_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide2d {
namespace {

using detail::Rotation;

double sign_of(double x) { return x < 0 ? -1.0 : 1.0; }

// Corner numbers of FeatureKind (query.h) from the signs of the local coordinates.
int corner_index(double sx, double sy) {
  if (sy < 0) return sx < 0 ? 0 : 1;
  return sx > 0 ? 2 : 3;
}

// The incident rectangle seen from the reference rectangle's frame.
struct View {
  Vec2 ref_half;
  Vec2 inc_half;
  Rotation<double> rot;  // the incident rectangle's axes in the reference frame
  Vec2 center;           // its centre there
  bool ref_is_a;

  Vec2 incident_point(const Vec2& local) const { return center + rot.apply(local); }
  // How far the incident rectangle lies beyond the reference's face on axis k that faces it.
  double face_separation(int k) const {
    const double c = std::abs(rot.c), s = std::abs(rot.s);
    const double reach = k == 0 ? inc_half.x() * c + inc_half.y() * s : inc_half.x() * s + inc_half.y() * c;
    return std::abs(center[k]) - ref_half[k] - reach;
  }
};

struct Feature {
  Vec2 on_ref = Vec2::Zero();
  Vec2 on_inc = Vec2::Zero();
  double separation = 0;
  int ref_index = 0;  // reference face (or corner, for corner pairs)
  int inc_index = 0;  // incident corner, or 4 / 5 where a side plane cut the incident face
};

// The incident face's ends: the face of the incident rectangle most opposed to the normal n.
std::array<Feature, 2> incident_face(const View& v, int k, double sigma) {
  const Vec2 u[2] = {v.rot.apply(Vec2(1, 0)), v.rot.apply(Vec2(0, 1))};
  const int m = std::abs(u[0][k]) >= std::abs(u[1][k]) ? 0 : 1;
  const double tau = -sign_of(sigma * u[m][k]);
  std::array<Feature, 2> out;
  for (int e = 0; e < 2; ++e) {
    // Built whole: written a coordinate at a time by index, the vector would be stored in halves
    // and read back whole, a stalled store forwarding.
    const double along = e == 0 ? -1.0 : 1.0;
    const Vec2 local = m == 0 ? Vec2(tau * v.inc_half.x(), along * v.inc_half.y())
                              : Vec2(along * v.inc_half.x(), tau * v.inc_half.y());
    out[e].on_inc = v.incident_point(local);
    out[e].inc_index = corner_index(local.x(), local.y());
  }
  return out;
}

// Cuts the incident segment to the reference face's side planes (coordinate j within +-limit);
// false when nothing is left. A cut point lies on its plane exactly: interpolated, its j coordinate
// would carry the rounding of the whole segment, and an incident face 1e20 long cut to a face 16
// wide landed beyond the other plane (the fuzzer; the pair was then taken for two corners).
bool clip(std::array<Feature, 2>& seg, int j, double limit) {
  for (const double sign : {-1.0, 1.0}) {
    const double d0 = sign * seg[0].on_inc[j] - limit, d1 = sign * seg[1].on_inc[j] - limit;
    if (d0 > 0 && d1 > 0) return false;
    const int id = sign < 0 ? 4 : 5;
    const auto cut = [&](const Vec2& from, const Vec2& to, double d_from, double d_to) {
      const Vec2 p = from + (d_from / (d_from - d_to)) * (to - from);
      const Vec2 on_plane = j == 0 ? Vec2(sign * limit, p.y()) : Vec2(p.x(), sign * limit);
      return Feature{Vec2::Zero(), on_plane, 0, 0, id};
    };
    if (d0 > 0) seg[0] = cut(seg[0].on_inc, seg[1].on_inc, d0, d1);
    if (d1 > 0) seg[1] = cut(seg[1].on_inc, seg[0].on_inc, d1, d0);
  }
  return true;
}

// The closest corners of two rectangles apart whose nearest features are corners (compared by
// squared distance: one square root in all).
Feature nearest_corners(const View& v) {
  Feature best{Vec2::Zero(), Vec2::Zero(), std::numeric_limits<double>::infinity(), 0, 0};
  for (const double rx : {-1.0, 1.0}) {
    for (const double ry : {-1.0, 1.0}) {
      const Vec2 r(rx * v.ref_half.x(), ry * v.ref_half.y());
      for (const double ix : {-1.0, 1.0}) {
        for (const double iy : {-1.0, 1.0}) {
          const Vec2 p = v.incident_point(Vec2(ix * v.inc_half.x(), iy * v.inc_half.y()));
          const double d = (p - r).squaredNorm();
          if (d < best.separation) best = {r, p, d, corner_index(rx, ry), corner_index(ix, iy)};
        }
      }
    }
  }
  best.separation = detail::hypotenuse(best.on_inc.x() - best.on_ref.x(), best.on_inc.y() - best.on_ref.y());
  return best;
}

// The contact with the reference face k of view v, whose separation is `best`, written in the
// caller's order (swapped: the caller gave B first).
Contact contact_on(const detail::RectPairFrame& f, const Rect& a, const View& v, int k, double best,
                   const ContactOptions& options, bool swapped) {
  const bool ref_first = v.ref_is_a != swapped;  // the reference rectangle is the caller's A
  const auto to_a = [&](const Vec2& p) -> Vec2 { return v.ref_is_a ? p : Vec2(f.b_center + f.b_rel.apply(p)); };
  const auto to_world = [&](const Vec2& p) -> Vec2 { return a.center + f.a_rot.apply(to_a(p)); };
  const auto direction_to_world = [&](const Vec2& n) -> Vec2 {
    return f.a_rot.apply(v.ref_is_a ? n : f.b_rel.apply(n));
  };
  const auto point = [&](const Feature& x, FeatureKind kind) {
    const Vec2 r = to_world(x.on_ref), i = to_world(x.on_inc);
    const std::uint32_t id = kind == FeatureKind::corner_corner && !ref_first
                                 ? feature_id(kind, x.inc_index, x.ref_index)
                                 : feature_id(kind, x.ref_index, x.inc_index);
    return ref_first ? ContactPoint{r, i, x.separation, id} : ContactPoint{i, r, x.separation, id};
  };

  const double sigma = sign_of(v.center[k]);
  const int j = 1 - k;
  const auto separation_of = [&](Feature& x) { x.separation = sigma * x.on_inc[k] - v.ref_half[k]; };
  std::array<Feature, 2> face = incident_face(v, k, sigma);
  for (Feature& x : face) separation_of(x);
  const Feature deep = face[0].separation <= face[1].separation ? face[0] : face[1];
  const bool cut = clip(face, j, v.ref_half[j]);
  for (Feature& x : face) separation_of(x);
  if (cut && face[1].separation < face[0].separation) std::swap(face[0], face[1]);
  // Apart, the face's separation is the distance only if the incident rectangle's nearest point
  // lies within the reference face's side planes; else the nearest features are two corners, and
  // every point of the incident face within the side planes is farther than the face's separation.
  const double rounding =
      8 * std::numeric_limits<double>::epsilon() * (v.center.norm() + v.ref_half.sum() + v.inc_half.sum());
  if (best > 0 && (!cut || face[0].separation > best + rounding)) {
    const Feature c = nearest_corners(v);
    const ContactPoint p = point(c, FeatureKind::corner_corner);
    // From the corners' difference in the frame, not from the world points, whose rounding grows
    // with the offset of the pair from the origin.
    const Vec2 towards_inc = direction_to_world(Vec2((c.on_inc - c.on_ref) / c.separation));
    return Contact::of(c.separation, ref_first ? towards_inc : Vec2(-towards_inc), p.point_a, p.point_b, p.id);
  }
  const Vec2 n_ref = k == 0 ? Vec2(sigma, 0) : Vec2(0, sigma);
  const Vec2 normal = (ref_first ? 1.0 : -1.0) * direction_to_world(n_ref);
  const FeatureKind kind = ref_first ? FeatureKind::face_of_a : FeatureKind::face_of_b;
  const int ref_face = k + (sigma < 0 ? 2 : 0);
  const auto on_face = [&](Feature x) {
    x.on_ref = x.on_inc - x.separation * n_ref;
    x.ref_index = ref_face;
    return point(x, kind);
  };
  // Overlapping, the separation is the deepest corner's; where that corner lies beyond the
  // reference face's ends, the points are those of the deepest point of the incident face within
  // them and of the reference face (so that both lie on their shapes), that separation apart.
  Feature deepest = best > 0 || (cut && std::abs(deep.on_inc[j]) > v.ref_half[j]) ? face[0] : deep;
  if (best <= 0) deepest.separation = deep.separation;
  const ContactPoint main = on_face(deepest);
  Contact out = Contact::of(main.separation, normal, main.point_a, main.point_b, main.id);
  if (!cut) return out;
  const double keep = std::max(main.separation, 0.0) + options.margin;
  int size = 0;
  for (const Feature& x : face) {
    if (x.separation <= keep) out.manifold[size++] = on_face(x);
  }
  out.manifold_size = std::max(size, 1);
  return out;
}

// The deepest face of v's reference rectangle: its axis and separation.
struct Face {
  int k = 0;
  double separation = -std::numeric_limits<double>::infinity();
};
Face deepest_face(const View& v) {
  Face out;
  for (int axis = 0; axis < 2; ++axis) {
    const double s = v.face_separation(axis);
    if (s > out.separation) out = {axis, s};
  }
  return out;
}

// The contact on the deeper of the two rectangles' deepest faces, with the manifold on the caller's
// first rectangle's face where the two tie (below); written in the caller's order.
Contact on_faces(const detail::RectPairFrame& f, const Rect& a, const View& from_a, const Face& on_a,
                 const View& from_b, const Face& on_b, const ContactOptions& options, bool swapped) {
  const bool b_deepest = on_b.separation > on_a.separation;
  Contact out = b_deepest ? contact_on(f, a, from_b, on_b.k, on_b.separation, options, swapped)
                          : contact_on(f, a, from_a, on_a.k, on_a.separation, options, swapped);
  const bool on_preferred = b_deepest == swapped;
  const double bias = 1e-9 * (a.half_extents.sum() + from_a.inc_half.sum());
  if (on_preferred || std::abs(on_b.separation - on_a.separation) > bias ||
      feature_kind(out.manifold[0].id) == FeatureKind::corner_corner) {
    return out;
  }
  const Contact kept = b_deepest ? contact_on(f, a, from_a, on_a.k, on_a.separation, options, swapped)
                                 : contact_on(f, a, from_b, on_b.k, on_b.separation, options, swapped);
  if (feature_kind(kept.manifold[0].id) == FeatureKind::corner_corner) return out;
  out.manifold = kept.manifold;
  out.manifold_size = kept.manifold_size;
  return out;
}

}  // namespace

// Separating axes give the signed distance wherever a face is involved: overlapping convex polygons
// always (the deepest way out is along a face normal of one of them), apart ones unless their
// nearest features are two corners. The separation and the normal are those of the face of
// greatest separation, the exact maximum (A's on a tie). The manifold's reference face is the
// preferred side's deepest face (A's for the kernel, the first argument's for the queries) unless
// the other side's is deeper by more than 1e-9 of the pair's size, as Box2D's b2CollidePolygons
// prefers A's by 0.1 linearSlop (absolute there; relative here, to hold at every scale): a box
// sliding on a box of equal face separation keeps its feature ids where rounding, or the kernel
// order of the two, would swap the faces. The incident face is the other rectangle's face most opposed
// to the reference face, clipped to its side planes.
Contact contact_rect_rect(const Rect& a, const Rect& b, const ContactOptions& options) {
  return contact_rect_rect(a, Orientation::of(a.angle), b, Orientation::of(b.angle), options);
}

Contact contact_rect_rect(const Rect& a, const Orientation& a_orientation, const Rect& b,
                          const Orientation& b_orientation, const ContactOptions& options) {
  return detail::contact_rect_rect(a, a_orientation, b, b_orientation, options, false);
}

Contact detail::contact_rect_rect(const Rect& a, const Orientation& a_orientation, const Rect& b,
                                  const Orientation& b_orientation, const ContactOptions& options, bool swapped) {
  // The fields as they are, not Rotation::of: through it GCC spills the rotations in halves and then
  // stalls reading them whole (bench_contact's rect_rect rows).
  const detail::RectPairFrame f(a, {a_orientation.c, a_orientation.s}, b, {b_orientation.c, b_orientation.s});
  const View from_a{a.half_extents, b.half_extents, f.b_rel, f.b_center, true};
  const View from_b{b.half_extents, a.half_extents, {f.b_rel.c, -f.b_rel.s}, -f.b_rel.apply_inverse(f.b_center), false};
  const Face on_a = deepest_face(from_a), on_b = deepest_face(from_b);
  // A face's separation is a lower bound of the pair's (its maximum over every direction).
  if (detail::has_limit(options)) {
    const double face_separation = std::max(on_a.separation, on_b.separation);
    const double scale = a.half_extents.sum() + b.half_extents.sum() + f.b_center.cwiseAbs().sum();
    if (detail::beyond_limit(face_separation, scale, options)) return Contact::beyond(face_separation);
  }
  return detail::limited(options, [&] { return on_faces(f, a, from_a, on_a, from_b, on_b, options, swapped); });
}

}  // namespace collide2d
