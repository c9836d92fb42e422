#include "narrowphase/overlap_rect_rect.h"

#include "narrowphase/rect_pair_frame.h"

#include <cmath>

namespace collide2d {

bool overlap_rect_rect(const Rect& a, const Rect& b) {
  return overlap_rect_rect(a, Orientation::of(a.angle), b, Orientation::of(b.angle));
}

bool overlap_rect_rect(const Rect& a, const Orientation& ao, const Rect& b, const Orientation& bo) {
  const detail::RectPairFrame f(a, {ao.c, ao.s}, b, {bo.c, bo.s});
  const double c = std::abs(f.b_rel.c);
  const double s = std::abs(f.b_rel.s);
  const Vec2& ha = a.half_extents;
  const Vec2& hb = b.half_extents;
  const Vec2& t = f.b_center;
  const Vec2 t_in_b = f.b_rel.apply_inverse(t);
  return std::abs(t.x()) <= ha.x() + hb.x() * c + hb.y() * s &&
         std::abs(t.y()) <= ha.y() + hb.x() * s + hb.y() * c &&
         std::abs(t_in_b.x()) <= hb.x() + ha.x() * c + ha.y() * s &&
         std::abs(t_in_b.y()) <= hb.y() + ha.x() * s + ha.y() * c;
}

}  // namespace collide2d
