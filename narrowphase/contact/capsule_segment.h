// Private: a capsule against a capsule or a segment, on their two segments directly
// (contact_capsule_capsule.cpp), the kernel of both pairs.
#pragma once

#include <collide2d/query.h>
#include <collide2d/shapes.h>

namespace collide2d::detail {

// B a Capsule or a Segment. Where `swapped`, the contact is written for the pair (B, A), as
// Contact::swapped() would turn it, at no cost.
template <class B>
Contact capsule_segment_contact(const Capsule& a, const Orientation& ao, const B& b, const Orientation& bo,
                                const ContactOptions& options, bool swapped);
// The same where the kernel decides; where features tie, a contact of manifold size -1, which
// capsule_segment_contact() leaves to the convex cores' contact.
template <class B>
Contact capsule_segment_direct(const Capsule& a, const Orientation& ao, const B& b, const Orientation& bo,
                               const ContactOptions& options, bool swapped);

}  // namespace collide2d::detail
