// The shapes module's interface to the rest of the library (not installed): rotations generic over
// the scalar, and the form of every validation message.
#pragma once

#include "shapes/rotation.h"

namespace collide2d::detail {

// Throws InvalidShape("<what> <field> <rule> (got <value>)"), the form of every validation message
// ("ellipse a must be positive (got -1)"), for the checks of other modules to share.
[[noreturn]] void reject(const char* what, const char* field, double value, const char* rule);

}  // namespace collide2d::detail
