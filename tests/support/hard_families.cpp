// The cases of the hard-case families (hard_cases.h), apart from their checks (hard_cases.cpp):
// no reference and no test framework, so that the query digest builds anywhere, WebAssembly too.
#include "hard_cases.h"

#include <collide2d/query.h>

#include "shapes/elementary.h"
#include "tools/random.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <tuple>
#include <type_traits>

namespace collide2d::testing {
namespace {

using Rng = std::mt19937_64;

using tool::log_uniform;
using tool::uniform;

// Directions come from tool::direction, and below the arc tangent and hypotenuse from the library,
// not the C library: the cases are the same with every C library.
using tool::direction;

Shape random_shape(Rng& rng, Kind kind, double size, const Family& f, const Vec2& center) {
  const double aspect = log_uniform(rng, f.aspect_min, f.aspect_max);
  const double turn = uniform(rng, 0.0, 2 * std::numbers::pi);
  const double angle = f.axis_aligned ? 0.0 : turn;
  const bool long_x = uniform(rng, 0.0, 1.0) < 0.5;
  const double u = long_x ? size : size / aspect;
  const double v = long_x ? size / aspect : size;
  switch (kind) {
    case Kind::circle:
      return Circle{center, size};
    case Kind::ellipse:
      return Ellipse{center, u, v, angle};
    case Kind::rect:
      break;
  }
  return Rect{center, Vec2(u, v), angle};
}

}  // namespace

double half_size(const Shape& s) {
  if (const auto* c = std::get_if<Circle>(&s)) return c->radius;
  if (const auto* e = std::get_if<Ellipse>(&s)) return std::max(e->a, e->b);
  return std::get<Rect>(s).half_extents.maxCoeff();
}

namespace {

void translate(Shape& s, const Vec2& by) {
  std::visit([&by](auto& x) { x.center += by; }, s);
}

struct BoundaryPoint {
  Vec2 point;
  Vec2 normal;
};

// A boundary point of `a` and its outward unit normal: a rectangle face point half of the time,
// otherwise the support point of a random direction (a corner, for a rectangle).
BoundaryPoint contact_on(Rng& rng, const Shape& a) {
  if (const auto* r = std::get_if<Rect>(&a); r && uniform(rng, 0.0, 1.0) < 0.5) {
    const int i = uniform(rng, 0.0, 1.0) < 0.5 ? 0 : 1;
    const double side = uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
    Vec2 local, normal = Vec2::Zero();
    local[i] = side * r->half_extents[i];
    local[1 - i] = uniform(rng, -0.9, 0.9) * r->half_extents[1 - i];
    normal[i] = side;
    const Vec2 c = direction(r->angle);
    const auto rotate = [&c](const Vec2& v) {
      return Vec2(c.x() * v.x() - c.y() * v.y(), c.y() * v.x() + c.x() * v.y());
    };
    return {r->center + rotate(local), rotate(normal)};
  }
  const Vec2 n = direction(uniform(rng, 0.0, 2 * std::numbers::pi));
  return {support(a, n), n};
}

// B placed against A with gap `gap` along the contact normal; a rectangle B faces A flat a third
// of the time.
void place_against(Rng& rng, Shape& b, const BoundaryPoint& c, double gap) {
  if (auto* r = std::get_if<Rect>(&b); r && uniform(rng, 0.0, 1.0) < 1.0 / 3) {
    r->angle = detail::arc_tangent(c.normal.y(), c.normal.x());
  }
  translate(b, Vec2(c.point + gap * c.normal - support(b, Vec2(-c.normal))));
}

Shape shrunk_inside(Rng& rng, const Shape& a, Kind kind, const Family& f) {
  double inner = 0.0;
  if (const auto* c = std::get_if<Circle>(&a)) inner = c->radius;
  if (const auto* e = std::get_if<Ellipse>(&a)) inner = std::min(e->a, e->b);
  if (const auto* r = std::get_if<Rect>(&a)) inner = r->half_extents.minCoeff();
  // One draw per statement (here and below): the order of two draws within one expression is
  // unspecified, and GCC and clang differ; this is GCC's.
  const double angle = uniform(rng, 0.0, 6.3);
  const Vec2 center = center_of(a) + uniform(rng, 0.0, 0.4 * inner) * direction(angle);
  return random_shape(rng, kind, 0.25 * inner, Family{.aspect_min = 1.0, .aspect_max = 2.0}, center);
}

// The smallest radius of curvature of a circle or ellipse: a disc of that radius rolls freely
// inside it (Blaschke), so a shape inside such a disc tangent at p stays inside.
double least_curvature_radius(const Shape& s) {
  if (const auto* c = std::get_if<Circle>(&s)) return c->radius;
  const auto& e = std::get<Ellipse>(s);
  return std::min(e.a, e.b) * std::min(e.a, e.b) / std::max(e.a, e.b);
}

// B inside A with gap delta at a random boundary point of A: B's major axis points along the
// normal there, so B lies in its circumscribed disc, which lies in A's rolling disc.
Shape inner_tangent(Rng& rng, const Shape& a, Kind kind, double delta) {
  const Vec2 n = direction(uniform(rng, 0.0, 2 * std::numbers::pi));
  const Vec2 p = support(a, n);
  const double size = 0.5 * least_curvature_radius(a);
  Shape b = kind == Kind::circle
                ? Shape(Circle{Vec2::Zero(), size})
                : Shape(Ellipse{Vec2::Zero(), size, size / uniform(rng, 1.0, 2.0), detail::arc_tangent(n.y(), n.x())});
  translate(b, Vec2(p - delta * n - support(b, n)));
  return b;
}

// B sharing A's centre, with axes between 0.3 and 1.2 of A's largest and its own angle: nested or
// crossing, with (at least) two equal extrema by central symmetry.
Shape concentric_to(Rng& rng, const Shape& a, Kind kind) {
  const Vec2 c = center_of(a);
  double size = 0.0;
  if (const auto* ci = std::get_if<Circle>(&a)) size = ci->radius;
  if (const auto* e = std::get_if<Ellipse>(&a)) size = std::max(e->a, e->b);
  if (kind == Kind::circle) return Circle{c, size * uniform(rng, 0.3, 1.2)};
  return Ellipse{c, size * uniform(rng, 0.3, 1.2), size * uniform(rng, 0.3, 1.2), uniform(rng, 0.0, 6.3)};
}

// The half size of a shape along n, one of its axis directions (its support function there).
double reach(const Shape& s, const Vec2& n) { return n.dot(support(s, n) - center_of(s)); }

void set_angle(Shape& s, double angle) {
  std::visit(
      [angle](auto& x) {
        if constexpr (!std::is_same_v<std::decay_t<decltype(x)>, Circle>) x.angle = angle;
      },
      s);
}

// One of A's four axis directions: exact unit vectors when A is axis-aligned.
Vec2 axis_direction(Rng& rng, const Shape& a, bool axis_aligned) {
  const int quarter = static_cast<int>(uniform(rng, 0.0, 4.0));
  if (axis_aligned) {
    const Vec2 exact[] = {Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1)};
    return exact[quarter];
  }
  return direction(angle_of(a) + quarter * std::numbers::pi / 2);
}

// B with its axes parallel to A's, against A at gap delta along the axis direction n, its centre on
// that axis line (mirror symmetric) or, for a rectangle A on odd cases, slid along A's face.
Shape mirrored_against(Rng& rng, const Shape& a, Shape b, double delta, int k, const Family& f) {
  set_angle(b, angle_of(a));
  const Vec2 n = axis_direction(rng, a, f.axis_aligned);
  const Vec2 across(-n.y(), n.x());
  Vec2 c = center_of(a) + (reach(a, n) + delta + reach(b, n)) * n;
  if (std::holds_alternative<Rect>(a) && k % 2 == 1) c += uniform(rng, -0.9, 0.9) * reach(a, across) * across;
  translate(b, Vec2(c - center_of(b)));
  return b;
}

// The farthest distance from (0, y), y >= 0, on the minor axis of the ellipse with semi-axes
// major >= minor (x along the major axis) to its curve: the far co-vertex beyond the evolute's cusp
// at y = (major^2 - minor^2) / minor, otherwise the two points off the axis.
double farthest_from_minor_axis(double major, double minor, double y) {
  const double spread = major * major - minor * minor;
  if (y * minor >= spread) return y + minor;
  const double x1 = -minor * minor * y / spread;
  return detail::hypotenuse(major * std::sqrt(std::max(0.0, 1 - (x1 / minor) * (x1 / minor))), x1 - y);
}

// An ellipse E and a circle or ellipse O (B's kind if A is the ellipse, else A's) with O's centre on
// an axis of E near a cusp of E's evolute, where two extrema of the gap merge. Even cases: O inside
// E on the major axis, eta = +-10^-U(0, 8) of the way from the cusp x_c = (a^2 - b^2) / a towards
// the vertex or the centre; O lies in the disc of radius min(b^2 / a, a - |x|) about its centre,
// which lies in E (inside the evolute the curve is at least b^2 / a away, outside it the vertex is
// nearest). Odd cases: E inside O, O centred on the minor axis near the far cusp y_c = (a^2 - b^2) /
// b, holding the disc about its centre that reaches past E's farthest point.
Case cusp_case(Rng& rng, const Family& f, int k, const Vec2& origin) {
  const bool ellipse_first = f.a == Kind::ellipse;
  const Ellipse e = std::get<Ellipse>(random_shape(rng, Kind::ellipse, f.size, f, origin));
  const Kind other = ellipse_first ? f.b : f.a;
  const double major = std::max(e.a, e.b), minor = std::min(e.a, e.b);
  const Vec2 u = f.axis_aligned ? Vec2(1, 0) : direction(e.angle), v(-u.y(), u.x());
  const Vec2 along = e.a >= e.b ? u : v, beside = e.a >= e.b ? v : u;
  const double side = uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
  const double eta_sign = uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
  const double eta = eta_sign * tool::exponential(-uniform(rng, 0.0, 8.0) * tool::logarithm(10.0));
  const double spread = major * major - minor * minor;
  Vec2 c;
  double radius = 0.0;
  if (k % 2 == 0) {
    const double x = spread / major + 0.5 * eta * (major - spread / major);
    c = e.center + side * x * along;
    radius = uniform(rng, 0.05, 0.95) * std::min(minor * minor / major, major - std::abs(x));
  } else {
    const double y = spread / minor * (1 + 0.5 * eta);
    c = e.center + side * y * beside;
    radius = uniform(rng, 1.02, 1.5) * farthest_from_minor_axis(major, minor, y);
  }
  // An ellipse O: the disc's radius as one semi-axis, the other smaller (inside E) or larger (around E).
  const double other_axis = radius * (k % 2 == 0 ? uniform(rng, 0.3, 1.0) : uniform(rng, 1.0, 1.5));
  const bool swap_axes = uniform(rng, 0.0, 1.0) < 0.5;
  const Shape o = other == Kind::circle
                      ? Shape(Circle{c, radius})
                      : Shape(Ellipse{c, swap_axes ? other_axis : radius, swap_axes ? radius : other_axis, e.angle});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return ellipse_first ? Case{e, o, nan} : Case{o, e, nan};
}

Shape congruent_copy(Rng& rng, const Ellipse& e, double by) {
  const double move = uniform(rng, 0.0, 2.0) * by * std::min(e.a, e.b);
  return Ellipse{e.center + move * direction(uniform(rng, 0.0, 2 * std::numbers::pi)), e.a * (1 - by), e.b * (1 - by),
                 e.angle + uniform(rng, -by, by)};
}

Kind kind_of(const Shape& s) {
  if (std::holds_alternative<Rect>(s)) return Kind::rect;
  return std::holds_alternative<Circle>(s) ? Kind::circle : Kind::ellipse;
}

// The same region where the kinds allow it; otherwise the twin inscribed in A (for a circle or an
// ellipse B) or circumscribed about it (for a rectangle B), sharing A's centre and axes.
Shape identical_to(const Shape& a, Kind kind) {
  if (kind_of(a) == kind) return a;
  if (const auto* r = std::get_if<Rect>(&a)) {
    if (kind == Kind::ellipse) return Ellipse{r->center, r->half_extents.x(), r->half_extents.y(), r->angle};
    return Circle{r->center, r->half_extents.minCoeff()};
  }
  if (const auto* c = std::get_if<Circle>(&a)) {
    if (kind == Kind::ellipse) return Ellipse{c->center, c->radius, c->radius, 0.0};
    return Rect{c->center, Vec2(c->radius, c->radius), 0.0};
  }
  const auto& e = std::get<Ellipse>(a);
  if (kind == Kind::circle) return Circle{e.center, std::min(e.a, e.b)};
  return Rect{e.center, Vec2(e.a, e.b), e.angle};
}

}  // namespace

