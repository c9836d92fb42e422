#include "tools/scene/scene.h"
#include "tools/random.h"

#include "shapes/kinds.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <sstream>

namespace collide2d::tool {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& field, const std::string& what) { throw SceneError(field + ": " + what); }

std::string child(const std::string& field, const char* key) { return field.empty() ? key : field + "." + key; }

const json& member(const json& object, const char* key, const std::string& field) {
  const auto it = object.find(key);
  if (it == object.end()) fail(child(field, key), "missing");
  return *it;
}

double number(const json& value, const std::string& field) {
  if (!value.is_number()) fail(field, "expected a number, got " + value.dump());
  const double x = value.get<double>();
  if (!std::isfinite(x)) fail(field, "must be finite");
  return x;
}

double optional_number(const json& object, const char* key, const std::string& field, double fallback) {
  const auto it = object.find(key);
  return it == object.end() ? fallback : number(*it, child(field, key));
}

Vec2 vec2(const json& value, const std::string& field) {
  if (!value.is_array() || value.size() != 2) fail(field, "expected an array of 2 numbers, got " + value.dump());
  return {number(value[0], field + "[0]"), number(value[1], field + "[1]")};
}

void require_positive(double x, const std::string& field) {
  if (!(x > 0)) {
    std::ostringstream msg;
    msg << "must be positive (got " << x << ')';
    fail(field, msg.str());
  }
}

void reject_unknown_keys(const json& object, std::initializer_list<const char*> known, const std::string& field) {
  for (const auto& [key, value] : object.items()) {
    bool ok = false;
    for (const char* k : known) ok = ok || key == k;
    if (!ok) fail(field, "unknown field '" + key + "'");
  }
}

// The fields of a body of one shape, besides its shape's own; of a body of several; and of each of
// its shapes, besides the shape's own.
constexpr std::initializer_list<const char*> kBodyFields = {"shape", "center",     "velocity", "angular_velocity",
                                                            "id",    "continuous", "category", "mask",
                                                            "group", "static",     "sensor"};
constexpr std::initializer_list<const char*> kCompoundFields = {
    "shapes",     "center",   "angle", "velocity", "angular_velocity", "id",
    "continuous", "category", "mask",  "group",    "static",           "sensor"};
constexpr std::initializer_list<const char*> kPartFields = {"shape", "center"};
constexpr std::initializer_list<const char*> kMoverFields = {
    "shape", "center", "walk", "jumps", "gravity", "jump_speed", "skin", "max_slope", "step_height", "snap_distance"};

// Each kind's own fields (its entry in shapes/kinds.h), and a chain body's.
struct ShapeFields {
  std::string_view kind;
  std::vector<std::string_view> fields;
};
const std::vector<ShapeFields>& shape_fields() {
  static const std::vector<ShapeFields> all = [] {
    std::vector<ShapeFields> out;
    detail::Kinds::each([&]<class T>() {
      const auto& own = detail::Kind<T>::fields;
      out.push_back({detail::Kind<T>::word, {own.begin(), own.end()}});
    });
    out.push_back({"chain", {"points", "loop"}});
    return out;
  }();
  return all;
}

bool listed(const std::vector<std::string_view>& names, const std::string& key) {
  return std::any_of(names.begin(), names.end(), [&key](std::string_view name) { return key == name; });
}
bool listed(std::initializer_list<const char*> names, const std::string& key) {
  return std::any_of(names.begin(), names.end(), [&key](const char* name) { return key == name; });
}

// "a, b and angle".
std::string spelled(const std::vector<std::string_view>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    out += k == 0 ? "" : k + 1 == names.size() ? " and " : ", ";
    out += names[k];
  }
  return out;
}

// Each field is one of its shape's or one of `others` (a body's, or a placed shape's): a circle's
// "a" is refused by name.
void reject_unknown_fields(const json& b, const std::string& kind, const std::string& field,
                           std::initializer_list<const char*> others) {
  const ShapeFields* own = nullptr;
  for (const ShapeFields& s : shape_fields()) own = kind == s.kind ? &s : own;
  for (const auto& item : b.items()) {
    const std::string& key = item.key();
    if (listed(others, key) || (own != nullptr && listed(own->fields, key))) continue;
    const bool elsewhere = std::any_of(shape_fields().begin(), shape_fields().end(),
                                       [&key](const ShapeFields& s) { return listed(s.fields, key); });
    if (own != nullptr && elsewhere) {
      const char* article = std::string_view("aeiou").find(kind[0]) == std::string_view::npos ? "a " : "an ";
      fail(field, article + kind + " has no field '" + key + "' (its own are " + spelled(own->fields) + ")");
    }
    fail(field, "unknown field '" + key + "'");
  }
}

