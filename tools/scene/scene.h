// Scenes for `collide2d run`: an arena, bodies with simple kinematics, and how long to run.
//
// The file is JSON:
//   {
//     "arena": {"min": [0, 0], "max": [100, 100]},
//     "frames": 600,                 // required, >= 1
//     "dt": 0.016667,                // seconds per frame, default 1/60
//     "fat_margin": 0.1,             // broad-phase margin, default 0.1
//     "proximity_margin": 0.5,       // report pairs closer than this, default 0 (off)
//     "bodies": [
//       {"shape": "circle",  "center": [10, 20], "radius": 1.5},
//       {"shape": "ellipse", "center": [30, 20], "a": 3, "b": 1, "angle": 0.4,
//        "velocity": [2, -1], "angular_velocity": 0.5, "id": 7},
//       {"shape": "rect",    "center": [50, 50], "half_extents": [2, 1], "angle": 0},
//       {"shape": "circle",  "center": [5, 5], "radius": 0.1, "velocity": [300, 40], "continuous": true,
//        "category": 2, "mask": 5, "group": -1},
//       {"shape": "rect",    "center": [50, 1], "half_extents": [50, 1], "static": true},
//       {"shape": "circle",  "center": [80, 80], "radius": 8, "static": true, "sensor": true}
//     ]
//   }
// velocity (default [0, 0]), angular_velocity (default 0), angle (default 0), id (default: the
// body's index), continuous (default false: a bullet, whose impacts within each frame the World
// finds), static (default false: level geometry, which never moves; it has no velocity and is not
// continuous), sensor (default false: reports the bodies inside it and is otherwise not solid) and
// the collision filter's category, mask and group (engine/world.h; defaults 1, every bit, 0: the
// body pairs with every other) are optional. Moving bodies move in straight lines and bounce off the
// arena walls (the velocity component towards a wall flips when the body's box crosses it); there is
// no physics: they pass through static bodies, which only report the overlaps.
//
// Errors: parse_scene throws SceneError naming the field, e.g. `bodies[3].radius: must be positive
// (got -1)`, `frames: missing`, `bodies[0]: unknown field 'radus'`.
#pragma once

#include <collide2d/shapes.h>
#include <collide2d/world.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace collide2d::tool {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SceneBody {
  Shape shape;
  Vec2 velocity = Vec2::Zero();
  double angular_velocity = 0.0;
  std::uint64_t id = 0;
  bool continuous = false;
  Filter filter;
  bool is_static = false;
  bool sensor = false;
  bool operator==(const SceneBody&) const;
};

struct Scene {
  Aabb arena{Vec2(0, 0), Vec2(100, 100)};
  int frames = 1;
  double dt = 1.0 / 60.0;
  double fat_margin = 0.1;
  double proximity_margin = 0.0;
  std::vector<SceneBody> bodies;
  bool operator==(const Scene&) const;
};

Scene parse_scene(std::string_view json);
std::string write_scene(const Scene& scene);  // JSON that parse_scene reads back to the same scene

// The built-in scene: `count` mixed circles, ellipses (aspect up to 8) and rectangles, sizes 0.3 to
// 2, random velocities up to 6 per second, in an arena sized for about 8% coverage, and one bullet
// per 500 of them (continuous circles of radius 0.1 at 300 per second: 25 radii a frame at 60 Hz);
// seeded. Every fourth body is on a second layer (category 2, mask 2) that never pairs with the
// first (category 1, mask 1; the bullets too). A static level on both layers: walls along the arena's
// sides, and one slope (a tilted rectangle) and one rock (an ellipse) per 200 bodies; and four static
// sensors (circles a twelfth of the arena across) at the quarter points, which sense both layers.
Scene default_scene(int count = 4000, int frames = 600, std::uint64_t seed = 1);

// One frame of kinematics: each body advances by dt and bounces off the walls.
void step(Scene& scene);

}  // namespace collide2d::tool
