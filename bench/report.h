// `collide2d_report` as a library: speed against error for every ellipse–ellipse distance method on
// one workload, and for the contact depth on another, as tables and as JSON (scripts/bench.sh keeps
// it with the benchmarks' results, and scripts/performance.py plots it).
//
// Workload: `pairs` separated ellipse pairs (seeded; centres in a 4 x 4 square, semi-axes 0.05 to
// 1, aspect up to 10). Reference: the 50-digit distance of tests/support/mp_reference.h. Methods: robust,
// gradient and polynomial, and Box2D's b2Distance on the inscribed and on the circumscribed N-gons
// for N = 8 ... 256. Time: the median over `repetitions` passes of the mean time per query in the
// pass. Error: |d - d_ref| / max(size, centre distance), median and maximum over the pairs.
//
// Contacts, for each pair with an ellipse (rectangle, circle, ellipse, polygon, capsule, segment):
// `pairs` overlapping pairs of the same generator (rectangles and capsules of aspect up to 10,
// circles, polygons of 3 to 8 vertices on such ellipses, segments up to 2 long), deeper than 2% of
// the larger size; collide2d's contact one pair at a time and, where there is one, its batch
// (timed over the whole list, per pair), and to each tolerance from 1e-1 to 1e-12 of the pair's size
// (the larger reach_of), against Box2D's manifold (b2CollidePolygons,
// b2CollidePolygonAndCircle) on the inscribed and the circumscribed N-gons, N = 5 ... 8
// (b2_maxPolygonVertices is 8 in 2.4.1) and 16 (the rebuilt 2.4.1), and where the build has Box2D
// v3 (COLLIDE2D_BOX2D_V3_SOURCE), v3's manifold (bench/box2d_v3/report.h) on the inscribed 5- to
// 8-gons, called as its World calls it. Error: |separation -
// reference| / scale, the reference being the 50-digit signed distance (a scan of the dual
// function); a Box2D manifold without points (inscribed polygons apart) counts as separation 0.
// Where the reference's maximiser is unique (its runner-up 1e-9 of the scale below), also the
// normal's angle from the reference's and the contact point's distance from the reference's
// support points' midpoint over the scale (Box2D's point is its deepest manifold point, midway
// between the surfaces; collide2d's the midpoint of point_a and point_b); a support set that is a
// face has no one point, and the pair's point goes unmeasured.
#pragma once

#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

namespace collide2d::report {

struct MethodResult {
  std::string method;  // e.g. "robust", "box2d inscribed"
  int sides = 0;       // N for the Box2D polygons, 0 otherwise
  double nanoseconds = 0.0;
  double median_error = 0.0;
  double max_error = 0.0;
  std::string pair;        // the pair kind of a contact measurement, e.g. "rect-ellipse"
  double tolerance = 0.0;  // a contact's ContactOptions::tolerance, as a fraction of the pair's size
  // A contact's normal (the angle from the reference's, rad) and point (the deepest points' midpoint,
  // over the scale) on the pairs whose maximiser is unique; NaN for a distance, or where no pair had one.
  double median_normal_error = std::numeric_limits<double>::quiet_NaN();
  double max_normal_error = std::numeric_limits<double>::quiet_NaN();
  double median_point_error = std::numeric_limits<double>::quiet_NaN();
  double max_point_error = std::numeric_limits<double>::quiet_NaN();
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
// each result {"method", "sides", "nanoseconds", "median_error", "max_error"} (an error that is not
// finite, where a method failed on some pair, as null), and "pair" for a contact's, "tolerance" for
// one to a tolerance, "median_normal_error" ... "max_point_error" where measured.
void write_report_json(const std::vector<MethodResult>& distance, const std::vector<MethodResult>& contact,
                       const ReportOptions& options, std::ostream& out);

// The same as one HTML page (bench/report.html, with that JSON inside): the speed-against-error plot,
// each method a point to hover for its figures, the pair kinds to show or hide, beside the tables.
void write_report_html(const std::vector<MethodResult>& distance, const std::vector<MethodResult>& contact,
                       const ReportOptions& options, std::ostream& out);

}  // namespace collide2d::report
