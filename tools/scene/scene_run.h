// The `collide2d run` command as a library: runs a scene through a World frame by frame, then
// summarises what the broad and narrow phases did and how long they took, and draws the last frame.
#pragma once

#include <collide2d/replay.h>
#include <collide2d/world.h>
#include "tools/scene/scene.h"

#include <array>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace collide2d::tool {

// A phase's wall-clock time per frame.
struct PhaseTimes {
  double median_ms = 0.0;
  double p95_ms = 0.0;
  double slowest_ms = 0.0;
  int slowest_frame = 0;  // counted from 0
};

struct RunSummary {
  int ranks = 1;         // MPI ranks (collide2d run under mpirun)
  unsigned threads = 1;  // the World's update threads (on each rank)
  int frames = 0;
  std::size_t bodies = 0;
  double candidates_per_frame = 0.0;   // broad-phase pairs, mean over frames
  double filtered_per_frame = 0.0;     // of them, dropped by the bodies' filters
  double overlapping_per_frame = 0.0;  // confirmed overlaps, mean
  double proximity_per_frame = 0.0;    // pairs apart but within the margin, mean
  std::size_t began = 0;               // overlap events over the run
  std::size_t ended = 0;
  std::size_t continuous = 0;  // bullets
  std::size_t impacts = 0;     // their first contacts within a frame, over the run
  std::size_t statics = 0;     // static bodies
  std::size_t sensors = 0;
  double sensing_per_frame = 0.0;  // sensor-visitor pairs, mean
  std::size_t sensor_began = 0;    // entries into sensors over the run
  std::size_t sensor_ended = 0;
  // With the scene's overlap_areas: the contacts' overlap areas and the sensor pairs', each summed
  // over a frame, mean over frames.
  std::optional<std::array<double, 2>> overlap_area_per_frame;
  struct Sensor {
    std::uint64_t id = 0;
    std::vector<std::uint64_t> visitors;  // scene ids, at the last frame
  };
  std::vector<Sensor> sensor_contents;
  std::size_t movers = 0;         // the scene's character movers
  double movers_on_ground = 0.0;  // the share of their moves that ended on the ground
  PhaseTimes broad;
  PhaseTimes narrow;
  std::optional<std::uint64_t> state_hash;  // World::state_hash() after the last frame (one process)
};

class SceneRun {
 public:
  // The World runs on `threads` threads (0: every hardware thread). Throws SceneError, before any
  // frame, for a motion check_motion() refuses.
  explicit SceneRun(Scene scene, unsigned threads = 0);

  // Runs every frame: kinematics, poses into the World, update. Draws a progress bar on `progress`
  // and records each frame into `recorder` when they are not null.
  RunSummary run(std::ostream* progress, Recorder* recorder = nullptr);
  // One frame of it (bench_world times this): the bodies' kinematics, poses into the World, update,
  // then each mover's move().
  void frame();

  const World& world() const { return world_; }
  const Scene& scene() const { return scene_; }
  // The movers where the last frame left them, as the replay records them.
  const std::vector<MoverRecord>& movers() const { return movers_; }

 private:
  void move_movers();

  Scene scene_;
  World world_;
  std::vector<BodyId> ids_;  // World id of each scene body
  std::vector<MoverRecord> movers_;
  std::vector<Vec2> mover_velocity_;
  int frame_ = 0;  // the frames run
};

// The scene's counts (frames, bodies, continuous, static, sensors) with nothing run.
RunSummary scene_totals(const Scene& scene);
// The mean per frame of each per-frame count and the percentiles of the phases' times, from sums
// over `frames` frames and each frame's times.
void finish(RunSummary& s, std::vector<double> broad_ms, std::vector<double> narrow_ms);

// Each sensor of the scene and its visitors, from (sensor, visitor) pairs of scene ids.
std::vector<RunSummary::Sensor> sensor_contents(const Scene& scene,
                                                const std::vector<std::pair<std::uint64_t, std::uint64_t>>& sensing);
// One frame's overlap areas, each summed: its contacts' and its sensor pairs'.
std::array<double, 2> overlap_areas(std::span<const BodyContact> contacts, std::span<const SensorPair> sensing);
// Adds one frame's overlap areas to the summary's sums.
void add_overlap_areas(const std::array<double, 2>& areas, RunSummary& s);
// A progress bar: `done` of `total` frames.
void draw_progress(std::ostream& out, int done, int total);

void print_summary(const RunSummary& s, std::ostream& out);

// An SVG picture of the current frame: every body, overlapping moving ones in red, static bodies in
// slate (outlined in red where touched), sensors as dashed outlines (filled while they sense a body), and a segment
// between the closest points of each proximity pair.
void write_svg(const SceneRun& run, std::ostream& out);

}  // namespace collide2d::tool
