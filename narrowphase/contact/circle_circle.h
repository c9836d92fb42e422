// Private: two circles along their line of centres (contact_circle_circle.cpp), the pair's kernel.
#pragma once

#include <collide2d/query.h>
#include <collide2d/shapes.h>

namespace collide2d::detail {

// Where `swapped`, the contact is written for the pair (B, A), as Contact::swapped() would turn it,
// at no cost.
Contact circle_circle_contact(const Circle& a, const Circle& b, const ContactOptions& options, bool swapped);

}  // namespace collide2d::detail
