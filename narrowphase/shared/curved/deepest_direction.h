// Private: the global maximum of the separation s(n) of a SupportPair over every unit direction n,
// the signed distance of the two solids (support_pair.h), with the direction that attains it.
//
// First a climb from the line of centres, kept only when disc_bound, an upper bound of s over every
// direction, shows that no direction does better (certified_climb, below); else the search.
//
// Why a search over the whole circle, and why it cannot stop at a local maximum. For disjoint
// shapes s is concave on the arc where it is positive (s'' = -(s + rho_A + rho_B)), so the distance
// solver may climb from any separating direction. For overlapping shapes no direction separates,
// s < 0 everywhere, and s + rho_A + rho_B changes sign where the shapes are thin: two needles
// crossing deep have one local maximum per way out (push along either needle's normal), and
// Newton from the wrong side ends at the smaller one. So the circle is cut into arcs, and an arc is
// dropped only when an upper bound of s over it is no more than the best value found plus its
// rounding (branch and bound). The bound: on an arc where a shape's radius of curvature is
// at least r, its support function is at least that of the disc of radius r tangent at the support
// point p_x found at the arc's end x, h(n) >= n.(p_x - r x) + r (the difference w satisfies
// w'' + w = rho - r >= 0 with w = w' = 0 at x, so w(t) is the integral of sin(t - t') (rho - r)
// >= 0 over less than a half turn); a rectangle's r is 0 and the disc its corner. Summed over both
// shapes, with r the least radii on the arc (an ellipse's radius is least at an end of the arc
// unless the arc holds its major axis' direction, where it is b^2 / a: rho_floor),
//   s(n) <= n.(gap_x + r x) - r       (gap_x = delta - p_A - p_B at x), and the same from y,
// and the maximum over the arc of the smaller of these two sinusoids lies at an end, at a peak of
// either, or where they cross. It is exact for polygons and for circles (a concentric pair's s is
// constant and its arcs drop at once), and for other curves its excess shrinks with the cube of
// the arc's width. At a polished maximum m, s'(m) = 0 and gap_m = s(m) m, so the sinusoid from m
// is (s(m) + r) cos(t - t_m) - r: it peaks at m with the value s(m) wherever the depth -s(m) is
// below the radii r, and every arc ending at m drops at once: the maximum certifies itself. Deeper
// (thin shapes), arcs near m are halved until the excess falls below the rounding. An arc whose
// ends' slopes show a maximum inside (rising, then falling) is split at the root of s' found by
// safeguarded Halley steps in tau = tan(angle / 2) (halley, ellipse_pair.h), any other arc at its
// bisector; the arc with the highest bound goes first. The arcs start as the four quarter turns
// between the frame's axes.
//
// The search serves two ellipses. A rectangle and an ellipse need none of it: each quarter turn
// between the rectangle's face normals is settled in closed form (contact_rect_ellipse.cpp). The
// climb also serves pairs with a rectangle, for the time of impact's steps.
#pragma once

#include "narrowphase/shared/ellipse/distance_point_ellipse.h"
#include "narrowphase/shared/ellipse/ellipse_pair.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace collide2d::detail {

template <class Real>
struct Arc {
  int x;  // from the direction ends[x] counter-clockwise to ends[y], less than a half turn
  int y;
  Real bound;  // no s on the arc exceeds it
};

// The candidates are tested for lying inside the arc before they are normalised (the test is
// scale-free): most are outside, and each square root and division costs as much as the rest. Each
// sinusoid is evaluated as n.gap - r |n - x|^2 / 2 (= n.(gap + r x) - r for unit n and x): on a
// needle's flat side r is its length times its aspect, and n.(gap + r x) - r lost the bound to the
// rounding of r (an ellipse of aspect 4,446 and 2.9e47 long ran the search to its cap that way).
template <class Real, class P>
Real arc_bound(const P& p, const Direction<Real>& x, const Direction<Real>& y) {
  using std::sqrt;
  const Real r = p.A.rho_floor(x.n, y.n, x.at.rho_a, y.at.rho_a) + p.B.rho_floor(x.n, y.n, x.at.rho_b, y.at.rho_b);
  const V2<Real> gx = x.at.gap + r * x.n;
  const V2<Real> gy = y.at.gap + r * y.n;
  Real best = std::max(x.at.s, y.at.s);
  const auto candidate = [&](const V2<Real>& v) {
    if (cross(x.n, v) >= 0 && cross(v, y.n) >= 0) {
      const Real length = sqrt(v.squaredNorm());
      if (!(length > 0)) return;
      const V2<Real> n = v / length;
      best = std::max(best, std::min(n.dot(x.at.gap) - r * (n - x.n).squaredNorm() / 2,
                                     n.dot(y.at.gap) - r * (n - y.n).squaredNorm() / 2));
    }
  };
  candidate(gx);
  candidate(gy);
  const V2<Real> across = perp<Real>(gx - gy);
  candidate(across);
  candidate(-across);
  return best;
}

