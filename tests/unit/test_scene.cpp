// Scene files for `collide2d run`: round trip, every kind of broken file named by its field, and a
// run whose last frame agrees with an all-pairs check.
#include "tools/scene/scene.h"
#include "tools/scene/scene_run.h"
#include "world_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <thread>

namespace collide2d::tool {
namespace {

TEST(Scene, WrittenSceneReadsBackTheSame) {
  // The level: the cave (a chain), a slope or a rock per 200 bodies, and 4 sensors, all static.
  const auto level = [](int n) { return 1u + static_cast<std::size_t>(n / 200) + 4u; };
  Scene scene = default_scene(60, 10, 3);
  scene.overlap_areas = true;
  scene.bodies.push_back({.pose = {Vec2(30, 30), 0.4},
                          .shapes = {Ellipse{Vec2(0, 0), 2, 0.5, 0.0}, Rect{Vec2(0, 1), Vec2(0.3, 0.8), 0.2}},
                          .velocity = Vec2(1, 2),
                          .id = 999});
  scene.bodies.push_back(
      {.pose = {Vec2(10, 30), 0.1},
       .shapes = {Capsule{Vec2(0, 0), 1.5, 0.25, 0.0}, ConvexPolygon::regular(5, 0.7, 0.1).at(Vec2(0, 1), 0.3)},
       .id = 1000});
  // A static ledge of two segments, its points binary fractions so that each reads back exactly.
  scene.bodies.push_back(
      {.pose = {Vec2(40, 8), 0.0},
       .shapes = {Segment::between(Vec2(-2, 0), Vec2(0.5, 0.25)), Segment::between(Vec2(0.5, 0.25), Vec2(3, 0))},
       .id = 1001,
       .is_static = true});
  scene.movers.push_back({.shape = Capsule{Vec2(20, 5), 0.25, 0.25, 1.5},
                          .walk = {{0, 3.0}, {120, -2.5}},
                          .jumps = {30, 90},
                          .gravity = 15.0,
                          .options = {.query = {.skin = 0.02}, .step_height = 0.25, .snap_distance = 0.5}});
  scene.movers.push_back({.shape = ConvexPolygon::regular(6, 0.5).at(Vec2(25, 5), 0.1)});
  const Scene back = parse_scene(write_scene(scene));
  EXPECT_TRUE(back == scene);
  ASSERT_EQ(back.movers.size(), 2u);
  EXPECT_EQ(back.movers[0].jumps, (std::vector<int>{30, 90}));
  EXPECT_EQ(back.bodies.size(), 60u + level(60) + 3u);  // and the ship, the lamp and the ledge
  EXPECT_FALSE(back.bodies[60].chain.empty()) << "the level's cave, a chain loop";
  EXPECT_TRUE(back.bodies[60].loop);
  // One bullet per 500 bodies, continuous, and read back so.
  const Scene big = default_scene(1000, 10, 3);
  ASSERT_EQ(big.bodies.size(), 1002u + level(1000));
  EXPECT_TRUE(big.bodies[1000].continuous && big.bodies[1001].continuous && !big.bodies[999].continuous);
  EXPECT_TRUE(parse_scene(write_scene(big)) == big);
  std::size_t statics = 0, sensors = 0;
  for (const SceneBody& b : big.bodies) {
    statics += b.is_static;
    sensors += b.sensor;
  }
  EXPECT_EQ(statics, level(1000));
  EXPECT_EQ(sensors, 4u);
}

// A bullet crossing a wall within one frame (300 per second at 60 Hz: 5 per frame; the wall is 0.2
// thick): the World's overlap test never sees it, its impacts do, once.
TEST(SceneRun, BulletsHitWithinAFrame) {
  const Scene scene = parse_scene(R"({"arena": {"min": [0, 0], "max": [100, 100]}, "frames": 2, "bodies": [
      {"shape": "rect", "center": [50, 50], "half_extents": [0.1, 5]},
      {"shape": "circle", "center": [47.6, 50], "radius": 0.1, "velocity": [300, 0], "continuous": true}]})");
  SceneRun run(scene);
  const RunSummary s = run.run(nullptr);
  EXPECT_EQ(s.continuous, 1u);
  EXPECT_EQ(s.impacts, 1u);
  EXPECT_EQ(s.began, 0u);
  std::ostringstream out;
  print_summary(s, out);
  EXPECT_NE(out.str().find("continuous bodies           1, 1 impacts within frames over the run"), std::string::npos)
      << out.str();
}

