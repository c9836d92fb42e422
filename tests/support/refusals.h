// Test helper: a call that must throw `Error` with a message that holds `words`.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace collide2d::testing {

template <class Error>
void expect_refused(const std::function<void()>& call, const std::string& words) {
  try {
    call();
    ADD_FAILURE() << "accepted, expected: " << words;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

}  // namespace collide2d::testing