std::string describe(const Shape& s) {
  std::ostringstream o;
  o.precision(17);
  std::visit(
      [&o](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        o << shape_name(Shape(x)) << ' ' << x.center.x() << ' ' << x.center.y() << ' ';
        if constexpr (std::is_same_v<T, Circle>) o << x.radius;
        if constexpr (std::is_same_v<T, Ellipse>) o << x.a << ' ' << x.b << ' ' << x.angle;
        if constexpr (std::is_same_v<T, Rect>) o << x.half_extents.x() << ' ' << x.half_extents.y() << ' ' << x.angle;
        if constexpr (std::is_same_v<T, Capsule>) o << x.half_length << ' ' << x.radius << ' ' << x.angle;
        if constexpr (std::is_same_v<T, ConvexPolygon>) {
          o << x.angle << ' ' << x.radius();
          for (const Vec2& v : x.vertices()) o << ' ' << v.x() << ' ' << v.y();
        }
      },
      s);
  return o.str();
}

namespace {

Case make_case(Rng& rng, const Family& f, int k) {
  const double y = uniform(rng, -1, 1);
  const Vec2 origin = f.offset * Vec2(1.0, -0.7) + f.size * Vec2(uniform(rng, -1, 1), y);
  if (f.placement == Placement::cusp) return cusp_case(rng, f, k, origin);
  Shape a = random_shape(rng, f.a, f.size, f, origin);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (f.placement == Placement::inside) return {a, shrunk_inside(rng, a, f.b, f), nan};
  if (f.placement == Placement::identical) return {a, identical_to(a, f.b), nan};
  if (f.placement == Placement::concentric) return {a, concentric_to(rng, a, f.b), nan};
  const double nominal = f.deltas[static_cast<std::size_t>(k) % f.deltas.size()];
  if (f.placement == Placement::congruent)
    return {a, congruent_copy(rng, std::get<Ellipse>(a), std::abs(nominal)), nan};
  if (f.placement == Placement::inner_tangent) {
    const double delta = nominal * f.size;
    return {a, inner_tangent(rng, a, f.b, delta), nan};  // the solids overlap clearly either way
  }
  const double ratio = log_uniform(rng, 1.0 / f.size_ratio, f.size_ratio);
  Shape b = random_shape(rng, f.b, f.size * ratio, f, origin);
  const double delta = nominal * std::max(f.size, f.size * ratio);
  if (f.placement == Placement::mirrored) return {a, mirrored_against(rng, a, b, delta, k, f), delta};
  place_against(rng, b, contact_on(rng, a), delta);
  return {a, b, delta};
}

const char* kind_word(Kind k) { return k == Kind::rect ? "rect" : k == Kind::circle ? "circle" : "ellipse"; }

}  // namespace