// "overlap_areas" turns on the World's overlap areas: two unit circles 1 apart share a lens of
// 2 pi / 3 - sqrt(3) / 2, reported with their contact, and a sensor box whose top edge runs through
// both centres holds half of each, pi in all; the summary gives both, and nothing without the flag.
TEST(SceneRun, OverlapAreasComeWithTheContacts) {
  for (const bool areas : {false, true}) {
    const std::string text = std::string(R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 2, "contacts": true,
        "overlap_areas": )") +
                             (areas ? "true" : "false") + R"(, "bodies": [
        {"shape": "circle", "center": [4.5, 5], "radius": 1}, {"shape": "circle", "center": [5.5, 5], "radius": 1},
        {"shape": "rect", "center": [5, 4], "half_extents": [2, 1], "static": true, "sensor": true}]})";
    const Scene scene = parse_scene(text);
    EXPECT_EQ(scene.overlap_areas, areas);
    EXPECT_TRUE(parse_scene(write_scene(scene)) == scene);
    SceneRun run(scene);
    const RunSummary s = run.run(nullptr);
    ASSERT_EQ(run.world().contacts().size(), 1u);
    const double lens = 2 * std::numbers::pi / 3 - std::sqrt(3.0) / 2;
    EXPECT_NEAR(run.world().contacts()[0].overlap.area, areas ? lens : 0.0, 1e-15) << areas;
    std::ostringstream out;
    print_summary(s, out);
    ASSERT_EQ(s.overlap_area_per_frame.has_value(), areas);
    if (!areas) {
      EXPECT_EQ(out.str().find("overlap area"), std::string::npos) << out.str();
      continue;
    }
    EXPECT_NEAR((*s.overlap_area_per_frame)[0], lens, 1e-15);
    EXPECT_NEAR((*s.overlap_area_per_frame)[1], std::numbers::pi, 1e-15);
    EXPECT_NE(out.str().find("overlap area per frame      1.22837 in contacts, 3.14159 inside sensors\n"),
              std::string::npos)
        << out.str();
  }
}

