// World fuzzer: a random sequence of add (one shape, or several placed in the body's frame; with a
// filter, static or moving, sensor or solid), add_shape, remove_shape, set_pose or move_to,
// set_filter (of a body or of a shape), set_sensor, set_local_shape, set_static, set_continuous,
// remove, update and filtered queries from the bytes, and past 64 of them a chain (a static body of
// one-sided segments) and 64 more. Bad input (an unknown body or shape, a handle
// kept past its removal, a body's last shape removed, a static body made continuous) must throw and
// leave the World as it was; after every update the overlapping shape pairs, the began/ended lists
// (of shapes and of bodies), the sensor pairs with their began/ended lists and the proximity pairs
// must equal an all-pairs check over the pairs of shapes the World's rules let through (no two
// shapes of one body; filters; no two static bodies; a sensor only with a solid shape; a chain's
// segment only where its rules give a contact; rays through a chain's back), and the
// impacts must be those of time_of_impact on such solid pairs with a continuous body, from the
// poses the fuzzer saw at the last update, the earliest for each pair of bodies: every pair of
// bodies with a hit where the boxes over the step meet, and none that time_of_impact does not find.
// (Where they do not meet the shapes can still come within the tolerance, which grows with the
// coordinates: 5e3 at 3e18; the World never pairs them, as with a proximity pair culled by its
// boxes.)
#include <collide2d/ray_cast.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>
#include "../support/chain_rules.h"
#include "fuzz_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using namespace collide2d;

using fuzz::check;

// Every shape of the World with its body, by body index.
std::vector<BodyShape> all_shapes(const World& w) {
  std::vector<BodyShape> out;
  for (const BodyId body : w.bodies()) {
    for (const ShapeId shape : w.shapes(body)) out.push_back({body, shape});
  }
  return out;
}

// How far apart two boxes are (0 when they meet): a lower bound on the distance of their shapes.
double box_gap(const Aabb& p, const Aabb& q) {
  const Vec2 gap = (p.min - q.max).cwiseMax(q.min - p.max).cwiseMax(0.0);
  return gap.norm();
}

// The World reports a pair when the bodies' boxes meet and the narrow phase says so; where the
// kernels are right, which at gaps above rounding they are, that is every overlapping pair. A
// proximity pair is culled by its boxes, which are exact, where the kernel's distance is accurate
// to 1e-12 of the pair's scale only (the documented tolerance): a pair the kernel puts within the
// margin but whose boxes are farther apart than that is missing for good reason, provided the
// kernel's shortfall below the box gap is within the tolerance (a needle 1e38 long puts the
// tolerance at 1e26). So is a pair the kernel calls touching although its boxes are apart, within
// the same tolerance: it is neither overlapping nor apart.
// Whether the World pairs the two shapes at all, and whether as a sensor pair.
bool paired(const World& w, const BodyShape& x, const BodyShape& y) {
  return x.body != y.body && should_pair(w.filter(x.shape), w.filter(y.shape)) &&
         !(w.is_static(x.body) && w.is_static(y.body)) && !(w.is_sensor(x.shape) && w.is_sensor(y.shape));
}
bool sensor_pair(const World& w, const BodyShape& x, const BodyShape& y) {
  return w.is_sensor(x.shape) || w.is_sensor(y.shape);
}
ShapePair pair_of(const BodyShape& x, const BodyShape& y) { return {x.body, y.body, x.shape, y.shape}; }

template <class Pair>
void check_changes(const std::vector<Pair>& before, const std::vector<Pair>& now, const std::vector<Pair>& began,
                   const std::vector<Pair>& ended, const char* what) {
  std::vector<Pair> gained, lost;
  std::set_difference(now.begin(), now.end(), before.begin(), before.end(), std::back_inserter(gained));
  std::set_difference(before.begin(), before.end(), now.begin(), now.end(), std::back_inserter(lost));
  check(began == gained && ended == lost, what);
}

