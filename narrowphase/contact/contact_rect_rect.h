// Private: the rectangle pair's contact with the manifold's reference face preferred on either
// side, so that the queries, which hand the kernel its shapes in kernel order, keep the preference
// for the face of the shape the caller named first.
#pragma once

#include <collide2d/query.h>

namespace collide2d::detail {

enum class PreferredFace { of_a, of_b };

Contact contact_rect_rect(const Rect& a, const Orientation& a_orientation, const Rect& b,
                          const Orientation& b_orientation, const ContactOptions& options, PreferredFace preferred);

}  // namespace collide2d::detail