// A bound of s over the arc from x to y far cheaper than arc_bound (its discs shrunk to points):
// each shape lies behind its tangent at the support point found at x, so s(n) <= n.gap_x, a
// sinusoid whose largest value on the arc is |gap_x| if gap_x points into it, else at an end (s(x)
// or y.gap_x). The same from y. Where it already lies within `floor` (the best value found plus
// the margin) it is returned instead of arc_bound's, whose square roots and divisions it spares
// most quarter turns; the contact is the same bit for bit.
template <class Real, class P>
Real cheap_arc_bound(const P& p, const Direction<Real>& x, const Direction<Real>& y, Real floor) {
  const auto along = [&](const V2<Real>& gap) {
    using std::sqrt;
    if (cross(x.n, gap) >= 0 && cross(gap, y.n) >= 0) return sqrt(gap.squaredNorm());
    return std::max(x.n.dot(gap), y.n.dot(gap));
  };
  const Real tangents = std::min(along(x.at.gap), along(y.at.gap));
  return tangents <= floor ? tangents : arc_bound(p, x, y);
}

// Which support point a contact within a tolerance keeps as found (its partner is that point moved
// by s along the normal), or none: the exact maximum, whose points curved_contact chooses.
enum class Kept : unsigned char { none, a, b };

// The global maximum: its direction, the separation there (with its support points), and the
// support evaluations it took (the search stops at `cap` of them, uncertified; the tests and the
// fuzzers require fewer); with a tolerance, the point kept.
template <class Real>
struct Deepest : Direction<Real> {
  int evaluations = 0;
  Kept kept = Kept::none;
};

// Whether s' at e is 0 to rounding: within `flat` (the rounding of the gap, a few u of the scale)
// plus s'' times the rounding of the direction itself (4 u rad), below which no double direction
// moves it. On a needle's flat side (s'' = 19) the slope stalled at 1.8e-14, above `flat` alone,
// and safeguarded Newton bisected its bracket to the last bit: 53 evaluations for one root.
template <class Real>
bool level(const Separation<Real>& e, Real flat) {
  using std::abs;
  return abs(e.slope) <= flat + 4 * std::numeric_limits<Real>::epsilon() * abs(e.bend);
}

// What a contact to a tolerance (ContactOptions::tolerance) accepts: `length` on the separation
// and on each point, `angle` on the normal; `rho_min` is the two shapes' least radii of curvature
// summed. A length of 0 asks for the exact maximum.
template <class Real>
struct Tolerance {
  Real length = 0;
  Real angle = 0;
  Real rho_min = 0;
};