// Two circles that overlap all run long: on layers that refuse each other, or sharing a negative
// group although their masks accept each other, they never pair, and the summary counts the
// candidate pair the filters dropped; on one layer they pair. The filter fields read back as written.
TEST(SceneRun, FiltersKeepLayersApart) {
  const std::pair<const char*, bool> cases[] = {{R"("category": 1, "mask": 1)", false},
                                                {R"("category": 2, "mask": 2, "group": -3)", false},
                                                {R"("category": 2, "mask": 2)", true}};
  for (const auto& [filters, pair] : cases) {
    const std::string text = std::string(R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 3, "bodies": [
        {"shape": "circle", "center": [5, 5], "radius": 1, "category": 2, "mask": 2, "group": -3},
        {"shape": "circle", "center": [5.5, 5], "radius": 1, )") +
                             filters + "}]}";
    const Scene scene = parse_scene(text);
    EXPECT_TRUE(parse_scene(write_scene(scene)) == scene);
    SceneRun run(scene);
    const RunSummary s = run.run(nullptr);
    EXPECT_EQ(s.overlapping_per_frame, pair ? 1.0 : 0.0) << filters;
    EXPECT_EQ(s.filtered_per_frame, pair ? 0.0 : 1.0) << filters;
    std::ostringstream out;
    print_summary(s, out);
    EXPECT_NE(out.str().find(pair ? "(broad phase), 0 of them" : "(broad phase), 1 of them dropped by filters"),
              std::string::npos)
        << out.str();
  }
}

TEST(Scene, ExampleFileParses) {
  std::ifstream in(std::string(COLLIDE2D_SOURCE_DIR) + "/examples/scene.json");
  std::stringstream text;
  text << in.rdbuf();
  const Scene scene = parse_scene(text.str());
  EXPECT_EQ(scene.bodies.size(), 13u);
  EXPECT_EQ(scene.bodies[11].shapes.size(), 3u);  // a ship: a hull and two wings
  EXPECT_EQ(scene.bodies[6].id, 42u);
  EXPECT_EQ(scene.bodies[5].id, 5u);
  EXPECT_TRUE(scene.bodies[8].is_static && !scene.bodies[8].sensor);
  EXPECT_TRUE(scene.bodies[10].is_static && scene.bodies[10].sensor);
  // A hill of 4 segments, its first and last points ghosts; static without saying so.
  EXPECT_TRUE(scene.bodies[12].is_static);
  EXPECT_EQ(scene.bodies[12].chain.size(), 7u);
  EXPECT_EQ(scene.bodies[12].shapes.size(), 4u);
  EXPECT_FALSE(scene.bodies[12].loop);
}

std::size_t occurrences(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

std::string with_body(const std::string& body) {
  return R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 3, "bodies": [)" + body + "]}";
}

std::string with_mover(const std::string& mover) {
  return R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 3, "bodies": [], "movers": [)" + mover + "]}";
}