std::vector<Family> standard_families(Kind a, Kind b) {
  const std::string pair = std::string(kind_word(a)) + "-" + kind_word(b) + " ";
  const auto family = [&](const std::string& what) { return Family{.name = pair + what, .a = a, .b = b}; };
  std::vector<Family> out;
  Family tangent = family("near-tangent");
  tangent.cases = 300;
  out.push_back(tangent);
  if (a != Kind::circle || b != Kind::circle) {
    for (const double aspect : {1e2, 1e3, 1e4, 1e5, 1e6}) {
      char what[32];
      std::snprintf(what, sizeof what, "aspect %.0e", aspect);
      Family f = family(what);
      f.aspect_min = f.aspect_max = aspect;
      f.seed = static_cast<std::uint64_t>(aspect);
      out.push_back(f);
    }
  }
  if (a == Kind::ellipse || b == Kind::ellipse) {
    Family f = family("near-circle 1+1e-12");
    f.aspect_min = f.aspect_max = 1 + 1e-12;
    out.push_back(f);
  }
  for (const auto& [what, offset, size] : {std::tuple{"offset 1e6", 1e6, 1.0}, std::tuple{"offset 1e9", 1e9, 1.0},
                                           std::tuple{"size 1e-6", 0.0, 1e-6}, std::tuple{"size 1e6", 0.0, 1e6}}) {
    Family f = family(what);
    f.offset = offset;
    f.size = size;
    f.seed = 7;
    out.push_back(f);
  }
  Family inside = family("B inside A");
  inside.placement = Placement::inside;
  inside.aspect_max = 100;
  out.push_back(inside);
  Family outside{.name = pair + "A inside B", .a = b, .b = a, .aspect_max = 100, .placement = Placement::inside};
  out.push_back(outside);
  Family same = family("identical or inscribed");
  same.placement = Placement::identical;
  same.aspect_max = 1e6;
  out.push_back(same);
  for (const bool aligned : {true, false}) {
    Family f = family(aligned ? "mirrored axis-aligned" : "mirrored turned");
    f.placement = Placement::mirrored;
    f.axis_aligned = aligned;
    f.aspect_max = 10;
    f.seed = aligned ? 19 : 20;
    out.push_back(f);
  }
  const bool round_pair = a != Kind::rect && b != Kind::rect;
  if (round_pair && (a == Kind::ellipse || b == Kind::ellipse)) {
    for (const bool aligned : {true, false}) {
      Family f = family(aligned ? "evolute cusp axis-aligned" : "evolute cusp turned");
      f.placement = Placement::cusp;
      f.axis_aligned = aligned;
      f.cases = 240;
      f.aspect_min = 1.2;
      f.aspect_max = 4;
      f.seed = aligned ? 23 : 24;
      out.push_back(f);
    }
  }
  return out;
}

void PrintTo(const Family& f, std::ostream* os) { *os << f.name; }

std::string test_name(const Family& f) {
  std::string out;
  for (const char ch : f.name) out += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return out;
}

Shape moved(const Shape& s, double turn, const Vec2& shift) {
  const Eigen::Rotation2Dd r(turn);
  return std::visit(
      [&](auto x) -> Shape {
        x.center = r * x.center + shift;
        if constexpr (!std::is_same_v<decltype(x), Circle>) x.angle += turn;
        return x;
      },
      s);
}

std::vector<Case> family_cases(const Family& f) {
  Rng rng(f.seed);
  std::vector<Case> out;
  for (int k = 0; k < f.cases; ++k) out.push_back(make_case(rng, f, k));
  return out;
}

}  // namespace collide2d::testing
