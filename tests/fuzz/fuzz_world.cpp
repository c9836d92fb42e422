// World fuzzer: a random sequence of add (with a filter), set_pose, set_filter, set_continuous,
// remove, update and filtered queries from the bytes. Bad input (an unknown body or a handle kept
// past its remove() among it) must throw and leave the World as it was; after every update the
// overlapping pairs, the began/ended lists and the proximity pairs must equal an all-pairs check over
// the pairs the filters let through, and the impacts must be those of time_of_impact on every such
// pair with a continuous body, from the poses the fuzzer saw at the last update: all of them
// where the boxes over the step meet, and none that time_of_impact does not find. (Where they do
// not meet the shapes can still come within the tolerance, which grows with the coordinates: 5e3 at
// 3e18; the World never pairs them, as with a proximity pair culled by its boxes.)
#include "engine/world.h"
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
void compare_with_all_pairs(const World& w, double margin, const std::vector<BodyPair>& before) {
  const std::vector<BodyId> ids = w.bodies();
  std::vector<BodyPair> hit, near, unresolved;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    for (std::size_t j = i + 1; j < ids.size(); ++j) {
      if (!should_pair(w.filter(ids[i]), w.filter(ids[j]))) continue;
      const Shape& a = w.shape(ids[i]);
      const Shape& b = w.shape(ids[j]);
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
  std::vector<BodyPair> reported, began, ended;
  for (const Proximity& p : w.proximity()) {
    if (!std::binary_search(unresolved.begin(), unresolved.end(), BodyPair{p.a, p.b})) reported.push_back({p.a, p.b});
  }
  check(reported == near, "proximity pairs equal all pairs");
  std::set_difference(hit.begin(), hit.end(), before.begin(), before.end(), std::back_inserter(began));
  std::set_difference(before.begin(), before.end(), hit.begin(), hit.end(), std::back_inserter(ended));
  check(w.began() == began && w.ended() == ended, "began and ended");
}

// Filters from three categories, every mask of them, and groups -2 … 2.
Filter filter_from(fuzz::Input& in) {
  return {.category = std::uint64_t{1} << (in.byte() % 3), .mask = static_cast<std::uint64_t>(in.byte() % 8),
          .group = static_cast<std::int32_t>(in.byte() % 5) - 2};
}

bool lets_through(const QueryFilter& q, const Filter& f) { return (f.category & q.mask) != 0 && (f.mask & q.category) != 0; }

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
      if (!should_pair(w.filter(ids[i]), w.filter(ids[j]))) continue;
      const Shape* si = start_of(ids[i]);
      const Shape* sj = start_of(ids[j]);
      if (!si && !sj) continue;
      const auto motion = [&](const Shape* start, BodyId id) {
        const Shape& now = w.shape(id);
        return start ? Motion{center_of(now) - center_of(*start), angle_of(now) - angle_of(*start)} : Motion{};
      };
      const TimeOfImpact r = time_of_impact(si ? *si : w.shape(ids[i]), motion(si, ids[i]), sj ? *sj : w.shape(ids[j]),
                                            motion(sj, ids[j]));
      if (r.status == ToiStatus::hit || r.status == ToiStatus::stalled) expected.push_back({ids[i], ids[j], r.t, r.normal, r.point});
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
          if (world.size() < 24) world.add(in.shape(), {.filter = filter_from(in)});
          break;
        case 6: {
          const BodyId id = target();
          world.set_filter(id, filter_from(in));
          check(std::find(removed.begin(), removed.end(), id) == removed.end(), "a stale handle is refused");
          break;
        }
        case 1: {
          const BodyId id = target();
          const Vec2 centre = in.point();
          world.set_pose(id, centre, in.number());
          check(std::find(removed.begin(), removed.end(), id) == removed.end(), "a stale handle is refused");
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
          compare_with_all_pairs(world, margin, before);
          check_impacts(world, starts);
          for (auto& [id, start] : starts) start = world.shape(id);
          before = world.overlapping();
          break;
        case 4: {
          std::vector<BodyId> expected;
          const QueryFilter q{.category = std::uint64_t{1} << (in.byte() % 3), .mask = static_cast<std::uint64_t>(in.byte() % 8)};
          if (in.byte() % 2 == 0) {
            const Shape probe = in.shape();
            const auto got = world.overlapping(probe, q);
            for (const BodyId id : world.bodies()) {
              if (!lets_through(q, world.filter(id))) continue;
              if (intersects(aabb(probe), aabb(world.shape(id))) && overlaps(probe, world.shape(id))) expected.push_back(id);
            }
            check(got == expected, "overlapping(shape) equals brute force");
          } else {
            const Vec2 corner = in.point();
            const Aabb box{corner, corner + in.point().cwiseAbs()};  // may have no width or height
            const auto got = world.overlapping(box, q);
            for (const BodyId id : world.bodies()) {
              if (lets_through(q, world.filter(id)) && overlaps(world.shape(id), box)) expected.push_back(id);
            }
            check(got == expected, "overlapping(box) equals brute force");
          }
          break;
        }
        default: {
          const Vec2 origin = in.point();
          const Vec2 direction = in.point();
          const auto hit = world.ray_cast(origin, direction, 100.0);
          if (hit) check(std::isfinite(hit->distance) && hit->distance >= 0 && hit->point.allFinite(), "ray hit finite");
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
