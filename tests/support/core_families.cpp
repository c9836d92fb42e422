#include "core_families.h"

#include "tools/random.h"

#include <Eigen/Geometry>

#include <cmath>
#include <functional>
#include <numbers>
#include <ostream>
#include <type_traits>
#include <variant>
#include <vector>

namespace collide2d::testing {

const char* name_of(Form k) {
  constexpr const char* names[] = {"rect",     "polygon", "rounded", "capsule", "circle", "ellipse",
                                   "triangle", "octagon", "kinked",  "needle",  "stub",   "segment"};
  return names[static_cast<int>(k)];
}

namespace {

constexpr double kPi = std::numbers::pi;

// Every shape made here is about the origin, its centre there but a segment's (its first point):
// each is moved by its centre's shift.
Shape shifted_by(Shape s, const Vec2& offset) {
  std::visit([&offset](auto& x) { x.center += offset; }, s);
  return s;
}

}  // namespace

namespace {

// n vertices on the ellipse of half axes size and thin, one to each of n equal arcs at a random
// place within its first 0.6.
std::vector<Vec2> polygon_around(int n, double size, double thin, std::mt19937_64& rng) {
  const tool::Uniform unit(0.0, 1.0);
  std::vector<Vec2> v;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * kPi * (k + 0.6 * unit(rng)) / n;
    v.emplace_back(size * std::cos(t), thin * std::sin(t));
  }
  return v;
}

// A vertex added 1e-12 of the size outside the middle of a random edge.
std::vector<Vec2> kinked(std::vector<Vec2> v, double size, std::mt19937_64& rng) {
  const std::size_t k = tool::uniform_index(rng, v.size());
  const Vec2 from = v[k], to = v[(k + 1) % v.size()];
  const Vec2 edge = to - from;
  const Vec2 out = Vec2(edge.y(), -edge.x()).normalized();
  v.insert(v.begin() + static_cast<std::ptrdiff_t>(k + 1), (from + to) / 2 + 1e-12 * size * out);
  return v;
}

}  // namespace

Shape random_shape(Form kind, double size, double aspect, std::mt19937_64& rng) {
  const tool::Uniform unit(0.0, 1.0);
  const double angle = 2 * kPi * unit(rng);
  const double thin = size / std::exp(std::log(aspect) * unit(rng));
  const auto polygon = [&](const std::vector<Vec2>& v, double radius) -> Shape {
    return ConvexPolygon::of(v, radius).at(Vec2::Zero(), angle);
  };
  const auto count = [&](int least, int most) { return least + static_cast<int>(unit(rng) * (most - least + 1)); };
  switch (kind) {
    case Form::rect:
      return Rect{Vec2::Zero(), Vec2(size, thin), angle};
    case Form::circle:
      return Circle{Vec2::Zero(), size};
    case Form::ellipse:
      return Ellipse{Vec2::Zero(), size, thin, angle};
    case Form::capsule: {
      const bool long_one = unit(rng) < 0.5;
      return Capsule{Vec2::Zero(), long_one ? size : thin, long_one ? thin : size, angle};
    }
    case Form::needle:
      return Capsule{Vec2::Zero(), size, 1e-9 * size, angle};
    case Form::stub:
      return Capsule{Vec2::Zero(), 1e-9 * size, size, angle};
    case Form::segment:
      return Segment{Vec2(-size * std::cos(angle), -size * std::sin(angle)), Vec2(2 * size, 0), angle};
    case Form::polygon:
      return polygon(polygon_around(count(3, 8), size, thin, rng), 0.0);
    case Form::rounded: {
      const std::vector<Vec2> v = polygon_around(count(3, 8), size, thin, rng);
      return polygon(v, thin * (0.05 + unit(rng)));
    }
    case Form::triangle:
      return polygon(polygon_around(3, size, thin, rng), 0.0);
    case Form::octagon:
      return polygon(polygon_around(8, size, thin, rng), 0.0);
    case Form::kinked:
      return polygon(kinked(polygon_around(count(3, 7), size, thin, rng), size, rng), 0.0);
  }
  return Circle{};
}