// The pairs of bodies of the shape pairs, each once.
std::vector<BodyPair> bodies_of(const std::vector<ShapePair>& pairs) {
  std::vector<BodyPair> out;
  for (const ShapePair& p : pairs) out.push_back({p.a, p.b});
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void compare_with_all_pairs(const World& w, double margin, const std::vector<ShapePair>& before,
                            const std::vector<SensorPair>& sensed_before) {
  const std::vector<BodyShape> ids = all_shapes(w);
  std::vector<ShapePair> hit, near, unresolved;
  std::vector<SensorPair> sensed;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    for (std::size_t j = i + 1; j < ids.size(); ++j) {
      if (!paired(w, ids[i], ids[j])) continue;
      const Shape& a = w.shape(ids[i].shape);
      const Shape& b = w.shape(ids[j].shape);
      if (sensor_pair(w, ids[i], ids[j])) {
        if (intersects(aabb(a), aabb(b)) && overlaps(a, b)) {
          const BodyShape& s = w.is_sensor(ids[i].shape) ? ids[i] : ids[j];
          const BodyShape& v = w.is_sensor(ids[i].shape) ? ids[j] : ids[i];
          sensed.push_back({s.body, v.body, s.shape, v.shape});
        }
        continue;
      }
      if (intersects(aabb(a), aabb(b)) && overlaps(a, b)) {
        if (reference::admitted_by_chain(w, ids[i].shape, ids[j].shape)) hit.push_back(pair_of(ids[i], ids[j]));
        continue;
      }
      if (margin == 0) continue;
      const DistanceResult r = distance(a, b);
      const double gap = box_gap(aabb(a), aabb(b));
      const double tolerance = 1e-12 * (fuzz::extent(a) + fuzz::extent(b));
      if (r.overlapping) {  // boxes apart, yet the kernel calls them touching: the World reports neither
        check(gap <= tolerance, "touching only within the kernel's tolerance of the box gap");
        unresolved.push_back(pair_of(ids[i], ids[j]));
        continue;
      }
      const double d = r.distance;
      if (d > margin) continue;
      if (gap <= margin) {
        near.push_back(pair_of(ids[i], ids[j]));
      } else {
        check(gap - d <= tolerance, "distance no shorter than the box gap");
        unresolved.push_back(pair_of(ids[i], ids[j]));
      }
    }
  }
  // all_shapes() lists a body's shapes in the order added; the World sorts by handles.
  std::sort(hit.begin(), hit.end());
  std::sort(near.begin(), near.end());
  std::sort(unresolved.begin(), unresolved.end());
  check(w.overlapping() == hit, "overlapping pairs equal all pairs");
  std::vector<ShapePair> reported;
  for (const Proximity& p : w.proximity()) {
    const ShapePair q{p.a, p.b, p.shape_a, p.shape_b};
    if (!std::binary_search(unresolved.begin(), unresolved.end(), q)) reported.push_back(q);
  }
  check(reported == near, "proximity pairs equal all pairs");
  check_changes(before, hit, w.began(), w.ended(), "began and ended");
  check(w.body_overlapping() == bodies_of(hit), "overlapping bodies are those of the shape pairs");
  check_changes(bodies_of(before), bodies_of(hit), w.body_began(), w.body_ended(), "bodies began and ended");
  std::sort(sensed.begin(), sensed.end());
  check(w.sensing() == sensed, "sensor pairs equal all pairs");
  check_changes(sensed_before, sensed, w.sensor_began(), w.sensor_ended(), "sensor began and ended");
}

// Filters from three categories, every mask of them, and groups -2 … 2.
Filter filter_from(fuzz::Input& in) {
  return {.category = std::uint64_t{1} << (in.byte() % 3),
          .mask = static_cast<std::uint64_t>(in.byte() % 8),
          .group = static_cast<std::int32_t>(in.byte() % 5) - 2};
}

bool lets_through(const QueryFilter& q, const Filter& f) {
  return (f.category & q.mask) != 0 && (f.mask & q.category) != 0;
}

