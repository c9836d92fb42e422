// Prints a hash of every query's results over fixed workloads, one line per (workload, query): the
// benchmarks' workloads, the hard-case families, the fuzz corpus's pairs and query lines, and two
// scenes run through the World. Two builds whose outputs are the same compute the same bits.
//
//   collide2d_digest CORPUS_FOLDER > digest.txt      (CORPUS_FOLDER: tests/fuzz/corpus)
#include <collide2d/collide2d.h>

#include "bench/scene_workload.h"
#include "bench/shape_pairs.h"
#include "fuzz/fuzz_input.h"
#include "hard_cases.h"
#include "narrowphase/baselines/baselines.h"
#include "narrowphase/internal.h"
#include "tools/query_command.h"
#include "tools/random.h"
#include "tools/scene/scene.h"
#include "tools/scene/scene_run.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace collide2d;

namespace {

bool rect_ellipse_method(const Rect& r, const Ellipse& e, int m) {
  return baselines::overlap_rect_ellipse(
      r, e, m == 1 ? baselines::RectEllipseTest::closest_features : baselines::RectEllipseTest::all_features);
}

detail::SolverReport ellipse_method(const Ellipse& a, const Ellipse& b, int m, bool boundary) {
  const auto s = m == 1 ? baselines::EllipseSolver::gradient : baselines::EllipseSolver::polynomial;
  return boundary ? baselines::curve_distance(a, b, s) : baselines::distance_ellipse_ellipse(a, b, s);
}

struct Hash {
  std::uint64_t h = 1469598103934665603ull;
  std::size_t n = 0;
  void bytes(const void* p, std::size_t size) {
    const auto* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < size; ++i) h = (h ^ c[i]) * 1099511628211ull;
  }
  void add(double x) { bytes(&x, sizeof x); }
  void add(int x) { bytes(&x, sizeof x); }
  void add(std::uint64_t x) { bytes(&x, sizeof x); }
  void add(bool x) { add(int(x)); }
  void add(const Vec2& v) {
    add(v.x());
    add(v.y());
  }
  void add(const std::string& s) { bytes(s.data(), s.size()); }
  void add(const DistanceResult& d) {
    add(d.overlapping);
    add(d.distance);
    add(d.point_a);
    add(d.point_b);
  }
  void add(const Contact& c) {
    add(c.separation);
    add(c.normal);
    add(c.point_a);
    add(c.point_b);
    add(c.manifold_size);
    add(c.evaluations);
    for (const ContactPoint& p : c.points()) {
      add(p.point_a);
      add(p.point_b);
      add(p.separation);
      add(std::uint64_t(p.id));
    }
  }
};

std::map<std::string, Hash> table;
Hash& at(const std::string& workload, const std::string& query) { return table[workload + " " + query]; }

template <class F>
void guarded(Hash& h, F f) {
  try {
    f();
  } catch (const std::exception& e) {
    h.add(std::string("throw:") + e.what());
  }
  ++h.n;
}

