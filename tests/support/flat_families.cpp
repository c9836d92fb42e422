#include "flat_families.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <ostream>
#include <variant>

namespace collide2d::testing {

const char* name_of(Flat k) {
  constexpr const char* names[] = {"rect", "polygon", "rounded", "capsule", "circle", "ellipse"};
  return names[static_cast<int>(k)];
}

namespace {

constexpr double kPi = std::numbers::pi;

Shape moved_to(Shape s, const Vec2& center) {
  std::visit([&center](auto& x) { x.center = center; }, s);
  return s;
}

}  // namespace

Shape random_shape(Flat kind, double size, double aspect, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double angle = 2 * kPi * unit(rng);
  const double thin = size / std::exp(std::log(aspect) * unit(rng));
  switch (kind) {
    case Flat::rect:
      return Rect{Vec2::Zero(), Vec2(size, thin), angle};
    case Flat::circle:
      return Circle{Vec2::Zero(), size};
    case Flat::ellipse:
      return Ellipse{Vec2::Zero(), size, thin, angle};
    case Flat::capsule: {
      const bool long_one = unit(rng) < 0.5;
      return Capsule{Vec2::Zero(), long_one ? size : thin, long_one ? thin : size, angle};
    }
    case Flat::polygon:
    case Flat::rounded: {
      const int n = 3 + static_cast<int>(unit(rng) * 6);
      std::vector<Vec2> v;
      for (int k = 0; k < n; ++k) {
        const double t = 2 * kPi * (k + 0.6 * unit(rng)) / n;
        v.emplace_back(size * std::cos(t), thin * std::sin(t));
      }
      const double radius = kind == Flat::rounded ? thin * (0.05 + unit(rng)) : 0.0;
      return ConvexPolygon::of(v, radius).at(Vec2::Zero(), angle);
    }
  }
  return Circle{};
}

void PrintTo(const FlatFamily& f, std::ostream* os) { *os << f.name; }

std::vector<FlatFamily> flat_families() {
  const Flat kinds[] = {Flat::rect, Flat::polygon, Flat::rounded, Flat::capsule, Flat::circle};
  const std::vector<double> near = {1e-3, -1e-3, 1e-6, -1e-6, 1e-9, -1e-9, 1e-12, -1e-12, 0.0};
  std::vector<FlatFamily> out;
  for (const Flat a : kinds) {
    for (const Flat b : {Flat::rect, Flat::polygon, Flat::rounded, Flat::capsule, Flat::circle, Flat::ellipse}) {
      if ((a == Flat::circle && b == Flat::circle) || (a == Flat::circle && b == Flat::ellipse)) continue;
      const std::string pair = std::string(name_of(a)) + "_" + name_of(b);
      out.push_back({pair + "_touching", a, b, 1.0, 0.0, 4.0, near});
      out.push_back({pair + "_deep", a, b, 1.0, 0.0, 4.0, {-0.1, -0.5, -0.9, -1.5}});
      out.push_back({pair + "_slivers", a, b, 1.0, 0.0, 1e6, near});
      out.push_back({pair + "_far", a, b, 1.0, 1e9, 4.0, near});
      out.push_back({pair + "_small", a, b, 1e-6, 1e6, 4.0, near});
      out.push_back({pair + "_large", a, b, 1e6, 0.0, 4.0, near});
    }
  }
  return out;
}

std::vector<FlatCase> cases_of(const FlatFamily& f) {
  std::mt19937_64 rng(std::hash<std::string>{}(f.name));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<FlatCase> out;
  for (int k = 0; k < f.cases; ++k) {
    const double delta = f.deltas[k % f.deltas.size()] * f.size;
    const double ratio = std::exp(std::log(3.0) * (2 * unit(rng) - 1));
    const Vec2 at = f.offset * Vec2(unit(rng) - 0.5, unit(rng) - 0.5);
    const Shape a = moved_to(random_shape(f.a, f.size, f.aspect, rng), at);
    const Shape b0 = random_shape(f.b, f.size * ratio, f.aspect, rng);
    const double t = 2 * kPi * unit(rng);
    const Vec2 n(std::cos(t), std::sin(t));
    const Vec2 pa = support(a, n);
    const Vec2 pb = support(b0, Vec2(-n));  // b0 is about the origin
    out.push_back({a, moved_to(b0, pa + delta * n - pb), delta});
  }
  return out;
}

}  // namespace collide2d::testing
