#include "bench/report.h"

#include <collide2d/batch.h>
#include <collide2d/kernels.h>
#include <collide2d/query.h>
#include "bench/box2d_baseline.h"
#ifdef COLLIDE2D_REPORT_BOX2D_V3
#include "bench/box2d_v3/report.h"
#endif
#include "mp_reference.h"

#include "narrowphase/baselines/baselines.h"
#include "tools/random.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

namespace collide2d::tool {
extern const char kReportPage[];  // bench/report.html
}  // namespace collide2d::tool

namespace collide2d::report {
namespace {

// A shape's largest half-size; a polygon's, capsule's or segment's reach_of.
double half_size(const Ellipse& e) { return std::max(e.a, e.b); }
double half_size(const Rect& r) { return r.half_extents.maxCoeff(); }
double half_size(const Circle& c) { return c.radius; }
template <class S>
double half_size(const S& s) {
  return reach_of(Shape(s));
}

// A query's answer: the separation (or distance), and a contact's normal and point (NaN where the
// query or the reference has none).
struct Answer {
  double separation = 0.0;
  Vec2 normal = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
  Vec2 point = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
};
Answer answer_of(double separation) { return {separation}; }
Answer answer_of(const Answer& a) { return a; }
Answer answer_of(const Contact& c) { return {c.separation, c.normal, (c.point_a + c.point_b) / 2}; }

template <class A, class B>
struct Workload {
  std::vector<A> a;
  std::vector<B> b;
  std::vector<Answer> reference;
  std::vector<double> scale;
};

// The random generator's shapes: centres in a 4 x 4 square, sizes 0.05 to 1, aspect up to 10.
struct Generator {
  std::mt19937_64 rng;
  double uniform(double lo, double hi) { return tool::uniform(rng, lo, hi); }
  double size() { return 0.05 * std::pow(20.0, uniform(0, 1)); }
  Vec2 centre() { return {uniform(-2, 2), uniform(-2, 2)}; }
  void make(Ellipse& e) {
    const double a = size();
    e = Ellipse{centre(), a, a / std::pow(10.0, uniform(0, 1)), uniform(0, 6.3)};
  }
  void make(Rect& r) {
    const double h = size();
    r = Rect{centre(), Vec2(h, h / std::pow(10.0, uniform(0, 1))), uniform(0, 6.3)};
  }
  void make(Circle& c) { c = Circle{centre(), size()}; }
  // A polygon: 3 to 8 vertices on an ellipse of the rectangles' sizes, at random angles.
  void make(ConvexPolygon& p) {
    const double h = size(), thin = h / std::pow(10.0, uniform(0, 1));
    const int count = 3 + static_cast<int>(uniform(0, 6));
    std::vector<Vec2> v;
    for (int k = 0; k < count; ++k) {
      const double t = 6.283185307179586 * (k + uniform(0.1, 0.9)) / count;
      v.emplace_back(h * std::cos(t), thin * std::sin(t));
    }
    p = ConvexPolygon::of(v).at(centre(), uniform(0, 6.3));
  }
  void make(Capsule& c) {
    const double h = size();
    c = Capsule{centre(), h, h / std::pow(10.0, uniform(0, 1)), uniform(0, 6.3)};
  }
  void make(Segment& g) {
    const double h = 2 * size(), t = uniform(0, 6.3);
    g = Segment{centre(), Vec2(h * std::cos(t), h * std::sin(t)), 0.0};
  }
};

// Pairs the generator draws until `keep` accepts `pairs` of them, with `reference` for each.
template <class A, class B, class Keep, class Reference>
Workload<A, B> make_workload(const ReportOptions& options, Keep keep, Reference reference) {
  Generator g{std::mt19937_64(options.seed)};
  Workload<A, B> w;
  while (static_cast<int>(w.a.size()) < options.pairs) {
    A a;
    B b;
    g.make(a);
    g.make(b);
    if (!keep(a, b)) continue;
    w.a.push_back(a);
    w.b.push_back(b);
    w.reference.push_back(answer_of(reference(a, b)));
    w.scale.push_back(std::max({half_size(a), half_size(b), (b.center - a.center).norm()}));
  }
  return w;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The median and the largest of a list, NaN for none.
std::pair<double, double> median_and_max(const std::vector<double>& v) {
  if (v.empty()) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  return {median(v), *std::max_element(v.begin(), v.end())};
}

// Runs query(k) over the workload `repetitions` times; the median pass gives the time per query.
template <class A, class B, class Query>
MethodResult measure(const Workload<A, B>& w, int repetitions, std::string method, int sides, Query query) {
  const std::size_t n = w.a.size();
  std::vector<Answer> got(n);
  std::vector<double> times;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < n; ++k) got[k] = answer_of(query(k));
    times.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / n);
  }
  std::vector<double> errors, normals, points;
  for (std::size_t k = 0; k < n; ++k) {
    const Answer &x = got[k], &want = w.reference[k];
    errors.push_back(std::abs(x.separation - want.separation) / w.scale[k]);
    if (x.normal.allFinite() && want.normal.allFinite())
      normals.push_back(std::atan2(std::abs(x.normal.x() * want.normal.y() - x.normal.y() * want.normal.x()),
                                   x.normal.dot(want.normal)));
    if (x.point.allFinite() && want.point.allFinite()) points.push_back((x.point - want.point).norm() / w.scale[k]);
  }
  MethodResult out{
      std::move(method), sides, median(times), median(errors), *std::max_element(errors.begin(), errors.end()), ""};
  std::tie(out.median_normal_error, out.max_normal_error) = median_and_max(normals);
  std::tie(out.median_point_error, out.max_point_error) = median_and_max(points);
  return out;
}

