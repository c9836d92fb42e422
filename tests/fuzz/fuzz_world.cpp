// World fuzzer: a random sequence of add (with a filter, static or moving, sensor or solid), set_pose or move_to,
// set_filter, set_static, set_continuous, remove, update and filtered queries from the bytes. Bad
// input (an unknown body, a handle kept past its remove(), a static body made continuous) must throw
// and leave the World as it was; after every update the overlapping pairs, the began/ended lists,
// the sensor pairs with their began/ended lists and the proximity pairs must equal an all-pairs check
// over the pairs the World's rules let through (filters; no two static bodies; a sensor only with a
// solid body), and the impacts must be those of time_of_impact on every such solid
// pair with a continuous body, from the poses the fuzzer saw at the last update: all of them
// where the boxes over the step meet, and none that time_of_impact does not find. (Where they do
// not meet the shapes can still come within the tolerance, which grows with the coordinates: 5e3 at
// 3e18; the World never pairs them, as with a proximity pair culled by its boxes.)
#include <collide2d/ray_cast.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>
#include "fuzz_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using namespace collide2d;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "property failed: %s\n", what);
    std::abort();
  }
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
// Whether the World pairs the two at all, and whether as a sensor pair.
bool paired(const World& w, BodyId x, BodyId y) {
  return should_pair(w.filter(x), w.filter(y)) && !(w.is_static(x) && w.is_static(y)) &&
         !(w.is_sensor(x) && w.is_sensor(y));
}
bool sensor_pair(const World& w, BodyId x, BodyId y) { return w.is_sensor(x) || w.is_sensor(y); }

template <class Pair>
void check_changes(const std::vector<Pair>& before, const std::vector<Pair>& now, const std::vector<Pair>& began,
                   const std::vector<Pair>& ended, const char* what) {
  std::vector<Pair> gained, lost;
  std::set_difference(now.begin(), now.end(), before.begin(), before.end(), std::back_inserter(gained));
  std::set_difference(before.begin(), before.end(), now.begin(), now.end(), std::back_inserter(lost));
  check(began == gained && ended == lost, what);
}

void compare_with_all_pairs(const World& w, double margin, const std::vector<BodyPair>& before,
                            const std::vector<SensorPair>& sensed_before) {
  const std::vector<BodyId> ids = w.bodies();
  std::vector<BodyPair> hit, near, unresolved;
  std::vector<SensorPair> sensed;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    for (std::size_t j = i + 1; j < ids.size(); ++j) {
      if (!paired(w, ids[i], ids[j])) continue;
      const Shape& a = w.shape(ids[i]);
      const Shape& b = w.shape(ids[j]);
      if (sensor_pair(w, ids[i], ids[j])) {
        if (intersects(aabb(a), aabb(b)) && overlaps(a, b)) {
          sensed.push_back(w.is_sensor(ids[i]) ? SensorPair{ids[i], ids[j]} : SensorPair{ids[j], ids[i]});
        }
        continue;
      }
      if (intersects(aabb(a), aabb(b)) && overlaps(a, b)) {
        hit.push_back({ids[i], ids[j]});
        continue;
      }
      if (margin == 0) continue;
      const DistanceResult r = distance(a, b);
      const double gap = box_gap(aabb(a), aabb(b));
      const double tolerance = 1e-12 * (fuzz::extent(a) + fuzz::extent(b));
      if (r.overlapping) {  // boxes apart, yet the kernel calls them touching: the World reports neither
        check(gap <= tolerance, "touching only within the kernel's tolerance of the box gap");
        unresolved.push_back({ids[i], ids[j]});
        continue;
      }
      const double d = r.distance;
      if (d > margin) continue;
      if (gap <= margin) {
        near.push_back({ids[i], ids[j]});
      } else {
        check(gap - d <= tolerance, "distance no shorter than the box gap");
        unresolved.push_back({ids[i], ids[j]});
      }
    }
  }
  check(w.overlapping() == hit, "overlapping pairs equal all pairs");
  std::vector<BodyPair> reported;
  for (const Proximity& p : w.proximity()) {
    if (!std::binary_search(unresolved.begin(), unresolved.end(), BodyPair{p.a, p.b})) reported.push_back({p.a, p.b});
  }
  check(reported == near, "proximity pairs equal all pairs");
  check_changes(before, hit, w.began(), w.ended(), "began and ended");
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

// The World's observable state, to check that a refused call changed nothing.
std::vector<std::pair<BodyId, std::size_t>> snapshot(const World& w) {
  std::vector<std::pair<BodyId, std::size_t>> out;
  for (const BodyId id : w.bodies()) out.emplace_back(id, std::hash<double>{}(aabb(w.shape(id)).min.x()));
  return out;
}

