#include "hard_cases.h"

#include "mp_reference.h"

#include "narrowphase/overlap_ellipse_ellipse.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <tuple>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>

namespace collide2d::testing {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
double log_uniform(Rng& rng, double lo, double hi) { return std::exp(uniform(rng, std::log(lo), std::log(hi))); }
Vec2 unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

Shape random_shape(Rng& rng, Kind kind, double size, const Family& f, const Vec2& center) {
  const double aspect = log_uniform(rng, f.aspect_min, f.aspect_max);
  const double angle = uniform(rng, 0.0, 2 * std::numbers::pi);
  const bool long_x = uniform(rng, 0.0, 1.0) < 0.5;
  const double u = long_x ? size : size / aspect;
  const double v = long_x ? size / aspect : size;
  switch (kind) {
    case Kind::circle: return Circle{center, size};
    case Kind::ellipse: return Ellipse{center, u, v, angle};
    case Kind::rect: break;
  }
  return Rect{center, Vec2(u, v), angle};
}

double half_size(const Shape& s) {
  if (const auto* c = std::get_if<Circle>(&s)) return c->radius;
  if (const auto* e = std::get_if<Ellipse>(&s)) return std::max(e->a, e->b);
  return std::get<Rect>(s).half_extents.maxCoeff();
}

void translate(Shape& s, const Vec2& by) { std::visit([&by](auto& x) { x.center += by; }, s); }

struct Contact {
  Vec2 point;
  Vec2 normal;
};

// A boundary point of `a` and its outward unit normal: a rectangle face point half of the time,
// otherwise the support point of a random direction (a corner, for a rectangle).
Contact contact_on(Rng& rng, const Shape& a) {
  if (const auto* r = std::get_if<Rect>(&a); r && uniform(rng, 0.0, 1.0) < 0.5) {
    const int i = uniform(rng, 0.0, 1.0) < 0.5 ? 0 : 1;
    const double side = uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
    Vec2 local, normal = Vec2::Zero();
    local[i] = side * r->half_extents[i];
    local[1 - i] = uniform(rng, -0.9, 0.9) * r->half_extents[1 - i];
    normal[i] = side;
    const Vec2 c = unit(r->angle);
    const auto rotate = [&c](const Vec2& v) { return Vec2(c.x() * v.x() - c.y() * v.y(), c.y() * v.x() + c.x() * v.y()); };
    return {r->center + rotate(local), rotate(normal)};
  }
  const Vec2 n = unit(uniform(rng, 0.0, 2 * std::numbers::pi));
  return {support(a, n), n};
}

// B placed against A with gap `gap` along the contact normal; a rectangle B faces A flat a third
// of the time.
void place_against(Rng& rng, Shape& b, const Contact& c, double gap) {
  if (auto* r = std::get_if<Rect>(&b); r && uniform(rng, 0.0, 1.0) < 1.0 / 3) {
    r->angle = std::atan2(c.normal.y(), c.normal.x());
  }
  translate(b, Vec2(c.point + gap * c.normal - support(b, Vec2(-c.normal))));
}

Shape shrunk_inside(Rng& rng, const Shape& a, Kind kind, const Family& f) {
  double inner = 0.0;
  if (const auto* c = std::get_if<Circle>(&a)) inner = c->radius;
  if (const auto* e = std::get_if<Ellipse>(&a)) inner = std::min(e->a, e->b);
  if (const auto* r = std::get_if<Rect>(&a)) inner = r->half_extents.minCoeff();
  const Vec2 center = center_of(a) + uniform(rng, 0.0, 0.4 * inner) * unit(uniform(rng, 0.0, 6.3));
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
  const Vec2 n = unit(uniform(rng, 0.0, 2 * std::numbers::pi));
  const Vec2 p = support(a, n);
  const double size = 0.5 * least_curvature_radius(a);
  Shape b = kind == Kind::circle ? Shape(Circle{Vec2::Zero(), size})
                                 : Shape(Ellipse{Vec2::Zero(), size, size / uniform(rng, 1.0, 2.0), std::atan2(n.y(), n.x())});
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

std::string describe(const Shape& s) {
  std::ostringstream o;
  o.precision(17);
  std::visit(
      [&o](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        o << (std::is_same_v<T, Circle> ? "circle " : std::is_same_v<T, Ellipse> ? "ellipse " : "rect ");
        o << x.center.x() << ' ' << x.center.y() << ' ';
        if constexpr (std::is_same_v<T, Circle>) o << x.radius;
        if constexpr (std::is_same_v<T, Ellipse>) o << x.a << ' ' << x.b << ' ' << x.angle;
        if constexpr (std::is_same_v<T, Rect>) o << x.half_extents.x() << ' ' << x.half_extents.y() << ' ' << x.angle;
      },
      s);
  return o.str();
}

double ulps_of(const Vec2& p) { return 4 * kU * 2 * std::max(std::abs(p.x()), std::abs(p.y())); }

struct Case {
  Shape a;
  Shape b;
  double delta;      // nominal gap (touching placement), or NaN
};

Case make_case(Rng& rng, const Family& f, int k) {
  const Vec2 origin = f.offset * Vec2(1.0, -0.7) + f.size * Vec2(uniform(rng, -1, 1), uniform(rng, -1, 1));
  Shape a = random_shape(rng, f.a, f.size, f, origin);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (f.placement == Placement::inside) return {a, shrunk_inside(rng, a, f.b, f), nan};
  if (f.placement == Placement::identical) return {a, identical_to(a, f.b), nan};
  if (f.placement == Placement::concentric) return {a, concentric_to(rng, a, f.b), nan};
  const double nominal = f.deltas[static_cast<std::size_t>(k) % f.deltas.size()];
  if (f.placement == Placement::inner_tangent) {
    const double delta = nominal * f.size;
    return {a, inner_tangent(rng, a, f.b, delta), nan};  // the solids overlap clearly either way
  }
  const double ratio = log_uniform(rng, 1.0 / f.size_ratio, f.size_ratio);
  Shape b = random_shape(rng, f.b, f.size * ratio, f, origin);
  const double delta = nominal * std::max(f.size, f.size * ratio);
  place_against(rng, b, contact_on(rng, a), delta);
  return {a, b, delta};
}

void check_points(const Case& c, const DistanceResult& d, double dist_ref, double tol, const std::string& what) {
  const double tol_a = tol + ulps_of(d.point_a);
  const double tol_b = tol + ulps_of(d.point_b);
  const double on_a = static_cast<double>(reference::distance_to(c.a, reference::to_mp(d.point_a)));
  const double on_b = static_cast<double>(reference::distance_to(c.b, reference::to_mp(d.point_b)));
  EXPECT_LE(on_a, tol_a) << what << " point_a is off A";
  EXPECT_LE(on_b, tol_b) << what << " point_b is off B";
  const double reach = static_cast<double>(reference::distance_to(c.b, reference::to_mp(d.point_a)));
  EXPECT_LE(std::abs(reach - dist_ref), tol_a + tol_b) << what << " point_a does not realise the distance";
  EXPECT_LE(std::abs((d.point_b - d.point_a).norm() - d.distance), tol_a + tol_b) << what << " |b - a| != distance";
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
  return out;
}

void PrintTo(const Family& f, std::ostream* os) { *os << f.name; }

std::string test_name(const Family& f) {
  std::string out;
  for (const char ch : f.name) out += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return out;
}

namespace {

bool is_round(const Shape& s) { return !std::holds_alternative<Rect>(s); }
bool is_ellipse(const Shape& s) { return std::holds_alternative<Ellipse>(s); }

Ellipse as_ellipse(const Shape& s) {
  if (const auto* c = std::get_if<Circle>(&s)) return {c->center, c->radius, c->radius, 0.0};
  return std::get<Ellipse>(s);
}

struct References {
  bool overlap = false;
  double distance = 0.0;
  std::optional<double> boundary;  // pairs of circles and ellipses
};

References references_for(const Case& c) {
  References r;
  if (is_round(c.a) && is_round(c.b)) {
    const auto pair = reference::ellipse_pair(as_ellipse(c.a), as_ellipse(c.b));
    r.boundary = static_cast<double>(pair.boundary);
    if (is_ellipse(c.a) && is_ellipse(c.b)) {
      r.overlap = pair.overlap;
      r.distance = static_cast<double>(pair.distance);
      return r;
    }
  }
  r.overlap = reference::overlap(c.a, c.b);
  r.distance = static_cast<double>(reference::distance(c.a, c.b));
  return r;
}

int filter_fallback(const Case& c) {
  if (const auto* r = std::get_if<Rect>(&c.a); r && is_ellipse(c.b)) {
    return overlap_rect_ellipse_filter(*r, std::get<Ellipse>(c.b)) == FilterVerdict::uncertain;
  }
  if (is_ellipse(c.a) && is_ellipse(c.b)) {
    return overlap_ellipse_ellipse_filter(std::get<Ellipse>(c.a), std::get<Ellipse>(c.b)) == FilterVerdict::uncertain;
  }
  return 0;
}

void check_boundary(const Case& c, double ref, double scale, const std::string& what, FamilyStats& stats) {
  const double tol = 1e-12 * scale;
  const DistanceResult d = boundary_distance(c.a, c.b);
  const double err = std::abs(d.distance - ref);
  stats.worst_boundary_error = std::max(stats.worst_boundary_error, err / scale);
  EXPECT_LE(err, tol) << what << " boundary distance " << d.distance << " reference " << ref;
  const double tol_a = tol + ulps_of(d.point_a);
  const double tol_b = tol + ulps_of(d.point_b);
  EXPECT_LE(static_cast<double>(reference::curve_distance(as_ellipse(c.a), reference::to_mp(d.point_a))), tol_a)
      << what << " boundary point_a is off A's curve";
  EXPECT_LE(static_cast<double>(reference::curve_distance(as_ellipse(c.b), reference::to_mp(d.point_b))), tol_b)
      << what << " boundary point_b is off B's curve";
  EXPECT_LE(std::abs((d.point_b - d.point_a).norm() - d.distance), tol_a + tol_b) << what << " boundary |b - a|";
  EXPECT_EQ(boundary_distance(c.b, c.a).distance, d.distance) << what << " boundary distance is not symmetric";
}

// The seed methods on an ellipse pair: measured against the reference, never asserted.
void measure_seed_methods(const Ellipse& a, const Ellipse& b, const References& ref, double scale, FamilyStats& stats) {
  const EllipseDistanceMethod methods[] = {EllipseDistanceMethod::gradient, EllipseDistanceMethod::polynomial};
  for (int m = 0; m < 2; ++m) {
    const auto record = [&](const SolverReport& r, double truth) {
      const double err = std::abs(r.result.distance - truth) / scale;
      stats.method_errors[m].push_back(std::isnan(err) ? INFINITY : err);
      stats.method_unconverged[m] += !r.converged;
      stats.method_wrong[m] += !(err <= 1e-6);
    };
    if (!ref.overlap) record(distance_ellipse_ellipse(a, b, methods[m]), ref.distance);
    record(boundary_distance_ellipse_ellipse(a, b, methods[m]), *ref.boundary);
  }
}

template <class T>
T median(std::vector<T> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

void print_summary(const Family& f, const FamilyStats& stats) {
  std::printf("[family] %-38s cases %4d  verdicts checked %5d  mismatches below target %3d (default %3d)  fallbacks %3d  worst distance error %.2e",
              f.name.c_str(), stats.cases, stats.verdicts_checked, stats.verdict_mismatches_below_target,
              stats.default_mismatches_below_target, stats.fallbacks, stats.worst_distance_error);
  if (f.a != Kind::rect && f.b != Kind::rect) std::printf("  boundary %.2e", stats.worst_boundary_error);
  if (!stats.robust_iterations.empty()) {
    std::printf("  robust median iterations %d", median(stats.robust_iterations));
    const char* names[] = {"gradient", "polynomial"};
    for (int m = 0; m < 2; ++m) {
      const auto& e = stats.method_errors[m];
      std::printf("  %s: %zu queries, median error %.1e, worst %.1e, unconverged %d, error > 1e-6 %d", names[m], e.size(),
                  median(e), *std::max_element(e.begin(), e.end()), stats.method_unconverged[m], stats.method_wrong[m]);
    }
  }
  std::printf("\n");
}

}  // namespace

FamilyStats run_family(const Family& f) {
  Rng rng(f.seed);
  FamilyStats stats;
  // The rect–ellipse overlap methods; other pairs have one overlap test.
  const bool rect_ellipse = (f.a == Kind::rect && f.b == Kind::ellipse) || (f.a == Kind::ellipse && f.b == Kind::rect);
  std::vector<OverlapOptions> methods{{RectEllipseMethod::minkowski}};
  if (rect_ellipse) methods.insert(methods.end(), {{RectEllipseMethod::closest_features}, {RectEllipseMethod::all_features}});
  for (int k = 0; k < f.cases; ++k) {
    const Case c = make_case(rng, f, k);
    const std::string what = f.name + " case " + std::to_string(k) + ": " + describe(c.a) + " ; " + describe(c.b);
    const double size = std::max(half_size(c.a), half_size(c.b));
    const double scale = std::max(size, (center_of(c.b) - center_of(c.a)).norm());
    const double rho = 16 * kU * (std::abs(f.offset) + 4 * size);
    const References ref = references_for(c);
    const double target = 1e-10 * size;
    const bool clear = ref.overlap ? (c.delta < -target - rho || std::isnan(c.delta)) : ref.distance > target;
    ++stats.cases;
    stats.fallbacks += filter_fallback(c);
    for (const OverlapOptions& m : methods) {
      for (const bool swap : {false, true}) {
        const bool got = swap ? overlaps(c.b, c.a, m) : overlaps(c.a, c.b, m);
        if (clear) {
          EXPECT_EQ(got, ref.overlap) << what << " method " << static_cast<int>(m.rect_ellipse) << " swap " << swap;
          ++stats.verdicts_checked;
        } else {
          stats.verdict_mismatches_below_target += got != ref.overlap;
          stats.default_mismatches_below_target += got != ref.overlap && m.rect_ellipse == RectEllipseMethod::minkowski;
        }
      }
    }
    const double tol = 1e-12 * scale;
    const DistanceResult d = distance(c.a, c.b);
    const double err = std::abs(d.distance - ref.distance);
    stats.worst_distance_error = std::max(stats.worst_distance_error, err / scale);
    EXPECT_LE(err, tol) << what << " distance " << d.distance << " reference " << ref.distance;
    check_points(c, d, ref.distance, tol, what);
    const DistanceResult back = distance(c.b, c.a);
    EXPECT_EQ(back.distance, d.distance) << what << " distance is not symmetric";
    EXPECT_EQ(back.point_a, d.point_b) << what << " swapped points";
    if (ref.boundary) check_boundary(c, *ref.boundary, scale, what, stats);
    if (is_ellipse(c.a) && is_ellipse(c.b)) {
      const Ellipse& ea = std::get<Ellipse>(c.a);
      const Ellipse& eb = std::get<Ellipse>(c.b);
      stats.robust_iterations.push_back(distance_ellipse_ellipse(ea, eb).iterations);
      measure_seed_methods(ea, eb, ref, scale, stats);
    }
  }
  print_summary(f, stats);
  return stats;
}

}  // namespace collide2d::testing
