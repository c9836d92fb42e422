// DistributedWorld's cost per frame, measured under mpirun (scripts/bench.sh runs it with 1 and 2
// ranks): a field of moving ellipses and circles at 8% coverage, BODIES per rank, each rank's slab
// of the same area; the field's height H is the slabs' boundary length, and the height is varied at
// a fixed area per rank, so that the ghosts and the bytes per frame show their growth with the
// boundary. Beside it, one rank's plain World on the same bodies, its posing timed with its update
// (DistributedWorld poses its World's bodies within its update). Each figure is the median over
// FRAMES frames after a warm-up; bytes and ghosts are per rank, the mean over the ranks. Rank 0
// prints one JSON object per line.
//   mpirun -np N bench_distributed [BODIES] [FRAMES]
#include <collide2d/distributed.h>

#include <mpi.h>

#include "tools/random.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace collide2d;
using Clock = std::chrono::steady_clock;

struct Body {
  Shape shape;
  Vec2 velocity;
};

// This rank's bodies: its slab of width `width` (the slabs side by side from x = 0) and height
// `height`, sizes 0.2 to 0.6, 8% of the area covered.
std::vector<Body> field(int rank, std::size_t count, double width, double height) {
  std::mt19937_64 rng(1234 + static_cast<std::uint64_t>(rank));
  const auto unit = [&rng] { return tool::uniform(rng, 0.0, 1.0); };
  std::vector<Body> out;
  for (std::size_t k = 0; k < count; ++k) {
    // One draw a statement, y before x: a call's arguments are evaluated in an order the compiler picks.
    const double y = unit() * height;
    const double x = (rank + unit()) * width;
    const Vec2 c(x, y);
    const double size = 0.2 + 0.4 * unit();
    const Shape s = k % 2 == 0 ? Shape(Circle{c, size}) : Shape(Ellipse{c, size, 0.5 * size, 6.3 * unit()});
    const double vy = 0.2 * (unit() - 0.5);
    const double vx = 0.2 * (unit() - 0.5);
    out.push_back({s, Vec2(vx, vy)});
  }
  return out;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Moves every body by its velocity, turning back at the field's edges.
void advance(std::vector<Body>& bodies, double right, double height) {
  for (Body& b : bodies) {
    Vec2 c = center_of(b.shape);
    if (c.x() + b.velocity.x() < 0 || c.x() + b.velocity.x() > right) b.velocity.x() = -b.velocity.x();
    if (c.y() + b.velocity.y() < 0 || c.y() + b.velocity.y() > height) b.velocity.y() = -b.velocity.y();
    c += b.velocity;
    std::visit([&](auto& s) { s.center = c; }, b.shape);
  }
}

void measure(std::size_t bodies, int frames, double height) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const double mean_area = 3.14159 * 0.16 * 0.75;  // circles and half-height ellipses of mean size 0.4
  const double width = static_cast<double>(bodies) * mean_area / 0.08 / height;
  std::vector<double> bounds;
  for (int k = 1; k < ranks; ++k) bounds.push_back(k * width);
  const WorldOptions options{.fat_margin = 0.1, .threads = 1};
  DistributedWorld world(MPI_COMM_WORLD, {.world = options, .bounds = bounds});
  std::vector<Body> mine = field(rank, bodies, width, height);
  const std::uint64_t first = static_cast<std::uint64_t>(rank) * bodies;
  // Beside it, the rank's own bodies in one plain World, moved alike: the same work without the
  // exchanges (a few bodies cross into the other slab and back; the plain World keeps them all).
  World plain(options);
  std::vector<BodyId> ids;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    world.add(first + k, mine[k].shape);
    ids.push_back(plain.add(mine[k].shape));
  }
  std::vector<double> seconds, bytes, ghosts, migrated, alone;
  for (int frame = 0; frame < frames + 5; ++frame) {
    advance(mine, ranks * width, height);
    for (std::size_t k = 0; k < mine.size(); ++k) {
      if (world.owns(first + k)) world.move_to(first + k, center_of(mine[k].shape), angle_of(mine[k].shape));
    }
    MPI_Barrier(MPI_COMM_WORLD);
    auto start = Clock::now();
    world.update();  // it poses its World's bodies in it
    double took = std::chrono::duration<double>(Clock::now() - start).count();
    MPI_Allreduce(MPI_IN_PLACE, &took, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    start = Clock::now();
    for (std::size_t k = 0; k < mine.size(); ++k)
      plain.move_to(ids[k], center_of(mine[k].shape), angle_of(mine[k].shape));
    plain.update();
    const double plain_took = std::chrono::duration<double>(Clock::now() - start).count();
    if (frame < 5) continue;
    seconds.push_back(took);
    alone.push_back(plain_took);
    bytes.push_back(static_cast<double>(world.stats().bytes_sent));
    ghosts.push_back(static_cast<double>(world.stats().ghosts));
    migrated.push_back(static_cast<double>(world.stats().migrated));
  }
  const std::vector<std::uint64_t> owned = world.owned();
  std::vector<double> sums{median(bytes), median(ghosts), median(migrated), median(alone),
                           static_cast<double>(owned.size())};
  MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf(
        "{\"ranks\": %d, \"bodies_per_rank\": %zu, \"height\": %.6g, \"width\": %.6g, \"frame_ms\": %.6g, "
        "\"world_alone_ms\": %.6g, \"bytes_per_rank\": %.6g, \"ghosts_per_rank\": %.6g, \"migrated_per_rank\": %.6g, "
        "\"owned_per_rank\": %.6g}\n",
        ranks, bodies, height, width, 1e3 * median(seconds), 1e3 * sums[3] / ranks, sums[0] / ranks, sums[1] / ranks,
        sums[2] / ranks, sums[4] / ranks);
  }
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const std::size_t bodies = argc > 1 ? std::stoul(argv[1]) : 50000;
  const int frames = argc > 2 ? std::stoi(argv[2]) : 30;
  // The same area per rank, its boundary with the next slab 1, 2 and 4 times as long.
  const double base = std::sqrt(static_cast<double>(bodies) * 3.14159 * 0.16 * 0.75 / 0.08);
  for (const double stretch : {0.5, 1.0, 2.0}) measure(bodies, frames, base * stretch);
  MPI_Finalize();
}