// Every query on one pair, hashed under the workload's name.
void pair_queries(const std::string& w, const Shape& a, const Shape& b, bool baselines) {
  guarded(at(w, "overlaps"), [&] {
    at(w, "overlaps").add(overlaps(a, b));
    at(w, "overlaps").add(overlaps(b, a));
  });
  guarded(at(w, "overlaps_box"), [&] { at(w, "overlaps_box").add(overlaps(a, aabb(b))); });
  guarded(at(w, "distance"), [&] {
    at(w, "distance").add(distance(a, b));
    at(w, "distance").add(distance(b, a));
  });
  if (!std::holds_alternative<Rect>(a) && !std::holds_alternative<Rect>(b)) {
    guarded(at(w, "boundary"), [&] { at(w, "boundary").add(boundary_distance(a, b)); });
  }
  guarded(at(w, "contact"), [&] {
    at(w, "contact").add(contact(a, b));
    at(w, "contact").add(contact(b, a, {.margin = 0.05}));
  });
  guarded(at(w, "contact_guess"), [&] {
    const Vec2 d = center_of(b) - center_of(a);
    const Vec2 g = d.norm() > 0 ? Vec2(d.y() * 0.3 + d.x(), d.y() - 0.3 * d.x()) : Vec2(0.6, 0.8);
    at(w, "contact_guess").add(contact(a, b, {.margin = 0.0, .guess = g}));
  });
  guarded(at(w, "posed"), [&] {
    validate(a);
    validate(b);
    const Orientation oa = Orientation::of(angle_of(a)), ob = Orientation::of(angle_of(b));
    at(w, "posed").add(overlaps(a, oa, b, ob));
    at(w, "posed").add(contact(a, oa, b, ob));
  });
  guarded(at(w, "toi"), [&] {
    const Vec2 d = center_of(b) - center_of(a);
    const Motion ma{1.3 * d + Vec2(0.1, -0.2), 0.4};
    const Motion mb{Vec2(-0.05, 0.02), -0.7};
    const TimeOfImpact t = time_of_impact(a, ma, b, mb);
    Hash& h = at(w, "toi");
    h.add(int(t.status));
    h.add(t.t);
    h.add(t.normal);
    h.add(t.point);
    h.add(t.iterations);
    const TimeOfImpact u = time_of_impact(a, {1.5 * d, 0.0}, b, {});
    h.add(int(u.status));
    h.add(u.t);
    h.add(u.normal);
    h.add(u.point);
    h.add(u.iterations);
  });
  guarded(at(w, "shape_cast"), [&] {
    const auto hit = shape_cast(a, 2.0 * (center_of(b) - center_of(a)), b);
    Hash& h = at(w, "shape_cast");
    h.add(hit.has_value());
    if (hit) {
      h.add(hit->fraction);
      h.add(hit->point);
      h.add(hit->normal);
    }
  });
  guarded(at(w, "ray"), [&] {
    const Vec2 origin = center_of(a) + Vec2(3 * reach_of(a), -2 * reach_of(a));
    Vec2 dir = center_of(b) - origin;
    if (dir.norm() == 0) dir = Vec2(1, 0);
    dir.normalize();
    Hash& h = at(w, "ray");
    for (const Shape* s : {&a, &b}) {
      const auto hit = ray_cast(*s, origin, dir, 10 * (reach_of(a) + reach_of(b)) + (center_of(b) - origin).norm());
      h.add(hit.has_value());
      if (hit) {
        h.add(hit->distance);
        h.add(hit->point);
        h.add(hit->normal);
      }
    }
  });
  if (!baselines) return;
  if (std::holds_alternative<Rect>(a) && std::holds_alternative<Ellipse>(b)) {
    guarded(at(w, "baseline_rect_ellipse"), [&] {
      for (int m = 1; m <= 2; ++m)
        at(w, "baseline_rect_ellipse").add(rect_ellipse_method(std::get<Rect>(a), std::get<Ellipse>(b), m));
    });
  }
  if (std::holds_alternative<Ellipse>(a) && std::holds_alternative<Ellipse>(b)) {
    const Ellipse& x = std::get<Ellipse>(a);
    const Ellipse& y = std::get<Ellipse>(b);
    guarded(at(w, "robust_iterations"), [&] {
      const auto r = detail::robust_distance_ellipse_ellipse(x, y);
      at(w, "robust_iterations").add(r.result);
      at(w, "robust_iterations").add(r.iterations);
    });
    for (int m = 1; m <= 2; ++m) {
      for (const bool boundary : {false, true}) {
        Hash& h = at(
            w, std::string("baseline_ellipse_") + (m == 1 ? "gradient" : "polynomial") + (boundary ? "_boundary" : ""));
        guarded(h, [&] {
          const auto r = ellipse_method(x, y, m, boundary);
          h.add(r.result);
          h.add(r.iterations);
          h.add(r.converged);
        });
      }
    }
  }
}

template <class A, class B>
void batches(const std::string& w, const std::vector<A>& a, const std::vector<B>& b) {
  std::vector<Orientation> oa, ob;
  for (const A& x : a) oa.push_back(Orientation::of(angle_of(x)));
  for (const B& y : b) ob.push_back(Orientation::of(angle_of(y)));
  std::vector<std::uint8_t> verdicts(a.size());
  detail::overlap_batch<A, B>(a, oa, b, ob, verdicts);
  Hash& h = at(w, "batch_overlap");
  for (const std::uint8_t v : verdicts) {
    h.add(int(v));
    ++h.n;
  }
  if constexpr (std::is_same_v<A, Circle> && std::is_same_v<B, Ellipse>) {
    std::vector<Contact> contacts(a.size());
    contact_circle_ellipse(a, b, ob, contacts);
    Hash& c = at(w, "batch_contact");
    for (const Contact& x : contacts) {
      c.add(x);
      ++c.n;
    }
  }
}

template <class A, class B>
void bench_workloads(const std::string& kind) {
  const auto run = [&](const std::string& name, const bench::Workload<A, B>& w) {
    for (std::size_t k = 0; k < w.a.size(); ++k) pair_queries(name + "/" + kind, w.a[k], w.b[k], k < 300);
    batches<A, B>(name + "/" + kind, w.a, w.b);
  };
  run("random", bench::workload<A, B>());
  run("candidates", bench::candidate_workload<A, B>());
  run("scene", bench::scene_workload<A, B>());
}

template <class A, class B>
bool is(const Shape& a, const Shape& b) {
  return std::holds_alternative<A>(a) && std::holds_alternative<B>(b);
}

