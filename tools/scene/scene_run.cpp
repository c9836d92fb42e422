#include "tools/scene/scene_run.h"

#include "tools/scene/svg_shape.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <numbers>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <utility>

namespace collide2d::tool {
namespace {

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
  return v[k];
}

PhaseTimes phase_times(std::vector<double> ms) {
  if (ms.empty()) return {};
  const auto slowest = std::max_element(ms.begin(), ms.end());
  PhaseTimes t{.slowest_ms = *slowest, .slowest_frame = static_cast<int>(slowest - ms.begin())};
  t.median_ms = percentile(ms, 0.5);
  t.p95_ms = percentile(ms, 0.95);
  return t;
}

std::ostream& operator<<(std::ostream& out, const PhaseTimes& t) {
  return out << "median " << t.median_ms << " ms, 95th percentile " << t.p95_ms << " ms, slowest " << t.slowest_ms
             << " ms (frame " << t.slowest_frame << ")";
}

}  // namespace

void draw_progress(std::ostream& out, int done, int total) {
  constexpr int kWidth = 40;
  const int filled = total > 0 ? done * kWidth / total : kWidth;
  out << "\r  [" << std::string(static_cast<std::size_t>(filled), '#')
      << std::string(static_cast<std::size_t>(kWidth - filled), '.') << "] " << (total > 0 ? 100 * done / total : 100)
      << "% (" << done << '/' << total << " frames)" << std::flush;
}

SceneRun::SceneRun(Scene scene, unsigned threads)
    : scene_(std::move(scene)),
      world_({.fat_margin = scene_.fat_margin,
              .proximity_margin = scene_.proximity_margin,
              .contacts = scene_.contacts,
              .threads = threads,
              .overlap_areas = scene_.overlap_areas}) {
  check_motion(scene_);
  std::vector<ShapeDef> shapes;
  for (const SceneBody& b : scene_.bodies) {
    if (!b.chain.empty()) {
      ids_.push_back(world_.add_chain(b.chain, b.loop, {.user_id = b.id, .filter = b.filter}));
      continue;
    }
    const BodyDef def{.user_id = b.id, .filter = b.filter, .is_static = b.is_static, .sensor = b.sensor};
    shapes.clear();
    for (const Shape& s : b.shapes) shapes.push_back({.shape = s});
    ids_.push_back(world_.add(b.pose, shapes, def));
    if (b.continuous) world_.set_continuous(ids_.back());
  }
  for (const SceneMover& m : scene_.movers) movers_.push_back({.shape = m.shape, .ground = {}, .planes = {}});
  mover_velocity_.assign(movers_.size(), Vec2::Zero());
}

RunSummary scene_totals(const Scene& scene) {
  const auto count = [&scene](bool SceneBody::*flag) {
    return static_cast<std::size_t>(
        std::count_if(scene.bodies.begin(), scene.bodies.end(), [flag](const SceneBody& b) { return b.*flag; }));
  };
  RunSummary s;
  s.frames = scene.frames;
  s.bodies = scene.bodies.size();
  s.continuous = count(&SceneBody::continuous);
  s.statics = count(&SceneBody::is_static);
  s.sensors = count(&SceneBody::sensor);
  s.movers = scene.movers.size();
  if (scene.overlap_areas) s.overlap_area_per_frame = std::array<double, 2>{0.0, 0.0};
  return s;
}

void finish(RunSummary& s, std::vector<double> broad_ms, std::vector<double> narrow_ms) {
  const double n = std::max(1, s.frames);
  s.candidates_per_frame /= n;
  s.filtered_per_frame /= n;
  s.overlapping_per_frame /= n;
  s.proximity_per_frame /= n;
  s.sensing_per_frame /= n;
  if (s.overlap_area_per_frame) {
    for (double& area : *s.overlap_area_per_frame) area /= n;
  }
  s.movers_on_ground /= n * static_cast<double>(std::max<std::size_t>(1, s.movers));
  s.broad = phase_times(std::move(broad_ms));
  s.narrow = phase_times(std::move(narrow_ms));
}

void SceneRun::frame() {
  step(scene_);
  for (std::size_t k = 0; k < ids_.size(); ++k) {
    const SceneBody& b = scene_.bodies[k];
    if (!b.is_static) world_.move_to(ids_[k], b.pose.position, b.pose.angle);
  }
  world_.update();
  move_movers();
  ++frame_;
}