void PrintTo(const CoreFamily& f, std::ostream* os) { *os << f.name; }

std::vector<CoreFamily> core_families() {
  const Form kinds[] = {Form::rect, Form::polygon, Form::rounded, Form::capsule, Form::circle};
  const std::vector<double> near = {1e-3, -1e-3, 1e-6, -1e-6, 1e-9, -1e-9, 1e-12, -1e-12, 0.0};
  std::vector<CoreFamily> out;
  const auto add = [&out](Form a, Form b, const std::string& what, double size, double offset, double aspect,
                          const std::vector<double>& deltas, Touch touch = Touch::any) {
    const std::string name = std::string(name_of(a)) + "_" + name_of(b) + "_" + what;
    out.push_back({name, a, b, size, offset, aspect, deltas, 24, touch});
  };
  for (const Form a : kinds) {
    for (const Form b : {Form::rect, Form::polygon, Form::rounded, Form::capsule, Form::circle, Form::ellipse}) {
      if ((a == Form::circle && b == Form::circle) || (a == Form::circle && b == Form::ellipse)) continue;
      add(a, b, "touching", 1.0, 0.0, 4.0, near);
      add(a, b, "deep", 1.0, 0.0, 4.0, {-0.1, -0.5, -0.9, -1.5});
      add(a, b, "slivers", 1.0, 0.0, 1e6, near);
      add(a, b, "far", 1.0, 1e9, 4.0, near);
      add(a, b, "small", 1e-6, 1e6, 4.0, near);
      add(a, b, "large", 1e6, 0.0, 4.0, near);
    }
  }
  const Form faced[] = {Form::rect,    Form::polygon, Form::rounded, Form::capsule, Form::triangle,
                        Form::octagon, Form::kinked,  Form::needle,  Form::stub};
  for (const Form a : faced) {
    for (const Form b : {Form::ellipse, Form::circle, Form::polygon, Form::capsule}) {
      add(a, b, "faces", 1.0, 0.0, 4.0, near, Touch::face);
    }
  }
  for (const Form a : {Form::rect, Form::polygon, Form::rounded, Form::capsule, Form::needle}) {
    for (const Form b : {Form::rect, Form::polygon, Form::rounded, Form::capsule, Form::kinked}) {
      add(a, b, "parallel", 1.0, 0.0, 4.0, near, Touch::parallel);
    }
  }
  for (const Form a : {Form::triangle, Form::octagon, Form::kinked, Form::needle, Form::stub}) {
    for (const Form b : {Form::ellipse, Form::circle, Form::polygon, Form::capsule, Form::needle}) {
      add(a, b, "touching", 1.0, 0.0, 4.0, near);
    }
  }
  for (const Form b : {Form::rect, Form::polygon, Form::rounded, Form::capsule, Form::circle, Form::ellipse,
                       Form::triangle, Form::kinked, Form::needle, Form::stub}) {
    add(Form::segment, b, "touching", 1.0, 0.0, 4.0, near);
    add(Form::segment, b, "deep", 1.0, 0.0, 4.0, {-0.1, -0.5, -0.9, -1.5});
    add(Form::segment, b, "slivers", 1.0, 0.0, 1e6, near);
    add(Form::segment, b, "far", 1.0, 1e9, 4.0, near);
    add(Form::segment, b, "small", 1e-6, 1e6, 4.0, near);
    add(Form::segment, b, "large", 1e6, 0.0, 4.0, near);
    add(Form::segment, b, "faces", 1.0, 0.0, 4.0, near, Touch::face);
    add(Form::segment, b, "parallel", 1.0, 0.0, 4.0, near, Touch::parallel);
  }
  return out;
}