TEST(Scene, BrokenFilesNameTheField) {
  const std::pair<std::string, std::string> cases[] = {
      {"{", "scene is not valid JSON"},
      {"[1, 2]", "scene: expected a JSON object"},
      {R"({"arena": {"min": [0, 0], "max": [10, 10]}, "bodies": []})", "frames: missing"},
      {R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 0, "bodies": []})", "frames: expected an integer"},
      {R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 2.5, "bodies": []})", "frames: expected an integer"},
      {R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 3, "dt": "fast", "bodies": []})",
       "dt: expected a number"},
      {R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 3, "dt": -1, "bodies": []})", "dt: must be positive"},
      {R"({"arena": {"min": [0, 0], "max": [-1, 10]}, "frames": 3, "bodies": []})", "arena: max must exceed min"},
      {R"({"arena": {"min": [0, 0]}, "frames": 3, "bodies": []})", "arena.max: missing"},
      {R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 3, "bodies": [], "gravity": 9.8})",
       "scene: unknown field 'gravity'"},
      {R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 3, "proximity_margin": -2, "bodies": []})",
       "proximity_margin: must not be negative"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": -1})"),
       "bodies[0].radius: must be positive (got -1)"},
      {with_body(
           R"({"shape": "circle", "center": [1, 1], "radius": 1}, {"shape": "ellipse", "center": [1, 1], "a": 0, "b": 1})"),
       "bodies[1].a: must be positive"},
      {with_body(R"({"shape": "rect", "center": [1, 1], "half_extents": [1, -3]})"),
       "bodies[0].half_extents[1]: must be positive"},
      {with_body(R"({"shape": "blob", "center": [1, 1]})"), "bodies[0].shape: unknown shape 'blob'"},
      {with_body(R"({"shape": "capsule", "center": [1, 1], "half_length": 0, "radius": 1})"),
       "bodies[0].half_length: must be positive (got 0)"},
      {with_body(R"({"shape": "capsule", "center": [1, 1], "half_length": 1, "radius": 1, "a": 2})"),
       "bodies[0]: a capsule has no field 'a' (its own are half_length, radius and angle)"},
      {with_body(R"({"shape": "polygon", "center": [1, 1], "vertices": [[0, 0], [0, 1], [1, 0]]})"),
       "bodies[0]: polygon vertex 2 lies right of the edge from vertex 0 to 1"},
      {with_body(R"({"shape": "segment", "points": [[0, 0], [1, 0]]})"),
       "bodies[0]: a segment is level geometry: its body must be static (\"static\": true)"},
      {with_body(R"({"shape": "segment", "center": [1, 1], "points": [[0, 0], [1, 0]], "static": true})"),
       "bodies[0].center: a segment has no centre: its two points place it"},
      {with_body(R"({"shape": "segment", "points": [[0, 0]], "static": true})"),
       "bodies[0].points: expected two [x, y] points"},
      {with_body(R"({"shape": "segment", "points": [[2, 1], [2, 1]], "static": true})"),
       "bodies[0]: segment length must be positive (its two points are one) (got 0)"},
      {with_body(R"({"shape": "chain", "points": [[3, 0], [2, 0], [1, 0], [0, 0]], "static": false})"),
       "bodies[0]: a chain is level geometry, always static: remove \"static\": false"},
      {with_body(R"({"shape": "chain", "points": [[3, 0], [2, 0], [1, 0], [0, 0]], "sensor": true})"),
       "bodies[0]: a chain is level geometry, not a sensor"},
      {with_body(R"({"shape": "chain", "points": [[3, 0], [2, 0], [1, 0]], "static": true})"),
       "bodies[0]: an open chain needs at least 4 points, its first and last ghosts only (got 3)"},
      {with_body(R"({"shape": "chain", "points": [[0, 0], [1, 0], [1, 1]], "loop": 1, "static": true})"),
       "bodies[0].loop: expected true or false"},
      {with_body(R"({"shape": "chain", "points": [[0, 0], [1, 0], [1, 1]], "radius": 1, "static": true})"),
       "bodies[0]: a chain has no field 'radius' (its own are points and loop)"},
      {with_body(R"({"center": [0, 0], "shapes": [{"shape": "chain", "points": [[0, 0], [1, 0], [1, 1]]}]})"),
       "bodies[0].shapes[0].shape: a chain is a body of its own, not one shape of a body"},
      {with_body(R"({"shape": "polygon", "center": [1, 1], "vertices": [[0, 0], [1]]})"),
       "bodies[0].vertices[1]: expected an array of 2 numbers"},
      {with_body(R"({"center": [1, 1], "radius": 1})"), "bodies[0].shape: missing"},
      {with_body(R"({"shape": "circle", "center": [1, 1, 1], "radius": 1})"),
       "bodies[0].center: expected an array of 2 numbers"},
      {with_body(R"({"shape": "circle", "center": [1, "x"], "radius": 1})"), "bodies[0].center[1]: expected a number"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radus": 1})"), "bodies[0]: unknown field 'radus'"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "velocity": [1]})"),
       "bodies[0].velocity: expected an array"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "id": -4})"),
       "bodies[0].id: expected a non-negative integer"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "continuous": "yes"})"),
       "bodies[0].continuous: expected true or false, got \"yes\""},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1e999})"), "number overflow parsing '1e999'"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "category": -1})"),
       "bodies[0].category: expected a non-negative integer of 64 bits, got -1"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "mask": "all"})"),
       "bodies[0].mask: expected a non-negative integer of 64 bits, got \"all\""},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "group": 3000000000})"),
       "bodies[0].group: expected an integer from -2147483648 to 2147483647, got 3000000000"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "static": true, "velocity": [1, 0]})"),
       "bodies[0]: a static body does not move: remove its velocity and angular_velocity"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "static": true, "continuous": true})"),
       "bodies[0]: a static body cannot be continuous"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "sensor": 1})"),
       "bodies[0].sensor: expected true or false, got 1"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 3, "a": 3})"),
       "bodies[0]: a circle has no field 'a' (its own are radius)"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 3, "angle": 0.5})"),
       "bodies[0]: a circle has no field 'angle' (its own are radius)"},
      {with_body(R"({"shape": "ellipse", "center": [1, 1], "a": 3, "b": 1, "half_extents": [1, 1]})"),
       "bodies[0]: an ellipse has no field 'half_extents' (its own are a, b and angle)"},
      {with_body(R"({"shape": "rect", "center": [1, 1], "half_extents": [1, 1], "radius": 2})"),
       "bodies[0]: a rect has no field 'radius' (its own are half_extents and angle)"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1e-60})"),
       "bodies[0]: circle radius is outside the supported range 1e-50 to 1e50 (got 1e-60)"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "velocity": [1e300, 0]})"),
       "bodies[0].velocity: a frame's step of 1.6666666666666668e+298 would carry the body beyond the supported "
       "range of +-1e50"},
      {R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 100, "dt": 100, "bodies": [
          {"shape": "rect", "center": [1, 1], "half_extents": [1, 1], "angular_velocity": 1e308}]})",
       "bodies[0].angular_velocity: turns the body to an angle beyond the finite numbers over the run"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "id": 7},
                    {"shape": "circle", "center": [5, 5], "radius": 1, "id": 7})"),
       "bodies[1]: id 7 is also the id of bodies[0] (a body's id defaults to its index)"},
      {with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "id": 1},
                    {"shape": "circle", "center": [5, 5], "radius": 1})"),
       "bodies[1]: id 1 is also the id of bodies[0]"},
      {R"({"arena": {"min": [0, 0], "max": [10, 10], "margin": 1}, "frames": 3, "bodies": []})",
       "arena: unknown field 'margin'"},
      {R"({"arena": {"min": [0, 0], "max": [1e51, 10]}, "frames": 3, "bodies": []})",
       "arena: beyond the supported range of +-1e50"},
      {with_body(R"({"center": [1, 1], "shapes": []})"), "bodies[0].shapes: expected an array of one or more shapes"},
      {with_body(R"({"shapes": [{"shape": "circle", "center": [0, 0], "radius": 1}]})"), "bodies[0].center: missing"},
      {with_body(R"({"center": [1, 1], "radius": 1, "shapes": [{"shape": "circle", "center": [0, 0], "radius": 1}]})"),
       "bodies[0]: unknown field 'radius'"},
      {with_body(R"({"center": [1, 1], "shapes": [{"shape": "circle", "center": [0, 0], "radius": 1, "id": 3}]})"),
       "bodies[0].shapes[0]: unknown field 'id'"},
      {with_body(R"({"center": [1, 1], "shapes": [{"shape": "rect", "center": [0, 0], "half_extents": [1, -1]}]})"),
       "bodies[0].shapes[0].half_extents[1]: must be positive (got -1)"},
      {with_body(R"({"center": [1, 1], "shapes": [3]})"), "bodies[0].shapes[0]: expected an object"},
      {with_mover(R"({"shape": "circle", "center": [1, 1], "radius": 0.5, "speed": 3})"),
       "movers[0]: unknown field 'speed'"},
      {with_mover(R"({"shape": "circle", "center": [1, 1], "radius": 0.5, "walk": [[10, 1], [5, 2]]})"),
       "movers[0].walk[1][0]: expected a frame after 10 (the frames ascend), got 5"},
      {with_mover(R"({"shape": "circle", "center": [1, 1], "radius": 0.5, "walk": [[0, "fast"]]})"),
       "movers[0].walk[0][1]: expected a number"},
      {with_mover(R"({"shape": "circle", "center": [1, 1], "radius": 0.5, "walk": [3]})"),
       "movers[0].walk[0]: expected [frame, speed], got 3"},
      {with_mover(R"({"shape": "circle", "center": [1, 1], "radius": 0.5, "jumps": [-1]})"),
       "movers[0].jumps[0]: expected a frame after -1"},
      {with_mover(R"({"shape": "circle", "center": [1, 1], "radius": 0.5, "skin": -0.1})"),
       "movers[0].skin: must not be negative (got -0.1)"},
      {with_mover(R"({"shape": "circle", "center": [1, 1], "radius": 0.5, "max_slope": 2})"),
       "movers[0].max_slope: expected an angle from 0 to pi/2 radians, got 2"},
      {with_mover(R"({"shape": "segment", "points": [[0, 0], [1, 0]]})"),
       "movers[0].shape: a segment is level geometry, not a mover"},
      {with_mover(R"({"shape": "circle", "center": [1, 1], "radius": 0.5, "gravity": 1e300})"),
       "movers[0]: its walk, jumps and fall over the run could carry it beyond the supported range of +-1e50"},
      {R"({"arena": {"min": [0, 0], "max": [10, 10]}, "frames": 3, "bodies": [], "movers": 3})",
       "movers: expected an array, got 3"},
  };
  for (const auto& [text, expected] : cases) {
    try {
      parse_scene(text);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what() << "\n  for " << text;
    }
  }
}

