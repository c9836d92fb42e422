// A capsule and a segment: the capsule–capsule kernel's (contact_capsule_capsule.cpp), the segment a
// capsule's segment of radius 0.
#include "narrowphase/contact/capsule_segment.h"

#include <collide2d/kernels.h>

namespace collide2d {

Contact contact_capsule_segment(const Capsule& a, const Orientation& a_orientation, const Segment& b,
                                const Orientation& b_orientation, const ContactOptions& options) {
  return detail::capsule_segment_contact(a, a_orientation, b, b_orientation, options, false);
}

Contact contact_capsule_segment(const Capsule& a, const Segment& b, const ContactOptions& options) {
  return contact_capsule_segment(a, Orientation::of(a.angle), b, Orientation::of(b.angle), options);
}

}  // namespace collide2d
