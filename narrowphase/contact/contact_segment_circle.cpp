// A segment and a circle: the centre against the segment, two faces one each way, on the core
// kernel the core shapes share (core_circle.h).
#include "narrowphase/contact/core_circle.h"

#include <array>

namespace collide2d {

// Its faces' lines pass through its first point, the origin of its frame.
constexpr std::array<double, 2> kSegmentOffsets{};

// The segment from its frame's origin to its end; its faces' lines pass through the origin.
Contact contact_segment_circle(const Segment& a, const Orientation& a_orientation, const Circle& b,
                               const ContactOptions& options) {
  const std::array<Vec2, 2> ends = detail::segment_of(a);
  const std::array<Vec2, 4> normals = detail::segment_normals(a);  // the faces' two first
  const detail::Discs discs = detail::discs_of(a);
  return detail::core_circle(
      a, detail::CoreView<2>{ends.data(), normals.data(), kSegmentOffsets.data(), 2, 0.0, discs.reach}, a_orientation,
      b, options);
}

Contact contact_segment_circle(const Segment& a, const Circle& b, const ContactOptions& options) {
  return contact_segment_circle(a, Orientation::of(a.angle), b, options);
}

}  // namespace collide2d