// The continuous bodies and where their step began.
using Starts = std::vector<std::pair<BodyId, Shape>>;

void check_impacts(const World& w, const Starts& starts) {
  const auto start_of = [&](BodyId id) -> const Shape* {
    for (const auto& [c, shape] : starts) {
      if (c == id) return &shape;
    }
    return nullptr;
  };
  const std::vector<BodyId> ids = w.bodies();
  std::vector<Impact> expected;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    for (std::size_t j = i + 1; j < ids.size(); ++j) {
      if (!paired(w, ids[i], ids[j]) || sensor_pair(w, ids[i], ids[j])) continue;
      const Shape* si = start_of(ids[i]);
      const Shape* sj = start_of(ids[j]);
      if (!si && !sj) continue;
      const auto motion = [&](const Shape* start, BodyId id) {
        const Shape& now = w.shape(id);
        return start ? Motion{center_of(now) - center_of(*start), angle_of(now) - angle_of(*start)} : Motion{};
      };
      const TimeOfImpact r = time_of_impact(si ? *si : w.shape(ids[i]), motion(si, ids[i]), sj ? *sj : w.shape(ids[j]),
                                            motion(sj, ids[j]));
      if (r.status == ToiStatus::hit || r.status == ToiStatus::stalled)
        expected.push_back({ids[i], ids[j], w.user_id(ids[i]), w.user_id(ids[j]), r.t, r.normal, r.point});
    }
  }
  // A box inside the one the World gives a body over the step: its box now, or for a continuous
  // body the segment between its centres grown by its least half-size, with both end boxes.
  const auto covered = [&](BodyId id) {
    const Shape& now = w.shape(id);
    const Shape* start = start_of(id);
    if (!start) return aabb(now);
    const double least = std::visit(
        [](const auto& x) {
          using T = std::decay_t<decltype(x)>;
          if constexpr (std::is_same_v<T, Circle>) return x.radius;
          if constexpr (std::is_same_v<T, Ellipse>) return std::min(x.a, x.b);
          if constexpr (std::is_same_v<T, Rect>) return x.half_extents.minCoeff();
        },
        now);
    const Vec2 c0 = center_of(*start), c1 = center_of(now);
    const Aabb path{c0.cwiseMin(c1).array() - least, c0.cwiseMax(c1).array() + least};
    const Aabb a = aabb(*start), b = aabb(now);
    return Aabb{path.min.cwiseMin(a.min).cwiseMin(b.min), path.max.cwiseMax(a.max).cwiseMax(b.max)};
  };
  std::size_t k = 0;
  for (const Impact& e : expected) {
    const bool found = k < w.impacts().size() && w.impacts()[k].a == e.a && w.impacts()[k].b == e.b;
    if (found) {
      check(w.impacts()[k].t == e.t && w.impacts()[k].normal == e.normal, "an impact equals time_of_impact");
      ++k;
    } else {
      check(!intersects(covered(e.a), covered(e.b)), "every impact whose boxes meet is reported");
    }
  }
  check(k == w.impacts().size(), "no impact that time_of_impact does not find");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input in(data, size);
  const double margin = (in.byte() % 4) * 0.25;
  World world({.fat_margin = (in.byte() % 3) * 0.1, .proximity_margin = margin});
  std::vector<BodyPair> before;
  std::vector<SensorPair> sensed_before;
  std::vector<BodyId> removed;  // stale handles: every call with one must be refused
  Starts starts;
  for (int op = 0; op < 64 && !in.empty(); ++op) {
    const auto state = snapshot(world);
    const std::vector<BodyId> ids = world.bodies();
    const BodyId some = ids.empty() ? BodyId{7, 1} : ids[in.byte() % ids.size()];
    // A live body, an unknown one or a stale handle.
    const auto target = [&]() {
      const int pick = in.byte() % 8;
      if (pick == 0) return BodyId{1000, 1};
      if (pick == 1 && !removed.empty()) return removed[in.byte() % removed.size()];
      return some;
    };
    try {
      switch (in.byte() % 8) {
        case 0:
          if (world.size() < 24) {
            const std::uint8_t kind = in.byte();
            world.add(in.shape(),
                      {.user_id = 0, .filter = filter_from(in), .is_static = kind % 3 == 0, .sensor = kind % 5 == 0});
          }
          break;
        case 6: {
          const BodyId id = target();
          if (in.byte() % 2 == 0) {
            world.set_filter(id, filter_from(in));
          } else {
            world.set_static(id, !world.is_static(id));
            if (world.is_static(id)) std::erase_if(starts, [&](const auto& c) { return c.first == id; });
          }
          check(std::find(removed.begin(), removed.end(), id) == removed.end(), "a stale handle is refused");
          break;
        }
        case 1: {
          const BodyId id = target();
          const Vec2 centre = in.point();
          const bool teleport = in.byte() % 2 == 0;
          if (teleport) {
            world.set_pose(id, centre, in.number());
          } else {
            world.move_to(id, centre, in.number());
          }
          check(std::find(removed.begin(), removed.end(), id) == removed.end(), "a stale handle is refused");
          if (teleport) {  // a continuous body's step starts where it lands
            for (auto& [c, start] : starts)
              if (c == id) start = world.shape(id);
          }
          break;
        }
        case 2: {
          const BodyId id = target();
          world.remove(id);
          check(std::find(removed.begin(), removed.end(), id) == removed.end(), "a stale handle is refused");
          removed.push_back(id);
          std::erase_if(starts, [&](const auto& c) { return c.first == id; });
          break;
        }
        case 5: {
          const BodyId id = target();
          const bool on = in.byte() % 2 == 0;
          world.set_continuous(id, on);
          check(std::find(removed.begin(), removed.end(), id) == removed.end(), "a stale handle is refused");
          const bool was = std::any_of(starts.begin(), starts.end(), [&](const auto& c) { return c.first == id; });
          if (!on) std::erase_if(starts, [&](const auto& c) { return c.first == id; });
          if (on && !was) starts.emplace_back(id, world.shape(id));  // flagging a flagged body keeps its start
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
          std::vector<BodyId> expected;
          const QueryFilter q{.category = std::uint64_t{1} << (in.byte() % 3),
                              .mask = static_cast<std::uint64_t>(in.byte() % 8)};
          if (in.byte() % 2 == 0) {
            const Shape probe = in.shape();
            const auto got = world.overlapping(probe, q);
            for (const BodyId id : world.bodies()) {
              if (world.is_sensor(id) || !lets_through(q, world.filter(id))) continue;
              if (intersects(aabb(probe), aabb(world.shape(id))) && overlaps(probe, world.shape(id)))
                expected.push_back(id);
            }
            check(got == expected, "overlapping(shape) equals brute force");
          } else {
            const Vec2 corner = in.point();
            const Aabb box{corner, corner + in.point().cwiseAbs()};  // may have no width or height
            const auto got = world.overlapping(box, q);
            for (const BodyId id : world.bodies()) {
              if (!world.is_sensor(id) && lets_through(q, world.filter(id)) && overlaps(world.shape(id), box))
                expected.push_back(id);
            }
            check(got == expected, "overlapping(box) equals brute force");
          }
          break;
        }
        default: {
          const Vec2 origin = in.point();
          const Vec2 direction = in.point();
          const auto hit = world.ray_cast(origin, direction, 100.0);
          if (hit)
            check(std::isfinite(hit->distance) && hit->distance >= 0 && hit->point.allFinite(), "ray hit finite");
          // Every solid body the ray meets, through the trees (moved bodies too, before the update
          // refreshes them), as the kernel finds them one by one.
          const std::vector<RayHit> all = world.ray_cast_all(origin, direction, 100.0);
          std::vector<std::pair<double, BodyId>> expected;
          for (const BodyId id : world.bodies()) {
            if (world.is_sensor(id) || !lets_through(QueryFilter{}, world.filter(id))) continue;
            if (contains(world.shape(id), origin)) continue;  // rays skip the bodies they start in
            const auto h = collide2d::ray_cast(world.shape(id), origin, Vec2(direction / direction.norm()), 100.0);
            if (h) expected.emplace_back(h->distance, id);
          }
          std::sort(expected.begin(), expected.end(), [](const auto& p, const auto& q) {
            return p.first < q.first || (p.first == q.first && p.second.index < q.second.index);
          });
          check(all.size() == expected.size(), "ray_cast_all finds every body the ray meets");
          for (std::size_t k = 0; k < all.size(); ++k) {
            check(all[k].body == expected[k].second && all[k].distance == expected[k].first, "ray_cast_all in order");
          }
          break;
        }
      }
    } catch (const std::invalid_argument&) {  // InvalidShape and bad poses or margins
      check(snapshot(world) == state, "a refused call changed nothing");
    } catch (const std::out_of_range&) {  // unknown body or stale handle
      check(snapshot(world) == state, "a refused call changed nothing");
    }
  }
  return 0;
}
