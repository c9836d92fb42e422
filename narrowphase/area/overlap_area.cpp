// The overlap of two convex solids by Green's theorem over its boundary. The boundary runs
// alternately along A and along B between the crossings, which two convex curves meet in the same
// counter-clockwise order; which of the two a run follows is read from the crossing where the
// curves cross most steeply and alternates from there. Each piece of a run adds its chord to a
// polygon fanned from the first crossing, and each arc the segment between it and its chord:
// for the unit disc, area (phi - sin phi) / 2 and first moment |d|^2 perp(d) / 12 about the centre
// (d the chord), carried onto the ellipse by its affine map. Two sharp polygons are clipped
// instead (narrowphase/area/clip.h), which keeps shared edges exact, and a sliver's digits in
// double-double.
#include <collide2d/area.h>

#include "narrowphase/area/boundary.h"
#include "narrowphase/area/clip.h"
#include "narrowphase/area/crossings.h"
#include "narrowphase/area/measures.h"
#include "narrowphase/area/overlap_rect_rect.h"
#include "narrowphase/dispatch.h"
#include "shapes/internal.h"
#include "shapes/kinds.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <type_traits>
#include <variant>

namespace collide2d {
namespace detail::areas {
namespace {

// x - sin x for x in [0, 2 pi], given sin x: by its series below 1.5, where the difference would
// cancel.
template <class Real>
Real x_minus_sin(const Real& x, const Real& sin_x) {
  if (x > 1.5) return x - sin_x;
  // (-1)^(k+1) / (2k+1)!, in double for k = 1 ... 11, in double-double for k = 1 ... 17 (the sine's
  // series past x, negated): the first term left out is below 2^-60 of the sum, or 2^-110.
  static constexpr auto terms = [] {
    if constexpr (std::is_same_v<Real, double>)
      return std::array<double, 11>{1.0 / 6,
                                    -1.0 / 120,
                                    1.0 / 5040,
                                    -1.0 / 362880,
                                    1.0 / 39916800,
                                    -1.0 / 6227020800,
                                    1.0 / 1307674368000,
                                    -1.0 / 355687428096000,
                                    1.0 / 121645100408832000,
                                    -1.0 / 51090942171709440000.0,
                                    1.0 / 25852016738884976640000.0};
    else {
      std::array<DoubleDouble, 17> t = extended_series<17>(3);
      for (DoubleDouble& c : t) c = -c;
      return t;
    }
  }();
  const Real x2 = x * x;
  Real sum = 0;
  for (auto k = terms.size(); k-- > 0;) sum = sum * x2 + terms[k];
  return x * x2 * sum;
}

double angle_of(double y, double x) { return arc_tangent(y, x); }
DoubleDouble angle_of(const DoubleDouble& y, const DoubleDouble& x) { return arc_tangent_extended(y, x); }

template <class Real>
Real length(const V2<Real>& v) {
  using std::sqrt;
  return sqrt(v.squaredNorm());
}

template <class Real>
constexpr Real kPiOf = std::numbers::pi;
template <>
constexpr DoubleDouble kPiOf<DoubleDouble> = kExtendedPi;

// The area and first moment of a region, summed over its boundary's pieces about `origin`.
template <class Real>
class Green {
 public:
  using V = V2<Real>;
  explicit Green(const V& origin) : origin_(origin) {}

  void chord(const V& p, const V& q) { fan_.add(p - origin_, q - origin_); }
  // The region between the arc from u0 counter-clockwise to u1 and its chord.
  void bulge(const ArcOf<Real>& arc, const V& u0, const V& u1) {
    const V d = u1 - u0;
    const Real sine = cross(u0, u1);
    Real half = angle_of(length(d), length(V(u0 + u1)));
    if (sine < 0) half = kPiOf<Real> - half;
    const Real segment = x_minus_sin(Real(2 * half), sine) / 2;
    bulge_area_ += arc.det * segment;
    bulge_moment_ += arc.det * (segment * (arc.c - origin_) + arc.m * ((d.squaredNorm() / 12) * V(d.y(), -d.x())));
  }
  // The piece from `from` to `to`.
  void along(const PieceOf<Real>& piece, const EndOf<Real>& from, const EndOf<Real>& to) {
    chord(from.p, to.p);
    if (piece.curved) bulge(piece.arc, from.u, to.u);
  }

  Real area() const { return fan_.twice_area / 2 + bulge_area_; }
  // The centroid, relative to the origin the pieces were given in.
  V centroid() const { return origin_ + (fan_.moment6 / 6 + bulge_moment_) / area(); }

