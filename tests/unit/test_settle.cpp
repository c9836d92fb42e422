// The discrete-element example run small: 150 bodies in a box 8 wide must come to rest, with no
// contact deeper than 1% of the smallest body and no body outside the box, packed as a pile (not
// flown apart, not collapsed into each other).
#include "examples/settle/settle.h"

#include <collide2d/area.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace collide2d::settle {
namespace {

TEST(Settle, SmallPileComesToRestInsideTheBox) {
  const SettleResult r = settle({.bodies = 150, .width = 8.0, .seed = 3});
  std::printf(
      "[settle] %zu bodies at rest %d after %.2f s (%d steps): fastest %.2e, deepest %.2e = %.3f%% of %.3f, %d "
      "outside\n",
      r.shapes.size(), r.at_rest, r.seconds, r.steps, r.max_speed, r.max_penetration,
      100 * r.max_penetration / r.smallest, r.smallest, r.outside);
  ASSERT_EQ(r.shapes.size(), 150u);
  EXPECT_TRUE(r.at_rest);
  EXPECT_LT(r.max_speed, 1e-2);
  EXPECT_LT(r.max_penetration, 0.01 * r.smallest);
  EXPECT_GT(r.max_penetration, 0.0);  // the pile rests on its contacts
  EXPECT_EQ(r.outside, 0);
  // Packed: the pile's top lies between its solid height and three times that.
  double total = 0, top = 0;
  for (const Shape& s : r.shapes) {
    total += area(s);
    top = std::max(top, aabb(s).max.y());
  }
  EXPECT_GT(top, total / r.width);
  EXPECT_LT(top, 3 * total / r.width);
  std::ostringstream svg;
  write_settle_svg(r, svg);
  EXPECT_NE(svg.str().find("150 bodies at rest"), std::string::npos);
}

}  // namespace
}  // namespace collide2d::settle
