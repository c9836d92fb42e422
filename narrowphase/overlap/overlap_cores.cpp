// Any two convex cores (narrowphase/shared/cores/convex_core.h): a rectangle, polygon, capsule or
// segment with any of those or a circle, where the pair has no kernel of its own. The best separating
// axis against the radii, and where it leaves the verdict open, the cores' gap (core_pair.h).
#include "narrowphase/shared/cores/core_pair.h"

namespace collide2d::detail {

bool core_overlap(const CorePair& p) { return verdict(p, axes_of(p, radii(p))).overlapping; }

}  // namespace collide2d::detail