// Whether the direction n the climb reached, with e = s(n), is within the tolerance of the global
// maximum, and then which support point to keep. Where s >= s0 = s(n), s'' = -(s + rho_A + rho_B)
// <= -(s0 + rho_min). For s0 + rho_min > 0 those directions form one arc, on which s is concave: by
// Blaschke's rolling theorem the pair's Minkowski difference K (s = -h_K) is a convex body K' grown
// by a disc of radius -s0, and s >= s0 is h_K' <= 0, a convex cone. Within the tolerance's angle
// of n the radii are at least rho_least_within's, so s'' <= -kappa there, and the slope falls to 0
// within turn = |s'| / kappa rad uphill: where that is inside the angle, the maximum is there,
// above s0 by at most |s'| turn / 2, and no bound over every direction is needed. Each support
// point moves by at most its radius of curvature times the turn; the steadier one is kept, and its
// partner, moved by s along n, errs by that, the separation's error and |s| turn more. None where
// that is not within the tolerance, or where the sign of the maximum is uncertain (the verdict
// must stay the exact one). `margin` covers the rounding of s and of s'.
template <class Real, class SA, class SB>
Kept within_tolerance(const SupportPair<Real, SA, SB>& p, const V2<Real>& n, const Separation<Real>& e,
                      const Tolerance<Real>& tolerance, Real margin) {
  using std::abs;
  const Real slope = abs(e.slope) + margin;
  // Most steps far from the tolerance fail here, before the radii's divisions: s'' at n itself,
  // -bend, is a fair guess of kappa.
  if (!(slope <= 2 * tolerance.angle * e.bend) || !(e.s + tolerance.rho_min > 0)) return Kept::none;
  const Real kappa =
      e.s + p.A.rho_least_within(e.offset_a, n, tolerance.angle) + p.B.rho_least_within(e.offset_b, n, tolerance.angle);
  if (!(slope <= tolerance.angle * kappa)) return Kept::none;
  const Real turn = slope / kappa;
  const Real error = slope * turn / 2 + margin;
  if (!(e.s > margin || e.s + error < 0)) return Kept::none;
  const Real move_a = p.A.rho_within(e.offset_a, n, turn) * turn;
  const Real move_b = p.B.rho_within(e.offset_b, n, turn) * turn;
  const Real partner = std::min(move_a, move_b) + error + (abs(e.s) + error) * turn;
  if (!(error <= tolerance.length && partner <= tolerance.length)) return Kept::none;
  return move_a <= move_b ? Kept::a : Kept::b;
}

// The direction inside the arc from x to y where s has its maximum (a root of s' by safeguarded
// Halley steps when the slopes at the ends show one beyond their rounding, `flat`), or the
// bisector, with s there; x itself when no double lies between the ends. A slope level to rounding
// (level, above) counts as 0: the iteration stops there instead of bisecting its bracket down to
// the last bit.
template <class Real, class P>
Direction<Real> split(const P& p, const Direction<Real>& x, const Direction<Real>& y, Real flat, int& evaluations) {
  using std::abs;
  const auto inside = [&](const V2<Real>& n) { return cross(x.n, n) > 0 && cross(n, y.n) > 0; };
  if (x.at.slope > flat && y.at.slope < -flat) {
    const Real end = cross(x.n, y.n) / (1 + x.n.dot(y.n));  // tan of half the arc's width
    Direction<Real> last;
    Real last_tau = -1;
    const auto f = [&](Real tau) {
      last = {turned(x.n, Real(1), tau), p.separation(turned(x.n, Real(1), tau))};
      last_tau = tau;
      const Real dslope = -last.at.bend * 2 / (1 + tau * tau) * halley(last.at, tau);
      return std::pair<Real, Real>(level(last.at, flat) ? Real(0) : last.at.slope, dslope);
    };
    const std::pair<Real, Real> start(x.at.slope, -x.at.bend * 2);
    const Real tau =
        newton_in_bracket(f, Real(0), end, start, evaluations, [](Real lo, Real hi) { return (lo + hi) / 2; });
    if (tau != last_tau) {  // the iteration ended on a point it had left
      ++evaluations;
      f(tau);
    }
    if (inside(last.n)) return last;
  }
  const V2<Real> mid = (x.n + y.n).normalized();
  if (!inside(mid)) return {x.n, Separation<Real>{}};
  ++evaluations;
  return {mid, p.separation(mid)};
}

// An upper bound of s over every direction, from a direction m and the separation there. An
// ellipse contains the largest disc tangent at its support point for m (EllipseSupport::
// inscribed_radius: b^2 / h(m), from b^2 / a at the ends of the major axis to b on the flat sides);
// with each ellipse replaced by that disc, s can only grow in every direction, and its maximum is
// then the signed distance of two discs, or of a disc and the rectangle (whose support function is
// exact and cheap, so it stays whole). The bound equals s(m) when m is a maximum and the depth is
// below those radii (for a rectangle: while the disc's centre is nearest to the same face). The
// disc of the least radius of curvature, b^2 / a, which Blaschke's rolling theorem puts at every
// boundary point, served before: on the flat side of an ellipse of aspect 10 it is ten times
// smaller, and the bound certified the climb in fewer pairs.
template <class Real, class SA, class SB>
Real disc_bound(const SupportPair<Real, SA, SB>& p, const V2<Real>& m, const Separation<Real>& e) {
  if constexpr (std::is_same_v<SA, RectSupport<Real>>) {
    const Real r = p.B.inscribed_radius(e.offset_b, m);
    return p.A.signed_distance(V2<Real>(p.delta - e.offset_b + r * m)) - r;
  } else if constexpr (std::is_same_v<SB, RectSupport<Real>>) {
    const Real r = p.A.inscribed_radius(e.offset_a, m);
    return p.B.signed_distance(V2<Real>(e.offset_a - r * m - p.delta)) - r;
  } else {
    const Real r = p.A.inscribed_radius(e.offset_a, m) + p.B.inscribed_radius(e.offset_b, m);
    return V2<Real>(e.gap + r * m).norm() - r;
  }
}

