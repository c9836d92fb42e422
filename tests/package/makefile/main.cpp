// A plain Makefile project that finds collide2d with pkg-config.
#include <collide2d/collide2d.h>

#include <cstdio>

int main() {
  using namespace collide2d;
  const Contact c = contact(Rect{Vec2(0, 0), Vec2(1, 1), 0.0}, Ellipse{Vec2(0, 1.75), 2.0, 1.0, 0.0});
  std::printf("collide2d %s: separation %g\n", COLLIDE2D_VERSION_STRING, c.separation);
  return c.separation == -0.25 ? 0 : 1;
}