// The script's walk and jump for this frame, gravity, then move(); the planes the replay shows are
// those of the surfaces within twice the skin of where it ends.
void SceneRun::move_movers() {
  for (std::size_t k = 0; k < movers_.size(); ++k) {
    const SceneMover& script = scene_.movers[k];
    MoverRecord& m = movers_[k];
    Vec2& v = mover_velocity_[k];
    const auto walking =
        std::find_if(script.walk.rbegin(), script.walk.rend(), [this](const auto& w) { return w.first <= frame_; });
    v.x() = walking == script.walk.rend() ? 0.0 : walking->second;
    v.y() -= script.gravity * scene_.dt;
    if (m.ground.on_ground && std::binary_search(script.jumps.begin(), script.jumps.end(), frame_))
      v.y() = script.jump_speed;
    const MoveResult r = move(world_, m.shape, v, scene_.dt, script.options, m.ground);
    m.shape = moved_to(m.shape, r.position);
    m.ground = r.ground;
    MoverQuery near = script.options.query;
    near.skin *= 2;  // a surface it rests on is the skin away, give or take rounding
    m.planes = world_.collide_mover(m.shape, near);
    v = r.velocity;
  }
}

RunSummary SceneRun::run(std::ostream* progress, Recorder* recorder) {
  RunSummary s = scene_totals(scene_);
  s.threads = world_.threads();
  std::vector<double> broad, narrow;
  const int every = std::max(1, scene_.frames / 50);
  for (int frame = 0; frame < scene_.frames; ++frame) {
    this->frame();
    if (recorder) recorder->record(world_, movers_);
    for (const MoverRecord& m : movers_) s.movers_on_ground += m.ground.on_ground;
    const FrameStats& f = world_.last_frame();
    broad.push_back(1e3 * f.broad_seconds);
    narrow.push_back(1e3 * f.narrow_seconds);
    s.candidates_per_frame += static_cast<double>(f.candidates);
    s.filtered_per_frame += static_cast<double>(f.filtered);
    s.overlapping_per_frame += static_cast<double>(f.overlapping);
    s.proximity_per_frame += static_cast<double>(f.proximity);
    s.began += world_.began().size();
    s.ended += world_.ended().size();
    s.impacts += world_.impacts().size();
    s.sensing_per_frame += static_cast<double>(world_.body_sensing().size());
    s.sensor_began += world_.body_sensor_began().size();
    s.sensor_ended += world_.body_sensor_ended().size();
    if (s.overlap_area_per_frame) add_overlap_areas(overlap_areas(world_.contacts(), world_.sensing()), s);
    if (progress && ((frame + 1) % every == 0 || frame + 1 == scene_.frames))
      draw_progress(*progress, frame + 1, scene_.frames);
  }
  if (progress) *progress << '\n';
  std::vector<std::pair<std::uint64_t, std::uint64_t>> sensing;
  for (const SensorVisit& p : world_.body_sensing()) sensing.emplace_back(p.user_sensor, p.user_visitor);
  s.sensor_contents = sensor_contents(scene_, sensing);
  s.state_hash = world_.state_hash();
  finish(s, std::move(broad), std::move(narrow));
  return s;
}

std::vector<RunSummary::Sensor> sensor_contents(const Scene& scene,
                                                const std::vector<std::pair<std::uint64_t, std::uint64_t>>& sensing) {
  std::vector<RunSummary::Sensor> out;
  for (const SceneBody& b : scene.bodies) {
    if (b.sensor) out.push_back({b.id, {}});
  }
  for (const std::pair<std::uint64_t, std::uint64_t>& p : sensing) {
    const auto it = std::find_if(out.begin(), out.end(), [&](const RunSummary::Sensor& x) { return x.id == p.first; });
    it->visitors.push_back(p.second);
  }
  return out;
}

std::array<double, 2> overlap_areas(std::span<const BodyContact> contacts, std::span<const SensorPair> sensing) {
  std::array<double, 2> sums{0.0, 0.0};
  for (const BodyContact& c : contacts) sums[0] += c.overlap.area;
  for (const SensorPair& p : sensing) sums[1] += p.overlap.area;
  return sums;
}

void add_overlap_areas(const std::array<double, 2>& areas, RunSummary& s) {
  for (std::size_t k = 0; k < areas.size(); ++k) (*s.overlap_area_per_frame)[k] += areas[k];
}