// The 50-digit signed distance, and where its maximiser is unique, its normal and the support
// points' midpoint (where neither support set is a face).
Answer contact_reference(const Shape& a, const Shape& b) {
  const reference::SignedDistance r = reference::signed_distance(a, b);
  Answer out{static_cast<double>(r.separation)};
  const double scale = std::max({reach_of(a), reach_of(b), (center_of(b) - center_of(a)).norm()});
  if (!(r.runner_up < r.separation - reference::Real(1e-9 * scale))) return out;
  out.normal = Vec2(static_cast<double>(r.normal.x), static_cast<double>(r.normal.y));
  const std::optional<reference::Point> pa = reference::support_point(a, r.normal);
  const std::optional<reference::Point> pb = reference::support_point(b, {-r.normal.x, -r.normal.y});
  if (pa && pb) out.point = Vec2(static_cast<double>((pa->x + pb->x) / 2), static_cast<double>((pa->y + pb->y) / 2));
  return out;
}

}  // namespace

std::vector<MethodResult> measure_methods(const ReportOptions& options) {
  const auto w = make_workload<Ellipse, Ellipse>(
      options, [](const Ellipse& a, const Ellipse& b) { return !overlap_ellipse_ellipse(a, b); },
      [](const Ellipse& a, const Ellipse& b) { return static_cast<double>(reference::ellipse_pair(a, b).distance); });
  std::vector<MethodResult> out;
  out.push_back(measure(w, options.repetitions, "robust", 0,
                        [&w](std::size_t k) { return distance_ellipse_ellipse(w.a[k], w.b[k]).distance; }));
  for (const auto& [name, s] : {std::pair{"gradient", baselines::EllipseSolver::gradient},
                                std::pair{"polynomial", baselines::EllipseSolver::polynomial}}) {
    const baselines::EllipseSolver solver = s;  // a structured binding cannot be captured before C++20 in clang 14
    out.push_back(measure(w, options.repetitions, name, 0, [&w, solver](std::size_t k) {
      return baselines::distance_ellipse_ellipse(w.a[k], w.b[k], solver).result.distance;
    }));
  }
  for (const auto& [name, fit] : {std::pair{"box2d inscribed", baseline::Fit::inscribed},
                                  std::pair{"box2d circumscribed", baseline::Fit::circumscribed}}) {
    for (int sides = 8; sides <= 256; sides *= 2) {
      std::vector<baseline::Polygon> pa, pb;
      for (std::size_t k = 0; k < w.a.size(); ++k) {
        pa.push_back(baseline::to_box2d(w.a[k], sides, fit, w.a[k].center));
        pb.push_back(baseline::to_box2d(w.b[k], sides, fit, w.a[k].center));
      }
      out.push_back(measure(w, options.repetitions, name, sides,
                            [&pa, &pb](std::size_t k) { return baseline::box2d_distance(pa[k], pb[k]); }));
    }
  }
  return out;
}