// Of the line of centres n and the two ellipses' axes (each turned towards B), the direction where
// s is largest, from support values alone (no points, no divisions): a climb from it is certified
// far more often than one from the line of centres, as thin ellipses side by side are separated
// across their axes, seldom along the line of centres. Along its own axes an ellipse's
// support value is its semi-axis: one square root per axis.
template <class Real>
V2<Real> best_of_axes(const SupportPair<Real, EllipseSupport<Real>, EllipseSupport<Real>>& p, V2<Real> n) {
  Real best = p.delta.dot(n) - p.A.extent(n) - p.B.extent(n);
  const auto consider = [&](const V2<Real>& axis, Real own, const EllipseSupport<Real>& other) {
    const V2<Real> f = p.delta.dot(axis) >= 0 ? axis : V2<Real>(-axis);
    const Real at = p.delta.dot(f) - own - other.extent(f);
    if (at > best) best = at, n = f;
  };
  consider(V2<Real>(p.A.rot.c, p.A.rot.s), p.A.a, p.B);
  consider(V2<Real>(-p.A.rot.s, p.A.rot.c), p.A.b, p.B);
  consider(V2<Real>(p.B.rot.c, p.B.rot.s), p.B.a, p.A);
  consider(V2<Real>(-p.B.rot.s, p.B.rot.c), p.B.b, p.A);
  return n;
}

// The rectangle's axis (x or y) whose face normal, turned towards B, has the largest s,
// |delta.f| - h_A(f) - h_B(f), from two support values of each shape (no points): a climb from it is
// certified more often than one from the face normal nearest the line of centres.
// `extent` receives the other shape's support value along it.
template <class Real, class SA, class SB>
V2<Real> best_face(const SupportPair<Real, SA, SB>& p, Real* extent = nullptr) {
  using std::abs;
  constexpr bool rect_a = std::is_same_v<SA, RectSupport<Real>>;
  const Rotation<Real>& rot = rect_a ? p.A.rot : p.B.rot;
  const V2<Real> x(rot.c, rot.s), y = perp(x);
  const Real other_x = rect_a ? p.B.extent(x) : p.A.extent(x), other_y = rect_a ? p.B.extent(y) : p.A.extent(y);
  const Real own_x = rect_a ? p.A.extent(x) : p.B.extent(x), own_y = rect_a ? p.A.extent(y) : p.B.extent(y);
  const bool along_x = abs(p.delta.dot(x)) - own_x - other_x >= abs(p.delta.dot(y)) - own_y - other_y;
  if (extent != nullptr) *extent = along_x ? other_x : other_y;
  return along_x ? x : y;
}

// The quick way, tried before the search: from `start` (a direction near the expected normal, such
// as the last step's; zero: best_of_axes), or with a rectangle from its face normal nearest that
// direction (zero: the one where s is largest), where s has a kink and the maximum of a face
// contact sits, Halley steps climb s' while s is concave, and the maximum reached is kept when
// disc_bound certifies it. Pairs apart, and overlaps shallower than the radii, end here after two
// or three evaluations; no maximum hands the rest (a step leaving its quarter turn, a convex
// stretch, a bound too loose) to the search. A caller that needs only a lower bound of s near its
// maximum (a time of impact's step far from contact) passes `rough` > 0: the climb then stops,
// uncertified, once the pair is apart and Newton's next gain, s'^2 / (2 |s''|), is below rough * s.
// A caller that needs s only up to a limit passes `stop`: the climb ends, uncertified, where s
// passes it. A caller with a tolerance passes it: the climb ends at the first direction
// within_tolerance certifies.
template <class Real>
struct Climb {
  std::optional<Deepest<Real>> deepest;  // the maximum, certified (or near enough, or past `stop`)
  // A maximum off the face normals, polished but not certified by the bound (an overlap deeper
  // than the discs), for the search to start from.
  std::optional<Direction<Real>> reached;
  int evaluations = 0;  // of the supports, either way
};

