/// @file
/// Continuous collision: the first time within a step at which two moving shapes touch, and the
/// shape cast a character controller needs.
///
/// Motion: over one step each shape's centre moves in a straight line and the shape turns at a
/// constant rate about its centre; at time t in [0, 1] its pose is (c + t v, angle + t w) (Box2D's
/// b2Sweep with the rotation centre at the shape's centre). The method is conservative advancement
/// on the exact signed distance of contact() (docs/time-of-impact.md): a step never passes the
/// first contact, and every result comes from an exact contact.
#pragma once

#include <collide2d/shapes.h>

#include <optional>

namespace collide2d {

/// How a shape moves over one step.
struct Motion {
  Vec2 velocity = Vec2::Zero();   ///< of the centre, per step
  double angular_velocity = 0.0;  ///< radians per step, counter-clockwise, about the centre
};

/// What a time of impact may use beyond the shapes and motions.
struct ToiOptions {
  /// The separation at which contact counts; 0 means 1e-9 of the two shapes' reaches summed. It is
  /// raised to 8 u of the pair's coordinates relative to A (|c_B - c_A| + |v_B - v_A|), below which
  /// poses are not resolved; the pair's offset from the origin does not count.
  double tolerance = 0.0;
  /// Steps at most (each a contact or a climb); then the status is stalled.
  int max_iterations = 1000;
};

/// How a time of impact ended.
enum class ToiStatus {
  hit,          ///< the separation of the exact poses at t is within (0, tolerance]: they first touch
                ///< at or after t, at most tolerance / (closing speed) later. Poses computed in
                ///< double add their rounding, u |c + t v| per coordinate.
  miss,         ///< they do not touch during the step
  overlapping,  ///< they overlap at t = 0
  stalled,      ///< max_iterations steps did not decide (a grazing spin); they do not touch before t
};

/// The result of a time of impact.
struct TimeOfImpact {
  ToiStatus status = ToiStatus::miss;
  double t = 1.0;               ///< hit or stalled: the time found; overlapping: 0; miss: 1
  Vec2 normal = Vec2::UnitX();  ///< from A to B, of the last contact evaluated (at t; for a miss, the last step)
  Vec2 point = Vec2::Zero();    ///< the midpoint of that contact's two points
  int iterations = 0;           ///< steps taken
};

/// The first time in [0, 1] at which the moving shapes touch. Throws InvalidShape for an invalid
/// shape, a motion that is not finite or carries a centre beyond +-1e50 ("A velocity x must be
/// finite (got nan)"), or a negative tolerance.
TimeOfImpact time_of_impact(const Shape& a, const Motion& a_motion, const Shape& b, const Motion& b_motion,
                            const ToiOptions& options = {});

/// The shape's pose at time t of its motion.
Shape at_time(const Shape& s, const Motion& m, double t);

/// A shape cast's first contact.
struct CastHit {
  double fraction = 0.0;  ///< of the translation; 0 when they overlap at the start
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::UnitX();  ///< the target's outward normal there, towards the moving shape
};
/// `shape` translated by `translation` (no turn) against a `target` at rest: the first contact, or
/// nullopt when the whole translation is free. For a stalled search the fraction is the one up to
/// which they certainly do not touch. Validates as time_of_impact().
std::optional<CastHit> shape_cast(const Shape& shape, const Vec2& translation, const Shape& target,
                                  const ToiOptions& options = {});

}  // namespace collide2d