// A polygon's vertices, counter-clockwise about its centre, as given (ConvexPolygon::of checks them).
Shape parse_polygon(const json& b, const std::string& field, const Vec2& center, double angle) {
  const json& list = member(b, "vertices", field);
  if (!list.is_array()) fail(field + ".vertices", "expected an array of [x, y] points, got " + list.dump());
  std::vector<Vec2> vertices;
  for (std::size_t k = 0; k < list.size(); ++k)
    vertices.push_back(vec2(list[k], field + ".vertices[" + std::to_string(k) + "]"));
  try {
    return ConvexPolygon::of(vertices, optional_number(b, "radius", field, 0.0)).at(center, angle);
  } catch (const InvalidShape& e) {
    fail(field, e.what());
  }
}

// A segment's two points (in its body's frame, for a shape of several): it has no centre or angle of
// its own, its first point being its frame's origin.
Shape parse_segment(const json& b, const std::string& field) {
  if (b.contains("center")) fail(field + ".center", "a segment has no centre: its two points place it");
  const json& points = member(b, "points", field);
  if (!points.is_array() || points.size() != 2)
    fail(field + ".points", "expected two [x, y] points, got " + points.dump());
  return Segment::between(vec2(points[0], field + ".points[0]"), vec2(points[1], field + ".points[1]"));
}

Shape parse_shape(const json& b, const std::string& field, std::initializer_list<const char*> others) {
  if (!b.is_object()) fail(field, "expected an object");
  const json& word = member(b, "shape", field);
  if (!word.is_string()) fail(field + ".shape", "expected a string, got " + word.dump());
  const std::string kind = word.get<std::string>();
  reject_unknown_fields(b, kind, field, others);
  if (kind == "segment") return parse_segment(b, field);
  if (kind == "chain") fail(field + ".shape", "a chain is a body of its own, not one shape of a body");
  const Vec2 center = vec2(member(b, "center", field), field + ".center");
  const double angle = optional_number(b, "angle", field, 0.0);
  if (kind == "circle") {
    const double r = number(member(b, "radius", field), field + ".radius");
    require_positive(r, field + ".radius");
    return Circle{center, r};
  }
  if (kind == "ellipse") {
    const double a = number(member(b, "a", field), field + ".a");
    const double bb = number(member(b, "b", field), field + ".b");
    require_positive(a, field + ".a");
    require_positive(bb, field + ".b");
    return Ellipse{center, a, bb, angle};
  }
  if (kind == "rect") {
    const Vec2 half = vec2(member(b, "half_extents", field), field + ".half_extents");
    require_positive(half.x(), field + ".half_extents[0]");
    require_positive(half.y(), field + ".half_extents[1]");
    return Rect{center, half, angle};
  }
  if (kind == "capsule") {
    const double h = number(member(b, "half_length", field), field + ".half_length");
    const double r = number(member(b, "radius", field), field + ".radius");
    require_positive(h, field + ".half_length");
    require_positive(r, field + ".radius");
    return Capsule{center, h, r, angle};
  }
  if (kind == "polygon") return parse_polygon(b, field, center, angle);
  fail(field + ".shape", "unknown shape '" + kind + "' (expected " + detail::Kinds::words("chain") + ")");
}

// A shape the library takes: the ranges it supports.
Shape valid_shape(const Shape& shape, const std::string& field) {
  try {
    validate(shape);
  } catch (const InvalidShape& e) {
    fail(field, e.what());
  }
  return shape;
}

// A body of several shapes: its pose, and its shapes placed in its frame.
void parse_shapes(const json& b, const std::string& field, SceneBody& body) {
  reject_unknown_keys(b, kCompoundFields, field);
  body.pose.position = vec2(member(b, "center", field), field + ".center");
  body.pose.angle = optional_number(b, "angle", field, 0.0);
  if (body.pose.position.cwiseAbs().maxCoeff() > kMaxMagnitude)
    fail(field + ".center", "beyond the supported range of +-1e50");
  const json& shapes = member(b, "shapes", field);
  if (!shapes.is_array() || shapes.empty()) fail(field + ".shapes", "expected an array of one or more shapes");
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const std::string part = field + ".shapes[" + std::to_string(k) + "]";
    body.shapes.push_back(valid_shape(parse_shape(shapes[k], part, kPartFields), part));
  }
}

