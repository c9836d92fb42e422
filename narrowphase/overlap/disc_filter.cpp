// The disc test (disc_filter-inl.h) on one pair, for the one-off overlap tests (query.cpp), with the
// batch's IEEE operations on a double.
#include "narrowphase/shared/cores/convex_core.h"
#include "narrowphase/shared/lanes.h"

#include <limits>
#include <optional>

namespace collide2d::detail {
#include "narrowphase/overlap/disc_filter-inl.h"

namespace {

template <class Lanes>
std::optional<bool> certain_verdict(const Lanes& discs) {
  const LaneVerdicts<bool> certain = disc_verdicts(Scalar{}, discs);
  if (certain.overlap || certain.separated) return certain.overlap;
  return std::nullopt;
}

}  // namespace

std::optional<bool> disc_verdict(const DiscEllipseLanes<double>& discs) { return certain_verdict(discs); }
std::optional<bool> disc_verdict(const DiscPairLanes<double>& discs) { return certain_verdict(discs); }

}  // namespace collide2d::detail