void hard_cases() {
  using testing::Kind;
  const Kind kinds[] = {Kind::rect, Kind::circle, Kind::ellipse};
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      for (const testing::Family& f : testing::standard_families(kinds[i], kinds[j])) {
        const auto cases = testing::family_cases(f);
        std::vector<Rect> rr_a, rr_b;
        std::vector<Rect> re_a;
        std::vector<Ellipse> re_b;
        std::vector<Ellipse> ee_a, ee_b;
        std::vector<Circle> ce_a;
        std::vector<Ellipse> ce_b;
        for (std::size_t k = 0; k < cases.size(); ++k) {
          const auto& c = cases[k];
          pair_queries("hard/" + f.name, c.a, c.b, k < 20);
          if (is<Rect, Ellipse>(c.a, c.b)) {
            re_a.push_back(std::get<Rect>(c.a));
            re_b.push_back(std::get<Ellipse>(c.b));
          }
          if (is<Ellipse, Ellipse>(c.a, c.b)) {
            ee_a.push_back(std::get<Ellipse>(c.a));
            ee_b.push_back(std::get<Ellipse>(c.b));
          }
          if (is<Circle, Ellipse>(c.a, c.b)) {
            ce_a.push_back(std::get<Circle>(c.a));
            ce_b.push_back(std::get<Ellipse>(c.b));
          }
          if (is<Rect, Rect>(c.a, c.b)) {
            rr_a.push_back(std::get<Rect>(c.a));
            rr_b.push_back(std::get<Rect>(c.b));
          }
        }
        if (!re_a.empty()) batches<Rect, Ellipse>("hard/" + f.name, re_a, re_b);
        if (!ee_a.empty()) batches<Ellipse, Ellipse>("hard/" + f.name, ee_a, ee_b);
        if (!ce_a.empty()) batches<Circle, Ellipse>("hard/" + f.name, ce_a, ce_b);
        if (!rr_a.empty()) batches<Rect, Rect>("hard/" + f.name, rr_a, rr_b);
      }
    }
  }
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::filesystem::path> files(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

void corpus(const std::filesystem::path& root) {
  for (const char* name : {"rect_ellipse", "ellipse_ellipse", "rect_rect", "circle"}) {
    for (const auto& p : files(root / name)) {
      const std::string bytes = read(p);
      fuzz::Input in(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      const Shape a = in.shape(), b = in.shape();
      pair_queries(std::string("corpus/") + name, a, b, false);
    }
  }
  // As the fuzz target reads them, a core shape, then any; the valid pairs (an outline that
  // ConvexPolygon::of refused is left out, and the helpers the queries here use take valid shapes).
  for (const auto& p : files(root / "polygon")) {
    const std::string bytes = read(p);
    fuzz::Input in(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    const Shape a = in.shape(fuzz::Kind::cored), b = in.shape(fuzz::Kind::all);
    if (fuzz::valid(a) && fuzz::valid(b)) pair_queries("corpus/polygon", a, b, false);
  }
  for (const auto& p : files(root / "query_line")) {
    const std::string text = read(p);
    for (const auto mode : {tool::Answer::distance, tool::Answer::boundary, tool::Answer::contact, tool::Answer::toi}) {
      std::istringstream in(text);
      std::ostringstream out, err;
      tool::QueryOptions options;
      options.answer = mode;
      const int status = tool::run_query(in, out, err, options);
      Hash& h = at("corpus/query_line", "mode" + std::to_string(int(mode)));
      h.add(status);
      h.add(out.str());
      ++h.n;
      Hash& e = at("corpus/query_line", "errors" + std::to_string(int(mode)));
      e.add(err.str());
      ++e.n;
    }
  }
}

void add(Hash& h, const World& world) {
  for (const ShapePair& p : world.overlapping()) {
    h.add(std::uint64_t(p.a.index));
    h.add(std::uint64_t(p.b.index));
  }
  for (const ShapePair& p : world.began()) {
    h.add(std::uint64_t(p.a.index));
    h.add(std::uint64_t(p.b.index));
  }
  for (const ShapePair& p : world.ended()) {
    h.add(std::uint64_t(p.a.index));
    h.add(std::uint64_t(p.b.index));
  }
  for (const Proximity& p : world.proximity()) {
    h.add(std::uint64_t(p.a.index));
    h.add(std::uint64_t(p.b.index));
    h.add(p.result);
  }
  for (const BodyContact& c : world.contacts()) {
    h.add(std::uint64_t(c.a.index));
    h.add(std::uint64_t(c.b.index));
    h.add(c.contact);
  }
  for (const Impact& i : world.impacts()) {
    h.add(std::uint64_t(i.a.index));
    h.add(std::uint64_t(i.b.index));
    h.add(i.t);
    h.add(i.normal);
    h.add(i.point);
  }
  for (const SensorPair& s : world.sensing()) {
    h.add(std::uint64_t(s.sensor.index));
    h.add(std::uint64_t(s.visitor.index));
  }
  for (const SensorPair& s : world.sensor_began()) {
    h.add(std::uint64_t(s.sensor.index));
    h.add(std::uint64_t(s.visitor.index));
  }
  for (const SensorPair& s : world.sensor_ended()) {
    h.add(std::uint64_t(s.sensor.index));
    h.add(std::uint64_t(s.visitor.index));
  }
  const FrameStats& f = world.last_frame();
  h.add(std::uint64_t(f.candidates));
  h.add(std::uint64_t(f.filtered));
  h.add(std::uint64_t(f.requeried));
  ++h.n;
}

void world_queries(Hash& h, const World& world, const Aabb& arena) {
  std::mt19937_64 rng(7);
  const auto u = [&](double lo, double hi) { return tool::uniform(rng, lo, hi); };
  for (int k = 0; k < 200; ++k) {
    // One draw a statement: a call's arguments are evaluated in an order the compiler picks.
    const double py = u(arena.min.y(), arena.max.y());
    const double px = u(arena.min.x(), arena.max.x());
    const Vec2 p(px, py);
    const double dy = u(-1, 1);
    const double dx = u(-1, 1);
    const Vec2 d(dx, dy);
    for (const BodyId id : world.overlapping(Aabb{p, p + Vec2(3, 2)})) h.add(std::uint64_t(id.index));
    for (const BodyId id : world.overlapping(Shape(Ellipse{p, 3, 1, 0.3}))) h.add(std::uint64_t(id.index));
    for (const BodyId id : world.within(p, 2.0)) h.add(std::uint64_t(id.index));
    for (const BodyId id : world.within(Shape(Rect{p, Vec2(1, 2), 0.2}), 0.5)) h.add(std::uint64_t(id.index));
    if (const auto r = world.ray_cast(p, d, 40)) {
      h.add(std::uint64_t(r->body.index));
      h.add(r->distance);
      h.add(r->point);
      h.add(r->normal);
    }
    for (const RayHit& r : world.ray_cast_all(p, d, 40)) {
      h.add(std::uint64_t(r.body.index));
      h.add(r.distance);
      h.add(r.point);
      h.add(r.normal);
    }
    if (const auto c = world.cast(Shape(Circle{p, 0.5}), 10 * d)) {
      h.add(std::uint64_t(c->body.index));
      h.add(c->fraction);
      h.add(c->point);
      h.add(c->normal);
    }
    ++h.n;
  }
}

void worlds() {
  {
    tool::SceneRun run(tool::default_scene(4000, 300));
    Hash& h = at("world", "builtin_scene");
    for (int k = 0; k < 300; ++k) {
      run.frame();
      add(h, run.world());
    }
    world_queries(at("world", "builtin_queries"), run.world(), run.scene().arena);
  }
  {
    tool::Scene scene = tool::default_scene(1500, 120, 3);
    World world(
        {.fat_margin = 0.1, .proximity_margin = 0.4, .contacts = true, .speculative_margin = 0.2, .threads = 1});
    std::vector<BodyId> ids;
    for (const tool::SceneBody& b : scene.bodies) {
      // The built-in scene's bodies are of one shape each but its cave.
      const BodyDef def{.user_id = b.id, .filter = b.filter, .is_static = b.is_static, .sensor = b.sensor};
      ids.push_back(b.chain.empty() ? world.add(tool::placed_first(b), def)
                                    : world.add_chain(b.chain, b.loop, {.user_id = b.id, .filter = b.filter}));
      if (b.continuous) world.set_continuous(ids.back());
    }
    Hash& h = at("world", "contacts_scene");
    for (int frame = 0; frame < scene.frames; ++frame) {
      tool::step(scene);
      for (std::size_t k = 0; k < ids.size(); ++k) {
        if (!scene.bodies[k].is_static)
          world.move_to(ids[k], scene.bodies[k].pose.position, scene.bodies[k].pose.angle);
      }
      world.update();
      add(h, world);
    }
    world_queries(at("world", "contacts_queries"), world, scene.arena);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: collide2d_digest CORPUS_FOLDER\n");
    return 2;
  }
  bench_workloads<Rect, Rect>("rect_rect");
  bench_workloads<Rect, Circle>("rect_circle");
  bench_workloads<Rect, Ellipse>("rect_ellipse");
  bench_workloads<Circle, Circle>("circle_circle");
  bench_workloads<Circle, Ellipse>("circle_ellipse");
  bench_workloads<Ellipse, Ellipse>("ellipse_ellipse");
  hard_cases();
  corpus(argv[1]);
  worlds();
  for (const auto& [name, h] : table) std::printf("%-70s %016llx %zu\n", name.c_str(), (unsigned long long)h.h, h.n);
}