 private:
  V origin_;
  Fan<Real> fan_;
  Real bulge_area_ = 0;
  V bulge_moment_ = V::Zero();
};

// The run along a loop from one crossing to the next.
template <class Real>
void run(const BoundaryOf<Real>& loop, const EndOf<Real>& from, const Place& a, const EndOf<Real>& to, const Place& b,
         Green<Real>& g) {
  const PieceOf<Real>& first = loop.pieces[a.piece];
  if (a.piece == b.piece && (a.key <= b.key || (first.curved && first.arc.full))) return g.along(first, from, to);
  g.along(first, from, first.end);
  for (int k = (a.piece + 1) % loop.count; k != b.piece; k = (k + 1) % loop.count)
    g.along(loop.pieces[k], loop.pieces[k].start, loop.pieces[k].end);
  g.along(loop.pieces[b.piece], loop.pieces[b.piece].start, to);
}

// The crossings in order along A, an even number of them, and which of them A enters B at.
struct Walk {
  Crossings x;
  bool first_enters = false;  // then every other one
};

Walk walk_of(const Boundary& a, const Boundary& b) {
  Walk w{crossings_of(a, b)};
  auto* list = w.x.list.data();
  std::sort(list, list + w.x.count, [](const Crossing& p, const Crossing& q) {
    return p.a.piece != q.a.piece ? p.a.piece < q.a.piece : p.a.key < q.a.key;
  });
  // Two crossings at one point are a tangency, which bounds no region: both go.
  int kept = 0;
  for (int i = 0; i < w.x.count; ++i) {
    if (i + 1 < w.x.count && list[i].p == list[i + 1].p)
      ++i;
    else
      list[kept++] = list[i];
  }
  w.x.count = kept;
  auto by_steepness = [](const Crossing& p, const Crossing& q) { return std::abs(p.entering) < std::abs(q.entering); };
  // An odd count is a crossing seen twice or once too few where the curves graze: the grazing one goes.
  if (w.x.count % 2 == 1) {
    Crossing* grazing = std::min_element(list, list + w.x.count, by_steepness);
    std::move(grazing + 1, list + w.x.count, grazing);
    --w.x.count;
  }
  if (w.x.count == 0) return w;
  const auto steepest = std::max_element(list, list + w.x.count, by_steepness) - list;
  w.first_enters = (list[steepest].entering > 0) == (steepest % 2 == 0);
  return w;
}

struct Region {
  double area = 0;
  Vec2 centroid = Vec2::Zero();  // relative to the pair's origin
};

// Green's theorem along A and B in turn between consecutive crossings, about the first one, from
// A's run after the first crossing if A enters B there, else from B's; meets(i) gives crossing i as
// an end on A and an end on B.
template <class Real, class Meets>
Green<Real> runs(const BoundaryOf<Real>& a, const BoundaryOf<Real>& b, const Walk& w, Meets meets) {
  const auto& list = w.x.list;
  Green<Real> g(meets(0).first.p);
  for (int i = 0; i < w.x.count; ++i) {
    const int next = (i + 1) % w.x.count;
    const auto [xa, xb] = meets(i);
    const auto [ya, yb] = meets(next);
    if ((i % 2 == 0) == w.first_enters)
      run(a, xa, list[i].a, ya, list[next].a, g);
    else
      run(b, xb, list[i].b, yb, list[next].b, g);
  }
  return g;
}

// The runs that leave where A enters B bound A ∩ B, and the others A ∪ B. Where the crossings all
// graze, the steepest one's sign that first_enters was read from is rounding: a region larger than
// the smaller shape is then the union, and the other runs are taken (first_enters turned with them).
template <class Real, class Meets>
Green<Real> along_crossings(const BoundaryOf<Real>& a, const BoundaryOf<Real>& b, Walk& w, Meets meets,
                            const Real& smaller) {
  const Green<Real> g = runs(a, b, w, meets);
  if (!(g.area() > smaller)) return g;
  w.first_enters = !w.first_enters;
  const Green<Real> other = runs(a, b, w, meets);
  if (other.area() < g.area()) return other;
  w.first_enters = !w.first_enters;
  return g;
}

Region along_crossings(const Boundary& a, const Boundary& b, Walk& w, double smaller) {
  const Green<double> g = along_crossings(
      a, b, w,
      [&w](int i) {
        const Crossing& x = w.x.list[i];
        return std::pair{End{x.p, x.a.u}, End{x.p, x.b.u}};
      },
      smaller);
  return {std::max(g.area(), 0.0), g.centroid()};
}

Vec2 centroid_of(const Shape& s) {
  if (const auto* p = std::get_if<ConvexPolygon>(&s)) return p->centroid();
  return center_of(s);
}

double rect_area(const Rect& r) { return 4 * r.half_extents.x() * r.half_extents.y(); }

// The area of a solid already validated.
double solid_area(const Shape& s) {
  constexpr double pi = std::numbers::pi;
  if (const auto* c = std::get_if<Circle>(&s)) return pi * c->radius * c->radius;
  if (const auto* e = std::get_if<Ellipse>(&s)) return pi * e->a * e->b;
  if (const auto* r = std::get_if<Rect>(&s)) return rect_area(*r);
  if (const auto* c = std::get_if<Capsule>(&s)) return 4 * c->half_length * c->radius + pi * c->radius * c->radius;
  return std::get<ConvexPolygon>(s).area();
}

bool sharp(const Shape& s) {
  const auto* p = std::get_if<ConvexPolygon>(&s);
  return std::holds_alternative<Rect>(s) || (p && p->outline->radius == 0);
}

// Below this fraction of the larger area a double clip's rounding, a few eps of that area, would
// cost the result more than 1e-13 of itself: the clip is taken again in double-double.
constexpr double kSliver = 0x1p-7;

// The overlap of two sharp polygons and their corners; the smaller one is clipped, so that its
// corners inside the other pass through exactly.
template <class Real>
Moments<Real> polygon_overlap(const Shape& a, const Corners<Real>& ca, const Shape& b, const Corners<Real>& cb) {
  return moments_of(solid_area(b) < solid_area(a) ? clipped(cb, ca) : clipped(ca, cb));
}
// The same, their corners taken relative to `origin`.
template <class Real>
Moments<Real> polygon_overlap(const Shape& a, const Shape& b, const Vec2& origin) {
  return polygon_overlap(a, corners_of<Real>(a, origin), b, corners_of<Real>(b, origin));
}

template <class Real>
Region region_of(const Moments<Real>& m) {
  if (!(m.area > 0)) return {};
  const V2<Real> centroid = m.moment / m.area;
  return {static_cast<double>(m.area), Vec2(static_cast<double>(centroid.x()), static_cast<double>(centroid.y()))};
}

// Whether an overlap of two sharp polygons found in double is a sliver, to be taken again.
bool sliver(double area, double area_a, double area_b) { return area > 0 && area < kSliver * std::max(area_a, area_b); }
bool sliver(double area, const Shape& a, const Shape& b) { return sliver(area, solid_area(a), solid_area(b)); }

Region polygons(const Shape& a, const Shape& b, const Vec2& origin) {
  const Moments<double> m = polygon_overlap<double>(a, b, origin);
  if (sliver(m.area, a, b)) return region_of(polygon_overlap<DoubleDouble>(a, b, origin));
  return region_of(m);
}

// The area of a sliver of two sharp polygons, clipped in double-double.
double polygons_area_exactly(const Shape& a, const Shape& b) {
  return region_of(polygon_overlap<DoubleDouble>(a, b, center_of(a))).area;
}

// The area alone: two rectangles without forming their overlap's corners
// (narrowphase/area/overlap_rect_rect.h).
double polygons_area(const Shape& a, const Shape& b) {
  const auto *ra = std::get_if<Rect>(&a), *rb = std::get_if<Rect>(&b);
  const double area = ra && rb ? rect_rect_area(*ra, *rb) : polygon_overlap<double>(a, b, center_of(a)).area;
  return sliver(area, a, b) ? polygons_area_exactly(a, b) : std::max(area, 0.0);
}

// Neither boundary crosses the other: one holds the other, or they share no open region.
OverlapArea nested(const Shape& a, const Shape& b) {
  const double area_a = solid_area(a), area_b = solid_area(b);
  if (!contains(b, centroid_of(a)) && !contains(a, centroid_of(b))) return {0.0, center_of(a)};
  return area_a <= area_b ? OverlapArea{area_a, centroid_of(a)} : OverlapArea{area_b, centroid_of(b)};
}

// The overlap of A and B from their boundaries about `origin` and the walk along them, which comes
// back turned where its first runs bound the union.
OverlapArea overlap_along(const Shape& a, const Shape& b, const Vec2& origin, const Boundary& pa, const Boundary& pb,
                          Walk& w) {
  Region r;
  if (pa.polygonal && pb.polygonal)
    r = polygons(a, b, origin);
  else if (w.x.count == 0)
    return nested(a, b);
  else
    r = along_crossings(pa, pb, w, std::min(solid_area(a), solid_area(b)));
  if (!(r.area > 0)) return {0.0, origin};  // touching: no crossing into an open region
  OverlapArea out{r.area, origin + r.centroid, w.x.count};
  if (w.x.count == 2) {
    const int in = w.first_enters ? 0 : 1;
    out.chord = {origin + w.x.list[in].p, origin + w.x.list[1 - in].p};
  }
  return out;
}

OverlapArea overlap_in_order(const Shape& a, const Shape& b) {
  const Vec2 origin = center_of(a);
  const Boundary pa = boundary_of(a, origin), pb = boundary_of(b, origin);
  Walk w = walk_of(pa, pb);
  return overlap_along(a, b, origin, pa, pb, w);
}

// The area of A ∩ B alone: two sharp polygons are clipped without the crossings, which only the
// chord needs.
double shared_area(const Shape& a, const Shape& b) {
  if (sharp(a) && sharp(b)) return polygons_area(a, b);
  return overlap_in_order(a, b).area;
}

double iou_in_order(const Shape& a, const Shape& b) {
  const double overlap = shared_area(a, b);
  return std::clamp(overlap / (solid_area(a) + solid_area(b) - overlap), 0.0, 1.0);
}

// The area a boundary encloses.
template <class Real>
Real enclosed(const BoundaryOf<Real>& b) {
  const PieceOf<Real>& first = b.pieces[0];
  if (first.curved && first.arc.full) return kPiOf<Real> * first.arc.det;
  Green<Real> g(first.start.p);
  for (int k = 0; k < b.count; ++k) g.along(b.pieces[k], b.pieces[k].start, b.pieces[k].end);
  return g.area();
}

// |A|, |B| and |A ∩ B| in double-double, for near-identical shapes, whose difference the double
// areas lose.
struct ExtendedAreas {
  DoubleDouble a;
  DoubleDouble b;
  DoubleDouble shared;
};

ExtendedAreas sharp_areas_exactly(const Shape& a, const Shape& b) {
  const Vec2 origin = center_of(a);
  const Corners<DoubleDouble> ca = corners_of<DoubleDouble>(a, origin), cb = corners_of<DoubleDouble>(b, origin);
  return {moments_of(ca).area, moments_of(cb).area, polygon_overlap(a, ca, b, cb).area};
}

// The crossings of a walk refined on double-double boundaries, in the walk's order.
struct ExtendedWalk {
  Walk w;
  std::array<ExtendedCrossing, kMaxCrossings> meets;
};

// Whether every unbroken run of crossings not found (round the loop of n) has an even number.
bool lost_in_pairs(const std::array<bool, kMaxCrossings>& found, int n) {
  const int start = static_cast<int>(std::find(found.begin(), found.begin() + n, true) - found.begin());
  int run_length = 0;
  for (int k = 1; k <= n && start < n; ++k) {
    const int i = (start + k) % n;
    if (found[i] && run_length % 2 == 1) return false;
    run_length = found[i] ? 0 : run_length + 1;
  }
  return true;
}

// The walk's crossings refined. One that does not refine is an end of a lens thinner than double
// resolves, which the curves may not make: each unbroken run of such crossings goes, if it has an
// even number (both ends of its lenses); none is the answer where a run has an odd number.
std::optional<ExtendedWalk> refined_walk(const BoundaryOf<DoubleDouble>& a, const BoundaryOf<DoubleDouble>& b,
                                         const Walk& w) {
  const int n = w.x.count;
  std::array<ExtendedCrossing, kMaxCrossings> meets;
  std::array<bool, kMaxCrossings> found;
  for (int i = 0; i < n; ++i) found[i] = refined(a, b, w.x.list[i], meets[i]);
  if (!lost_in_pairs(found, n)) return std::nullopt;
  ExtendedWalk out;
  out.w.x.count = 0;
  for (int i = 0; i < n; ++i) {
    if (!found[i]) continue;
    if (out.w.x.count == 0) out.w.first_enters = (i % 2 == 0) == w.first_enters;
    out.meets[out.w.x.count] = meets[i];
    out.w.x.list[out.w.x.count++] = w.x.list[i];
  }
  return out;
}

// Along the crossings of the walk found in double about `origin`, refined; none where they do not
// refine.
std::optional<ExtendedAreas> curved_areas_exactly(const Shape& a, const Shape& b, const Vec2& origin, const Walk& w) {
  const auto pa = boundary_of<DoubleDouble>(a, origin), pb = boundary_of<DoubleDouble>(b, origin);
  std::optional<ExtendedWalk> e = refined_walk(pa, pb, w);
  if (!e) return std::nullopt;
  ExtendedAreas out{enclosed(pa), enclosed(pb), 0};
  if (e->w.x.count == 0) {
    if (nested(a, b).area > 0) out.shared = std::min(out.a, out.b);
    return out;
  }
  const auto meets = [&e](int i) { return std::pair{e->meets[i].a, e->meets[i].b}; };
  out.shared = along_crossings(pa, pb, e->w, meets, std::min(out.a, out.b)).area();
  return out;
}

// Below this distance the double one, whose numerator |A| + |B| - 2 |A ∩ B| is a few eps of the
// areas off, would be more than a few units off in its own last place.
constexpr double kFarApart = 0.5;

// |A delta B| / |A u B| from |A|, |B| and |A ∩ B|, in [0, 1].
template <class Real>
double distance_of(const Real& area_a, const Real& area_b, const Real& shared) {
  const Real both = area_a + area_b;
  return std::clamp(static_cast<double>((both - 2 * shared) / (both - shared)), 0.0, 1.0);
}

// |A delta B| / |A u B|. Where it is below kFarApart the areas and the overlap are taken again in
// double-double, so that the difference keeps its digits however near-identical the shapes are; a
// curved pair's crossings are the ones the double overlap walked.
double distance_in_order(const Shape& a, const Shape& b) {
  const double area_a = solid_area(a), area_b = solid_area(b);
  if (sharp(a) && sharp(b)) {
    const double d = distance_of(area_a, area_b, polygons_area(a, b));
    if (!(d < kFarApart)) return d;
    const ExtendedAreas e = sharp_areas_exactly(a, b);
    return distance_of(e.a, e.b, e.shared);
  }
  const Vec2 origin = center_of(a);
  const Boundary pa = boundary_of(a, origin), pb = boundary_of(b, origin);
  Walk w = walk_of(pa, pb);
  const double d = distance_of(area_a, area_b, overlap_along(a, b, origin, pa, pb, w).area);
  if (!(d < kFarApart)) return d;
  const std::optional<ExtendedAreas> e = curved_areas_exactly(a, b, origin, w);
  return e ? distance_of(e->a, e->b, e->shared) : d;
}

void require_solid(const Shape& s) {
  validate(s);
  if (std::holds_alternative<Segment>(s)) throw InvalidShape("a segment has no area: give a solid shape");
}

}  // namespace

OverlapArea overlap_of(const Shape& a, const Shape& b) {
  return in_rank_order<Kinds>(a, b, [&a](const auto& x, const auto& y, bool swapped) {
    OverlapArea out = overlap_in_order(x, y);
    if (!swapped) return out;
    std::swap(out.chord[0], out.chord[1]);
    if (out.area == 0) out.centroid = center_of(a);
    return out;
  });
}

double rect_iou(const Rect& a, const Rect& b, double area) {
  const double area_a = rect_area(a), area_b = rect_area(b);
  const double overlap = sliver(area, area_a, area_b) ? polygons_area_exactly(a, b) : std::max(area, 0.0);
  return std::clamp(overlap / (area_a + area_b - overlap), 0.0, 1.0);
}

double iou_of(const Shape& a, const Shape& b) {
  return in_rank_order<Kinds>(a, b, [](const auto& x, const auto& y, bool) {
    if constexpr (std::is_same_v<decltype(x), const Rect&> && std::is_same_v<decltype(y), const Rect&>)
      return rect_iou(x, y, rect_rect_area(x, y));
    else
      return iou_in_order(x, y);
  });
}

}  // namespace detail::areas

double area(const Shape& s) {
  detail::areas::require_solid(s);
  return detail::areas::solid_area(s);
}

OverlapArea overlap_area(const Shape& a, const Shape& b) {
  detail::areas::require_solid(a);
  detail::areas::require_solid(b);
  return detail::areas::overlap_of(a, b);
}

double iou(const Shape& a, const Shape& b) {
  detail::areas::require_solid(a);
  detail::areas::require_solid(b);
  return detail::areas::iou_of(a, b);
}

double iou_distance(const Shape& a, const Shape& b) {
  detail::areas::require_solid(a);
  detail::areas::require_solid(b);
  return detail::in_rank_order<detail::Kinds>(
      a, b, [](const auto& x, const auto& y, bool) { return detail::areas::distance_in_order(x, y); });
}

double iof(const Shape& a, const Shape& b) {
  detail::areas::require_solid(a);
  detail::areas::require_solid(b);
  const double overlap = detail::in_rank_order<detail::Kinds>(
      a, b, [](const auto& x, const auto& y, bool) { return detail::areas::shared_area(x, y); });
  return std::clamp(overlap / detail::areas::solid_area(a), 0.0, 1.0);
}

}  // namespace collide2d