// The World's observable state, to check that a refused call changed nothing: every shape, where it
// is, what it is.
std::vector<std::tuple<BodyId, ShapeId, std::size_t, bool, std::uint64_t>> snapshot(const World& w) {
  std::vector<std::tuple<BodyId, ShapeId, std::size_t, bool, std::uint64_t>> out;
  for (const BodyShape& s : all_shapes(w)) {
    out.emplace_back(s.body, s.shape, std::hash<double>{}(aabb(w.shape(s.shape)).min.x()), w.is_sensor(s.shape),
                     w.filter(s.shape).mask);
  }
  return out;
}

// The continuous bodies' shapes and where their step began.
using Starts = std::map<ShapeId, Shape>;

void check_impacts(const World& w, const Starts& starts) {
  const auto start_of = [&](ShapeId id) -> const Shape* {
    const auto found = starts.find(id);
    return found == starts.end() ? nullptr : &found->second;
  };
  // A box inside the one the World gives a shape over the step: its box now, or for a continuous
  // body's shape the segment between its centres grown by its least half-size, with both end boxes.
  const auto covered = [&](ShapeId id) {
    const Shape& now = w.shape(id);
    const Shape* start = start_of(id);
    if (!start) return aabb(now);
    const double least = std::visit(
        [](const auto& x) {
          using T = std::decay_t<decltype(x)>;
          if constexpr (std::is_same_v<T, Circle>) return x.radius;
          if constexpr (std::is_same_v<T, Ellipse>) return std::min(x.a, x.b);
          if constexpr (std::is_same_v<T, Rect>) return x.half_extents.minCoeff();
          if constexpr (std::is_same_v<T, Capsule>) return x.radius;
          if constexpr (std::is_same_v<T, ConvexPolygon>) {
            double inner = std::numeric_limits<double>::infinity();  // the centre's depth in the core
            for (int i = 0; i < x.count(); ++i) inner = std::min(inner, -x.outline->normals[i].dot(x.vertices()[i]));
            return std::max(inner, 0.0) + x.radius();
          }
          if constexpr (std::is_same_v<T, Segment>) return 0.0;  // static: never continuous
        },
        now);
    const Vec2 c0 = center_of(*start), c1 = center_of(now);
    const Aabb path{c0.cwiseMin(c1).array() - least, c0.cwiseMax(c1).array() + least};
    const Aabb a = aabb(*start), b = aabb(now);
    return Aabb{path.min.cwiseMin(a.min).cwiseMin(b.min), path.max.cwiseMax(a.max).cwiseMax(b.max)};
  };
  // Each shape pair's hit, and for each pair of bodies the earliest hit whose boxes over the step
  // meet (the World must report one at least that early).
  std::map<ShapePair, TimeOfImpact> hits;
  std::map<BodyPair, double> must;
  const std::vector<BodyShape> ids = all_shapes(w);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    for (std::size_t j = i + 1; j < ids.size(); ++j) {
      if (!paired(w, ids[i], ids[j]) || sensor_pair(w, ids[i], ids[j])) continue;
      const Shape* si = start_of(ids[i].shape);
      const Shape* sj = start_of(ids[j].shape);
      if (!si && !sj) continue;
      // A chain's segment stops only what starts in front of it.
      const auto chain_i = w.chain_segment(ids[i].shape), chain_j = w.chain_segment(ids[j].shape);
      if (chain_i && !in_front(*chain_i, sj ? *sj : w.shape(ids[j].shape))) continue;
      if (chain_j && !in_front(*chain_j, si ? *si : w.shape(ids[i].shape))) continue;
      const auto motion = [&](const Shape* start, ShapeId id) {
        const Shape& now = w.shape(id);
        return start ? Motion{center_of(now) - center_of(*start), angle_of(now) - angle_of(*start)} : Motion{};
      };
      const TimeOfImpact r = time_of_impact(si ? *si : w.shape(ids[i].shape), motion(si, ids[i].shape),
                                            sj ? *sj : w.shape(ids[j].shape), motion(sj, ids[j].shape));
      if (r.status != ToiStatus::hit && r.status != ToiStatus::stalled) continue;
      hits.emplace(pair_of(ids[i], ids[j]), r);
      if (intersects(covered(ids[i].shape), covered(ids[j].shape))) {
        const BodyPair bodies{ids[i].body, ids[j].body};
        const auto [at, fresh] = must.emplace(bodies, r.t);
        if (!fresh) at->second = std::min(at->second, r.t);
      }
    }
  }
  std::vector<BodyPair> reported;
  for (const Impact& i : w.impacts()) {
    const auto hit = hits.find({i.a, i.b, i.shape_a, i.shape_b});
    check(hit != hits.end(), "no impact that time_of_impact does not find");
    check(hit->second.t == i.t && hit->second.normal == i.normal, "an impact equals time_of_impact");
    const auto bound = must.find({i.a, i.b});
    check(bound == must.end() || i.t <= bound->second, "an impact is its bodies' earliest");
    reported.push_back({i.a, i.b});
  }
  check(std::is_sorted(reported.begin(), reported.end()) &&
            std::adjacent_find(reported.begin(), reported.end()) == reported.end(),
        "one impact per pair of bodies, sorted");
  for (const auto& [bodies, t] : must)
    check(std::binary_search(reported.begin(), reported.end(), bodies), "every impact whose boxes meet is reported");
}

