// The README's usage example, built against an installed collide2d by the test suite.
#include <collide2d/collide2d.h>
#include <cstdio>

int main() {
  using namespace collide2d;
  const Shape wall = Rect{Vec2(0, 0), Vec2(2, 0.5), 0.3};          // centre, half extents, angle
  const Shape rock = Ellipse{Vec2(1, 2), 1.5, 0.4, 1.0};           // centre, a, b, angle of the a-axis
  if (overlaps(wall, rock)) std::puts("hit");                      // yes/no only
  const DistanceResult d = distance(wall, rock);                   // 0 and a witness when overlapping
  std::printf("%g from (%g, %g) to (%g, %g)\n", d.distance,
              d.point_a.x(), d.point_a.y(), d.point_b.x(), d.point_b.y());
}