void print_summary(const RunSummary& s, std::ostream& out) {
  // Under mpirun each rank's broad phase also pairs its ghosts, and each frame waits for the slowest rank.
  if (s.ranks > 1) out << "ranks                       " << s.ranks << " (MPI; times: the slowest rank's)\n";
  out << "frames                      " << s.frames << '\n'
      << "bodies                      " << s.bodies << '\n'
      << "candidate pairs per frame   " << s.candidates_per_frame
      << (s.ranks > 1 ? " (broad phases, summed over the ranks), " : " (broad phase), ") << s.filtered_per_frame
      << " of them dropped by filters\n"
      << "overlapping pairs per frame " << s.overlapping_per_frame << " (narrow phase), " << s.began << " began, "
      << s.ended << " ended over the run\n"
      << "proximity pairs per frame   " << s.proximity_per_frame << '\n'
      << "continuous bodies           " << s.continuous << ", " << s.impacts << " impacts within frames over the run\n"
      << "static bodies               " << s.statics << " (level geometry; sensors included)\n"
      << "sensors                     " << s.sensors << ", " << s.sensing_per_frame << " bodies inside them per frame, "
      << s.sensor_began << " entries and " << s.sensor_ended << " exits over the run\n"
      << "threads                     " << s.threads << (s.ranks > 1 ? " on each rank\n" : "\n");
  if (s.overlap_area_per_frame) {
    const auto& [contacts, sensors] = *s.overlap_area_per_frame;
    out << "overlap area per frame      " << contacts << " in contacts, " << sensors << " inside sensors\n";
  }
  if (s.movers > 0) {
    out << "movers                      " << s.movers << ", on the ground " << 100 * s.movers_on_ground
        << "% of their frames\n";
  }
  out << "broad phase per frame       " << s.broad << '\n' << "narrow phase per frame      " << s.narrow << '\n';
  if (s.state_hash) {
    out << "state hash                  " << std::hex << std::setw(16) << std::setfill('0') << *s.state_hash << std::dec
        << std::setfill(' ') << " (World::state_hash() after the last frame)\n";
  }
  for (const RunSummary::Sensor& sensor : s.sensor_contents) {
    out << "sensor " << sensor.id << " at the last frame: " << sensor.visitors.size() << " bodies";
    constexpr std::size_t kListed = 12;
    for (std::size_t k = 0; k < std::min(kListed, sensor.visitors.size()); ++k)
      out << (k == 0 ? ": " : ", ") << sensor.visitors[k];
    out << (sensor.visitors.size() > kListed ? ", ...\n" : "\n");
  }
}

namespace {

// The fills of the moving bodies' filter categories, in the order the categories sort.
constexpr std::pair<const char*, const char*> kLayerColours[] = {
    {"#9db4cc", "blue"}, {"#c39bd3", "violet"}, {"#82e0aa", "green"}, {"#f7dc6f", "yellow"}, {"#f0b27a", "orange"}};

// What the picture's lines and markers need: the pixel (1/1000 of the arena's width) and a caption
// of at most two lines sized to the width.
struct SvgLayout {
  double pixel;
  double font;
  double height;
};

// The caption spans at most 98% of the width at 0.6 em a character, more than a sans-serif font's
// average, and is 14 pixels high where that allows, in a strip below the arena. Sized by the
// arena's height instead, it would run past the right edge of a square scene.
SvgLayout layout(const Vec2& size, const std::string& line1, const std::string& line2) {
  const double chars = static_cast<double>(std::max(line1.size(), line2.size()));
  const double font = std::min(0.98 * size.x() / (0.6 * chars), 0.014 * size.x());
  return {size.x() / 1000, font, size.y() + 3.5 * font};
}

}  // namespace

