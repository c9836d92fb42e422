// The shapes module's interface to the rest of the library (not installed): rotations generic over
// the scalar, and the form of every validation message.
#pragma once

#include "shapes/rotation.h"

#include <string>

namespace collide2d::detail {

// Throws InvalidShape("<what> <field> <rule> (got <value>)"), the form of every validation message
// ("ellipse a must be positive (got -1)"), for the checks of other modules to share.
[[noreturn]] void reject(const char* what, const char* field, double value, const char* rule);

// The shortest digits that read back as the value ("0.1", "1e+51", "nan"), for messages.
std::string shortest(double value);

}  // namespace collide2d::detail