namespace {

// The pair kind's contact and its batch (none where there is no batch), by overload; a polygon's,
// capsule's or segment's through contact(), as the World calls it.
template <class A>
Contact one_off(const A& a, const Ellipse& b, const ContactOptions& options = {}) {
  return contact(Shape(a), Shape(b), options);
}
Contact one_off(const Rect& a, const Ellipse& b, const ContactOptions& options = {}) {
  return contact_rect_ellipse(a, b, options);
}
Contact one_off(const Circle& a, const Ellipse& b, const ContactOptions& options = {}) {
  return contact_circle_ellipse(a, b, options);
}
Contact one_off(const Ellipse& a, const Ellipse& b, const ContactOptions& options = {}) {
  return contact_ellipse_ellipse(a, b, options);
}
bool batch(const std::vector<Circle>& a, const std::vector<Ellipse>& b, std::vector<Contact>& out) {
  std::vector<Orientation> orientations;
  for (const Ellipse& e : b) orientations.push_back(Orientation::of(e.angle));
  contact_circle_ellipse(a, b, orientations, out);
  return true;
}
template <class A>
bool batch(const std::vector<A>&, const std::vector<Ellipse>&, std::vector<Contact>&) {
  return false;
}

// The contact depth of one pair kind: overlapping pairs deeper than 2% of the larger size.
template <class A, class B>
void measure_contact_pairs(const ReportOptions& options, const char* pair, std::vector<MethodResult>& out) {
  const auto w = make_workload<A, B>(
      options,
      [](const A& a, const B& b) { return one_off(a, b).separation < -0.02 * std::max(half_size(a), half_size(b)); },
      [](const A& a, const B& b) { return contact_reference(a, b); });
  const std::size_t first = out.size();
  out.push_back(
      measure(w, options.repetitions, "collide2d contact", 0, [&w](std::size_t k) { return one_off(w.a[k], w.b[k]); }));
  for (int exponent = 1; exponent <= 12; ++exponent) {
    const double fraction = std::pow(10.0, -exponent);
    std::vector<ContactOptions> to(w.a.size());
    for (std::size_t k = 0; k < w.a.size(); ++k)
      to[k].tolerance = fraction * std::max(reach_of(Shape(w.a[k])), reach_of(Shape(w.b[k])));
    out.push_back(measure(w, options.repetitions, "collide2d contact to a tolerance", 0,
                          [&w, &to](std::size_t k) { return one_off(w.a[k], w.b[k], to[k]); }));
    out.back().tolerance = fraction;
  }
  std::vector<Contact> contacts(w.a.size());
  if (batch(w.a, w.b, contacts)) {
    // Timed as a whole list per pass, divided by its pairs; the separations are read back from it.
    out.push_back(measure(w, options.repetitions, "collide2d batch", 0, [&](std::size_t k) {
      if (k == 0) batch(w.a, w.b, contacts);
      return contacts[k];
    }));
  }
  for (const auto& [name, fit] : {std::pair{"box2d manifold inscribed", baseline::Fit::inscribed},
                                  std::pair{"box2d manifold circumscribed", baseline::Fit::circumscribed}}) {
    for (const int sides : {5, 6, 7, 8, 16}) {
      std::vector<baseline::ShapePair> pairs;
      for (std::size_t k = 0; k < w.a.size(); ++k) {
        pairs.push_back(baseline::to_box2d_shapes(baseline::to_box2d(w.a[k], sides, fit, w.a[k].center),
                                                  baseline::to_box2d(w.b[k], sides, fit, w.a[k].center)));
      }
      out.push_back(measure(w, options.repetitions, name, sides, [&pairs, &w](std::size_t k) {
        const auto c = baseline::box2d_contact(pairs[k]);
        return c ? Answer{c->separation, c->normal, c->point + w.a[k].center} : Answer{};
      }));
    }
  }
#ifdef COLLIDE2D_REPORT_BOX2D_V3
  for (int sides = 5; sides <= 8; ++sides) {
    const auto manifold = box2d_v3::manifolds(w.a, w.b, sides);
    out.push_back(measure(w, options.repetitions, "box2d v3 manifold inscribed", sides, [&manifold](std::size_t k) {
      const std::optional<box2d_v3::Deepest> m = manifold(k);
      return m ? Answer{m->separation, m->normal, m->point} : Answer{};
    }));
  }
#endif
  for (std::size_t k = first; k < out.size(); ++k) out[k].pair = pair;
}

}  // namespace

