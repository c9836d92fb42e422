// Private: the rectangle pair's contact for the queries, which hand the kernel its shapes in kernel
// order: where `swapped` (the caller gave B first), the manifold's reference face on a tie is B's,
// the caller's first rectangle's, and the contact is written for the pair (B, A), as
// Contact::swapped() would turn it, at no cost.
#pragma once

#include <collide2d/query.h>

namespace collide2d::detail {

Contact contact_rect_rect(const Rect& a, const Orientation& a_orientation, const Rect& b,
                          const Orientation& b_orientation, const ContactOptions& options, bool swapped);

}  // namespace collide2d::detail