std::uint64_t bits(const json& object, const char* key, const std::string& field, std::uint64_t fallback) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number_unsigned())
    fail(child(field, key), "expected a non-negative integer of 64 bits, got " + it->dump());
  return it->get<std::uint64_t>();
}

bool flag(const json& object, const char* key, const std::string& field) {
  const auto it = object.find(key);
  if (it == object.end()) return false;
  if (!it->is_boolean()) fail(child(field, key), "expected true or false, got " + it->dump());
  return it->get<bool>();
}

std::string body_field(std::size_t index) { return "bodies[" + std::to_string(index) + "]"; }

// A chain's segments as a body's shapes, at the origin; throws InvalidShape as chain_segments().
std::vector<Shape> chain_shapes(std::span<const Vec2> points, bool loop) {
  std::vector<Shape> out;
  for (const ChainSegment& s : chain_segments(points, loop)) out.emplace_back(s.segment);
  return out;
}

// A chain's points and "loop", checked as World::add_chain checks them; its segments are the body's
// shapes, at the origin.
void parse_chain(const json& b, const std::string& field, SceneBody& body) {
  reject_unknown_fields(b, "chain", field, kBodyFields);
  if (b.contains("center")) fail(field + ".center", "a chain has no centre: its points place it");
  const json& points = member(b, "points", field);
  if (!points.is_array()) fail(field + ".points", "expected an array of [x, y] points, got " + points.dump());
  for (std::size_t k = 0; k < points.size(); ++k)
    body.chain.push_back(vec2(points[k], field + ".points[" + std::to_string(k) + "]"));
  body.loop = flag(b, "loop", field);
  try {
    body.shapes = chain_shapes(body.chain, body.loop);
  } catch (const InvalidShape& e) {
    fail(field, e.what());
  }
}

bool is_chain(const json& b) {
  const auto it = b.find("shape");
  return it != b.end() && it->is_string() && it->get<std::string>() == "chain";
}

SceneBody parse_body(const json& b, std::size_t index) {
  const std::string field = body_field(index);
  if (!b.is_object()) fail(field, "expected an object");
  SceneBody body;
  if (b.contains("shapes")) {
    parse_shapes(b, field, body);
  } else if (is_chain(b)) {
    parse_chain(b, field, body);
  } else {
    const Shape shape = valid_shape(parse_shape(b, field, kBodyFields), field);
    body.pose = pose_of(shape);
    body.shapes = at_origin(shape);
  }
  if (const auto it = b.find("velocity"); it != b.end()) body.velocity = vec2(*it, field + ".velocity");
  body.angular_velocity = optional_number(b, "angular_velocity", field, 0.0);
  body.id = index;
  if (const auto it = b.find("id"); it != b.end()) {
    if (!it->is_number_unsigned()) fail(field + ".id", "expected a non-negative integer, got " + it->dump());
    body.id = it->get<std::uint64_t>();
  }
  body.continuous = flag(b, "continuous", field);
  // A chain is level geometry: static unless it says otherwise, which is refused below.
  body.is_static = b.contains("static") ? flag(b, "static", field) : !body.chain.empty();
  body.sensor = flag(b, "sensor", field);
  if (!body.chain.empty() && body.sensor) fail(field, "a chain is level geometry, not a sensor");
  if (body.is_static && (body.velocity != Vec2::Zero() || body.angular_velocity != 0.0)) {
    fail(field, "a static body does not move: remove its velocity and angular_velocity");
  }
  if (body.is_static && body.continuous) fail(field, "a static body cannot be continuous");
  if (!body.is_static && std::any_of(body.shapes.begin(), body.shapes.end(), detail::is_level_geometry)) {
    fail(field, body.chain.empty() ? "a segment is level geometry: its body must be static (\"static\": true)"
                                   : "a chain is level geometry, always static: remove \"static\": false");
  }
  body.filter.category = bits(b, "category", field, body.filter.category);
  body.filter.mask = bits(b, "mask", field, body.filter.mask);
  if (const auto it = b.find("group"); it != b.end()) {
    if (!it->is_number_integer() || it->get<long long>() < INT32_MIN || it->get<long long>() > INT32_MAX) {
      fail(field + ".group", "expected an integer from -2147483648 to 2147483647, got " + it->dump());
    }
    body.filter.group = static_cast<std::int32_t>(it->get<long long>());
  }
  return body;
}

