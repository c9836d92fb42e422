// Soak run: a World of moving bodies and static bodies (a quarter), 2% of either kind sensors, with
// churn (1% of the moving bodies and one static body removed and as many of each added every frame).
// At every CHECK_EVERY-th frame, the World's overlapping and sensor pairs must equal a brute-force
// test of every pair of bodies under the World's rules (no two static bodies; a sensor only with a
// solid body): no missed and no phantom pair; 100 sampled solid pairs must agree with the
// 50-digit reference, and the heap is compared with its size after the first check (it must not
// grow beyond the live set's). The brute force culls with exact boxes computed in 50 digits and
// rounded outward, not with the aabb() the World uses; the sampled pairs check the overlaps() both
// use, half of them among the World's overlapping pairs.
//
//   collide2d_soak BODIES FRAMES CHECK_EVERY      (exit status 0 when every check passed)
// ctest runs a short one (soak_short); docs/testing.md gives the long one.
#include <collide2d/world.h>
#include "mp_reference.h"
#include "tools/random.h"
#include "world_reference.h"

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace {

using namespace collide2d;

struct Mover {
  BodyId id;
  Vec2 velocity;
};

std::size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

// Brute force: every pair of bodies, exact box against exact box and then shape against shape (an
// overlap lies inside both boxes, so the box test only saves time). At 100,000 bodies this is 5e9
// box tests. Also returns the pairs whose boxes meet, for sampling.
struct BruteForce {
  std::vector<ShapePair> overlapping;
  std::vector<SensorPair> sensing;
  std::vector<ShapePair> boxes_meet;  // the solid pairs the World pairs
};

BruteForce all_pairs(const World& world) {
  BruteForce out;
  for (const ShapePair& p : reference::exact_box_pairs(world, 0.0)) {
    if (world.is_static(p.a) && world.is_static(p.b)) continue;
    const bool sa = world.is_sensor(p.shape_a), sb = world.is_sensor(p.shape_b);
    if (sa && sb) continue;
    const bool touch = overlaps(world.shape(p.shape_a), world.shape(p.shape_b));
    if (sa || sb) {
      if (touch)
        out.sensing.push_back(sa ? SensorPair{p.a, p.b, p.shape_a, p.shape_b}
                                 : SensorPair{p.b, p.a, p.shape_b, p.shape_a});
      continue;
    }
    out.boxes_meet.push_back(p);
    if (touch) out.overlapping.push_back(p);
  }
  std::sort(out.sensing.begin(), out.sensing.end());
  return out;
}

// Pairs sampled from `overlapping` and `boxes_meet` alternately whose verdict in the World differs
// from the 50-digit reference's.
int reference_disagreements(const World& world, const BruteForce& all, std::mt19937_64& rng, int samples) {
  int wrong = 0;
  for (int k = 0; k < samples; ++k) {
    const auto& from = k % 2 == 0 && !all.overlapping.empty() ? all.overlapping : all.boxes_meet;
    if (from.empty()) continue;
    const ShapePair p = from[tool::uniform_index(rng, from.size())];
    const bool reported = std::binary_search(world.overlapping().begin(), world.overlapping().end(), p);
    if (reported != reference::overlap(world.shape(p.shape_a), world.shape(p.shape_b))) {
      std::printf("pair %u-%u: the World says %d, the 50-digit reference %d\n", p.a.index, p.b.index, reported,
                  !reported);
      ++wrong;
    }
  }
  return wrong;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: collide2d_soak BODIES FRAMES CHECK_EVERY\n");
    return 2;
  }
  const int bodies = std::atoi(argv[1]), frames = std::atoi(argv[2]), every = std::max(1, std::atoi(argv[3]));
  std::mt19937_64 rng(99), sample_rng(7);
  constexpr int kReferenceSamples = 100;
  const tool::Uniform u(0.0, 1.0);
  const double side = std::sqrt(28.0 * bodies);
  const auto fresh_shape = [&]() -> Shape {
    const Vec2 c = tool::uniform_point(rng, 0, side);
    const double size = 0.3 + 1.7 * u(rng);
    switch (static_cast<int>(3 * u(rng))) {
      case 0:
        return Circle{c, size};
      case 1:
        return Ellipse{c, size, size / (1 + 7 * u(rng)), 6.3 * u(rng)};
      default:
        return Rect{c, Vec2(size, size * (0.2 + 0.8 * u(rng))), 6.3 * u(rng)};
    }
  };
  World world({.fat_margin = 0.1});
  std::vector<Mover> movers;
  std::vector<BodyId> statics;
  const auto add = [&](bool is_static) {
    const BodyDef def{.user_id = 0, .filter = {}, .is_static = is_static, .sensor = u(rng) < 0.02};
    const BodyId id = world.add(fresh_shape(), def);
    if (is_static) {
      statics.push_back(id);
    } else {
      const double vy = 0.1 * (u(rng) - 0.5);
      movers.push_back({id, Vec2(0.1 * (u(rng) - 0.5), vy)});
    }
  };
  for (int k = 0; k < bodies; ++k) add(k % 4 == 3);
  std::size_t baseline = 0;
  const auto start = std::chrono::steady_clock::now();
  int failures = 0, checks = 0;
  const int churn = std::max(1, static_cast<int>(movers.size()) / 100);
  const auto take = [&](auto& from) {  // a random element out of `from`, swapped with the last
    const auto i = static_cast<std::size_t>(u(rng) * static_cast<double>(from.size()));
    std::swap(from[i], from.back());
    const auto taken = from.back();
    from.pop_back();
    return taken;
  };
  for (int frame = 1; frame <= frames; ++frame) {
    for (int k = 0; k < churn; ++k) {
      world.remove(take(movers).id);
      add(false);
    }
    if (!statics.empty()) {
      world.remove(take(statics));
      add(true);
    }
    for (Mover& m : movers) {
      const Vec2 c = center_of(world.shape(m.id));
      for (int a = 0; a < 2; ++a) {
        if ((c[a] < 0 && m.velocity[a] < 0) || (c[a] > side && m.velocity[a] > 0)) m.velocity[a] = -m.velocity[a];
      }
      world.move_by(m.id, m.velocity, 0.01);
    }
    world.update();
    if (frame % every != 0) continue;
    ++checks;
    const BruteForce all = all_pairs(world);
    if (world.overlapping() != all.overlapping) ++failures;
    if (world.sensing() != all.sensing) ++failures;
    failures += reference_disagreements(world, all, sample_rng, kReferenceSamples);
    const std::size_t heap = heap_in_use();
    if (baseline == 0) baseline = heap;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "frame %6d at %.0f s: %zu bodies (%zu static), %zu overlapping pairs, %zu sensor pairs, heap %.1f MB (first "
        "check %.1f MB), %d failures\n",
        frame, seconds, world.size(), statics.size(), world.overlapping().size(), world.sensing().size(), heap / 1e6,
        baseline / 1e6, failures);
    std::fflush(stdout);
    if (heap > baseline + baseline / 4 + (1u << 20)) {
      std::printf("heap grew beyond the live set\n");
      ++failures;
    }
  }
  std::printf("%d checks (%d pairs against the 50-digit reference each), %d failures\n", checks, kReferenceSamples,
              failures);
  return failures == 0 && checks > 0 ? 0 : 1;
}