// The climb's state: the direction n and s there; with a rectangle, the face normal it started
// from and the side of it, which keep it in one quarter turn. Its steps are inlined into
// certified_climb, so that the state lives in registers rather than in the object.
template <class Real, class SA, class SB>
class Climber {
 public:
  static constexpr bool sided = std::is_same_v<SA, RectSupport<Real>> || std::is_same_v<SB, RectSupport<Real>>;

  Climber(const SupportPair<Real, SA, SB>& p, Real margin, Real rough, Real stop, const Tolerance<Real>& tolerance)
      : p_(p), margin_(margin), flat_(margin / 2), rough_(rough), stop_(stop), tolerance_(tolerance) {}

  // The first direction and s there; false where there is none (the centres coincide, no guess).
  [[gnu::always_inline]] bool begin(const V2<Real>& start) {
    using std::abs;
    const V2<Real>& toward = start == V2<Real>::Zero() ? p_.delta : start;
    if (toward == V2<Real>::Zero()) return false;
    // Scaled to its largest coordinate before it is squared: centres 1e-158 apart square to a
    // denormal, and the direction divided by that norm comes out 1e-9 off unit length.
    // Not Eigen's stableNormalized, which divides the unscaled vector: 1e-321 apart, 2e-3 off.
    // Without a guess a rectangle's face normal starts the climb, and takes only its sign from the
    // line of centres, which is then left as it is.
    const bool unit = !sided || start != V2<Real>::Zero();
    n_ = unit ? V2<Real>(V2<Real>(toward / toward.cwiseAbs().maxCoeff()).normalized()) : toward;
    face_ = side_ = n_;
    if constexpr (sided) {
      const Rotation<Real>& rot = std::is_same_v<SA, RectSupport<Real>> ? p_.A.rot : p_.B.rot;
      const V2<Real> x(rot.c, rot.s), y = perp(x);
      const V2<Real> axis = start == V2<Real>::Zero() ? best_face(p_) : (abs(n_.dot(x)) >= abs(n_.dot(y)) ? x : y);
      face_ = n_.dot(axis) >= 0 ? axis : V2<Real>(-axis);
      if (start != V2<Real>::Zero() && abs(cross(face_, n_)) > Real(1e-2)) {
        // A guess clear of the face normals (a contact at a corner): the climb starts there.
        side_ = n_;
        e_ = p_.separation(n_, side_);
        ++evaluations_;
      } else {
        from_face(face_);
      }
    } else {
      if constexpr (std::is_same_v<SA, EllipseSupport<Real>> && std::is_same_v<SB, EllipseSupport<Real>>) {
        if (start == V2<Real>::Zero()) n_ = best_of_axes(p_, n_);
      }
      e_ = p_.separation(n_);
      ++evaluations_;
    }
    return true;
  }

  // Converged when s' is flat to rounding and the angle to the maximum, about s' / s'', is below
  // 1e-12 rad: on a deep, nearly flat maximum a flat slope alone left the normal 1e-8 rad off. With
  // a tolerance, as soon as within_tolerance certifies the direction.
  [[gnu::always_inline]] bool done() {
    using std::abs;
    if constexpr (!sided) {
      if (tolerance_.length > 0) {
        kept_ = within_tolerance(p_, n_, e_, tolerance_, margin_);
        if (kept_ != Kept::none) return true;
      }
    }
    return near_enough() || kink_ || e_.s > stop_ || (level(e_, flat_) && !(abs(e_.slope) > Real(1e-12) * e_.bend));
  }

