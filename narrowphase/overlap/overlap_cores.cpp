// Any two convex cores (narrowphase/shared/cores/convex_core.h): a rectangle, polygon, capsule or
// segment with any of those or a circle, where the pair has no kernel of its own. The best separating
// axis against the radii, and where it leaves the verdict open, the cores' gap (core_pair.h).
#include "narrowphase/shared/cores/core_pair.h"

namespace collide2d::detail {

template <class X, class Y>
bool core_overlap(const CorePairOf<X, Y>& p) {
  return verdict(p, axes_of(p, radii(p))).overlapping;
}
template bool core_overlap(const CorePairOf<Core, Core>&);
template bool core_overlap(const CorePairOf<Core, SegmentCore>&);
template bool core_overlap(const CorePairOf<SegmentCore, Core>&);
template bool core_overlap(const CorePairOf<SegmentCore, SegmentCore>&);
template bool core_overlap(const CorePairOf<OwnFrameCore<Rect>, SegmentCore>&);
template bool core_overlap(const CorePairOf<OwnFrameCore<Rect>, Core>&);
template bool core_overlap(const CorePairOf<OwnFrameCore<ConvexPolygon>, SegmentCore>&);
template bool core_overlap(const CorePairOf<OwnFrameCore<ConvexPolygon>, Core>&);

}  // namespace collide2d::detail
