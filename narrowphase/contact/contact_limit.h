// Private: ContactOptions::max_separation, as every contact kernel applies it.
#pragma once

#include <collide2d/query.h>

#include <limits>

namespace collide2d::detail {

// Whether the caller set a limit (a bound costs work that the full contact would not need).
inline bool limited(const ContactOptions& options) {
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

// A contact computed whole (the closed forms cost no more than a bound would): empty beyond the
// limit, its separation kept as the bound.
inline Contact within_limit(const Contact& c, const ContactOptions& options) {
  return c.separation > options.max_separation ? Contact::beyond(c.separation) : c;
}

}  // namespace collide2d::detail
