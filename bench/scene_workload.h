// The third narrow-phase workload: pairs as the built-in scene's broad phase hands them over (the
// scene of `collide2d run`: 4,000 mixed bodies, two layers, a static level). Its sweep and prune,
// frame after frame, lists the pairs whose fat boxes meet; those the layers' filters let through
// and that are not two static bodies or a sensor are kept, by kind, in kernel order, until 4,096
// of the kind are found (frames repeat pairs that stay in contact, as a narrow phase sees them).
#pragma once

#include <collide2d/broad_phase.h>
#include <collide2d/world.h>
#include "bench/shape_pairs.h"
#include "tools/scene/scene.h"

#include <stdexcept>
#include <type_traits>
#include <variant>

namespace collide2d::bench {

// Whether S is one of Shape's kinds: a benchmark's own kind (RoundedPolygon) is no scene body's.
template <class S, class V = Shape>
constexpr bool kShapeKind = false;
template <class S, class... Kinds>
constexpr bool kShapeKind<S, std::variant<Kinds...>> = (std::is_same_v<S, Kinds> || ...);

template <class A, class B>
const Workload<A, B>& scene_workload() {
  static const Workload<A, B> w = [] {
    tool::Scene scene = tool::default_scene();
    SweepAndPrune broad(scene.fat_margin);
    std::vector<ProxyId> ids;
    // The built-in scene's bodies are of one shape each but its cave, a chain whose segments pair
    // with no kind here.
    for (const tool::SceneBody& body : scene.bodies) ids.push_back(broad.insert(tool::box_of(body)));
    Workload<A, B> out;
    const auto take = [&](const Shape& x, const Shape& y) {
      if constexpr (!kShapeKind<A> || !kShapeKind<B>) {
        return;
      } else if (std::holds_alternative<A>(x) && std::holds_alternative<B>(y)) {
        out.a.push_back(std::get<A>(x));
        out.b.push_back(std::get<B>(y));
      } else if (std::holds_alternative<B>(x) && std::holds_alternative<A>(y)) {
        out.a.push_back(std::get<A>(y));
        out.b.push_back(std::get<B>(x));
      }
    };
    for (int frame = 0; frame < scene.frames && out.a.size() < kPairs; ++frame) {
      broad.update();
      for (const ProxyPair& p : broad.pairs()) {
        const tool::SceneBody &x = scene.bodies[p.a], &y = scene.bodies[p.b];
        if ((x.is_static && y.is_static) || x.sensor || y.sensor || !should_pair(x.filter, y.filter)) continue;
        if (out.a.size() < kPairs) take(tool::placed_first(x), tool::placed_first(y));
      }
      tool::step(scene);
      for (std::size_t k = 0; k < ids.size(); ++k) broad.move(ids[k], tool::box_of(scene.bodies[k]));
    }
    if (out.a.empty()) throw std::logic_error("the built-in scene pairs no bodies of this kind");
    for (std::size_t k = 0; out.a.size() < kPairs; ++k) {
      out.a.push_back(out.a[k]);
      out.b.push_back(out.b[k]);
    }
    return out;
  }();
  return w;
}

}  // namespace collide2d::bench
