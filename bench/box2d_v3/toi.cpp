// Time of impact against Box2D v3's b2TimeOfImpact (linked into bench_toi when a Box2D v3 source is
// given), on the moving pairs of bench/toi_pairs.h: each shape as v3's proxy of it (an ellipse its
// inscribed 8-gon, bench/box2d_v3/shapes.h), each motion as v3's sweep about the shape's centre, both
// relative to A's centre at t = 0, the inputs built beforehand. v3 turns a shape by interpolating
// its rotation's cosine and sine and normalising, where collide2d turns it at a constant rate: the
// two sweeps of a turning pair start and end alike and part between.
#include "bench/box2d_v3/shapes.h"
#include "bench/toi_pairs.h"

#include <box2d/collision.h>

#include <benchmark/benchmark.h>

#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace collide2d {
namespace {

using box2d_v3::posed;

b2ShapeProxy proxy_of(const Shape& shape) {
  return std::visit(
      [](const auto& s) {
        const auto p = posed(s).shape;
        using S = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<S, b2Circle>) {
          return b2MakeProxy(&p.center, 1, p.radius);
        } else if constexpr (std::is_same_v<S, b2Capsule>) {
          const b2Vec2 points[2] = {p.center1, p.center2};
          return b2MakeProxy(points, 2, p.radius);
        } else if constexpr (std::is_same_v<S, b2Segment>) {
          const b2Vec2 points[2] = {p.point1, p.point2};
          return b2MakeProxy(points, 2, 0.0f);
        } else {
          return b2MakeProxy(p.vertices, p.count, p.radius);
        }
      },
      shape);
}

b2Sweep sweep_of(const Shape& s, const Motion& m, const Vec2& origin) {
  const double angle = angle_of(s);
  const b2Transform from = box2d_v3::transform_of(center_of(s) - origin, angle);
  const b2Transform to = box2d_v3::transform_of(center_of(s) + m.velocity - origin, angle + m.angular_velocity);
  return {{0.0f, 0.0f}, from.p, to.p, from.q, to.q};
}

template <class A, class B, bool Turning>
void box2d_v3_toi(benchmark::State& state) {
  const bench::Moving& w = bench::toi_workload<A, B, Turning>();
  std::vector<b2TOIInput> inputs;
  for (std::size_t k = 0; k < bench::kPairs; ++k) {
    const Vec2 origin = center_of(w.a[k]);
    inputs.push_back({proxy_of(w.a[k]), proxy_of(w.b[k]), sweep_of(w.a[k], w.ma[k], origin),
                      sweep_of(w.b[k], w.mb[k], origin), 1.0f});
  }
  bench::time_queries(state, [&](std::size_t k) { return b2TimeOfImpact(&inputs[k]).fraction; });
}

template <class A, class B>
void race(const std::string& name) {
  const std::string gons = std::is_same_v<A, Ellipse> ? "_8gons" : std::is_same_v<B, Ellipse> ? "_8gon" : "";
  benchmark::RegisterBenchmark(("box2d_v3_toi/" + name + "_translating" + gons).c_str(), box2d_v3_toi<A, B, false>);
  benchmark::RegisterBenchmark(("box2d_v3_toi/" + name + "_turning" + gons).c_str(), box2d_v3_toi<A, B, true>);
}

[[maybe_unused]] const bool registered = [] {
  race<Ellipse, Ellipse>("ellipse_ellipse");
  race<Rect, Ellipse>("rect_ellipse");
  race<Circle, Ellipse>("circle_ellipse");
  benchmark::RegisterBenchmark("box2d_v3_toi/rect_rect_turning", box2d_v3_toi<Rect, Rect, true>);
  return true;
}();

}  // namespace
}  // namespace collide2d