// A circle standing on a floor walks at 3 per second and jumps at frame 60: it keeps the commanded
// pace, rises the jump's height (6 per second against 20 per second squared: 0.9), lands, and ends
// on the floor the skin above it; the summary counts it.
TEST(SceneRun, MoversWalkAndJumpAsScripted) {
  const Scene scene = parse_scene(R"({"arena": {"min": [0, -2], "max": [40, 10]}, "frames": 120,
    "bodies": [{"shape": "rect", "center": [20, -1], "half_extents": [20, 1], "static": true}],
    "movers": [{"shape": "circle", "center": [2, 0.51], "radius": 0.5, "walk": [[0, 3]], "jumps": [60]}]})");
  SceneRun run(scene, 1);
  double highest = 0.0;
  for (int f = 0; f < scene.frames; ++f) {
    run.frame();
    highest = std::max(highest, center_of(run.movers()[0].shape).y());
  }
  const MoverRecord& m = run.movers()[0];
  EXPECT_NEAR(center_of(m.shape).x(), 2 + 3.0 * scene.frames * scene.dt, 1e-9);
  EXPECT_NEAR(highest - 0.51, 0.9, 0.06);  // a frame's step of the rise
  EXPECT_TRUE(m.ground.on_ground);
  ASSERT_EQ(m.planes.size(), 1u);
  EXPECT_NEAR(m.planes[0].separation, 0.01, 1e-9);
  EXPECT_EQ(scene_totals(scene).movers, 1u);
}

