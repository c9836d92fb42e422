// Continuous collision: the first time within a step at which two moving shapes touch.
//
// Motion. Over one step each shape's centre moves in a straight line and the shape turns at a
// constant rate about its centre: at time t in [0, 1] its pose is (c + t v, angle + t w). This is
// Box2D's b2Sweep with the rotation centre at the shape's centre (collide2d's shapes are their own
// bodies, so there is no separate centre of mass).
//
// Method: conservative advancement on the exact signed distance d(t) (contact(), narrowphase/
// contact.h). At time t, with separation d and normal n, the separation of the pair along the fixed
// direction n changes at the rate n.(v_B - v_A) plus that of the two support functions, and a
// shape turning at rate w changes its support function at most |w| L, L the largest distance of its
// normal lines from its centre (a - b for an ellipse, the longer half side of a rectangle, 0 for a
// circle; time_of_impact.cpp derives them), less than the farthest point that Mirtich's
// conservative advancement uses. As d(t') >= s(n, t'),
//   d(t') >= d - (W - n.(v_B - v_A)) (t' - t),      W = |w_A| L_A + |w_B| L_B,
// and the step goes to where this lower bound reaches half the tolerance: never past the first time
// the shapes touch, nor past the first time their separation falls to half the tolerance. For
// translation alone (W = 0) d is convex in t (a maximum of functions affine in t) with slope
// n.(v_B - v_A) at t, so the step is Newton's on d from below its root: quadratic, never past it.
// With rotation that bound alone converges linearly, so Taylor bounds ride along. d(t') is at least
// the separation along any axis u(t'), as it is the largest over all of them; take u turning from
// n at a constant rate omega. Each shape then turns relative to the axis, and its support function
// along u is at most a parabola in t' - t (an ellipse's from its exact slope and h'' <= a^2 / b - b;
// a rectangle's the largest of one parabola per corner), as is the centres' offset projected on u
// from below, so d(t') is at least a concave function whose first root is safe too. The axes: the
// fixed one and one turning with the shape that turns, or, where both turn, one axis only, turning
// with a rectangle (a contact on a rectangle's face: along a fixed axis its far corner crosses at
// once while d does not move to first order; Box2D's face separation functions turn with the body
// too; of two rectangles, the one whose face normal lies nearest n) or with the slower of two
// ellipses (time_of_impact.cpp, leading_axis). The step goes to the latest of all the
// first roots (time_of_impact.cpp). On bench_toi's pairs turning up to 2 radians per step the
// mean steps fell from 10.2 to 5.1 (ellipse pairs), 12.1 to 5.5 (rect–ellipse) and 13.4 to 5.5
// (rectangle pairs). Each step's probe, and the contact of two ellipses, climb from the last step's
// normal (ContactOptions::guess); each step reuses the cosine and sine of a shape that does not
// turn, and takes a turning one's from a polynomial (shapes/quick_orientation.h). Far from contact a pair with an
// ellipse (and no circle) takes the climb's direction once Newton's next gain is below 3% of the
// separation, without certifying the maximum, and two rectangles the widest gap along the last
// normal and their face normals: any direction's separation is a lower bound of d, and the step
// stays safe. Every result comes from an exact contact().
//
// Result. hit: the separation at t is within (0, tolerance]; the solids first touch at or after t,
// and at most tolerance / (closing speed) later. miss: the lower bound stays above half the
// tolerance up to t = 1, so they do not touch during the step. overlapping: they overlap at t = 0.
// stalled: options.max_iterations steps did not decide (a grazing spin); t is a time
// up to which they certainly do not touch, and callers that must not tunnel stop there. The normal
// (A towards B) and the point (the midpoint of the closest points, or of the deepest points when
// overlapping) are those of the last contact evaluated: at t, or for a miss at the last step.
#pragma once

#include <collide2d/shapes.h>

#include <optional>

namespace collide2d {

struct Motion {
  Vec2 velocity = Vec2::Zero();   // of the centre, per step
  double angular_velocity = 0.0;  // radians per step, counter-clockwise, about the centre
};

struct ToiOptions {
  // The separation at which contact counts; 0 means 1e-9 of the two shapes' reaches summed. It is
  // raised to 8 u of the largest coordinates the step reaches, below which poses are not resolved.
  double tolerance = 0.0;
  // Steps at most (each a contact() query or a climb); then the status is stalled.
  int max_iterations = 1000;
};

enum class ToiStatus { hit, miss, overlapping, stalled };

struct TimeOfImpact {
  ToiStatus status = ToiStatus::miss;
  double t = 1.0;  // hit or stalled: the time found; overlapping: 0; miss: 1
  Vec2 normal = Vec2::UnitX();
  Vec2 point = Vec2::Zero();
  int iterations = 0;  // steps
};

// Validates both shapes and motions (finite, and every centre within range over the step) and
// throws InvalidShape naming the field: "A velocity x is nan", "B angular velocity is inf".
TimeOfImpact time_of_impact(const Shape& a, const Motion& a_motion, const Shape& b, const Motion& b_motion,
                            const ToiOptions& options = {});

// The shape's pose at time t of its motion.
Shape at_time(const Shape& s, const Motion& m, double t);

// A shape cast: `shape` translated by `translation` (no turn) against a `target` at rest, the query
// a character controller or a thrown object needs. The fraction of the translation at the first
// contact (0 when they overlap at the start; for a stalled search the fraction up to which they
// certainly do not touch), the point, and the target's outward normal there (towards the moving
// shape); nullopt when the whole translation is free.
struct CastHit {
  double fraction = 0.0;
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::UnitX();
};
std::optional<CastHit> shape_cast(const Shape& shape, const Vec2& translation, const Shape& target,
                                  const ToiOptions& options = {});

}  // namespace collide2d