  // The k-th Halley step on s' in tan(angle / 2), slope / (2 bend d) with d = halley(e, 0) =
  // 1 + sq / b2, in one division: slope bend / (b2 + sq); Newton's where d leaves [1/2, 2]. Where
  // s > 0 the shapes are apart and s is concave on the whole arc where it is positive, with the
  // maximum inside: a step that is too long (over half a right angle, or landing lower) is cut
  // instead of handing over to the search. A time of impact climbs from the last step's normal,
  // which the shapes' approach has turned away from, and one in six of its climbs ended there. For
  // the same reason a step out of the quarter turn, apart, goes on from the face normal it crossed
  // (the maximum lies on it or beyond): a fifth of a rectangle–ellipse time of impact's climbs
  // ended there. False where the climb gives up.
  [[gnu::always_inline]] bool step(int k) {
    using std::abs;
    const bool apart = e_.s > 0;
    // At least, not equal: touching, s flips sign from one direction to the next.
    if (k >= (apart ? 12 : 6) || !(e_.bend > 0)) return false;
    const Real b2 = 2 * e_.bend * e_.bend, sq = e_.slope * (e_.slope + e_.rho_slope);
    Real tau = sq >= -b2 / 2 && sq <= b2 ? e_.slope * e_.bend / (b2 + sq) : e_.slope / (2 * e_.bend);
    if (!(abs(tau) < Real(0.5))) {
      if (!apart) return false;
      tau = std::copysign(Real(0.5), tau);
    }
    for (;;) {
      const V2<Real> next = turned(n_, Real(1), tau);
      if (!in_quarter(next)) {
        if (!apart) return false;
        const V2<Real> across = cross(face_, side_) > 0 ? perp(face_) : V2<Real>(-perp(face_));
        from_face(cross(face_, next) * cross(face_, side_) > 0 ? across : face_);
        return true;
      }
      const Separation<Real> en = p_.separation(next, sided ? side_ : next);
      ++evaluations_;
      if (en.s >= e_.s - margin_) {
        n_ = next, e_ = en;
        return true;
      }
      if (!apart || evaluations_ > 16) return false;
      tau /= 2;
    }
  }

  // The maximum reached, where the bound certifies it (or the caller asked for less).
  [[gnu::always_inline]] Climb<Real> finish() const {
    if (kept_ != Kept::none) return {Deepest<Real>{{n_, e_}, evaluations_, kept_}, std::nullopt, evaluations_};
    if (!near_enough() && !(e_.s > stop_) && !(disc_bound(p_, n_, e_) <= e_.s + margin_)) {
      if (kink_) return gave_up();
      return {std::nullopt, Direction<Real>{n_, e_}, evaluations_};
    }
    return {Deepest<Real>{{n_, e_}, evaluations_}, std::nullopt, evaluations_};
  }
  Climb<Real> gave_up() const { return {std::nullopt, std::nullopt, evaluations_}; }

 private:
  // At a rectangle's face normal f, s seen from both sides: a kink where it rises into f and falls
  // after it (a face contact's maximum), else the climb goes on into the quarter on the rising side.
  [[gnu::always_inline]] void from_face(const V2<Real>& f) {
    const V2<Real> before = f - perp(f), after = f + perp(f);
    const std::array<Separation<Real>, 2> at = p_.separations(f, before, after);
    ++evaluations_;
    kink_ = at[0].slope >= -flat_ && at[1].slope <= flat_;
    const bool rising = at[1].slope > flat_;
    face_ = f, n_ = f, e_ = at[rising ? 1 : 0], side_ = rising ? after : before;
  }
  bool in_quarter(const V2<Real>& v) const {
    return !sided || (cross(face_, v) * cross(face_, side_) > 0 && v.dot(face_) > 0);
  }
  bool near_enough() const {
    return rough_ > 0 && e_.s > 0 && (kink_ || e_.slope * e_.slope <= 2 * e_.bend * rough_ * e_.s);
  }

  const SupportPair<Real, SA, SB>& p_;
  Real margin_, flat_, rough_, stop_;
  Tolerance<Real> tolerance_;
  V2<Real> n_, face_, side_;
  Separation<Real> e_;
  bool kink_ = false;
  Kept kept_ = Kept::none;
  int evaluations_ = 0;
};

template <class Real, class SA, class SB>
Climb<Real> certified_climb(const SupportPair<Real, SA, SB>& p, const V2<Real>& start, Real margin, Real rough = 0,
                            Real stop = std::numeric_limits<Real>::infinity(), const Tolerance<Real>& tolerance = {}) {
  Climber<Real, SA, SB> climber(p, margin, rough, stop, tolerance);
  if (!climber.begin(start)) return {};
  for (int k = 0; !climber.done(); ++k) {
    if (!climber.step(k)) return climber.gave_up();
  }
  return climber.finish();
}

// The rounding within which the climb and the search take two values of s as equal, 8 u of the
// pair's scale: arcs are dropped within it of the best value, as the bound's own rounding is a few
// u of the scale (the pair's margin(), 64 u, left the 1e-12 target met but let a needle pair's
// distance fall 138 u short).
template <class Real, class SA, class SB>
Real climb_margin(const SupportPair<Real, SA, SB>& p) {
  return 8 * std::numeric_limits<Real>::epsilon() * p.scale;
}