std::string mover_field(std::size_t index) { return "movers[" + std::to_string(index) + "]"; }

void require_not_negative(double x, const std::string& field) {
  if (!(x >= 0)) fail(field, "must not be negative (got " + json(x).dump() + ")");
}

// A frame number of a mover's script, after `after`.
int script_frame(const json& value, const std::string& field, long long after) {
  if (!value.is_number_integer() || value.get<long long>() <= after || value.get<long long>() > 100000000)
    fail(field, "expected a frame after " + std::to_string(after) + " (the frames ascend), got " + value.dump());
  return static_cast<int>(value.get<long long>());
}

// The script's frames as they come; the list itself may be absent.
const json& script_list(const json& m, const char* key, const std::string& field) {
  static const json none = json::array();
  const auto it = m.find(key);
  if (it == m.end()) return none;
  if (!it->is_array()) fail(child(field, key), "expected an array, got " + it->dump());
  return *it;
}

SceneMover parse_mover(const json& m, std::size_t index) {
  const std::string field = mover_field(index);
  SceneMover mover{valid_shape(parse_shape(m, field, kMoverFields), field)};
  if (detail::is_level_geometry(mover.shape)) fail(field + ".shape", "a segment is level geometry, not a mover");
  const json& walk = script_list(m, "walk", field);
  for (std::size_t k = 0; k < walk.size(); ++k) {
    const std::string entry = field + ".walk[" + std::to_string(k) + "]";
    if (!walk[k].is_array() || walk[k].size() != 2) fail(entry, "expected [frame, speed], got " + walk[k].dump());
    const long long after = mover.walk.empty() ? -1 : mover.walk.back().first;
    mover.walk.emplace_back(script_frame(walk[k][0], entry + "[0]", after), number(walk[k][1], entry + "[1]"));
  }
  const json& jumps = script_list(m, "jumps", field);
  for (std::size_t k = 0; k < jumps.size(); ++k)
    mover.jumps.push_back(script_frame(jumps[k], field + ".jumps[" + std::to_string(k) + "]",
                                       mover.jumps.empty() ? -1 : mover.jumps.back()));
  mover.gravity = optional_number(m, "gravity", field, mover.gravity);
  mover.jump_speed = optional_number(m, "jump_speed", field, mover.jump_speed);
  MoverOptions& o = mover.options;
  o.query.skin = optional_number(m, "skin", field, o.query.skin);
  o.max_slope = optional_number(m, "max_slope", field, o.max_slope);
  o.step_height = optional_number(m, "step_height", field, o.step_height);
  o.snap_distance = optional_number(m, "snap_distance", field, o.snap_distance);
  for (const auto& [key, x] : {std::pair{"gravity", mover.gravity},
                               {"jump_speed", mover.jump_speed},
                               {"skin", o.query.skin},
                               {"step_height", o.step_height},
                               {"snap_distance", o.snap_distance}})
    require_not_negative(x, field + "." + key);
  if (!(o.max_slope >= 0 && o.max_slope <= std::numbers::pi / 2))
    fail(field + ".max_slope", "expected an angle from 0 to pi/2 radians, got " + json(o.max_slope).dump());
  return mover;
}

json shape_json(const Shape& s) {
  return std::visit(
      [](const auto& x) -> json {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, Segment>) {  // no centre of its own: its two points
          const Vec2 to = x.point2();
          return {{"shape", "segment"}, {"points", {{x.center.x(), x.center.y()}, {to.x(), to.y()}}}};
        }
        json j{{"center", {x.center.x(), x.center.y()}}};
        if constexpr (std::is_same_v<T, Circle>) {
          j["shape"] = "circle";
          j["radius"] = x.radius;
        } else if constexpr (std::is_same_v<T, Ellipse>) {
          j["shape"] = "ellipse";
          j["a"] = x.a;
          j["b"] = x.b;
          j["angle"] = x.angle;
        } else if constexpr (std::is_same_v<T, Rect>) {
          j["shape"] = "rect";
          j["half_extents"] = {x.half_extents.x(), x.half_extents.y()};
          j["angle"] = x.angle;
        } else if constexpr (std::is_same_v<T, Capsule>) {
          j["shape"] = "capsule";
          j["half_length"] = x.half_length;
          j["radius"] = x.radius;
          j["angle"] = x.angle;
        } else if constexpr (std::is_same_v<T, ConvexPolygon>) {
          j["shape"] = "polygon";
          j["vertices"] = json::array();
          for (const Vec2& v : x.vertices()) j["vertices"].push_back({v.x(), v.y()});
          j["radius"] = x.radius();
          j["angle"] = x.angle;
        }
        return j;
      },
      s);
}