namespace {

// A face of a shape's core, from one end to the other counter-clockwise, with its outward unit normal
// and the rounding radius that moves it out along that normal.
struct Face {
  Vec2 from, to, normal;
  double radius;
};

std::vector<Face> faces_of(const ConvexPolygon& p) {
  const Eigen::Rotation2Dd turn(p.angle);
  const PolygonOutline& o = *p.outline;
  std::vector<Face> out;
  for (int k = 0; k < o.count; ++k) {
    const Vec2 from = p.center + turn * o.vertices[k], to = p.center + turn * o.vertices[(k + 1) % o.count];
    out.push_back({from, to, turn * o.normals[k], o.radius});
  }
  return out;
}

std::vector<Face> faces_of(const Shape& s) {
  if (const auto* r = std::get_if<Rect>(&s)) {
    return faces_of(ConvexPolygon::box(r->half_extents.x(), r->half_extents.y()).at(r->center, r->angle));
  }
  if (const auto* p = std::get_if<ConvexPolygon>(&s)) return faces_of(*p);
  if (const auto* c = std::get_if<Capsule>(&s)) {
    const Vec2 axis(std::cos(c->angle), std::sin(c->angle));
    const Vec2 end = c->half_length * axis, side(axis.y(), -axis.x());
    return {{c->center - end, c->center + end, side, c->radius}, {c->center + end, c->center - end, -side, c->radius}};
  }
  if (const auto* g = std::get_if<Segment>(&s)) {
    const Vec2 to = g->point2(), side = Vec2((to - g->center).y(), -(to - g->center).x()).normalized();
    return {{g->center, to, side, 0.0}, {to, g->center, -side, 0.0}};
  }
  return {};
}

// The point of the rounded face a fraction t of the way along it.
Vec2 point_of(const Face& f, double t) { return f.from + t * (f.to - f.from) + f.radius * f.normal; }

Shape turned(Shape s, double by) {
  std::visit(
      [by](auto& x) {
        if constexpr (!std::is_same_v<std::decay_t<decltype(x)>, Circle>) x.angle += by;
      },
      s);
  return s;
}

double direction_of(const Vec2& v) { return std::atan2(v.y(), v.x()); }

}  // namespace

std::vector<CoreCase> cases_of(const CoreFamily& f) {
  std::mt19937_64 rng(tool::seed_of(f.name));
  const tool::Uniform unit(0.0, 1.0);
  std::vector<CoreCase> out;
  for (int k = 0; k < f.cases; ++k) {
    const double delta = f.deltas[k % f.deltas.size()] * f.size;
    const double ratio = std::exp(std::log(3.0) * (2 * unit(rng) - 1));
    const double y = unit(rng) - 0.5;
    const Vec2 at = f.offset * Vec2(unit(rng) - 0.5, y);
    const Shape a = shifted_by(random_shape(f.a, f.size, f.aspect, rng), at);
    Shape b0 = random_shape(f.b, f.size * ratio, f.aspect, rng);
    const double t = 2 * kPi * unit(rng);
    Vec2 n(std::cos(t), std::sin(t));
    Vec2 pa = support(a, n);
    Vec2 pb = support(b0, Vec2(-n));  // b0 is about the origin
    const std::vector<Face> faces = faces_of(a);
    if (f.touch != Touch::any && !faces.empty()) {
      const Face& face = faces[static_cast<std::size_t>(unit(rng) * faces.size())];
      n = face.normal;
      pa = point_of(face, unit(rng));
      pb = support(b0, Vec2(-n));
      const std::vector<Face> b_faces = faces_of(b0);
      if (f.touch == Touch::parallel && !b_faces.empty()) {
        const Face& b_face = b_faces[static_cast<std::size_t>(unit(rng) * b_faces.size())];
        b0 = turned(b0, direction_of(-n) - direction_of(b_face.normal));
        const std::vector<Face> b_turned = faces_of(b0);
        pb = point_of(b_turned[static_cast<std::size_t>(&b_face - b_faces.data())], unit(rng));
      }
    }
    out.push_back({a, shifted_by(b0, pa + delta * n - pb), delta});
  }
  return out;
}

}  // namespace collide2d::testing
