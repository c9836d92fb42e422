// The broad phase module's interface to the rest of the library (not installed).
#pragma once

#include <compare>
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
  // One merge of the two lists, each pair compared once.
  auto was = pairs.begin();
  auto is = now.begin();
  while (was != pairs.end() && is != now.end()) {
    const auto order = *is <=> *was;
    if (order < 0) {
      began.push_back(*is++);
    } else if (order > 0) {
      ended.push_back(*was++);
    } else {
      ++is;
      ++was;
    }
  }
  began.insert(began.end(), is, now.end());
  ended.insert(ended.end(), was, pairs.end());
  pairs.swap(now);
}

}  // namespace collide2d::detail