// Stale handles kept: every call with one must be refused.
struct Removed {
  std::vector<BodyId> bodies;
  std::vector<ShapeId> shapes;
  bool has(BodyId id) const { return std::find(bodies.begin(), bodies.end(), id) != bodies.end(); }
  bool has(ShapeId id) const { return std::find(shapes.begin(), shapes.end(), id) != shapes.end(); }
};

// A body's shapes as ShapeDefs in its frame: one, or up to three, some with their own user id,
// filter or sensor flag.
std::vector<ShapeDef> shape_defs(fuzz::Input& in, Filter (*filter)(fuzz::Input&)) {
  std::vector<ShapeDef> defs(1 + in.byte() % 3);
  for (ShapeDef& d : defs) {
    d.shape = in.shape();
    const std::uint8_t own = in.byte();
    if (own & 1) d.user_id = own;
    if (own & 2) d.filter = filter(in);
    if (own & 4) d.sensor = (own & 8) != 0;
  }
  return defs;
}

// The queries against brute force over every solid shape the filter lets through: each body once,
// by index.
template <class Test>
void check_query(const World& w, const QueryFilter& q, const std::vector<BodyId>& got, Test test, const char* what) {
  std::vector<BodyId> expected;
  for (const BodyShape& s : all_shapes(w)) {
    if (!w.is_sensor(s.shape) && lets_through(q, w.filter(s.shape)) && test(w.shape(s.shape)) &&
        (expected.empty() || expected.back() != s.body))
      expected.push_back(s.body);
  }
  check(got == expected, what);
}

void check_rays(const World& world, fuzz::Input& in) {
  const Vec2 origin = in.point();
  const Vec2 direction = in.point();
  const auto hit = world.ray_cast(origin, direction, 100.0);
  if (hit) check(std::isfinite(hit->distance) && hit->distance >= 0 && hit->point.allFinite(), "ray hit finite");
  // Every solid shape the ray meets, through the trees (moved shapes too, before the update
  // refreshes them), as the kernel finds them one by one.
  const std::vector<RayHit> all = world.ray_cast_all(origin, direction, 100.0);
  std::vector<std::tuple<double, std::uint32_t, std::uint32_t>> expected;
  for (const BodyShape& s : all_shapes(world)) {
    if (world.is_sensor(s.shape) || !lets_through(QueryFilter{}, world.filter(s.shape))) continue;
    const Shape& shape = world.shape(s.shape);
    if (contains(shape, origin)) continue;  // rays skip the shapes they start in
    const Vec2 unit = direction / direction.norm();
    const auto chain = world.chain_segment(s.shape);  // one-sided
    const auto h =
        chain ? collide2d::ray_cast(*chain, origin, unit, 100.0) : collide2d::ray_cast(shape, origin, unit, 100.0);
    if (h) expected.emplace_back(h->distance, s.body.index, s.shape.index);
  }
  std::sort(expected.begin(), expected.end());
  check(all.size() == expected.size(), "ray_cast_all finds every shape the ray meets");
  for (std::size_t k = 0; k < all.size(); ++k) {
    check(std::tuple(all[k].distance, all[k].body.index, all[k].shape.index) == expected[k], "ray_cast_all in order");
    check(world.body(all[k].shape) == all[k].body, "a ray hit names the shape's body");
  }
  if (hit) check(hit->shape == all.front().shape, "ray_cast is ray_cast_all's first");
}

