// The broad phase module's interface to the rest of the library (not installed).
#pragma once

#include <algorithm>
#include <iterator>
#include <vector>

namespace collide2d::detail {

// A sorted pair list becomes `now` (sorted too); began and ended get what it gained and lost. The
// broad phases keep their pairs so, and the World its overlapping and sensor pairs. The lists trade
// places: `now` is left holding the old pairs, whose storage the caller's next frame fills again, so
// that a steady frame allocates nothing.
template <class Pair>
void replace_pairs(std::vector<Pair>& pairs, std::vector<Pair>& now, std::vector<Pair>& began,
                   std::vector<Pair>& ended) {
  began.clear();
  ended.clear();
  std::set_difference(now.begin(), now.end(), pairs.begin(), pairs.end(), std::back_inserter(began));
  std::set_difference(pairs.begin(), pairs.end(), now.begin(), now.end(), std::back_inserter(ended));
  pairs.swap(now);
}

}  // namespace collide2d::detail