bool same_shape(const Shape& a, const Shape& b) {
  if (a.index() != b.index()) return false;
  return std::visit(
      [&b](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        const T& y = std::get<T>(b);
        if constexpr (std::is_same_v<T, Circle>) return x.center == y.center && x.radius == y.radius;
        if constexpr (std::is_same_v<T, Ellipse>)
          return x.center == y.center && x.a == y.a && x.b == y.b && x.angle == y.angle;
        if constexpr (std::is_same_v<T, Rect>)
          return x.center == y.center && x.half_extents == y.half_extents && x.angle == y.angle;
        if constexpr (std::is_same_v<T, Capsule>) {
          return x.center == y.center && x.half_length == y.half_length && x.radius == y.radius && x.angle == y.angle;
        }
        if constexpr (std::is_same_v<T, ConvexPolygon>) {
          return x.center == y.center && x.angle == y.angle && x.radius() == y.radius() &&
                 std::equal(x.vertices().begin(), x.vertices().end(), y.vertices().begin(), y.vertices().end());
        }
        if constexpr (std::is_same_v<T, Segment>) return x.center == y.center && x.end == y.end && x.angle == y.angle;
      },
      a);
}

}  // namespace

std::vector<Shape> at_origin(const Shape& shape) {
  return {std::visit(
      [](auto s) -> Shape {
        s.center = Vec2::Zero();
        if constexpr (!std::is_same_v<decltype(s), Circle>) s.angle = 0.0;
        return s;
      },
      shape)};
}

std::vector<Shape> placed_shapes(const SceneBody& body) {
  std::vector<Shape> out;
  const Orientation turn = Orientation::of(body.pose.angle);
  for (const Shape& s : body.shapes) out.push_back(placed(s, body.pose, turn));
  return out;
}

Shape placed_first(const SceneBody& body) {
  return placed(body.shapes.front(), body.pose, Orientation::of(body.pose.angle));
}

// Without a list of the placed shapes, and with one sine and cosine for the shapes with no angle of
// their own: step() takes every body's box every frame.
Aabb box_of(const SceneBody& body) {
  const Orientation turn = Orientation::of(body.pose.angle);
  const auto box = [&](const Shape& local) {
    const Shape s = placed(local, body.pose, turn);
    if (std::holds_alternative<Circle>(s)) return aabb(s, Orientation{});
    return aabb(s, angle_of(local) == 0.0 ? turn : Orientation::of(angle_of(s)));
  };
  Aabb all = box(body.shapes.front());
  for (const Shape& s : body.shapes) {
    const Aabb b = box(s);
    all = {all.min.cwiseMin(b.min), all.max.cwiseMax(b.max)};
  }
  return all;
}

bool SceneBody::operator==(const SceneBody& o) const {
  return pose.position == o.pose.position && pose.angle == o.pose.angle &&
         std::equal(shapes.begin(), shapes.end(), o.shapes.begin(), o.shapes.end(), same_shape) &&
         velocity == o.velocity && angular_velocity == o.angular_velocity && id == o.id && continuous == o.continuous &&
         filter == o.filter && is_static == o.is_static && sensor == o.sensor && chain == o.chain && loop == o.loop;
}

bool SceneMover::operator==(const SceneMover& o) const {
  const MoverOptions& a = options;
  const MoverOptions& b = o.options;
  return same_shape(shape, o.shape) && walk == o.walk && jumps == o.jumps && gravity == o.gravity &&
         jump_speed == o.jump_speed && a.query.skin == b.query.skin && a.max_slope == b.max_slope &&
         a.step_height == b.step_height && a.snap_distance == b.snap_distance;
}

bool Scene::operator==(const Scene& o) const {
  return arena.min == o.arena.min && arena.max == o.arena.max && frames == o.frames && dt == o.dt &&
         fat_margin == o.fat_margin && proximity_margin == o.proximity_margin && contacts == o.contacts &&
         overlap_areas == o.overlap_areas && bodies == o.bodies && movers == o.movers;
}

