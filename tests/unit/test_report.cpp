// `collide2d_report`: every method measured on the same pairs, errors against the 50-digit
// reference, and the JSON that keeps them with the benchmarks' results.
#include "bench/report.h"

#include <gtest/gtest.h>

#include <sstream>

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
}

// The contact depth: ours exact, Box2D's manifolds closer as N grows from 5 to 8.
TEST(Report, MeasuresTheContactDepth) {
  const ReportOptions options{.pairs = 20, .repetitions = 1, .seed = 4};
  const std::vector<MethodResult> results = measure_contact_methods(options);
  ASSERT_EQ(results.size(), 1u + 2u * 4u);
  EXPECT_EQ(results[0].method, "collide2d contact");
  EXPECT_LE(results[0].max_error, 1e-15);
  EXPECT_EQ(results[1].sides, 5);
  EXPECT_EQ(results[4].sides, 8);
  for (const std::size_t circumscribed : {5u, 8u})
    EXPECT_EQ(results[circumscribed].method, "box2d manifold circumscribed");
  EXPECT_LT(results[8].median_error, results[5].median_error);
  std::ostringstream table;
  print_report(results, "contact depth", options, table);
  EXPECT_NE(table.str().find("| box2d manifold inscribed | 8 |"), std::string::npos);
}

}  // namespace
}  // namespace collide2d::report
