// `collide2d_report` as a library: speed against error for every ellipse–ellipse distance method on
// one workload, and for the contact depth on another, as tables and as JSON (scripts/bench.sh keeps
// it with the benchmarks' results, and scripts/performance.py plots it).
//
// Workload: `pairs` separated ellipse pairs (seeded; centres in a 4 x 4 square, semi-axes 0.05 to
// 1, aspect up to 10). Reference: the 50-digit distance of tests/mp_reference.h. Methods: robust,
// gradient and polynomial, and Box2D's b2Distance on the inscribed and on the circumscribed N-gons
// for N = 8 ... 256. Time: the median over `repetitions` passes of the mean time per query in the
// pass. Error: |d - d_ref| / max(size, centre distance), median and maximum over the pairs.
//
// Contacts: `pairs` overlapping ellipse pairs of the same generator, deeper than 2% of the larger
// size; collide2d's contact() against Box2D's manifold (b2CollidePolygons) on the inscribed and
// the circumscribed N-gons, N = 5 ... 8 (b2_maxPolygonVertices is 8 in 2.4.1). Error: |separation -
// reference| / scale, the reference being the 50-digit signed distance (a scan of the dual
// function); a Box2D manifold without points (inscribed polygons apart) counts as separation 0.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace collide2d::report {

struct MethodResult {
  std::string method;  // e.g. "robust", "box2d inscribed"
  int sides = 0;       // N for the Box2D polygons, 0 otherwise
  double nanoseconds = 0.0;
  double median_error = 0.0;
  double max_error = 0.0;
};

struct ReportOptions {
  int pairs = 200;
  int repetitions = 5;
  unsigned seed = 1;
};

std::vector<MethodResult> measure_methods(const ReportOptions& options);
std::vector<MethodResult> measure_contact_methods(const ReportOptions& options);

// `title` heads the table, e.g. "ellipse-ellipse distance, 200 separated pairs".
void print_report(const std::vector<MethodResult>& results, const std::string& title, const ReportOptions& options,
                  std::ostream& out);

// Both measurements as one JSON object: {"pairs", "repetitions", "distance": [...], "contact": [...]},
// each result {"method", "sides", "nanoseconds", "median_error", "max_error"}.
void write_report_json(const std::vector<MethodResult>& distance, const std::vector<MethodResult>& contact,
                       const ReportOptions& options, std::ostream& out);

}  // namespace collide2d::report
