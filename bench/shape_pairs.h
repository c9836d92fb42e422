// The seeded narrow-phase workloads shared by the benchmarks and the query digest: 4,096 pairs of
// each kind, generated once, cycled so that no input stays in a register.
#pragma once

#include <collide2d/chain.h>
#include <collide2d/query.h>
#include <collide2d/shapes.h>

#include "tools/random.h"

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace collide2d::bench {

constexpr std::size_t kPairs = 4096;  // a power of two: the cycle index is a mask

// A convex 8-gon rounded by a radius (ConvexPolygon::radius()): Box2D v3's rounded hulls
// (b2MakePolygon with a radius, b2MakeRoundedBox). A type of its own so that a workload can name it.
struct RoundedPolygon : ConvexPolygon {};

template <class A, class B>
struct Workload {
  std::vector<A> a;
  std::vector<B> b;
};

// Each shape's orientation, kept as the World keeps it (and Box2D its polygons' transforms).
template <class S>
std::vector<Orientation> orientations(const std::vector<S>& shapes) {
  std::vector<Orientation> out;
  for (const S& s : shapes) out.push_back(Orientation::of(angle_of(s)));
  return out;
}

// Random centres in a 4 x 4 square, sizes log-uniform in [0.05, 1], ellipse aspect up to `aspect`.
// The numbers come from tools/random.h and the directions from Orientation::of, the same with every
// standard library and C library; the draws of one call's arguments, whose order the compiler picks,
// are made one a statement (braced lists are in order).
struct Generator {
  std::mt19937_64 rng{2024};
  double aspect = 10.0;
  double uniform(double lo, double hi) { return tool::uniform(rng, lo, hi); }
  double size() { return tool::log_uniform(rng, 0.05, 1.0); }
  Vec2 center() { return {uniform(-2, 2), uniform(-2, 2)}; }
  void make(Rect& r) {
    const Vec2 c = center();
    const double half_y = size();
    const double half_x = size();
    r = Rect{c, Vec2(half_x, half_y), uniform(0, 6.3)};
  }
  void make(Ellipse& e) {
    const double a = size();
    e = Ellipse{center(), a, a / tool::log_uniform(rng, 1.0, aspect), uniform(0, 6.3)};
  }
  void make(Circle& c) { c = Circle{center(), size()}; }
  // A capsule whose radius is its half length over 1 to 4.
  void make(Capsule& c) {
    const double h = size();
    c = Capsule{center(), h, h / uniform(1, 4), uniform(0, 6.3)};
  }
  // A segment of half length size() through a random centre.
  void make(Segment& s) {
    const double h = size();
    const Vec2 c = center();
    const double t = uniform(0, 6.3);
    const Vec2 d = tool::direction(t);
    s = Segment::between(c - h * d, c + h * d);
  }
  // A convex 8-gon: vertices on an ellipse of aspect up to 2, each within a sixteenth of a turn of
  // its regular place; `rounded`, rounded by 5% to 30% of the ellipse's smaller half axis.
  ConvexPolygon polygon(bool rounded) {
    const double a = size(), b = a / uniform(1, 2);
    std::array<Vec2, 8> v;
    for (int k = 0; k < 8; ++k) {
      const double t = (k + uniform(-0.25, 0.25)) * std::numbers::pi / 4;
      const Orientation o = Orientation::of(t);
      v[k] = Vec2(a * o.c, b * o.s);
    }
    const double angle = uniform(0, 6.3);
    const Vec2 c = center();
    const double radius = rounded ? uniform(0.05, 0.3) * b : 0.0;
    return ConvexPolygon::of(v, radius).at(c, angle);
  }
  void make(ConvexPolygon& p) { p = polygon(false); }
  void make(RoundedPolygon& p) { p = {polygon(true)}; }
};

template <class A, class B>
const Workload<A, B>& workload() {
  static const Workload<A, B> w = [] {
    Generator g;
    Workload<A, B> out{std::vector<A>(kPairs), std::vector<B>(kPairs)};
    for (std::size_t k = 0; k < kPairs; ++k) {
      g.make(out.a[k]);
      g.make(out.b[k]);
    }
    return out;
  }();
  return w;
}

// The pairs' shapes made again in pair order, as Box2D's are built into one array in pair order
// (bench/box2d_baseline.h): a polygon's outline then follows the previous pair's in memory, as a
// level built in order has them, rather than wherever the generator's discarded shapes left room.
template <class S>
S made_again(const S& s) {
  return s;
}
inline ConvexPolygon made_again(const ConvexPolygon& p) {
  return ConvexPolygon::of(p.outline->points(), p.radius()).at(p.center, p.angle);
}
inline RoundedPolygon made_again(const RoundedPolygon& p) { return {made_again(static_cast<const ConvexPolygon&>(p))}; }
template <class A, class B>
Workload<A, B> in_pair_order(const Workload<A, B>& w) {
  Workload<A, B> out;
  for (std::size_t k = 0; k < w.a.size(); ++k) {
    out.a.push_back(made_again(w.a[k]));
    out.b.push_back(made_again(w.b[k]));
  }
  return out;
}

// Candidate pairs, as a broad phase hands them over: the same generator, keeping the pairs whose
// boxes overlap.
template <class A, class B>
const Workload<A, B>& candidate_workload() {
  static const Workload<A, B> w = [] {
    Generator g;
    Workload<A, B> out;
    while (out.a.size() < kPairs) {
      A a;
      B b;
      g.make(a);
      g.make(b);
      if (!intersects(aabb(a), aabb(b))) continue;
      out.a.push_back(a);
      out.b.push_back(b);
    }
    return in_pair_order(out);
  }();
  return w;
}

// The built-in scene's broad-phase pairs (bench/scene_workload.h, which a benchmark using them
// includes: it needs the scene code of the command line).
template <class A, class B>
const Workload<A, B>& scene_workload();

// The pairs of w whose solids overlap (touching counts), cycled up to kPairs: the pairs a contact
// solver works on, where Box2D's manifolds are never empty.
template <class A, class B>
Workload<A, B> overlapping(const Workload<A, B>& w) {
  Workload<A, B> out;
  for (std::size_t k = 0; k < w.a.size(); ++k) {
    if (!overlaps(w.a[k], w.b[k])) continue;
    out.a.push_back(w.a[k]);
    out.b.push_back(w.b[k]);
  }
  for (std::size_t k = 0; out.a.size() < kPairs; ++k) {
    out.a.push_back(out.a[k]);
    out.b.push_back(out.b[k]);
  }
  return in_pair_order(out);
}

// The workload's segments as chain segments, each end's neighbour turned 0.3 rad one way or the
// other by the pair's index (convex and concave vertices alike).
inline std::vector<ChainSegment> chain_segments_of(const std::vector<Segment>& segments) {
  std::vector<ChainSegment> out;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const Segment& s = segments[k];
    const auto turned = [&](double t) {
      return Vec2(std::cos(t) * s.end.x() - std::sin(t) * s.end.y(), std::sin(t) * s.end.x() + std::cos(t) * s.end.y());
    };
    out.push_back({s, -turned(k % 2 == 0 ? 0.3 : -0.3), s.end + turned(k % 4 < 2 ? 0.3 : -0.3)});
  }
  return out;
}

}  // namespace collide2d::bench
