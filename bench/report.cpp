#include "bench/report.h"

#include <collide2d/kernels.h>
#include "bench/box2d_baseline.h"
#include "mp_reference.h"

#include "narrowphase/baselines/baselines.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <random>

namespace collide2d::report {
namespace {

struct Workload {
  std::vector<Ellipse> a;
  std::vector<Ellipse> b;
  std::vector<double> reference;
  std::vector<double> scale;
};

// Pairs the generator draws until `keep` accepts `pairs` of them, with `reference` for each.
template <class Keep, class Reference>
Workload make_workload(const ReportOptions& options, Keep keep, Reference reference) {
  std::mt19937_64 rng(options.seed);
  const auto uniform = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const auto ellipse = [&] {
    const double a = 0.05 * std::pow(20.0, uniform(0, 1));
    return Ellipse{Vec2(uniform(-2, 2), uniform(-2, 2)), a, a / std::pow(10.0, uniform(0, 1)), uniform(0, 6.3)};
  };
  Workload w;
  while (static_cast<int>(w.a.size()) < options.pairs) {
    const Ellipse a = ellipse(), b = ellipse();
    if (!keep(a, b)) continue;
    w.a.push_back(a);
    w.b.push_back(b);
    w.reference.push_back(reference(a, b));
    w.scale.push_back(std::max({a.a, a.b, b.a, b.b, (b.center - a.center).norm()}));
  }
  return w;
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Runs query(k) over the workload `repetitions` times; the median pass gives the time per query.
template <class Query>
MethodResult measure(const Workload& w, int repetitions, std::string method, int sides, Query query) {
  const std::size_t n = w.a.size();
  std::vector<double> got(n), times;
  for (int r = 0; r < repetitions; ++r) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < n; ++k) got[k] = query(k);
    times.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / n);
  }
  std::vector<double> errors;
  for (std::size_t k = 0; k < n; ++k) errors.push_back(std::abs(got[k] - w.reference[k]) / w.scale[k]);
  return {std::move(method), sides, median(times), median(errors), *std::max_element(errors.begin(), errors.end())};
}

}  // namespace

std::vector<MethodResult> measure_methods(const ReportOptions& options) {
  const Workload w = make_workload(
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

std::vector<MethodResult> measure_contact_methods(const ReportOptions& options) {
  const Workload w = make_workload(
      options,
      [](const Ellipse& a, const Ellipse& b) {
        return contact_ellipse_ellipse(a, b).separation < -0.02 * std::max({a.a, a.b, b.a, b.b});
      },
      [](const Ellipse& a, const Ellipse& b) {
        return static_cast<double>(reference::signed_distance(a, b).separation);
      });
  std::vector<MethodResult> out;
  out.push_back(measure(w, options.repetitions, "collide2d contact", 0,
                        [&w](std::size_t k) { return contact_ellipse_ellipse(w.a[k], w.b[k]).separation; }));
  for (const auto& [name, fit] : {std::pair{"box2d manifold inscribed", baseline::Fit::inscribed},
                                  std::pair{"box2d manifold circumscribed", baseline::Fit::circumscribed}}) {
    for (int sides = 5; sides <= 8; ++sides) {
      std::vector<baseline::ShapePair> pairs;
      for (std::size_t k = 0; k < w.a.size(); ++k) {
        pairs.push_back(baseline::to_box2d_shapes(baseline::to_box2d(w.a[k], sides, fit, w.a[k].center),
                                                  baseline::to_box2d(w.b[k], sides, fit, w.a[k].center)));
      }
      out.push_back(measure(w, options.repetitions, name, sides, [&pairs](std::size_t k) {
        const auto c = baseline::box2d_contact(pairs[k]);
        return c ? c->separation : 0.0;
      }));
    }
  }
  return out;
}

void print_report(const std::vector<MethodResult>& results, const std::string& title, const ReportOptions& options,
                  std::ostream& out) {
  char line[200];
  std::snprintf(line, sizeof line, "%s, time = median of %d passes\n", title.c_str(), options.repetitions);
  out << line;
  out << "| method | N | time per query | median error | max error |\n| --- | --- | --- | --- | --- |\n";
  for (const MethodResult& r : results) {
    std::snprintf(line, sizeof line, "| %s | %s | %.0f ns | %.1e | %.1e |\n", r.method.c_str(),
                  r.sides ? std::to_string(r.sides).c_str() : "-", r.nanoseconds, r.median_error, r.max_error);
    out << line;
  }
  out << "errors are |d - d_ref| / max(size, centre distance); d_ref from 50-digit arithmetic\n";
}

void write_report_json(const std::vector<MethodResult>& distance, const std::vector<MethodResult>& contact,
                       const ReportOptions& options, std::ostream& out) {
  const auto list = [&out](const char* name, const std::vector<MethodResult>& results) {
    out << "  \"" << name << "\": [\n";
    for (std::size_t k = 0; k < results.size(); ++k) {
      const MethodResult& r = results[k];
      char line[300];
      std::snprintf(line, sizeof line,
                    "    {\"method\": \"%s\", \"sides\": %d, \"nanoseconds\": %.6g, \"median_error\": %.6g, "
                    "\"max_error\": %.6g}%s\n",
                    r.method.c_str(), r.sides, r.nanoseconds, r.median_error, r.max_error,
                    k + 1 < results.size() ? "," : "");
      out << line;
    }
    out << "  ]";
  };
  out << "{\n  \"pairs\": " << options.pairs << ",\n  \"repetitions\": " << options.repetitions << ",\n";
  list("distance", distance);
  out << ",\n";
  list("contact", contact);
  out << "\n}\n";
}

}  // namespace collide2d::report
