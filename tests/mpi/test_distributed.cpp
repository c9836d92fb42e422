// DistributedWorld under mpirun against one World in each process: every rank builds the same scene
// (tests/support/split_scene.h) as a whole World, and drives the distributed one with its share of
// the bodies: each rank adds the bodies whose id modulo the rank count is its own, wherever they
// are, and moves and removes those it owns. Each frame the ranks' reports and events, gathered on
// rank 0, must be the whole World's, line for line with every number written exactly; so must the
// totals, and the collective queries on every rank. Run with the bounds fixed, and moved to the
// bodies' distribution every 3 frames. Prints what it compared; exits 1 on the first difference.
//   mpirun -np N test_distributed
#include <collide2d/distributed.h>

#include "split_scene.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide2d {
namespace {

std::string hex(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%a", x);
  return text;
}
std::string hex(const Vec2& v) { return hex(v.x()) + " " + hex(v.y()); }

std::string ids(std::uint64_t a, std::uint64_t b) { return std::to_string(a) + " " + std::to_string(b); }

// A report as lines, one per record, every number exact.
std::vector<std::string> lines(const RegionReport& r) {
  std::vector<std::string> out;
  for (const ShapePair& p : r.overlapping) out.push_back("overlap " + ids(p.user_a, p.user_b));
  for (const Proximity& p : r.proximity) {
    out.push_back("near " + ids(p.user_a, p.user_b) + " " + hex(p.result.distance) + " " + hex(p.result.point_a) + " " +
                  hex(p.result.point_b));
  }
  for (const BodyContact& c : r.contacts) {
    std::string line = "contact " + ids(c.user_a, c.user_b) + " " + (c.touching ? "t " : "s ") +
                       hex(c.contact.separation) + " " + hex(c.contact.normal) + " " + hex(c.contact.point_a) + " " +
                       hex(c.contact.point_b);
    for (const ContactPoint& p : c.contact.points()) {
      line += " | " + hex(p.point_a) + " " + hex(p.point_b) + " " + hex(p.separation) + " " + std::to_string(p.id);
    }
    out.push_back(line);
  }
  for (const Impact& i : r.impacts) {
    out.push_back("impact " + ids(i.user_a, i.user_b) + " " + hex(i.t) + " " + hex(i.normal) + " " + hex(i.point));
  }
  for (const SensorPair& s : r.sensing) out.push_back("sensing " + ids(s.user_sensor, s.user_visitor));
  return out;
}

using Pairs = std::vector<std::pair<std::uint64_t, std::uint64_t>>;

template <class List, class Get>
Pairs pairs_of(const List& list, Get get) {
  Pairs out;
  for (const auto& p : list) out.push_back(get(p));
  return out;
}

std::vector<std::string> event_lines(const Pairs& began, const Pairs& ended, const Pairs& sensor_began,
                                     const Pairs& sensor_ended) {
  std::vector<std::string> out;
  for (const auto& [name, pairs] :
       {std::pair("began", &began), std::pair("ended", &ended), std::pair("sensor-began", &sensor_began),
        std::pair("sensor-ended", &sensor_ended)}) {
    for (const auto& [a, b] : *pairs) out.push_back(std::string(name) + " " + ids(a, b));
  }
  return out;
}

// The whole World's events by ids, the lower first (a sensor pair keeps its roles).
std::vector<std::string> whole_events(const World& world) {
  const auto by_ids = [](const ShapePair& p) {
    return std::pair(std::min(p.user_a, p.user_b), std::max(p.user_a, p.user_b));
  };
  const auto roles = [](const SensorPair& p) { return std::pair(p.user_sensor, p.user_visitor); };
  return event_lines(pairs_of(world.began(), by_ids), pairs_of(world.ended(), by_ids),
                     pairs_of(world.sensor_began(), roles), pairs_of(world.sensor_ended(), roles));
}

std::vector<std::string> rank_events(const DistributedWorld& d) {
  const auto plain = [](const IdPair& p) { return std::pair(p.a, p.b); };
  const auto roles = [](const IdSensorPair& p) { return std::pair(p.sensor, p.visitor); };
  return event_lines(pairs_of(d.began(), plain), pairs_of(d.ended(), plain), pairs_of(d.sensor_began(), roles),
                     pairs_of(d.sensor_ended(), roles));
}

// Every rank's lines on rank 0, sorted.
std::vector<std::string> gather_lines(const std::vector<std::string>& mine) {
  std::string text;
  for (const std::string& line : mine) text += line + "\n";
  int size = static_cast<int>(text.size()), rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  std::vector<int> sizes(static_cast<std::size_t>(ranks)), at(static_cast<std::size_t>(ranks));
  MPI_Gather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < ranks; ++r)
    at[static_cast<std::size_t>(r)] = std::exchange(total, total + sizes[static_cast<std::size_t>(r)]);
  std::string all(static_cast<std::size_t>(total), '\0');
  MPI_Gatherv(text.data(), size, MPI_CHAR, all.data(), sizes.data(), at.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  std::vector<std::string> out;
  for (std::size_t from = 0; from < all.size();) {
    const std::size_t end = all.find('\n', from);
    out.push_back(all.substr(from, end - from));
    from = end + 1;
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The first line where the two differ, or "" where they are the same.
std::string first_difference(const std::vector<std::string>& got, std::vector<std::string> want) {
  std::sort(want.begin(), want.end());
  for (std::size_t k = 0; k < std::max(got.size(), want.size()); ++k) {
    const std::string g = k < got.size() ? got[k] : "(none)", w = k < want.size() ? want[k] : "(none)";
    if (g != w) return "ranks gave  " + g + "\n  one World " + w;
  }
  return "";
}

// The scene's bodies as DistributedWorld calls: added by the rank that id % ranks names, moved and
// removed by their owners.
void drive(const testing::SplitScene& scene, DistributedWorld& d, const std::vector<std::uint64_t>& added,
           const std::vector<std::uint64_t>& removed) {
  for (const std::uint64_t id : removed) {
    if (d.owns(id)) d.remove(id);
  }
  for (const std::uint64_t id : d.owned()) {
    const Pose p = scene.world.pose(scene.bodies.at(id));
    d.move_to(id, p.position, p.angle);
  }
  for (const std::uint64_t id : added) {
    if (static_cast<int>(id % static_cast<std::uint64_t>(d.ranks())) != d.rank()) continue;
    const BodyId b = scene.bodies.at(id);
    d.add(id, scene.world.shape(b),
          {.filter = scene.world.filter(b), .is_static = scene.world.is_static(b), .sensor = scene.world.is_sensor(b)},
          scene.world.is_continuous(b));
  }
}

// Bounds across the scene's boundaries; for four ranks the last slab lies past the scene, a rank
// with no moving body.
std::vector<double> bounds_for(int ranks) {
  switch (ranks) {
    case 1:
      return {};
    case 2:
      return {0.0};
    case 3:
      return {-7.0, 7.0};
    case 4:
      return {-10.0, 0.0, 60.0};
    default: {
      std::vector<double> out;
      for (int k = 1; k < ranks; ++k) out.push_back(-20.0 + 40.0 * k / ranks);
      return out;
    }
  }
}

bool run(int rebalance_every) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  testing::SplitScene scene;
  DistributedWorld d(
      MPI_COMM_WORLD,
      {.world = testing::kSplitOptions, .bounds = bounds_for(ranks), .rebalance_every = rebalance_every});
  d.add_chain(scene.chain_id, scene.chain, false);
  std::size_t compared = 0, found = 0, casts = 0, rays = 0;
  for (int frame = 0; frame < 16; ++frame) {
    if (frame > 0) scene.step();
    drive(scene, d, scene.added, scene.removed);
    scene.world.update();
    d.update();
    std::vector<std::string> mine = lines(d.report()), want = lines(whole_report(scene.world));
    const std::vector<std::string> events = rank_events(d), whole = whole_events(scene.world);
    mine.insert(mine.end(), events.begin(), events.end());
    want.insert(want.end(), whole.begin(), whole.end());
    const std::vector<std::string> got = gather_lines(mine);
    int bad = 0;
    if (rank == 0) {
      const std::string diff = first_difference(got, want);
      if (!diff.empty()) {
        std::printf("frame %d, rebalance every %d: %s\n", frame, rebalance_every, diff.c_str());
        bad = 1;
      }
      compared += got.size();
    }
    const FrameStats totals = d.totals();
    const RegionReport all = whole_report(scene.world);
    if (totals.overlapping != all.overlapping.size() || totals.contacts != all.contacts.size() ||
        totals.impacts != all.impacts.size()) {
      std::printf("rank %d frame %d: totals differ\n", rank, frame);
      bad = 1;
    }
    const Shape probe = Ellipse{Vec2(-8.0 + frame, 1.0), 6.0, 3.0, 0.3 * frame};
    std::vector<std::uint64_t> want_found;
    for (const BodyId b : scene.world.overlapping(probe)) want_found.push_back(scene.world.user_id(b));
    std::sort(want_found.begin(), want_found.end());
    if (d.overlapping(probe) != want_found) {
      std::printf("rank %d frame %d: the shape query differs\n", rank, frame);
      bad = 1;
    }
    std::vector<std::uint64_t> in_box;
    const Aabb box{Vec2(-12.0 + frame, -4.0), Vec2(3.0 + frame, 2.0)};
    for (const BodyId b : scene.world.overlapping(box)) in_box.push_back(scene.world.user_id(b));
    std::sort(in_box.begin(), in_box.end());
    found += in_box.size();
    if (d.overlapping(box) != in_box) {
      std::printf("rank %d frame %d: the box query differs\n", rank, frame);
      bad = 1;
    }
    const Shape mover = Capsule{Vec2(-26.0, 9.0 - frame), 0.8, 0.3, 0.2};
    const auto met = d.cast(mover, Vec2(52.0, -1.0));
    const auto want_met = scene.world.cast(mover, Vec2(52.0, -1.0));
    casts += want_met ? 1 : 0;
    if (met.has_value() != want_met.has_value() ||
        (met && (met->first != scene.world.user_id(want_met->body) || met->second != want_met->fraction))) {
      std::printf("rank %d frame %d: the shape cast differs\n", rank, frame);
      bad = 1;
    }
    const Vec2 origin(-30, -11.5 + 1.5 * frame), direction(1, 0.05);
    const auto hit = d.ray_cast(origin, direction, 80);
    const auto want_hit = scene.world.ray_cast(origin, direction, 80);
    rays += want_hit ? 1 : 0;
    if (hit.has_value() != want_hit.has_value() ||
        (hit && (hit->first != scene.world.user_id(want_hit->body) || hit->second != want_hit->distance))) {
      std::printf("rank %d frame %d: the ray cast differs\n", rank, frame);
      bad = 1;
    }
    int any = 0;
    MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (any != 0) return false;
  }
  if (rank == 0) {
    std::printf(
        "%d ranks, rebalance every %d: 16 frames, %zu records and events the same as one World's; queries the "
        "same: %zu bodies in boxes, %zu casts and %zu rays that hit\n",
        d.ranks(), rebalance_every, compared, found, casts, rays);
  }
  return true;
}

// Every rank adds a body under one id: with more than one rank, the update that hands them to one
// rank refuses on every rank, naming the id.
bool one_id_on_two_ranks_is_refused() {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  DistributedWorld d(MPI_COMM_WORLD, {.bounds = bounds_for(ranks)});
  d.add(999, Circle{Vec2(0.5, 0.5), 0.25});
  try {
    d.update();
  } catch (const std::logic_error& e) {
    const bool named = std::string(e.what()) == "body id 999 was added on two ranks: ids must be unique";
    if (!named || ranks == 1) std::printf("rank %d: %s\n", rank, e.what());
    return named && ranks > 1;
  }
  if (ranks > 1) std::printf("rank %d: one id on %d ranks was not refused\n", rank, ranks);
  return ranks == 1;
}

}  // namespace
}  // namespace collide2d

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const bool ok = collide2d::run(0) && collide2d::run(3) && collide2d::one_id_on_two_ranks_is_refused();
  MPI_Finalize();
  return ok ? 0 : 1;
}
