// The golden scene: a World with every shape kind, compound bodies, a chain, segments, sensors,
// continuous bodies, churn and contacts, run for 600 frames; its state hash (World::state_hash())
// every 60th frame must equal the hashes in the file given, on 1, 2 and 8 threads and on every
// Highway target this CPU runs (built for WebAssembly, on its one target and one thread). Those hashes
// were written by this program (--write) and are the same in every build the tests make
// (docs/determinism.md): a build that computes other bits fails here.
//
//   collide2d_golden HASH_FILE           (exit status 0 when every run gives the file's hashes)
//   collide2d_golden --write HASH_FILE   (writes the hashes of a run on one thread)
#include <collide2d/world.h>

#include "tools/random.h"

#include <hwy/targets.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace collide2d;

constexpr int kFrames = 600, kEvery = 60;
constexpr double kSide = 40.0, kStep = 1.0 / 60.0;

struct Mover {
  BodyId id;
  Vec2 velocity;
  double spin;
};

class GoldenScene {
 public:
  explicit GoldenScene(unsigned threads)
      : world_({.fat_margin = 0.1,
                .proximity_margin = 0.3,
                .contacts = true,
                .speculative_margin = 0.1,
                .threads = threads}) {
    add_level();
    for (int k = 0; k < 240; ++k) add_mover(k);
    for (int k = 0; k < 6; ++k) add_bullet();
  }

  // The hash after each kEvery-th of kFrames frames.
  std::vector<std::uint64_t> run() {
    std::vector<std::uint64_t> hashes;
    for (int frame = 1; frame <= kFrames; ++frame) {
      step(frame);
      world_.update();
      count();
      if (frame % kEvery == 0) hashes.push_back(world_.state_hash());
    }
    return hashes;
  }

  // What the frames held, summed: the scene exercises every report the hash covers.
  std::string totals() const {
    char line[160];
    std::snprintf(line, sizeof line, "%zu contacts (%zu touching), %zu proximity pairs, %zu impacts, %zu sensor pairs",
                  contacts_, touching_, proximity_, impacts_, sensing_);
    return line;
  }

 private:
  World world_;
  std::mt19937_64 rng_{2026};
  std::vector<Mover> movers_;
  std::uint64_t next_id_ = 1;
  std::size_t contacts_ = 0, touching_ = 0, proximity_ = 0, impacts_ = 0, sensing_ = 0;

  void count() {
    contacts_ += world_.contacts().size();
    for (const BodyContact& c : world_.contacts()) touching_ += c.touching ? 1 : 0;
    proximity_ += world_.proximity().size();
    impacts_ += world_.impacts().size();
    sensing_ += world_.sensing().size();
  }

  double uniform(double lo, double hi) { return tool::uniform(rng_, lo, hi); }

  // A walled box with a zigzag left wall (a loop chain), two segments, a static polygon, two static
  // sensors, and a compound static body.
  void add_level() {
    std::vector<Vec2> walls{{0, 0}, {kSide, 0}, {kSide, kSide}, {0, kSide}};
    for (int k = 1; k < 8; ++k) walls.emplace_back(k % 2 == 1 ? 1.5 : 0.0, kSide - 5 * k);
    world_.add_chain(walls, true, {.user_id = next_id_++});
    const BodyDef level{.is_static = true};
    world_.add(Segment::between(Vec2(5, 30), Vec2(15, 27)), with_id(level));
    world_.add(Segment::between(Vec2(25, 10), Vec2(35, 13)), with_id(level));
    world_.add(ConvexPolygon::of(std::vector<Vec2>{{-2, -1}, {2, -1}, {0, 2}}, 0.1).at(Vec2(20, 20), 0.3),
               with_id(level));
    const BodyDef sensor{.is_static = true, .sensor = true};
    world_.add(Circle{Vec2(10, 10), 4.0}, with_id(sensor));
    world_.add(Ellipse{Vec2(30, 30), 5.0, 2.0, 0.7}, with_id(sensor));
    const std::vector<ShapeDef> pillar{{.shape = Rect{Vec2(0, 0), Vec2(0.5, 2.0), 0.0}},
                                       {.shape = Circle{Vec2(0, 2.5), 0.8}}};
    world_.add(Pose{.position = Vec2(30, 20)}, pillar, with_id(level));
  }

  BodyDef with_id(BodyDef def) {
    def.user_id = next_id_++;
    return def;
  }

  // Every kind in turn; one in nine a compound of three shapes, one in eleven a sensor.
  Shape random_shape(int k) {
    const double size = uniform(0.3, 1.2);
    const double aspect = uniform(0.2, 1.0);
    const double angle = uniform(-3.0, 3.0);
    switch (k % 5) {
      case 0:
        return Circle{Vec2(0, 0), size};
      case 1:
        return Ellipse{Vec2(0, 0), size, size * aspect, angle};
      case 2:
        return Rect{Vec2(0, 0), Vec2(size, size * aspect), angle};
      case 3:
        return Capsule{Vec2(0, 0), size, size * aspect * 0.5, angle};
      default:
        return ConvexPolygon::of(std::vector<Vec2>{{-size, -0.5 * size}, {size, -aspect * size}, {0.3 * size, size}})
            .at(Vec2(0, 0), angle);
    }
  }

