// Test helpers for the World's frame-by-frame lists, shared by its unit tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <string>
#include <vector>

namespace collide2d::testing {

// began and ended are what `now` gained and lost since `previous`.
template <class Pair>
void expect_changes(const std::vector<Pair>& previous, const std::vector<Pair>& now, const std::vector<Pair>& began,
                    const std::vector<Pair>& ended, const std::string& what) {
  std::vector<Pair> gained, lost;
  std::set_difference(now.begin(), now.end(), previous.begin(), previous.end(), std::back_inserter(gained));
  std::set_difference(previous.begin(), previous.end(), now.begin(), now.end(), std::back_inserter(lost));
  ASSERT_EQ(began, gained) << what;
  ASSERT_EQ(ended, lost) << what;
}

}  // namespace collide2d::testing
