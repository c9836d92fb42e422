// The C++ side of bench/python/bench_python.py: the same work as the Python module's calls, on the
// same rows (read from the files the script writes), timed the same way, so that the script can set
// the two side by side. Prints one line per measurement: `<name> <seconds per item>`.
//   python_rival ROWS_A ROWS_B BODIES REPEATS
// ROWS_A, ROWS_B: float64 rows of ellipses (cx cy a b theta), row i with row i; BODIES: the World's
// bodies as the same rows, and after them a frame's new centres and angles (cx cy theta).
#include <collide2d/batch.h>
#include <collide2d/query.h>
#include <collide2d/world.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace collide2d;
using Clock = std::chrono::steady_clock;

std::vector<double> read_doubles(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(std::string("cannot read ") + path);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<double> out(bytes.size() / sizeof(double));
  std::copy(bytes.begin(), bytes.begin() + static_cast<long>(out.size() * sizeof(double)),
            reinterpret_cast<char*>(out.data()));
  return out;
}

std::vector<Ellipse> ellipses(const std::vector<double>& rows, std::size_t count) {
  std::vector<Ellipse> out;
  for (std::size_t i = 0; i < count; ++i) {
    const double* r = &rows[5 * i];
    out.push_back(Ellipse{{r[0], r[1]}, r[2], r[3], r[4]});
  }
  return out;
}

// The median over `repeats` runs of run()'s seconds, per item.
template <class Run>
double median_seconds(int repeats, double items, Run run) {
  std::vector<double> times;
  for (int k = 0; k < repeats; ++k) {
    const auto start = Clock::now();
    run();
    times.push_back(std::chrono::duration<double>(Clock::now() - start).count() / items);
  }
  std::nth_element(times.begin(), times.begin() + repeats / 2, times.end());
  return times[static_cast<std::size_t>(repeats / 2)];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: python_rival ROWS_A ROWS_B BODIES REPEATS\n");
    return 2;
  }
  const std::vector<double> ra = read_doubles(argv[1]), rb = read_doubles(argv[2]), rw = read_doubles(argv[3]);
  const int repeats = std::stoi(argv[4]);
  const std::size_t n = ra.size() / 5;
  const std::vector<Ellipse> a = ellipses(ra, n), b = ellipses(rb, n);
  std::vector<std::uint8_t> hits(n);
  volatile int sink = 0;
  // One call per pair through the Shape entry point, as the module's overlaps(a, b).
  const std::vector<Shape> sa(a.begin(), a.end()), sb(b.begin(), b.end());
  std::printf("overlaps_one_call %.6g\n", median_seconds(repeats, static_cast<double>(n), [&] {
                int count = 0;
                for (std::size_t i = 0; i < n; ++i) count += overlaps(sa[i], sb[i]);
                sink = count;
              }));
  // The batch, the orientations made as the array form makes them.
  std::printf("overlaps_batch %.6g\n", median_seconds(repeats, static_cast<double>(n), [&] {
                std::vector<Orientation> oa, ob;
                for (const Ellipse& e : a) oa.push_back(Orientation::of(e.angle));
                for (const Ellipse& e : b) ob.push_back(Orientation::of(e.angle));
                overlap_ellipse_ellipse(a, oa, b, ob, hits);
              }));
  // A World of the bodies, stepped to the new poses (one thread, as the script's).
  const std::size_t bodies = rw.size() / 8;
  const std::vector<Ellipse> shapes = ellipses(rw, bodies);
  const double* poses = &rw[5 * bodies];
  World world({.fat_margin = 0.05, .threads = 1});
  std::vector<BodyId> ids;
  for (const Ellipse& e : shapes) ids.push_back(world.add(e));
  world.update();
  int frame = 0;
  std::printf("world_step %.6g\n", median_seconds(repeats, 1.0, [&] {
                const double shift = (++frame % 2) * 1e-3;  // to and fro, as the script moves its bodies
                for (std::size_t i = 0; i < bodies; ++i) {
                  const double* p = poses + 3 * i;
                  world.move_to(ids[i], {p[0] + shift, p[1]}, p[2]);
                }
                world.update();
              }));
  return sink < 0 ? 1 : 0;
}
