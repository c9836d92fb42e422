// A capsule and a circle: the centre against the capsule's segment, two faces one each way, on the
// core kernel the core shapes share (core_circle.h).
#include "narrowphase/contact/core_circle.h"

#include <array>

namespace collide2d {

// The segment's faces' lines pass through its centre.
constexpr std::array<double, 2> kSegmentOffsets{};

Contact contact_capsule_circle(const Capsule& a, const Orientation& a_orientation, const Circle& b,
                               const ContactOptions& options) {
  const std::array<Vec2, 2> ends = detail::segment_of(a), normals = detail::segment_normals();
  const detail::Discs discs = detail::discs_of(a);
  return detail::core_circle(
      a, detail::CoreView<2>{ends.data(), normals.data(), kSegmentOffsets.data(), 2, a.radius, discs.reach},
      a_orientation, b, options);
}

Contact contact_capsule_circle(const Capsule& a, const Circle& b, const ContactOptions& options) {
  return contact_capsule_circle(a, Orientation::of(a.angle), b, options);
}

}  // namespace collide2d