// The global maximum of s: certified_climb from `start`, else the search; or, once s passes
// `stop` at some direction, that direction. The directions and arcs live in buffers kept per
// thread, so that a query allocates nothing once warm.
template <class Real, class SA, class SB>
Deepest<Real> deepest_direction(const SupportPair<Real, SA, SB>& p, const V2<Real>& start,
                                Real stop = std::numeric_limits<Real>::infinity(),
                                const Tolerance<Real>& tolerance = {}) {
  constexpr int cap = 4096;
  static_assert(!std::is_same_v<SA, RectSupport<Real>> && !std::is_same_v<SB, RectSupport<Real>>,
                "a rectangle's quarter turns are settled in closed form (contact_rect_ellipse.cpp)");
  const Real margin = climb_margin(p);
  const Climb<Real> climb = certified_climb(p, start, margin, Real(0), stop, tolerance);
  if (climb.deepest) return *climb.deepest;
  const std::optional<Direction<Real>>& reached = climb.reached;
  Deepest<Real> best;
  best.evaluations = climb.evaluations;
  // The best value is not seeded from a climb that stopped short (a point short of its maximum by
  // less than the rounding of s would be kept over the polished one); a polished maximum it
  // reached joins the arc ends below.
  best.at.s = -std::numeric_limits<Real>::infinity();
  thread_local std::vector<Direction<Real>> ends;
  thread_local std::vector<Arc<Real>> arcs;
  ends.clear();
  arcs.clear();
  const auto add = [&](const V2<Real>& n, const Separation<Real>& e) {
    ends.push_back({n, e});
    if (e.s > best.at.s) best.n = n, best.at = e;
    return static_cast<int>(ends.size()) - 1;
  };
  const auto end = [&](int i) -> const Direction<Real>& { return ends[static_cast<std::size_t>(i)]; };
  // The frame's axes; the last two are the first two negated, where s follows from the same support
  // points: two supports are evaluated.
  const V2<Real> x(1, 0), y(0, 1);
  const Separation<Real> ex = p.separation(x), ey = p.separation(y);
  best.evaluations += 2;
  const int starts[5] = {add(x, ex), add(y, ey), add(-x, p.opposite(x, ex)), add(-y, p.opposite(y, ey)), 0};
  for (int k = 0; k < 4; ++k)
    arcs.push_back(
        {starts[k], starts[k + 1], cheap_arc_bound(p, end(starts[k]), end(starts[k + 1]), best.at.s + margin)});
  // The climb's maximum, polished (s' = 0 to rounding) but not certified, splits its arc as an end:
  // the search need not find it again, and the arcs beside it start flat there.
  if (reached) {
    for (Arc<Real>& arc : arcs) {
      if (!(cross(end(arc.x).n, reached->n) > 0 && cross(reached->n, end(arc.y).n) > 0)) continue;
      const Arc<Real> whole = arc;
      const int mi = add(reached->n, reached->at);
      arc = {whole.x, mi, cheap_arc_bound(p, end(whole.x), end(mi), best.at.s + margin)};
      arcs.push_back({mi, whole.y, cheap_arc_bound(p, end(mi), end(whole.y), best.at.s + margin)});
      break;
    }
  }
  while (!arcs.empty() && best.evaluations < cap && !(best.at.s > stop)) {
    const auto top = std::max_element(arcs.begin(), arcs.end(),
                                      [](const Arc<Real>& l, const Arc<Real>& r) { return l.bound < r.bound; });
    if (top->bound <= best.at.s + margin) break;
    const Arc<Real> arc = *top;
    *top = arcs.back();
    arcs.pop_back();
    const Direction<Real> m = split(p, end(arc.x), end(arc.y), margin / 2, best.evaluations);
    if (m.n == end(arc.x).n) continue;  // no direction between the ends: they bound the arc
    const int mi = add(m.n, m.at);
    for (const auto& [from, to] : {std::pair{arc.x, mi}, std::pair{mi, arc.y}}) {
      const Real bound = cheap_arc_bound(p, end(from), end(to), best.at.s + margin);
      if (bound > best.at.s + margin) arcs.push_back({from, to, bound});
    }
  }
  return best;
}

}  // namespace collide2d::detail