void write_svg(const SceneRun& run, std::ostream& out) {
  const Aabb& arena = run.scene().arena;
  const Vec2 size = arena.max - arena.min;
  const World& world = run.world();
  std::set<BodyId> hit, sensing;
  for (const ShapePair& p : world.overlapping()) hit.insert({p.a, p.b});
  for (const SensorPair& p : world.sensing()) sensing.insert(p.sensor);
  std::set<std::uint64_t> categories;
  std::size_t bullets = 0;
  for (const BodyId id : world.bodies()) {
    if (!world.is_static(id) && !world.is_sensor(id)) categories.insert(world.filter(id).category);
    bullets += world.is_continuous(id);
  }
  const auto layer = [&categories](std::uint64_t category) {
    const auto rank = static_cast<std::size_t>(std::distance(categories.begin(), categories.find(category)));
    return rank % std::size(kLayerColours);
  };
  const RunSummary totals = scene_totals(run.scene());
  std::ostringstream line1, line2;
  line1 << world.size() << " bodies (" << totals.statics << " static, slate, outlined red where touched; "
        << totals.sensors << " sensors, dashed): " << world.overlapping().size() << " overlapping pairs (red), "
        << world.proximity().size() << " pairs within " << run.scene().proximity_margin << " (green, ringed)";
  line2 << "moving bodies by filter category:";
  for (const std::uint64_t c : categories) line2 << ' ' << c << ' ' << kLayerColours[layer(c)].second << ',';
  line2 << ' ' << bullets << " continuous (magenta rings)";
  const SvgLayout at = layout(size, line1.str(), line2.str());
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << arena.min.x() << ' ' << -arena.max.y() << ' '
      << size.x() << ' ' << at.height << "\" width=\"1000\" height=\"" << static_cast<int>(1000 * at.height / size.x())
      << "\">\n<style>.body{stroke:#34495e;vector-effect:non-scaling-stroke;stroke-width:0.5}";
  for (std::size_t k = 0; k < std::size(kLayerColours); ++k)
    out << ".layer" << k << "{fill:" << kLayerColours[k].first << '}';
  out << ".body.hit{fill:#e74c3c;stroke:#7b241c}"
         ".static{fill:#5d6d7e;stroke:#1c2833;vector-effect:non-scaling-stroke;stroke-width:0.5}"
         ".static.hit{stroke:#e74c3c;stroke-width:2.5}"
         "line.static{stroke-width:1.5}"
         ".sensor{fill:none;stroke:#b9770e;vector-effect:non-scaling-stroke;stroke-width:1.5;stroke-dasharray:6 4}"
         ".sensor.sensing{fill:#f8c471;fill-opacity:0.35}"
         ".near{fill:none;stroke:#1e8449;vector-effect:non-scaling-stroke;stroke-width:1}"
         ".bullet{fill:none;stroke:#c0399b;vector-effect:non-scaling-stroke;stroke-width:1.5}"
         "text{font-family:sans-serif}</style>\n"
      << "<rect x=\"" << arena.min.x() << "\" y=\"" << -arena.max.y() << "\" width=\"" << size.x() << "\" height=\""
      << size.y() << "\" fill=\"#fbfcfc\" stroke=\"#566573\" vector-effect=\"non-scaling-stroke\"/>\n"
      << "<g transform=\"scale(1,-1)\">\n";
  // Sensors last, so that their outlines are not hidden.
  for (const bool sensors : {false, true}) {
    for (const BodyId id : world.bodies()) {
      if (world.is_sensor(id) != sensors) continue;
      std::string css = sensors               ? (sensing.count(id) ? "sensor sensing" : "sensor")
                        : world.is_static(id) ? "static"
                                              : "body layer" + std::to_string(layer(world.filter(id).category));
      if (!sensors && hit.count(id)) css += " hit";
      for (const ShapeId s : world.shapes(id)) svg_shape(out, world.shape(s), css.c_str());
    }
  }
  // Markers a few pixels across, so that what the caption counts shows at any scale: a ring around
  // each continuous body (a bullet may be smaller than a pixel), and around the middle of each
  // proximity segment (a pair a pixel apart draws a segment a pixel long).
  const auto ring = [&](const char* css, const Vec2& centre, double pixels) {
    out << "<circle class=\"" << css << "\" cx=\"" << centre.x() << "\" cy=\"" << centre.y() << "\" r=\""
        << pixels * at.pixel << "\"/>\n";
  };
  for (const BodyId id : world.bodies()) {
    if (world.is_continuous(id)) ring("bullet", world.pose(id).position, 6);
  }
  for (const Proximity& p : world.proximity()) {
    out << "<line class=\"near\" x1=\"" << p.result.point_a.x() << "\" y1=\"" << p.result.point_a.y() << "\" x2=\""
        << p.result.point_b.x() << "\" y2=\"" << p.result.point_b.y() << "\"/>\n";
    ring("near", 0.5 * (p.result.point_a + p.result.point_b), 3);
  }
  out << "</g>\n";
  const double x = arena.min.x() + 0.01 * size.x();
  out << "<text x=\"" << x << "\" y=\"" << -arena.min.y() + 1.5 * at.font << "\" font-size=\"" << at.font << "\">"
      << line1.str() << "</text>\n<text x=\"" << x << "\" y=\"" << -arena.min.y() + 3 * at.font << "\" font-size=\""
      << at.font << "\">" << line2.str() << "</text>\n</svg>\n";
}

}  // namespace collide2d::tool
