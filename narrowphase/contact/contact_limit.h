// Private: ContactOptions::max_separation, as every contact kernel applies it.
#pragma once

#include <collide2d/query.h>

#include <limits>

namespace collide2d::detail {

// Throws std::invalid_argument for a guess that is not finite or a limit that is NaN.
void validate(const ContactOptions& options);

// Whether the caller set a limit (a bound costs work that the full contact would not need).
inline bool has_limit(const ContactOptions& options) {
  return options.max_separation < std::numeric_limits<double>::infinity();
}

// The value a lower bound of the separation must pass to show the pair beyond the caller's limit:
// the limit and the bound's own rounding, 64 u of the pair's scale, so that no pair the full
// contact finds within the limit is cut off by a bound that rounded up.
inline double separation_limit(double scale, const ContactOptions& options) {
  return options.max_separation + 64 * std::numeric_limits<double>::epsilon() * scale;
}
inline bool beyond_limit(double lower_bound, double scale, const ContactOptions& options) {
  return lower_bound > separation_limit(scale, options);
}

// The contact make() computes whole (the closed forms cost no more than a bound would), its
// manifold emptied beyond the limit. One named result and one return, so that the compiler builds
// the contact where the caller receives it; a kernel with other returns (its early-outs) returns
// this call's value rather than a named contact of its own, which would be built aside and copied.
template <class Make>
Contact limited(const ContactOptions& options, Make make) {
  Contact c = make();
  if (c.separation > options.max_separation) c.manifold_size = 0;
  return c;
}

}  // namespace collide2d::detail