// A scene changed in code after parsing is checked again before its first frame.
TEST(SceneRun, RefusesAMotionBeyondTheRangeBeforeTheFirstFrame) {
  Scene scene = parse_scene(with_body(R"({"shape": "circle", "center": [1, 1], "radius": 1, "velocity": [1, 0]})"));
  scene.bodies[0].velocity = Vec2(0, 1e300);
  try {
    SceneRun run(scene);
    ADD_FAILURE() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(),
                 "bodies[0].velocity: a frame's step of 1.6666666666666668e+298 would carry the body beyond the "
                 "supported range of +-1e50");
  }
}

// After the run, the World's overlapping and sensor pairs are exactly those of the final shapes
// under the World's rules (the built-in scene's two layers never pair; its static level never pairs
// with itself), the summary lists each sensor's contents, and the picture draws every body, static
// bodies and sensors in their own styles.
TEST(SceneRun, LastFrameAgreesWithAllPairs) {
  SceneRun run(default_scene(300, 30, 5));
  const RunSummary s = run.run(nullptr);
  EXPECT_EQ(s.frames, 30);
  EXPECT_EQ(s.bodies, 306u);
  EXPECT_EQ(s.statics, 6u);
  const World& w = run.world();
  const reference::AllPairs expected = reference::all_pairs(w, 0.0);
  EXPECT_EQ(w.overlapping(), expected.overlapping);
  EXPECT_EQ(w.sensing(), expected.sensing);
  EXPECT_GT(s.overlapping_per_frame, 0.0);
  EXPECT_GT(s.filtered_per_frame, 0.0);
  EXPECT_GT(s.sensor_began, 0u);
  ASSERT_EQ(s.sensor_contents.size(), 4u);
  std::size_t listed = 0;
  for (const RunSummary::Sensor& sensor : s.sensor_contents) listed += sensor.visitors.size();
  EXPECT_EQ(listed, expected.sensing.size());
  std::ostringstream summary;
  print_summary(s, summary);
  EXPECT_NE(summary.str().find("sensor " + std::to_string(s.sensor_contents[0].id) + " at the last frame: "),
            std::string::npos);
  std::ostringstream svg;
  write_svg(run, svg);
  const std::string text = svg.str();
  std::size_t shapes = 0;
  for (const char* css : {"class=\"body", "class=\"static", "class=\"sensor"}) shapes += occurrences(text, css);
  std::size_t in_world = 0;
  for (const BodyId id : w.bodies()) in_world += w.shapes(id).size();
  EXPECT_EQ(shapes, in_world);  // each body's shape, and each segment of the cave
  EXPECT_GT(in_world, 306u);
  EXPECT_GT(occurrences(text, "class=\"sensor"), 0u);
  EXPECT_GT(occurrences(text, "class=\"static"), 0u);
  EXPECT_NE(text.find("</svg>"), std::string::npos);
}

