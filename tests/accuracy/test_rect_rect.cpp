// Rectangle–rectangle overlap and distance on the hard-case families, against the 50-digit reference.
#include "hard_cases.h"

#include <gtest/gtest.h>

namespace collide2d::testing {
namespace {

class RectRectFamilies : public ::testing::TestWithParam<Family> {};

TEST_P(RectRectFamilies, MeetTargets) { run_family(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Standard, RectRectFamilies, ::testing::ValuesIn(standard_families(Kind::rect, Kind::rect)),
                         [](const auto& info) { return test_name(info.param); });

}  // namespace
}  // namespace collide2d::testing