// A chain of 4 to 8 points, open or closed, on a static body; where its points are refused
// (InvalidShape), nothing changes.
void add_chain(World& world, fuzz::Input& in) {
  const auto state = snapshot(world);
  std::vector<Vec2> points(4 + in.byte() % 5);
  for (Vec2& p : points) p = in.point();
  const bool loop = in.byte() & 1;
  const Filter filter = filter_from(in);
  try {
    world.add_chain(points, loop, {.filter = filter});
  } catch (const InvalidShape&) {
    check(snapshot(world) == state, "a refused chain changed nothing");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input in(data, size);
  const double margin = (in.byte() % 4) * 0.25;
  World world({.fat_margin = (in.byte() % 3) * 0.1, .proximity_margin = margin});
  std::vector<ShapePair> before;
  std::vector<SensorPair> sensed_before;
  Removed removed;
  Starts starts;
  const auto restart = [&](BodyId id) {  // a continuous body's steps start where its shapes are now
    if (!world.is_continuous(id)) return;
    for (const ShapeId s : world.shapes(id)) starts[s] = world.shape(s);
  };
  // The first 64 ops decode as the corpus was written; bytes past them add a chain, then 64 more.
  for (int op = 0; op < 129 && !in.empty(); ++op) {
    if (op == 64) {
      add_chain(world, in);
      continue;
    }
    const auto state = snapshot(world);
    const std::vector<BodyId> ids = world.bodies();
    const BodyId some = ids.empty() ? BodyId{7, 1} : ids[in.byte() % ids.size()];
    // A live body, an unknown one or a stale handle.
    const auto target = [&]() {
      const int pick = in.byte() % 8;
      if (pick == 0) return BodyId{1000, 1};
      if (pick == 1 && !removed.bodies.empty()) return removed.bodies[in.byte() % removed.bodies.size()];
      return some;
    };
    // A live shape, an unknown one or a stale handle.
    const auto target_shape = [&]() {
      const int pick = in.byte() % 8;
      if (pick == 0 || ids.empty()) return ShapeId{1000, 1};
      if (pick == 1 && !removed.shapes.empty()) return removed.shapes[in.byte() % removed.shapes.size()];
      const std::vector<ShapeId> shapes = world.shapes(some);
      return shapes[in.byte() % shapes.size()];
    };
    try {
      switch (in.byte() % 11) {
        case 0:
          if (world.size() < 24) {
            const std::uint8_t kind = in.byte();
            const BodyDef def{
                .user_id = kind, .filter = filter_from(in), .is_static = kind % 3 == 0, .sensor = kind % 5 == 0};
            if (kind % 2 == 0) {
              world.add(in.shape(), def);
            } else {
              const Vec2 position = in.point();
              const Pose pose{position, in.number()};
              world.add(pose, shape_defs(in, filter_from), def);
            }
          }
          break;
        case 6: {
          const BodyId id = target();
          if (in.byte() % 2 == 0) {
            world.set_filter(id, filter_from(in));
          } else {
            world.set_static(id, !world.is_static(id));
            if (world.is_static(id)) std::erase_if(starts, [&](const auto& c) { return world.body(c.first) == id; });
          }
          check(!removed.has(id), "a stale handle is refused");
          break;
        }
        case 1: {
          const BodyId id = target();
          const Vec2 centre = in.point();
          const bool teleport = in.byte() % 2 == 0;
          if (teleport) {
            world.set_pose(id, centre, in.number());
            restart(id);
          } else {
            world.move_to(id, centre, in.number());
          }
          check(!removed.has(id), "a stale handle is refused");
          break;
        }
        case 2: {
          const BodyId id = target();
          const std::vector<ShapeId> shapes = world.shapes(id);
          world.remove(id);
          check(!removed.has(id), "a stale handle is refused");
          removed.bodies.push_back(id);
          for (const ShapeId s : shapes) {
            check(!world.contains(s), "a removed body's shapes are gone");
            removed.shapes.push_back(s);
            starts.erase(s);
          }
          break;
        }
        case 5: {
          const BodyId id = target();
          const bool on = in.byte() % 2 == 0;
          const bool was = world.contains(id) && world.is_continuous(id);
          world.set_continuous(id, on);
          check(!removed.has(id), "a stale handle is refused");
          if (!on) std::erase_if(starts, [&](const auto& c) { return world.body(c.first) == id; });
          if (on && !was) restart(id);  // flagging a flagged body keeps its start
          break;
        }
        case 8: {
          const BodyId id = target();
          const std::vector<ShapeDef> defs = shape_defs(in, filter_from);
          const ShapeId s = world.add_shape(id, defs.front());
          check(!removed.has(id), "a stale handle is refused");
          check(world.body(s) == id && world.shapes(id).back() == s, "an added shape is its body's last");
          if (world.is_continuous(id)) starts[s] = world.shape(s);
          break;
        }
        case 9: {
          const ShapeId s = target_shape();
          const bool last = world.contains(s) && world.shapes(world.body(s)).size() == 1;
          world.remove_shape(s);
          check(!removed.has(s) && !last, "a stale handle or a body's last shape is refused");
          removed.shapes.push_back(s);
          starts.erase(s);
          break;
        }
        case 10: {
          const ShapeId s = target_shape();
          switch (in.byte() % 3) {
            case 0:
              world.set_filter(s, filter_from(in));
              break;
            case 1:
              world.set_sensor(s, !world.is_sensor(s));
              break;
            default:
              world.set_local_shape(s, in.shape());
              if (starts.contains(s)) starts[s] = world.shape(s);  // its step starts at its new place
          }
          check(!removed.has(s), "a stale handle is refused");
          break;
        }
        case 3:
          world.update();
          compare_with_all_pairs(world, margin, before, sensed_before);
          check_impacts(world, starts);
          for (auto& [id, start] : starts) start = world.shape(id);
          before = world.overlapping();
          sensed_before = world.sensing();
          break;
        case 4: {
          const QueryFilter q{.category = std::uint64_t{1} << (in.byte() % 3),
                              .mask = static_cast<std::uint64_t>(in.byte() % 8)};
          if (in.byte() % 2 == 0) {
            const Shape probe = in.shape();
            check_query(
                world, q, world.overlapping(probe, q),
                [&](const Shape& s) { return intersects(aabb(probe), aabb(s)) && overlaps(probe, s); },
                "overlapping(shape) equals brute force");
          } else {
            const Vec2 corner = in.point();
            const Aabb box{corner, corner + in.point().cwiseAbs()};  // may have no width or height
            check_query(
                world, q, world.overlapping(box, q), [&](const Shape& s) { return overlaps(s, box); },
                "overlapping(box) equals brute force");
          }
          break;
        }
        default:
          check_rays(world, in);
      }
    } catch (const std::invalid_argument&) {  // InvalidShape, bad poses or margins, a body's last shape
      check(snapshot(world) == state, "a refused call changed nothing");
    } catch (const std::out_of_range&) {  // unknown body or shape, or a stale handle
      check(snapshot(world) == state, "a refused call changed nothing");
    }
  }
  return 0;
}