// The summary names the threads asked for (every hardware thread when none is named), and each
// phase's slowest frame is the frame of its largest time: the percentiles lie between the frames'
// fastest and that one.
TEST(SceneRun, SummaryNamesThreadsAndSlowestFrames) {
  EXPECT_EQ(SceneRun(default_scene(20, 1, 3), 3).run(nullptr).threads, 3u);
  EXPECT_EQ(SceneRun(default_scene(20, 1, 3), 0).run(nullptr).threads,
            std::max(1u, std::thread::hardware_concurrency()));
  SceneRun run(default_scene(200, 12, 3), 1);
  const RunSummary s = run.run(nullptr);
  EXPECT_EQ(s.threads, 1u);
  for (const PhaseTimes& t : {s.broad, s.narrow}) {
    ASSERT_GE(t.slowest_frame, 0);
    ASSERT_LT(t.slowest_frame, 12);
    EXPECT_LE(t.median_ms, t.p95_ms);
    EXPECT_LE(t.p95_ms, t.slowest_ms);
    EXPECT_GT(t.slowest_ms, 0.0);
  }
  std::ostringstream summary;
  print_summary(s, summary);
  EXPECT_NE(summary.str().find("\nthreads                     1\n"), std::string::npos) << summary.str();
  EXPECT_NE(summary.str().find(" ms (frame " + std::to_string(s.narrow.slowest_frame) + ")\n"), std::string::npos);
}

