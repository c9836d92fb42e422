// A segment and a circle: the centre against the segment, two faces one each way, on the core
// kernel the core shapes share (core_circle.h).
#include "narrowphase/contact/core_circle.h"

namespace collide2d {

Contact contact_segment_circle(const Segment& a, const Orientation& a_orientation, const Circle& b,
                               const ContactOptions& options) {
  return detail::core_circle(a, detail::SegmentView(a).view(), a_orientation, b, options);
}

Contact contact_segment_circle(const Segment& a, const Circle& b, const ContactOptions& options) {
  return contact_segment_circle(a, Orientation::of(a.angle), b, options);
}

}  // namespace collide2d
