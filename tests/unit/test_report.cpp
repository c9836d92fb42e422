// `collide2d_report`: every method measured on the same pairs, errors against the 50-digit
// reference, and the JSON that keeps them with the benchmarks' results.
#include "bench/report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace collide2d::report {
namespace {

TEST(Report, MeasuresEveryMethodAgainstTheReference) {
  const ReportOptions options{.pairs = 20, .repetitions = 1, .seed = 3};
  const std::vector<MethodResult> results = measure_methods(options);
  ASSERT_EQ(results.size(), 3u + 2u * 6u);
  EXPECT_EQ(results[0].method, "robust");
  EXPECT_LE(results[0].max_error, 1e-15);
  for (const MethodResult& r : results) EXPECT_GT(r.nanoseconds, 0.0) << r.method;
  // Box2D's polygons converge as N grows: the N = 256 error is far below the N = 8 one.
  EXPECT_LT(results[8].median_error, 1e-2 * results[3].median_error);
  EXPECT_EQ(results[3].sides, 8);
  EXPECT_EQ(results[8].sides, 256);
  std::ostringstream table, json;
  print_report(results, "distance", options, table);
  EXPECT_NE(table.str().find("| box2d circumscribed | 256 |"), std::string::npos);
  write_report_json(results, {}, options, json);
  std::size_t records = 0;
  for (std::size_t at = json.str().find("\"method\""); at != std::string::npos;
       at = json.str().find("\"method\"", at + 1))
    ++records;
  EXPECT_EQ(records, results.size());  // one per measurement
  EXPECT_NE(json.str().find("{\"method\": \"box2d circumscribed\", \"sides\": 256, "), std::string::npos);
  // A method that failed on some pair has no finite error, which JSON writes as null.
  std::ostringstream failed;
  write_report_json({MethodResult{"polynomial", 0, 10.0, 1e-16, std::numeric_limits<double>::infinity(), ""}}, {},
                    options, failed);
  EXPECT_NE(failed.str().find("\"median_error\": 1e-16, \"max_error\": null}"), std::string::npos) << failed.str();
}

// Box2D v3's rows of each pair (its inscribed 5- to 8-gons), in a build given its source.
#ifdef COLLIDE2D_REPORT_BOX2D_V3
constexpr std::size_t kV3Rows = 4;
#else
constexpr std::size_t kV3Rows = 0;
#endif

// The contact depth of each pair with an ellipse: ours exact one pair at a time, batched (the same
// separations) and to each tolerance, Box2D's manifolds closer as N grows from 5 to 16 (v3's from 5
// to 8).
TEST(Report, MeasuresTheContactDepthOfEveryPairWithAnEllipse) {
  const ReportOptions options{.pairs = 20, .repetitions = 1, .seed = 4};
  const std::vector<MethodResult> results = measure_contact_methods(options);
  ASSERT_EQ(results.size(), 23u + 24u + 4 * 23u + 6 * kV3Rows);
  std::size_t k = 0;
  for (const std::string pair :
       {"rect-ellipse", "circle-ellipse", "ellipse-ellipse", "polygon-ellipse", "capsule-ellipse", "segment-ellipse"}) {
    const MethodResult& ours = results[k++];
    EXPECT_EQ(ours.pair, pair);
    EXPECT_EQ(ours.method, "collide2d contact") << pair;
    EXPECT_LE(ours.max_error, 1e-15) << pair;
    EXPECT_LE(ours.max_normal_error, 1e-14) << pair;
    EXPECT_LE(ours.max_point_error, 1e-14) << pair;
    // To each tolerance, within it: it is a fraction of the larger reach, which is at most sqrt(2)
    // times the larger half-size in the error's scale; the normal within that fraction, in rad.
    for (int exponent = 1; exponent <= 12; ++exponent) {
      const MethodResult& loose = results[k++];
      EXPECT_EQ(loose.method, "collide2d contact to a tolerance") << pair;
      EXPECT_EQ(loose.tolerance, std::pow(10.0, -exponent)) << pair;
      EXPECT_LE(loose.max_error, std::sqrt(2.0) * loose.tolerance + 1e-15) << pair << " " << loose.tolerance;
      EXPECT_LE(loose.max_normal_error, loose.tolerance + 1e-14) << pair << " " << loose.tolerance;
      EXPECT_LE(loose.max_point_error, std::sqrt(2.0) * loose.tolerance + 1e-14) << pair << " " << loose.tolerance;
    }
    if (pair == "circle-ellipse") {
      const MethodResult& batch = results[k++];
      EXPECT_EQ(batch.method, "collide2d batch");
      EXPECT_EQ(batch.median_error, ours.median_error);
      EXPECT_EQ(batch.max_error, ours.max_error);
    }
    for (const std::string fit : {"inscribed", "circumscribed"}) {
      const MethodResult& five = results[k];
      const MethodResult& sixteen = results[k + 4];
      EXPECT_EQ(five.method, "box2d manifold " + fit) << pair;
      EXPECT_EQ(five.sides, 5) << pair;
      EXPECT_EQ(sixteen.sides, 16) << pair;
      EXPECT_EQ(sixteen.pair, pair);
      EXPECT_LT(sixteen.median_error, five.median_error) << pair << " " << fit;
      EXPECT_LT(sixteen.median_point_error, five.median_point_error) << pair << " " << fit;
      k += 5;
    }
    for (std::size_t sides = 5; sides < 5 + kV3Rows; ++sides) {
      const MethodResult& v3 = results[k++];
      EXPECT_EQ(v3.method, "box2d v3 manifold inscribed") << pair;
      EXPECT_EQ(v3.sides, static_cast<int>(sides)) << pair;
      EXPECT_EQ(v3.pair, pair);
    }
    if (kV3Rows > 0) EXPECT_LT(results[k - 1].median_error, results[k - kV3Rows].median_error) << pair;
  }
  std::ostringstream table, json;
  print_report(results, "contact depth", options, table);
  EXPECT_NE(table.str().find("| box2d manifold inscribed | 16 |"), std::string::npos);
  write_report_json({}, results, options, json);
  EXPECT_NE(json.str().find("\"sides\": 16, "), std::string::npos);
  EXPECT_NE(json.str().find(", \"pair\": \"circle-ellipse\", \"median_normal_error\": "), std::string::npos);
  EXPECT_NE(json.str().find(", \"pair\": \"circle-ellipse\", \"tolerance\": 0.001, \"median_normal_error\": "),
            std::string::npos);
  EXPECT_NE(table.str().find("| collide2d contact to a tolerance | 1e-03 |"), std::string::npos);
}

}  // namespace
}  // namespace collide2d::report
