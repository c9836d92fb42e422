// Scenes for `collide2d run`: an arena, bodies with simple kinematics, and how long to run.
//
// The file is JSON; docs/command-line.md lists its fields, and examples/scene.json is a whole scene
// (tested). "arena" (min and max corners) and "frames" are required; "dt", "fat_margin",
// "proximity_margin", "contacts" and "overlap_areas" are optional, and so is every body field but the shape's own
// ("shape", "center", and a circle's "radius", an ellipse's "a" and "b", a rectangle's "half_extents"). A body of
// several shapes gives its pose ("center", "angle") and "shapes", each placed in its frame. Moving bodies move in
// straight lines and bounce off the arena walls (the velocity component towards a wall flips when the body's box
// crosses it); there is no physics: they pass through static bodies, which only report the overlaps. "movers"
// (optional) are characters moved by move() after each update, by a script of walking speeds and jumps (SceneMover).
//
// Errors: parse_scene throws SceneError naming the field, e.g. `bodies[3].radius: must be positive
// (got -1)`, `frames: missing`, `bodies[0]: a circle has no field 'a' (its own are radius)`.
#pragma once

#include <collide2d/mover.h>
#include <collide2d/shapes.h>
#include <collide2d/world.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace collide2d::tool {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SceneBody {
  Pose pose{};                  // where the body's origin is
  std::vector<Shape> shapes{};  // in its frame; a body of one shape has it at the origin
  Vec2 velocity = Vec2::Zero();
  double angular_velocity = 0.0;
  std::uint64_t id = 0;
  bool continuous = false;
  Filter filter;
  bool is_static = false;
  bool sensor = false;
  // A chain's points and whether it closes (World::add_chain): its body is static at the origin and
  // `shapes` are its segments. Empty for the other bodies.
  std::vector<Vec2> chain{};
  bool loop = false;
  bool operator==(const SceneBody&) const;
};

// A character the run moves with move() (mover.h) every frame, after the update: it walks at the
// script's speed (from each (frame, speed) entry's frame on; none before the first), falls under
// gravity, and jumps at the script's frames where it stands on the ground. The World does not hold
// it: the bodies do not meet it, nor it the other movers.
struct SceneMover {
  Shape shape;  // where it starts
  std::vector<std::pair<int, double>> walk{};
  std::vector<int> jumps{};
  double gravity = 20.0;
  double jump_speed = 6.0;
  MoverOptions options{};  // its skin, max_slope, step_height and snap_distance
  bool operator==(const SceneMover&) const;
};

struct Scene {
  Aabb arena{Vec2(0, 0), Vec2(100, 100)};
  int frames = 1;
  double dt = 1.0 / 60.0;
  double fat_margin = 0.1;
  double proximity_margin = 0.0;
  bool contacts = false;       // a contact for every overlapping pair (WorldOptions::contacts)
  bool overlap_areas = false;  // the exact overlap of contacts and sensor pairs (WorldOptions::overlap_areas)
  std::vector<SceneBody> bodies;
  std::vector<SceneMover> movers;
  bool operator==(const Scene&) const;
};

// The body of one shape: its origin at the shape's pose (pose_of in world.h), the shape at the
// origin.
std::vector<Shape> at_origin(const Shape& shape);
// Each of the body's shapes where its pose puts it, and the box around them all.
std::vector<Shape> placed_shapes(const SceneBody& body);
Aabb box_of(const SceneBody& body);
// The body's first shape where its pose puts it: the shape of a body of one shape, without placing
// every segment of a chain body.
Shape placed_first(const SceneBody& body);

// Throws SceneError for a broken scene, before any frame is run: a field the format lacks or a
// shape kind does not take, a duplicate id, a value out of range, or a motion that would carry a
// body beyond the range the library supports within the run.
Scene parse_scene(std::string_view json);
// The last of parse_scene's checks, for a scene built or changed in code (SceneRun makes it).
void check_motion(const Scene& scene);
std::string write_scene(const Scene& scene);  // JSON that parse_scene reads back to the same scene

// The built-in scene: `count` mixed circles, ellipses (aspect up to 8) and rectangles, sizes 0.3 to
// 2, random velocities up to 6 per second, in an arena sized for about 8% coverage, and one bullet
// per 500 of them (continuous circles of radius 0.1 at 300 per second: 25 radii a frame at 60 Hz);
// seeded. Every fourth body is on a second layer (category 2, mask 2) that never pairs with the
// first (category 1, mask 1; the bullets too). A static level on both layers: a chain loop inside the
// arena's sides, clockwise (the inside of a cave), its floor rolling in hills 3 high, and one slope
// (a tilted rectangle) and one rock (an ellipse) per 200 bodies; and four static sensors (circles a
// twelfth of the arena across) at the quarter points, which sense both layers.
Scene default_scene(int count = 4000, int frames = 600, std::uint64_t seed = 1);

// One frame of kinematics: each body advances by dt and bounces off the walls.
void step(Scene& scene);

}  // namespace collide2d::tool