std::vector<MethodResult> measure_contact_methods(const ReportOptions& options) {
  std::vector<MethodResult> out;
  measure_contact_pairs<Rect, Ellipse>(options, "rect-ellipse", out);
  measure_contact_pairs<Circle, Ellipse>(options, "circle-ellipse", out);
  measure_contact_pairs<Ellipse, Ellipse>(options, "ellipse-ellipse", out);
  measure_contact_pairs<ConvexPolygon, Ellipse>(options, "polygon-ellipse", out);
  measure_contact_pairs<Capsule, Ellipse>(options, "capsule-ellipse", out);
  measure_contact_pairs<Segment, Ellipse>(options, "segment-ellipse", out);
  return out;
}

void print_report(const std::vector<MethodResult>& results, const std::string& title, const ReportOptions& options,
                  std::ostream& out) {
  char line[200];
  std::snprintf(line, sizeof line, "%s, time = median of %d passes\n", title.c_str(), options.repetitions);
  out << line;
  const bool contacts = std::any_of(results.begin(), results.end(),
                                    [](const MethodResult& r) { return std::isfinite(r.median_normal_error); });
  out << "| method | N | time per query | median error | max error |"
      << (contacts ? " normal (median / max, rad) | point (median / max) |\n" : "\n")
      << "| --- | --- | --- | --- | --- |" << (contacts ? " --- | --- |\n" : "\n");
  for (const MethodResult& r : results) {
    char n[32] = "-";  // the polygons' N, or a tolerance's fraction of the size
    if (r.sides) std::snprintf(n, sizeof n, "%d", r.sides);
    if (r.tolerance > 0) std::snprintf(n, sizeof n, "%.0e", r.tolerance);
    std::snprintf(line, sizeof line, "| %s | %s | %.0f ns | %.1e | %.1e |", r.method.c_str(), n, r.nanoseconds,
                  r.median_error, r.max_error);
    out << line;
    if (contacts) {
      std::snprintf(line, sizeof line, " %.1e / %.1e | %.1e / %.1e |", r.median_normal_error, r.max_normal_error,
                    r.median_point_error, r.max_point_error);
      out << line;
    }
    out << '\n';
  }
  out << "errors are |d - d_ref| / max(size, centre distance); d_ref from 50-digit arithmetic\n";
}

namespace {

// A number as JSON: null where it is not finite (an error is, where a method failed on some pair).
std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

}  // namespace

void write_report_json(const std::vector<MethodResult>& distance, const std::vector<MethodResult>& contact,
                       const ReportOptions& options, std::ostream& out) {
  const auto list = [&out](const char* name, const std::vector<MethodResult>& results) {
    out << "  \"" << name << "\": [\n";
    for (std::size_t k = 0; k < results.size(); ++k) {
      const MethodResult& r = results[k];
      char line[300];
      std::snprintf(line, sizeof line,
                    "    {\"method\": \"%s\", \"sides\": %d, \"nanoseconds\": %s, \"median_error\": %s, "
                    "\"max_error\": %s%s%s%s%s%s",
                    r.method.c_str(), r.sides, json_number(r.nanoseconds).c_str(), json_number(r.median_error).c_str(),
                    json_number(r.max_error).c_str(), r.pair.empty() ? "" : ", \"pair\": \"", r.pair.c_str(),
                    r.pair.empty() ? "" : "\"", r.tolerance > 0 ? ", \"tolerance\": " : "",
                    r.tolerance > 0 ? json_number(r.tolerance).c_str() : "");
      out << line;
      const std::pair<const char*, double> measured[] = {{"median_normal_error", r.median_normal_error},
                                                         {"max_normal_error", r.max_normal_error},
                                                         {"median_point_error", r.median_point_error},
                                                         {"max_point_error", r.max_point_error}};
      for (const auto& [name, value] : measured) {
        if (std::isfinite(value)) out << ", \"" << name << "\": " << json_number(value);
      }
      out << '}' << (k + 1 < results.size() ? "," : "") << '\n';
    }
    out << "  ]";
  };
  out << "{\n  \"pairs\": " << options.pairs << ",\n  \"repetitions\": " << options.repetitions << ",\n";
  list("distance", distance);
  out << ",\n";
  list("contact", contact);
  out << "\n}\n";
}

void write_report_html(const std::vector<MethodResult>& distance, const std::vector<MethodResult>& contact,
                       const ReportOptions& options, std::ostream& out) {
  std::ostringstream json;
  write_report_json(distance, contact, options, json);
  const std::string_view page = tool::kReportPage, placeholder = "%%REPORT%%";
  const std::size_t at = page.find(placeholder);
  out << page.substr(0, at) << json.str() << page.substr(at + placeholder.size());
}

}  // namespace collide2d::report
