#include <collide2d/kernels.h>

#include "narrowphase/overlap/overlap_rect_ellipse.h"

#include "narrowphase/shared/frames/rect_ellipse_frame.h"
#include "narrowphase/shared/lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/overlap_rect_ellipse-inl.h"
}  // namespace detail
namespace {

using detail::FilterVerdict;
using detail::RectEllipseFrame;

// The filter on a single pair (overlap_rect_ellipse-inl.h, shared with the batch).
FilterVerdict minkowski_filter(const RectEllipseFrame<double>& f) {
  using detail::Scalar;
  const detail::LaneVerdicts<bool> v = detail::RectEllipseFilter<Scalar>(Scalar{}, detail::rect_ellipse_lanes(f)).run();
  return v.separated ? FilterVerdict::separated : v.overlap ? FilterVerdict::overlap : FilterVerdict::uncertain;
}

}  // namespace

bool detail::minkowski_overlap(const RectEllipseFrame<double>& f, const Rect& r, const Ellipse& e) {
  const FilterVerdict v = minkowski_filter(f);
  if (v != FilterVerdict::uncertain) return v == FilterVerdict::overlap;
  return detail::minkowski_fallback(r, e);
}

bool detail::minkowski_fallback(const Rect& r, const Ellipse& e) {
  return detail::closest_features_overlap(detail::rect_ellipse_frame<DoubleDouble>(r, e));
}

detail::FilterVerdict detail::overlap_rect_ellipse_filter(const Rect& r, const Ellipse& e) {
  return minkowski_filter(detail::rect_ellipse_frame<double>(r, e));
}

bool overlap_rect_ellipse(const Rect& r, const Orientation& ro, const Ellipse& e, const Orientation& eo) {
  return detail::minkowski_overlap(
      detail::rect_ellipse_frame<double>(r, detail::Rotation<double>::of(ro), e, detail::Rotation<double>::of(eo)), r,
      e);
}

bool overlap_rect_ellipse(const Rect& r, const Ellipse& e) {
  return detail::minkowski_overlap(detail::rect_ellipse_frame<double>(r, e), r, e);
}

}  // namespace collide2d
