// A program that uses an installed collide2d, as a user's project does; the test suite builds it
// against the package it installs (tests/package).
#include <collide2d/collide2d.h>
#include <cstdio>

int main() {
  using namespace collide2d;
  // One pair at a time: the narrow phase.
  const Shape wall = Rect{Vec2(0, 0), Vec2(2, 0.5), 0.3};  // centre, half extents, angle
  const Shape rock = Ellipse{Vec2(1, 2), 1.5, 0.4, 1.0};   // centre, a, b, angle of the a-axis
  if (overlaps(wall, rock)) std::puts("hit");              // yes/no only
  const DistanceResult d = distance(wall, rock);           // 0 and a witness when overlapping
  std::printf("%g from (%g, %g) to (%g, %g)\n", d.distance, d.point_a.x(), d.point_a.y(), d.point_b.x(), d.point_b.y());
  const Contact c = contact(wall, rock);  // how deep, along which normal, where
  std::printf("separation %g along (%g, %g)\n", c.separation, c.normal.x(), c.normal.y());

  // Many bodies moving every frame: the World (sweep and prune, then the narrow phase).
  World world({.fat_margin = 0.1, .proximity_margin = 0.5, .contacts = true});
  const BodyId ship = world.add(Ellipse{Vec2(0, 0), 1.0, 0.3, 0.0}, {.user_id = 1});
  world.add(Circle{Vec2(3, 0), 1.0}, {.user_id = 2});
  // Level geometry that never moves, and a trigger zone that only reports what enters it.
  world.add(Rect{Vec2(0, -1.5), Vec2(10, 0.5), 0.0}, {.user_id = 3, .filter = {}, .is_static = true, .sensor = false});
  world.add(Circle{Vec2(1.5, 0), 0.2}, {.user_id = 4, .filter = {}, .is_static = true, .sensor = true});
  for (int frame = 0; frame < 3; ++frame) {
    world.move_by(ship, Vec2(0.5, 0.0), 0.1);
    world.update();
    for (const ShapePair& p : world.began()) {
      std::printf("frame %d: bodies %llu and %llu touch\n", frame, static_cast<unsigned long long>(world.user_id(p.a)),
                  static_cast<unsigned long long>(world.user_id(p.b)));
    }
    for (const Proximity& p : world.proximity()) std::printf("frame %d: %g apart\n", frame, p.result.distance);
    for (const BodyContact& b : world.contacts()) std::printf("frame %d: %g deep\n", frame, 0.0 - b.contact.separation);
    for (const SensorPair& s : world.sensor_began()) {
      std::printf("frame %d: body %llu entered zone %llu\n", frame,
                  static_cast<unsigned long long>(world.user_id(s.visitor)),
                  static_cast<unsigned long long>(world.user_id(s.sensor)));
    }
  }
  // Queries go through the World's trees and test the exact shapes (sensors are not solid).
  if (const auto hit = world.ray_cast(Vec2(3, 5), Vec2(0, -1), 10.0)) {
    std::printf("ray hits body %llu at %g\n", static_cast<unsigned long long>(world.user_id(hit->body)), hit->distance);
  }
}