// What the caption counts can be seen at 1000 pixels: each proximity pair is ringed 3 pixels
// across its middle (the built-in scene's segments are about a pixel long), each continuous body
// 6 pixels around; the two layers are filled differently and named in the legend; rotations stay
// within (-180, 180] after bodies have turned for many frames.
TEST(SceneRun, PictureShowsWhatTheCaptionCounts) {
  SceneRun run(default_scene(1000, 200, 7));
  run.run(nullptr);
  std::ostringstream svg;
  write_svg(run, svg);
  const std::string text = svg.str();
  const World& world = run.world();
  const double pixel = run.scene().arena.max.x() / 1000;
  ASSERT_GT(world.proximity().size(), 10u);
  EXPECT_EQ(occurrences(text, "<line class=\"near\""), world.proximity().size());
  EXPECT_EQ(occurrences(text, "<circle class=\"near\""), world.proximity().size());
  EXPECT_EQ(occurrences(text, "<circle class=\"bullet\""), 2u);
  const std::size_t ring = text.find("<circle class=\"near\"");
  const std::size_t r = text.find(" r=\"", ring) + 4;
  EXPECT_NEAR(std::stod(text.substr(r)), 3 * pixel, 1e-5 * pixel);  // 6 digits
  EXPECT_GT(occurrences(text, "class=\"body layer0"), 500u);
  EXPECT_GT(occurrences(text, "class=\"body layer1"), 200u);
  EXPECT_NE(text.find("moving bodies by filter category: 1 blue, 2 violet, 2 continuous (magenta rings)"),
            std::string::npos);
  // A static body that a moving one touches keeps its slate fill and is outlined in red, which the
  // caption says, so that it is not taken for an overlapping moving body (filled red).
  std::size_t touched = 0;
  for (const BodyId id : world.bodies()) {
    const bool hit = std::any_of(world.overlapping().begin(), world.overlapping().end(),
                                 [id](const ShapePair& p) { return p.a == id || p.b == id; });
    if (world.is_static(id) && !world.is_sensor(id) && hit) touched += world.shapes(id).size();
  }
  EXPECT_GT(touched, 0u);
  EXPECT_EQ(occurrences(text, "class=\"static hit\""), touched);
  EXPECT_NE(text.find(".static.hit{stroke:#e74c3c;"), std::string::npos);
  EXPECT_NE(text.find("static, slate, outlined red where touched"), std::string::npos);
  EXPECT_EQ(text.find(".static.hit{fill"), std::string::npos);
  std::size_t rotations = 0;
  for (std::size_t at = text.find("rotate("); at != std::string::npos; at = text.find("rotate(", at + 1)) {
    const double degrees = std::stod(text.substr(at + 7));
    EXPECT_GT(degrees, -180.0);
    EXPECT_LE(degrees, 180.0);
    ++rotations;
  }
  EXPECT_GT(rotations, 600u);
}

// Both caption lines fit the picture's width at 0.6 em a character, for a wide, a square and a tall
// arena.
TEST(Run, SvgCaptionFitsTheWidth) {
  for (const Vec2& extent : {Vec2(40, 10), Vec2(30, 30), Vec2(10, 40)}) {
    Scene scene = parse_scene(R"({"arena": {"min": [0, 0], "max": [1, 1]}, "frames": 1, "bodies": []})");
    scene.arena = Aabb{Vec2(0, 0), extent};
    for (int k = 0; k < 20; ++k) {
      const Shape ball = Circle{Vec2(1 + k, 1 + k) / 2, 0.5};
      scene.bodies.push_back({.pose = pose_of(ball), .shapes = at_origin(ball), .id = static_cast<std::uint64_t>(k)});
    }
    SceneRun run(scene);
    run.run(nullptr);
    std::ostringstream svg;
    write_svg(run, svg);
    const std::string text = svg.str();
    ASSERT_EQ(occurrences(text, "<text "), 2u);
    for (std::size_t open = text.find("<text "); open != std::string::npos; open = text.find("<text ", open + 1)) {
      const std::size_t start = text.find('>', open) + 1, end = text.find("</text>", open);
      const auto attribute = [&](const char* name) {
        const std::size_t at = text.find(name, open) + std::strlen(name);
        return std::stod(text.substr(at, text.find('"', at) - at));
      };
      const double x = attribute(" x=\""), font = attribute("font-size=\"");
      EXPECT_LE(x + 0.6 * font * static_cast<double>(end - start), extent.x()) << extent.transpose();
      EXPECT_GE(font * 1000 / extent.x(), 12.0) << "at least 12 pixels in the 1000-pixel-wide picture";
    }
  }
}

}  // namespace
}  // namespace collide2d::tool
