// Hard-case families for the narrow-phase tests, checked against the 50-digit reference.
//
// Construction: A is a random shape; p is a point of A's boundary with outward unit normal n (on a
// rectangle edge with its face normal, or any n with p = support_A(n), which for a rectangle is a
// corner and n any direction of its normal cone). B is translated so that support_B(-n) sits at
// p + delta n: the gap is then delta (distance delta when delta > 0, overlap iff delta <= 0) up to
// the rounding of B's centre, which the check bounds by rho = 16 u (|offset| + 4 size).
//
// Asserted (size = the larger shape's largest half-size, scale = max(size, centre distance)):
// - verdict: the default overlap test equal to the reference's exact verdict for the rounded input
//   in every case, rounding-level gaps included; the plain-double rect–ellipse tests wherever the
//   true gap exceeds 1e-10 size in magnitude (the reference distance for separated pairs, delta +
//   rho for overlapping ones);
// - distance: |d - d_ref| <= 8 u scale (u = 2^-53), not the product target of 1e-12 scale: the
//   measured worst is about 4 u, and a regression should fail long before it reaches the target;
// - closest points, beyond 4 ulps of their coordinates: each within p u scale of its own shape,
//   the point on A within d + p u scale of B, and |b - a| within p u scale of d (p = point_bound,
//   64 unless a family says why not);
// - for pairs of circles and ellipses, the boundary distance too: within 8 u scale of the
//   reference, its points within p u scale of their curves.
// For ellipse pairs the two seed methods (gradient, polynomial) are measured, not asserted.
#pragma once

#include <collide2d/query.h>

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace collide2d::testing {

enum class Kind { rect, circle, ellipse };
// touching: B against A with gap delta; inside: B well inside A; identical: B the same region or
// its inscribed/circumscribed twin; inner_tangent: B inside A near its boundary, gap delta (circles
// and ellipses); concentric: B shares A's centre, with its own axes and angle (circles and ellipses);
// mirrored: B's axes parallel to A's and B against A with gap delta along one of A's axes, on the
// line of that axis (every other case slid along a rectangle's face), so that the pair is mirror
// symmetric; cusp: a circle or ellipse nested in an ellipse (or holding one) with its centre on the
// ellipse's axis near a cusp of the ellipse's evolute, where two extrema of the gap merge into one
// (an ellipse and a circle or ellipse; either may be A); congruent: B a copy of A scaled by 1 - e,
// turned by up to e and moved by up to 2 e of A's minor axis (e = |delta|): a thin ring, nested or
// crossing, where the two curves' radii of curvature nearly cancel (ellipses).
enum class Placement { touching, inside, identical, inner_tangent, concentric, mirrored, cusp, congruent };

struct Family {
  std::string name;
  Kind a = Kind::rect;
  Kind b = Kind::ellipse;
  int cases = 120;
  double size = 1.0;
  double offset = 0.0;
  double aspect_min = 1.0;  // aspect ratios of rectangles and ellipses, log-uniform
  double aspect_max = 4.0;
  double size_ratio = 3.0;  // B's size over A's, log-uniform in [1/ratio, ratio]
  std::vector<double> deltas{1e-3, -1e-3, 1e-6, -1e-6, 1e-9, -1e-9, 1e-10, -1e-10, 1e-12, -1e-12};
  Placement placement = Placement::touching;
  bool axis_aligned = false;  // every angle exactly 0 (a/b and half extents in either order)
  double point_bound = 64;    // the closest points' asserted accuracy, in u of the scale
  std::uint64_t seed = 1;
};

struct FamilyStats {
  int cases = 0;
  int verdicts_checked = 0;
  int rounding_verdicts_checked = 0;      // default verdicts where |gap| <= 1e-10 size, asserted too
  int plain_mismatches_below_target = 0;  // plain-double rect–ellipse tests there (allowed)
  int fallbacks = 0;                      // the filter (rect–ellipse, ellipse–ellipse) was `uncertain`
  double worst_distance_error = 0.0;      // |d - d_ref| / scale
  double worst_boundary_error = 0.0;      // the same for the boundary distance (circles, ellipses)
  double worst_point_error = 0.0;         // closest points beyond coordinate rounding, / scale
  std::vector<int> robust_iterations;     // ellipse pairs: support evaluations of the distance
  // Ellipse pairs, per seed method (0 gradient, 1 polynomial), over the solid distance of separated
  // pairs and the boundary distance of every pair; errors relative to the scale:
  std::vector<double> method_errors[2];
  int method_unconverged[2] = {0, 0};  // the method's own stopping rule was not met
  int method_wrong[2] = {0, 0};        // error above 1e-6
};

// gtest prints a family by its name.
void PrintTo(const Family& f, std::ostream* os);

// The standard hard-case families for a pair: near-tangent contacts (delta = +-1e-3 ... +-1e-12 of
// the size), aspect ratios 1e2 ... 1e6 and near-circles (where a rectangle or ellipse is involved),
// offsets 1e6 and 1e9, sizes 1e-6 and 1e6, each shape inside the other, identical or inscribed,
// mirror-symmetric contacts axis-aligned (exactly) and turned (to rounding), and for an ellipse
// with a circle or an ellipse, nesting at the evolute's cusps, axis-aligned and turned.
std::vector<Family> standard_families(Kind a, Kind b);

// A gtest-safe name for a family.
std::string test_name(const Family& f);

struct Case {
  Shape a;
  Shape b;
  double delta;  // nominal gap (touching and mirrored placements), or NaN
};

// The family's cases, the same every call (seeded by the family).
std::vector<Case> family_cases(const Family& f);

// The shape moved by the rigid motion p -> R(turn) p + shift.
Shape moved(const Shape& s, double turn, const Vec2& shift);

// A shape's largest half-size, and the shape as text for failure messages.
double half_size(const Shape& s);
std::string describe(const Shape& s);

// How far the boundary distance's points lie off their curves (circles or ellipses), and how far
// |point_b - point_a| is from the distance, beyond the rounding of the points' coordinates: the worst.
double boundary_point_error(const Shape& a, const Shape& b, const DistanceResult& d);

// Runs every case through overlaps() with each rect–ellipse method and distance(), in both orders,
// records gtest failures for missed targets, prints one summary line and returns the statistics.
FamilyStats run_family(const Family& family);

}  // namespace collide2d::testing
