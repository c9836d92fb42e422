#include "tools/scene/distributed_run.h"

#include <collide2d/distributed.h>

#include <algorithm>
#include <array>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace collide2d::tool {
namespace {

// The bodies go by their index in the scene; a body of one shape goes in where its pose puts it.
void add_bodies(const Scene& scene, DistributedWorld& world) {
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const SceneBody& b = scene.bodies[k];
    if (!b.chain.empty()) {
      world.add_chain(k, b.chain, b.loop, {.filter = b.filter});
    } else if (k % static_cast<std::size_t>(world.ranks()) == static_cast<std::size_t>(world.rank())) {
      world.add(k, placed_first(b), {.filter = b.filter, .is_static = b.is_static, .sensor = b.sensor}, b.continuous);
    }
  }
}

// Bounds at the quantiles of the bodies' centres along x, so that each rank starts with about as
// many.
std::vector<double> starting_bounds(const Scene& scene, int ranks) {
  std::vector<double> xs;
  for (const SceneBody& b : scene.bodies) {
    if (!b.is_static) xs.push_back(b.pose.position.x());
  }
  return xs.empty() ? std::vector<double>{} : Slabs::balanced(std::move(xs), ranks).bounds();
}

// The sensors' contents over every rank, sorted as one World sorts them (by index), as scene ids.
std::vector<RunSummary::Sensor> gathered_sensors(const Scene& scene, DistributedWorld& world) {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> pairs;
  for (const IdSensorPair& p : world.sensing_everywhere()) {
    pairs.emplace_back(scene.bodies[p.sensor].id, scene.bodies[p.visitor].id);
  }
  return sensor_contents(scene, pairs);
}

}  // namespace

RunSummary run_distributed(Scene scene, MPI_Comm comm, unsigned threads, std::ostream* progress) {
  check_motion(scene);
  // A mover reads the whole World each move; the ranks hold a slab each.
  if (!scene.movers.empty()) throw SceneError("movers: a scene with movers runs in one process, not under mpirun");
  for (const SceneBody& b : scene.bodies) {
    if (b.chain.empty() && b.shapes.size() != 1) {
      throw SceneError("body " + std::to_string(b.id) + " has " + std::to_string(b.shapes.size()) +
                       " shapes: a run on several ranks takes bodies of one shape (and chains)");
    }
  }
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  DistributedWorld world(comm, {.world = {.fat_margin = scene.fat_margin,
                                          .proximity_margin = scene.proximity_margin,
                                          .contacts = scene.contacts,
                                          .threads = threads,
                                          .overlap_areas = scene.overlap_areas},
                                .bounds = starting_bounds(scene, ranks),
                                .rebalance_every = 30});
  add_bodies(scene, world);
  RunSummary s = scene_totals(scene);
  s.threads = world.world().threads();
  s.ranks = ranks;
  std::vector<double> broad, narrow;
  const int every = std::max(1, scene.frames / 50);
  for (int frame = 0; frame < scene.frames; ++frame) {
    step(scene);
    for (const std::uint64_t id : world.owned()) {
      const Pose& p = scene.bodies[id].pose;
      if (!scene.bodies[id].is_static) world.move_to(id, p.position, p.angle);
    }
    world.update();
    const FrameStats& f = world.world().last_frame();
    const auto& r = world.report();
    std::array<std::uint64_t, 10> counts{f.candidates,
                                         f.filtered,
                                         r.overlapping.size(),
                                         r.proximity.size(),
                                         world.began().size(),
                                         world.ended().size(),
                                         r.impacts.size(),
                                         r.sensing.size(),
                                         world.sensor_began().size(),
                                         world.sensor_ended().size()};
    MPI_Allreduce(MPI_IN_PLACE, counts.data(), static_cast<int>(counts.size()), MPI_UINT64_T, MPI_SUM, comm);
    std::array<double, 2> times{1e3 * f.broad_seconds, 1e3 * f.narrow_seconds};
    MPI_Allreduce(MPI_IN_PLACE, times.data(), 2, MPI_DOUBLE, MPI_MAX, comm);
    broad.push_back(times[0]);
    narrow.push_back(times[1]);
    s.candidates_per_frame += static_cast<double>(counts[0]);
    s.filtered_per_frame += static_cast<double>(counts[1]);
    s.overlapping_per_frame += static_cast<double>(counts[2]);
    s.proximity_per_frame += static_cast<double>(counts[3]);
    s.began += counts[4];
    s.ended += counts[5];
    s.impacts += counts[6];
    s.sensing_per_frame += static_cast<double>(counts[7]);
    s.sensor_began += counts[8];
    s.sensor_ended += counts[9];
    if (s.overlap_area_per_frame) {
      std::array<double, 2> areas = overlap_areas(r.contacts, r.sensing);
      MPI_Allreduce(MPI_IN_PLACE, areas.data(), 2, MPI_DOUBLE, MPI_SUM, comm);
      add_overlap_areas(areas, s);
    }
    if (progress && ((frame + 1) % every == 0 || frame + 1 == scene.frames))
      draw_progress(*progress, frame + 1, scene.frames);
  }
  if (progress) *progress << '\n';
  s.sensor_contents = gathered_sensors(scene, world);
  finish(s, std::move(broad), std::move(narrow));
  return s;
}

}  // namespace collide2d::tool