Scene parse_scene(std::string_view text) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::exception& e) {  // syntax errors, and numbers beyond double range
    throw SceneError(std::string("scene is not valid JSON: ") + e.what());
  }
  if (!root.is_object()) fail("scene", "expected a JSON object");
  reject_unknown_keys(
      root,
      {"arena", "frames", "dt", "fat_margin", "proximity_margin", "contacts", "overlap_areas", "bodies", "movers"},
      "scene");
  Scene scene;
  const json& arena = member(root, "arena", "");
  if (!arena.is_object()) fail("arena", "expected an object with min and max");
  reject_unknown_keys(arena, {"min", "max"}, "arena");
  scene.arena = {vec2(member(arena, "min", "arena"), "arena.min"), vec2(member(arena, "max", "arena"), "arena.max")};
  for (int k = 0; k < 2; ++k) {
    if (std::abs(scene.arena.min[k]) > kMaxMagnitude || std::abs(scene.arena.max[k]) > kMaxMagnitude)
      fail("arena", "beyond the supported range of +-1e50");
  }
  if (!(scene.arena.min.array() < scene.arena.max.array()).all()) fail("arena", "max must exceed min on both axes");
  const json& frames = member(root, "frames", "");
  if (!frames.is_number_integer() || frames.get<long long>() < 1 || frames.get<long long>() > 100000000) {
    fail("frames", "expected an integer from 1 to 100000000, got " + frames.dump());
  }
  scene.frames = static_cast<int>(frames.get<long long>());
  scene.dt = optional_number(root, "dt", "", scene.dt);
  require_positive(scene.dt, "dt");
  scene.fat_margin = optional_number(root, "fat_margin", "", scene.fat_margin);
  scene.proximity_margin = optional_number(root, "proximity_margin", "", scene.proximity_margin);
  if (scene.fat_margin < 0) fail("fat_margin", "must not be negative");
  if (scene.proximity_margin < 0) fail("proximity_margin", "must not be negative");
  scene.contacts = flag(root, "contacts", "");
  scene.overlap_areas = flag(root, "overlap_areas", "");
  const json& bodies = member(root, "bodies", "");
  if (!bodies.is_array()) fail("bodies", "expected an array");
  std::map<std::uint64_t, std::size_t> owners;
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    scene.bodies.push_back(parse_body(bodies[k], k));
    const auto [at, fresh] = owners.emplace(scene.bodies.back().id, k);
    if (!fresh) {
      fail(body_field(k), "id " + std::to_string(at->first) + " is also the id of " + body_field(at->second) +
                              " (a body's id defaults to its index)");
    }
  }
  const json& movers = script_list(root, "movers", "");
  for (std::size_t k = 0; k < movers.size(); ++k) scene.movers.push_back(parse_mover(movers[k], k));
  check_motion(scene);
  return scene;
}

// A moving body stays within the hull of its start and the arena, give or take its reach and one
// frame's step (it turns back once its box crosses the arena's side), and its angle grows by at
// most frames dt |w|: both must stay where the World computes.
void check_motion(const Scene& scene) {
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const SceneBody& b = scene.bodies[k];
    if (b.is_static) continue;
    const Aabb box = box_of(b);
    const Vec2 reach = (box.max - b.pose.position).cwiseMax(b.pose.position - box.min);
    const Vec2 step = scene.dt * b.velocity.cwiseAbs();
    for (int i = 0; i < 2; ++i) {
      const double far = std::max({std::abs(b.pose.position[i]), std::abs(scene.arena.min[i]) + reach[i],
                                   std::abs(scene.arena.max[i]) + reach[i]});
      if (!(far + step[i] <= kMaxMagnitude)) {
        fail(body_field(k) + ".velocity", "a frame's step of " + json(step[i]).dump() +
                                              " would carry the body beyond the supported range of +-1e50");
      }
    }
    const double turn = static_cast<double>(scene.frames) * scene.dt * std::abs(b.angular_velocity);
    if (!std::isfinite(std::abs(b.pose.angle) + turn)) {
      fail(body_field(k) + ".angular_velocity", "turns the body to an angle beyond the finite numbers over the run");
    }
  }
  // A mover goes no farther than its fastest walk, its jumps and its fall over the run take it.
  const double time = static_cast<double>(scene.frames) * scene.dt;
  for (std::size_t k = 0; k < scene.movers.size(); ++k) {
    const SceneMover& m = scene.movers[k];
    double walk = 0.0;
    for (const auto& [frame, speed] : m.walk) walk = std::max(walk, std::abs(speed));
    const double far =
        center_of(m.shape).cwiseAbs().maxCoeff() + time * (walk + m.jump_speed) + 0.5 * m.gravity * time * time;
    if (!(far <= kMaxMagnitude))
      fail(mover_field(k), "its walk, jumps and fall over the run could carry it beyond the supported range of +-1e50");
  }
}

