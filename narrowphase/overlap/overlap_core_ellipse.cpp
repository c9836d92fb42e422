// A convex core and an ellipse (narrowphase/shared/cores/convex_core.h): a rectangle, polygon,
// capsule or segment against an ellipse, where the pair has no kernel of its own. The core's point
// least in the ellipse's quadratic, and where it leaves the verdict open, the signed distance against
// the core's radius (core_ellipse.h).
#include "narrowphase/shared/cores/core_ellipse.h"

namespace collide2d::detail {

bool core_ellipse_overlap(const CoreEllipse& p) { return verdict(p).overlapping; }

}  // namespace collide2d::detail
