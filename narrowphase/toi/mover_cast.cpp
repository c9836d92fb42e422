// A mover's cast against one shape: the first fraction of a translation at which the mover's
// separation falls below a floor. Under translation alone the signed separation d(t) of two convex
// shapes is convex in t (the largest over directions n of the gap along n, each affine in t), and
// the contact's normal at t gives a tangent d(t) + n.v (t' - t) that lies below it: Newton's step to
// the floor from there never passes the first time d reaches it, converges quadratically where the
// closest features are curved and in one step where they are faces. The floor is the smaller of the
// initial separation and the skin, less a hair (mover.h), so that a mover starting within its skin
// or slightly inside a surface moves freely along it and away from it.
#include "narrowphase/toi/mover_cast.h"

#include <collide2d/kernels.h>
#include <collide2d/mover.h>
#include <collide2d/time_of_impact.h>

#include "shapes/internal.h"

#include <algorithm>
#include <cmath>

namespace collide2d {
namespace detail {
namespace {

// Newton steps at most; a step short of the floor is safe, so a search cut off keeps its fraction.
constexpr int kMaxSteps = 64;

}  // namespace

double mover_floor_hair(const Shape& mover) {
  return 1e-12 * std::max(reach_of(mover), center_of(mover).cwiseAbs().maxCoeff());
}

double mover_cast(const Shape& mover, const Orientation& mover_orientation, const Vec2& translation,
                  const Shape& target, const Orientation& target_orientation, double skin, double reach) {
  const double hair = mover_floor_hair(mover);
  const double tolerance = 1e-9 * reach_of(mover);
  const double speed = translation.norm();
  // d(t) of the target (A) and the mover (B) at t, with no contact needed beyond what the rest of
  // the reach could close.
  const auto at = [&](double t, double limit) {
    const Shape moved = t == 0.0 ? mover : at_time(mover, {translation, 0.0}, t);
    return contact(target, target_orientation, moved, mover_orientation, {.max_separation = limit});
  };
  // Beyond the skin by more than the reach can close, the floor is the skin and is never reached.
  Contact c = at(0.0, skin + speed * reach);
  const double floor = std::min(c.separation, skin) - hair;
  double t = 0.0;
  for (int k = 0; k < kMaxSteps; ++k) {
    if (c.empty()) return reach;  // farther than the rest of the reach can close
    const double gap = c.separation - floor, closing = -c.normal.dot(translation);
    if (!(closing > 0.0)) return reach;  // d is convex and its slope here >= 0: it never falls
    if (!(gap > 0.0)) return t;          // at the floor, by the rounding of the pose
    const double step = gap / closing;
    t += step;
    if (!(t < reach)) return reach;
    // A step this short ends the search, and the separation is then within the tolerance of the
    // floor (gap = step closing). A small gap alone would not: passing over a corner in line with
    // a face at the skin (the seam between two tiles), d comes down to the floor plus the hair
    // and goes no lower, while Newton's steps halve until one passes the corner.
    if (step * speed <= tolerance) return t;
    c = at(t, floor + speed * (reach - t));
  }
  return t;
}

}  // namespace detail

double cast_mover(const Shape& mover, const Vec2& translation, const Shape& target, double skin) {
  validate(mover);
  validate(target);
  for (int k = 0; k < 2; ++k) {
    const double v = translation[k];
    if (!std::isfinite(v))
      detail::reject("mover cast", k == 0 ? "translation x" : "translation y", v, "must be finite");
  }
  if (!(skin >= 0.0) || !std::isfinite(skin))
    detail::reject("mover cast", "skin", skin, "must be finite and not negative");
  validate(at_time(mover, {translation, 0.0}, 1.0));  // the range of the centre
  return detail::mover_cast(mover, Orientation::of(angle_of(mover)), translation, target,
                            Orientation::of(angle_of(target)), skin, 1.0);
}

}  // namespace collide2d
