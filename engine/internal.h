// The World's interface to the modules beside it (engine/distributed/, engine/replay/), not
// installed: the checks its calls make of their arguments, with the same messages.
#pragma once

namespace collide2d::detail {

// Throws std::invalid_argument("<what> must be finite (got <value>)") for NaN or infinity.
void require_finite(double value, const char* what);
// The same, and "<what> must not be negative" below 0.
void require_margin(double value, const char* what);

}  // namespace collide2d::detail