  void add_mover(int k) {
    const double y = uniform(3, kSide - 3);
    const double x = uniform(8, kSide - 3);
    const double vy = uniform(-4, 4);
    const double vx = uniform(-4, 4);
    const double spin = uniform(-1, 1);
    const BodyDef def = with_id({.sensor = k % 11 == 5});
    std::vector<ShapeDef> shapes{{.shape = random_shape(k)}};
    if (k % 9 == 4) {
      shapes.push_back({.shape = Circle{Vec2(1.2, 0), 0.4}});
      shapes.push_back({.shape = Capsule{Vec2(-1.0, 0.5), 0.5, 0.2, 1.0}, .sensor = true});
    }
    movers_.push_back({world_.add(Pose{.position = Vec2(x, y)}, shapes, def), Vec2(vx, vy), spin});
  }

  void add_bullet() {
    const double y = uniform(3, kSide - 3);
    const double vy = uniform(-200, 200);
    const BodyId id = world_.add(Circle{Vec2(20, y), 0.1}, with_id({}));
    world_.set_continuous(id);
    movers_.push_back({id, Vec2(150, vy), 0.0});
  }

  // Moves every mover, turning it back at the walls; every 50th frame replaces the oldest mover.
  void step(int frame) {
    for (Mover& m : movers_) {
      const Pose p = world_.pose(m.id);
      Vec2 at = p.position + kStep * m.velocity;
      for (int axis = 0; axis < 2; ++axis) {
        if ((at[axis] < 1 && m.velocity[axis] < 0) || (at[axis] > kSide - 1 && m.velocity[axis] > 0)) {
          m.velocity[axis] = -m.velocity[axis];
          at[axis] = p.position[axis];
        }
      }
      world_.move_to(m.id, at, p.angle + kStep * m.spin);
    }
    if (frame % 50 == 0) {
      world_.remove(movers_.front().id);
      movers_.erase(movers_.begin());
      add_mover(frame);
    }
  }
};

std::vector<std::uint64_t> read_hashes(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::uint64_t> out;
  std::string word;
  while (in >> word) {
    if (word == "#") {
      std::getline(in, word);
      continue;
    }
    out.push_back(std::stoull(word, nullptr, 16));
  }
  return out;
}

bool write_hashes(const std::string& path) {
  std::ofstream out(path);
  out << "# World::state_hash() of tests/regression/golden.cpp's scene at every " << kEvery << "th frame\n";
  for (const std::uint64_t h : GoldenScene(1).run()) {
    char line[32];
    std::snprintf(line, sizeof line, "%016llx\n", static_cast<unsigned long long>(h));
    out << line;
  }
  return static_cast<bool>(out);
}

// Runs the scene on `threads` threads and says where it departs from `golden`.
bool matches(const std::vector<std::uint64_t>& golden, unsigned threads, const char* target) {
  GoldenScene scene(threads);
  const std::vector<std::uint64_t> got = scene.run();
  for (std::size_t k = 0; k < got.size(); ++k) {
    if (k >= golden.size() || got[k] != golden[k]) {
      std::printf("%s, %u thread(s): frame %zu hashes to %016llx, not %016llx\n", target, threads, (k + 1) * kEvery,
                  static_cast<unsigned long long>(got[k]),
                  static_cast<unsigned long long>(k < golden.size() ? golden[k] : 0));
      return false;
    }
  }
  std::printf("%s, %u thread(s): %zu hashes as golden; %d frames, %s\n", target, threads, got.size(), kFrames,
              scene.totals().c_str());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "--write") return write_hashes(argv[2]) ? 0 : 1;
  if (argc != 2) {
    std::fprintf(stderr, "usage: collide2d_golden [--write] HASH_FILE\n");
    return 2;
  }
  const std::vector<std::uint64_t> golden = read_hashes(argv[1]);
  if (golden.size() != kFrames / kEvery) {
    std::fprintf(stderr, "collide2d_golden: %s holds %zu hashes, not %d\n", argv[1], golden.size(), kFrames / kEvery);
    return 2;
  }
#if HWY_COMPILE_ONLY_STATIC
  // A build with one Highway target and no threads (WebAssembly, scripts/wasm.sh).
  return matches(golden, 1, "static target") ? 0 : 1;
#else
  bool all = true;
  // The best target on 1, 2 and 8 threads; every other target on one.
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  for (const std::int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    for (const unsigned threads : {1u, 2u, 8u}) {
      if (threads > 1 && target != targets.front()) continue;
      all = matches(golden, threads, hwy::TargetName(target)) && all;
    }
  }
  hwy::SetSupportedTargetsForTest(0);
  return all ? 0 : 1;
#endif
}