namespace {

json movers_json(const std::vector<SceneMover>& movers) {
  json out = json::array();
  for (const SceneMover& m : movers) {
    json j = shape_json(m.shape);
    j["walk"] = m.walk;
    j["jumps"] = m.jumps;
    j["gravity"] = m.gravity;
    j["jump_speed"] = m.jump_speed;
    j["skin"] = m.options.query.skin;
    j["max_slope"] = m.options.max_slope;
    j["step_height"] = m.options.step_height;
    j["snap_distance"] = m.options.snap_distance;
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace

std::string write_scene(const Scene& scene) {
  json bodies = json::array();
  for (const SceneBody& b : scene.bodies) {
    json j;
    if (!b.chain.empty()) {
      j = {{"shape", "chain"}, {"points", json::array()}, {"loop", b.loop}};
      for (const Vec2& p : b.chain) j["points"].push_back({p.x(), p.y()});
    } else if (b.shapes.size() == 1 && center_of(b.shapes[0]) == Vec2::Zero() && angle_of(b.shapes[0]) == 0.0) {
      j = shape_json(placed_first(b));
    } else {
      j["center"] = {b.pose.position.x(), b.pose.position.y()};
      j["angle"] = b.pose.angle;
      for (const Shape& s : b.shapes) j["shapes"].push_back(shape_json(s));
    }
    j["velocity"] = {b.velocity.x(), b.velocity.y()};
    j["angular_velocity"] = b.angular_velocity;
    j["id"] = b.id;
    if (b.continuous) j["continuous"] = true;
    if (b.is_static) {
      j["static"] = true;
      j.erase("velocity");
      j.erase("angular_velocity");
    }
    if (b.sensor) j["sensor"] = true;
    const Filter pairs_with_all;
    if (b.filter.category != pairs_with_all.category) j["category"] = b.filter.category;
    if (b.filter.mask != pairs_with_all.mask) j["mask"] = b.filter.mask;
    if (b.filter.group != pairs_with_all.group) j["group"] = b.filter.group;
    bodies.push_back(std::move(j));
  }
  json root{
      {"arena",
       {{"min", {scene.arena.min.x(), scene.arena.min.y()}}, {"max", {scene.arena.max.x(), scene.arena.max.y()}}}},
      {"frames", scene.frames},
      {"dt", scene.dt},
      {"fat_margin", scene.fat_margin},
      {"proximity_margin", scene.proximity_margin},
      {"contacts", scene.contacts},
      {"overlap_areas", scene.overlap_areas},
      {"bodies", bodies}};
  if (!scene.movers.empty()) root["movers"] = movers_json(scene.movers);
  return root.dump(1);
}

namespace {

// The built-in scene's two layers, which pair within themselves and never with each other.
constexpr Filter kFirstLayer{.category = 1, .mask = 1};
constexpr Filter kSecondLayer{.category = 2, .mask = 2};

// The built-in scene's cave: a clockwise loop half a unit inside the arena's sides, the floor (run
// from right to left) rolling in hills 3 high and 48 long, a point every unit or so.
std::vector<Vec2> cave(const Aabb& arena) {
  const Vec2 lo = arena.min.array() + 0.5, hi = arena.max.array() - 0.5;
  std::vector<Vec2> points{Vec2(lo.x(), hi.y()), hi, Vec2(hi.x(), lo.y())};
  const int steps = static_cast<int>(hi.x() - lo.x());
  for (int k = 1; k < steps; ++k) {
    const double x = hi.x() - (hi.x() - lo.x()) * k / steps;
    points.emplace_back(x, lo.y() + 1.5 * (1 - Orientation::of(2 * std::numbers::pi * (x - lo.x()) / 48).c));
  }
  points.push_back(lo);
  return points;
}

// The built-in scene's level (on both layers): the cave, slopes and rocks, and four sensors at the
// quarter points.
template <class Uniform>
void add_level(Scene& scene, int count, Uniform& uniform) {
  const Filter both{.category = 3, .mask = 3};
  const Vec2 size = scene.arena.max - scene.arena.min;
  auto next_id = static_cast<std::uint64_t>(scene.bodies.size());
  const auto add = [&](const Shape& shape, bool sensor) {
    scene.bodies.push_back({.pose = pose_of(shape),
                            .shapes = at_origin(shape),
                            .id = next_id++,
                            .filter = both,
                            .is_static = true,
                            .sensor = sensor});
  };
  const std::vector<Vec2> walls = cave(scene.arena);
  scene.bodies.push_back({.shapes = chain_shapes(walls, true),
                          .id = next_id++,
                          .filter = both,
                          .is_static = true,
                          .chain = walls,
                          .loop = true});
  for (int k = 0; k < count / 200; ++k) {
    // One draw a statement, so that every compiler draws in this order (y, then x).
    const double y = uniform(scene.arena.min.y() + 8, scene.arena.max.y() - 8);
    const Vec2 at(uniform(scene.arena.min.x() + 8, scene.arena.max.x() - 8), y);
    if (k % 2 == 0) {
      add(Rect{at, Vec2(uniform(6, 14), 0.8), uniform(-0.6, 0.6)}, false);
    } else {
      add(Ellipse{at, uniform(3, 7), uniform(1.5, 3), uniform(0, std::numbers::pi)}, false);
    }
  }
  for (const Vec2& quarter : {Vec2(0.25, 0.25), Vec2(0.75, 0.25), Vec2(0.25, 0.75), Vec2(0.75, 0.75)}) {
    add(Circle{scene.arena.min + Vec2(quarter.cwiseProduct(size)), size.x() / 24}, true);
  }
}

}  // namespace

Scene default_scene(int count, int frames, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto uniform = [&rng](double lo, double hi) { return tool::uniform(rng, lo, hi); };
  // Mean body area about 2.2 (sizes 0.3 to 2): an arena of 28 count units^2 is about 8% covered.
  const double side = std::sqrt(28.0 * count);
  Scene scene;
  scene.arena = {Vec2(0, 0), Vec2(side, side)};
  scene.frames = frames;
  scene.proximity_margin = 0.5;
  for (int k = 0; k < count; ++k) {
    // One draw a statement, so that every compiler draws in this order (y, then x).
    const double y = uniform(2, side - 2);
    const Vec2 c(uniform(2, side - 2), y);
    const double size = uniform(0.3, 2.0);
    const double angle = uniform(0, 2 * std::numbers::pi);
    const auto shape = [&]() -> Shape {
      if (k % 3 == 0) return Circle{c, size};
      if (k % 3 == 1) return Ellipse{c, size, size / uniform(1, 8), angle};
      return Rect{c, Vec2(size, size * uniform(0.2, 1)), angle};
    }();
    const double heading = uniform(0, 2 * std::numbers::pi);
    const double speed = uniform(0, 6);
    scene.bodies.push_back({.pose = pose_of(shape),
                            .shapes = at_origin(shape),
                            .velocity = speed * direction(heading),
                            .angular_velocity = uniform(-1, 1),
                            .id = static_cast<std::uint64_t>(k),
                            .filter = k % 4 == 3 ? kSecondLayer : kFirstLayer});
  }
  for (int k = 0; k < count / 500; ++k) {
    const double heading = uniform(0, 2 * std::numbers::pi);
    const double y = uniform(2, side - 2);
    const Shape bullet = Circle{Vec2(uniform(2, side - 2), y), 0.1};
    scene.bodies.push_back({.pose = pose_of(bullet),
                            .shapes = at_origin(bullet),
                            .velocity = 300 * direction(heading),
                            .id = static_cast<std::uint64_t>(count + k),
                            .continuous = true,
                            .filter = kFirstLayer});
  }
  add_level(scene, count, uniform);
  return scene;
}

void step(Scene& scene) {
  for (SceneBody& b : scene.bodies) {
    if (b.is_static) continue;
    b.pose.position += scene.dt * b.velocity;
    b.pose.angle += scene.dt * b.angular_velocity;
    const Aabb box = box_of(b);
    for (int k = 0; k < 2; ++k) {
      if (box.min[k] < scene.arena.min[k] && b.velocity[k] < 0) b.velocity[k] = -b.velocity[k];
      if (box.max[k] > scene.arena.max[k] && b.velocity[k] > 0) b.velocity[k] = -b.velocity[k];
    }
  }
}

}  // namespace collide2d::tool
