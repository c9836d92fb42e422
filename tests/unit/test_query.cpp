// The user-facing dispatch (invariants, errors) and the `collide2d query` command.
#include "contact_testing.h"
#include "hard_cases.h"
#include "mp_reference.h"

#include <collide2d/chain.h>
#include <collide2d/query.h>
#include "tools/query_command.h"
#include "tools/random.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>

namespace collide2d {
namespace {

using testing::moved;

std::vector<std::pair<Shape, Shape>> random_pairs(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const tool::Uniform u(0.05, 1.5), pos(-2, 2), angle(-7, 7);
  const auto shape = [&](int kind) -> Shape {
    const double y = pos(rng);
    const Vec2 c(pos(rng), y);
    if (kind == 0) return Circle{c, u(rng)};
    if (kind == 1) return Ellipse{c, u(rng), u(rng) / 20, angle(rng)};
    const double height = u(rng);
    return Rect{c, Vec2(u(rng), height), angle(rng)};
  };
  std::vector<std::pair<Shape, Shape>> out;
  for (int k = 0; k < n; ++k) {
    const Shape b = shape((k / 3) % 3);
    out.emplace_back(shape(k % 3), b);
  }
  return out;
}

// The motion rounds the centres to u of the shift (up to 50) and the angles to u of the turn, and
// 60 bounds the coordinates after it: the distance may move by a few u x 60 (asserted: 16; measured
// 1.1), the points as much again (asserted: 64, the families' bound; measured 1.5).
TEST(Dispatch, InvariantUnderRigidMotionOfBoth) {
  constexpr double kU = std::numeric_limits<double>::epsilon() / 2;
  constexpr double kDistanceBound = 16 * kU * 60, kPointBound = 64 * kU * 60;
  double worst_distance = 0, worst_point = 0;
  const auto what = [](const Shape& a, const Shape& b) { return std::string(shape_name(a)) + "-" + shape_name(b); };
  std::mt19937_64 rng(3);
  const tool::Uniform angle(-std::numbers::pi, std::numbers::pi), shift(-50, 50);
  for (const auto& [a, b] : random_pairs(3000, 4)) {
    const double phi = angle(rng);
    const double ty = shift(rng);
    const Vec2 t(shift(rng), ty);
    const DistanceResult d0 = distance(a, b);
    const DistanceResult d1 = distance(moved(a, phi, t), moved(b, phi, t));
    ASSERT_LE(std::abs(d0.distance - d1.distance), kDistanceBound) << what(a, b);
    worst_distance = std::max(worst_distance, std::abs(d0.distance - d1.distance));
    if (d0.distance > 1e-9) {
      ASSERT_EQ(overlaps(a, b), overlaps(moved(a, phi, t), moved(b, phi, t)));
      const Eigen::Rotation2Dd r(phi);
      const double off = std::max((r * d0.point_a + t - d1.point_a).norm(), (r * d0.point_b + t - d1.point_b).norm());
      worst_point = std::max(worst_point, off);
      ASSERT_LE(off, kPointBound) << what(a, b);
    }
  }
  std::printf("[measure] rigid motion moved the distance by at most %.1f u x 60, the points by %.1f u x 60\n",
              worst_distance / (kU * 60), worst_point / (kU * 60));
}

// A contact with the pair swapped is Contact::swapped() of the other, with a limit and without,
// where a kernel writes the caller's order itself as where the dispatch turns it.
TEST(Dispatch, SwappingSwapsTheResultExactly) {
  for (const auto& [a, b] : random_pairs(3000, 5)) {
    ASSERT_EQ(overlaps(a, b), overlaps(b, a));
    const DistanceResult ab = distance(a, b), ba = distance(b, a);
    ASSERT_EQ(ab.distance, ba.distance);
    ASSERT_EQ(ab.point_a, ba.point_b);
    ASSERT_EQ(ab.point_b, ba.point_a);
    ASSERT_EQ(ab.overlapping, ab.distance == 0.0);
    const std::string what = std::string(shape_name(a)) + "-" + shape_name(b);
    testing::expect_same_contact(contact(a, b), contact(b, a).swapped(), what);
    const ContactOptions near{.max_separation = 0.02};
    testing::expect_same_contact(contact(a, b, near), contact(b, a, near).swapped(), what + " within 0.02");
  }
}

TEST(Dispatch, RejectsInvalidShapesAndUnsupportedPairs) {
  const Shape good = Circle{Vec2(0, 0), 1};
  const Shape bad = Rect{Vec2(0, 0), Vec2(1, std::nan("")), 0};
  EXPECT_THROW(overlaps(good, bad), InvalidShape);
  EXPECT_THROW(distance(bad, good), InvalidShape);
  const Shape r = Rect{Vec2(0, 0), Vec2(2, 1), 0};
  EXPECT_THROW(boundary_distance(r, good), UnsupportedPair);
  EXPECT_THROW(boundary_distance(good, bad), InvalidShape);
}

// Magnitudes beyond what a double can square and cube are refused, naming the field.
TEST(Dispatch, RejectsAbsurdMagnitudes) {
  const Shape good = Circle{Vec2(0, 0), 1};
  const Shape cases[] = {Circle{Vec2(2e50, 0), 1},          Circle{Vec2(0, 0), 1e51},
                         Circle{Vec2(0, 0), 1e-51},         Ellipse{Vec2(0, -1e60), 1, 1, 0},
                         Ellipse{Vec2(0, 0), 1, 1e-300, 0}, Rect{Vec2(0, 0), Vec2(1e200, 1), 0}};
  const char* fields[] = {"circle cx", "circle radius", "circle radius", "ellipse cy", "ellipse b", "rect hx"};
  for (std::size_t k = 0; k < std::size(cases); ++k) {
    try {
      distance(good, cases[k]);
      ADD_FAILURE() << "accepted case " << k;
    } catch (const InvalidShape& e) {
      EXPECT_NE(std::string(e.what()).find(fields[k]), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("range"), std::string::npos) << e.what();
    }
  }
}

// At the edges of the accepted range every query still answers with finite numbers, symmetric in A
// and B, with distance 0 exactly for overlapping solids.
TEST(Dispatch, ExtremeAcceptedMagnitudesGiveFiniteAnswers) {
  std::mt19937_64 rng(23);
  const tool::Uniform u(0.0, 1.0);
  const auto magnitude = [&] { return std::pow(10.0, -50 + 100 * u(rng)); };
  const auto coordinate = [&] {
    const double sign = u(rng) < 0.5 ? -1 : 1;
    return sign * (u(rng) < 0.2 ? 0.0 : magnitude());
  };
  const auto shape = [&](int kind) -> Shape {
    const double y = coordinate();
    const Vec2 c(coordinate(), y);
    if (kind == 0) return Circle{c, magnitude()};
    if (kind == 1) return Ellipse{c, magnitude(), magnitude(), 7 * u(rng)};
    const double height = magnitude();
    return Rect{c, Vec2(magnitude(), height), 7 * u(rng)};
  };
  for (int k = 0; k < 20000; ++k) {
    const Shape a = shape(k % 3), b = shape((k / 3) % 3);
    const bool hit = overlaps(a, b);
    ASSERT_EQ(hit, overlaps(b, a)) << k;
    const DistanceResult d = distance(a, b);
    ASSERT_TRUE(std::isfinite(d.distance) && d.distance >= 0) << k << " " << d.distance;
    ASSERT_TRUE(d.point_a.allFinite() && d.point_b.allFinite()) << k;
    ASSERT_EQ(d.distance, distance(b, a).distance) << k;
    ASSERT_EQ(d.overlapping, hit) << k;
    if (!std::holds_alternative<Rect>(a) && !std::holds_alternative<Rect>(b)) {
      const DistanceResult g = boundary_distance(a, b);
      ASSERT_TRUE(std::isfinite(g.distance) && g.distance >= 0 && g.point_a.allFinite()) << k;
    }
  }
}

struct CommandRun {
  int status;
  std::vector<std::string> out;
  std::string err;
};

CommandRun run(const std::string& input, const char* method = nullptr, tool::Answer answer = tool::Answer::distance) {
  std::istringstream in(input);
  std::ostringstream out, err;
  tool::QueryOptions options;
  if (method != nullptr) tool::apply_method(method, options);
  options.answer = answer;
  const int status = tool::run_query(in, out, err, options);
  std::vector<std::string> lines;
  std::istringstream o(out.str());
  for (std::string line; std::getline(o, line);) lines.push_back(line);
  return {status, lines, err.str()};
}

// Every number printed parses back to the very double the library computed.
TEST(QueryCommand, RoundTripsTheLibraryResults) {
  std::ostringstream input;
  input.precision(17);
  const auto pairs = random_pairs(300, 6);
  const auto word = [](const Shape& s) {
    std::ostringstream o;
    o.precision(17);
    if (const auto* c = std::get_if<Circle>(&s))
      o << "circle " << c->center.x() << ' ' << c->center.y() << ' ' << c->radius;
    if (const auto* e = std::get_if<Ellipse>(&s))
      o << "ellipse " << e->center.x() << ' ' << e->center.y() << ' ' << e->a << ' ' << e->b << ' ' << e->angle;
    if (const auto* r = std::get_if<Rect>(&s))
      o << "rect " << r->center.x() << ' ' << r->center.y() << ' ' << r->half_extents.x() << ' ' << r->half_extents.y()
        << ' ' << r->angle;
    return o.str();
  };
  input << "# a comment\n\n";
  for (const auto& [a, b] : pairs) input << word(a) << " ; " << word(b) << '\n';
  const CommandRun r = run(input.str());
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(r.out.size(), pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    std::istringstream line(r.out[k]);
    int hit = -1;
    std::string fields[5];
    line >> hit >> fields[0] >> fields[1] >> fields[2] >> fields[3] >> fields[4];
    const DistanceResult d = distance(pairs[k].first, pairs[k].second);
    EXPECT_EQ(hit, overlaps(pairs[k].first, pairs[k].second) ? 1 : 0);
    const double expected[5] = {d.distance, d.point_a.x(), d.point_a.y(), d.point_b.x(), d.point_b.y()};
    for (int i = 0; i < 5; ++i) EXPECT_EQ(std::strtod(fields[i].c_str(), nullptr), expected[i]) << r.out[k];
  }
}

TEST(QueryCommand, EachBadLineGetsAnErrorInPlace) {
  const std::string input =
      "circle 0 0 1 ; circle 3 0 1\n"
      "blob 0 0 1 ; circle 0 0 1\n"
      "circle 0 0 ; circle 0 0 1\n"
      "rect 0 0 1 1 0 ; ellipse 0 0 1 1 zero\n"
      "circle 0 0 1 circle 1 1 1\n"
      "circle 0 0 1 ; circle 1 1 1 ; circle 2 2 2\n"
      "circle 0 0 nan ; circle 1 1 1\n"
      "rect 0 0 -1 1 0 ; circle 1 1 1\n"
      "circle 0 0 1 ; \n"
      "ellipse 0 0 2 inf 0 ; ellipse 1 0 2 1 0\n"
      "circle 0 0 1e999 ; circle 1 1 1\n"
      "circle 0 0 1 foo ; circle 1 1 1\n"
      "circle 0 0 1 2 ; circle 1 1 1\n"
      "# fine again\n"
      "rect 0 0 1 1 0 ; circle 3 0 1\n";
  const CommandRun r = run(input);
  EXPECT_EQ(r.status, 2);
  const std::vector<std::string> expected_errors = {"unknown shape 'blob'",
                                                    "circle takes 3 numbers (cx cy r), got 2",
                                                    "'zero' is not a number",
                                                    "expected '<shape> ; <shape>', found no ';'",
                                                    "expected one ';', found more",
                                                    "circle radius must be finite",
                                                    "rect hx must be positive",
                                                    "shape B is missing",
                                                    "ellipse b must be finite",
                                                    "'1e999' is out of range",
                                                    "unexpected 'foo' after circle's 3 numbers (cx cy r)",
                                                    "circle takes 3 numbers (cx cy r), got 4"};
  ASSERT_EQ(r.out.size(), expected_errors.size() + 2);
  EXPECT_EQ(r.out.front(), "0 1 1 0 2 0");
  EXPECT_EQ(r.out.back(), "0 1 1 0 2 0");
  for (std::size_t k = 0; k < expected_errors.size(); ++k) {
    EXPECT_EQ(r.out[k + 1].rfind("error: ", 0), 0u) << r.out[k + 1];
    EXPECT_NE(r.out[k + 1].find(expected_errors[k]), std::string::npos) << r.out[k + 1];
    EXPECT_NE(r.err.find("line " + std::to_string(k + 2) + ": "), std::string::npos) << r.err;
  }
}

// A chain segment as shape A: its contact and time of impact follow the chain's rules (the library's
// own results, to the bit), its overlap and distance are its segment's; it is refused as shape B,
// moving, or short of numbers.
TEST(QueryCommand, ChainSegmentLines) {
  const ChainSegment floor = ChainSegment::of(Vec2(2, 0), Vec2(0, 0), Vec2(-2, 0), Vec2(-3, 0));
  const std::string chain = "chain 2 0 0 0 -2 0 -3 0 ; ";
  const CommandRun contacts = run(chain + "rect 0.4921875 0.484375 0.5 0.5 0\n" + chain + "circle -1 -0.25 0.5\n",
                                  nullptr, tool::Answer::contact);
  ASSERT_EQ(contacts.status, 0) << contacts.err;
  const Contact c = contact(floor, Rect{Vec2(0.4921875, 0.484375), Vec2(0.5, 0.5), 0.0});
  std::ostringstream expected;
  expected.precision(17);
  expected << c.separation << ' ' << c.normal.x() + 0.0 << ' ' << c.normal.y() + 0.0 << ' ' << c.point_a.x() + 0.0
           << ' ' << c.point_a.y() + 0.0 << ' ' << c.point_b.x() + 0.0 << ' ' << c.point_b.y() + 0.0;
  EXPECT_EQ(contacts.out, (std::vector<std::string>{expected.str(), "none"}));
  const CommandRun impacts =
      run(chain + "circle -1 5 0.5 @ 0 -10 0\n" + chain + "circle -1 -5 0.5 @ 0 10 0\n", nullptr, tool::Answer::toi);
  ASSERT_EQ(impacts.out.size(), 2u);
  EXPECT_EQ(impacts.out[0].rfind("1 0.44999", 0), 0u) << impacts.out[0];
  EXPECT_EQ(impacts.out[1], "0 1 1 0 0 0") << "from below it passes";
  const CommandRun sight = run(chain + "circle -1 -0.25 0.5\n");
  ASSERT_EQ(sight.out.size(), 1u);
  EXPECT_EQ(sight.out[0].rfind("1 0 ", 0), 0u) << "the segment's geometry overlaps: " << sight.out[0];
  const CommandRun bad =
      run("circle 0 0 1 ; chain 2 0 0 0 -2 0 -3 0\n" + chain.substr(0, 17) + " ; circle 1 1 1\n" +
          "chain 2 0 0 0 -2 0 -3 0 @ 1 0 0 ; circle 1 1 1\n" + "chain 0 0 0 0 1 0 2 0 ; circle 1 1 1\n");
  const std::vector<std::string> errors = {"a chain segment is shape A only", "chain takes 8 numbers",
                                           "a chain segment is level geometry: it does not move",
                                           "chain segment ghost1 must differ from point1"};
  ASSERT_EQ(bad.out.size(), errors.size());
  for (std::size_t k = 0; k < errors.size(); ++k)
    EXPECT_NE(bad.out[k].find(errors[k]), std::string::npos) << bad.out[k];
}

TEST(QueryCommand, MethodsNameTheRectEllipseTest) {
  // The seed's corner rule calls this pair overlapping; every method here must not.
  const std::string q = "rect 0 0 0.1 0.1 0 ; ellipse 1.1 6.1 10 0.01 0.78539816339744828\n";
  for (const char* m : {"minkowski", "closest-features", "all-features"}) {
    const CommandRun r = run(q, m);
    ASSERT_EQ(r.out.size(), 1u);
    EXPECT_EQ(r.out[0].substr(0, 2), "0 ") << m;
  }
  tool::QueryOptions options;
  EXPECT_THROW(tool::apply_method("gjk", options), tool::ParseError);
}

// --method picks the ellipse solver, --boundary the curve gap: nested circles (radii 3 and 1,
// centres 1 apart) have solid distance 0 and boundary gap 3 - 1 - 1 = 1 on the line of centres.
TEST(QueryCommand, MethodsAndBoundaryForEllipses) {
  const std::string nested = "circle 0 0 3 ; ellipse 1 0 1 1 0.5\n";
  EXPECT_EQ(run(nested).out.at(0).substr(0, 4), "1 0 ");
  for (const char* m : {"robust", "gradient", "polynomial"}) {
    const CommandRun r = run(nested, m, tool::Answer::boundary);
    ASSERT_EQ(r.status, 0) << m;
    std::istringstream line(r.out.at(0));
    int hit = -1;
    double gap = 0, ax = 0, ay = 0, bx = 0, by = 0;
    line >> hit >> gap >> ax >> ay >> bx >> by;
    EXPECT_EQ(hit, 1) << m;
    EXPECT_NEAR(gap, 1.0, 1e-7) << m;  // gradient descent stops at a gradient of 1e-8
    EXPECT_NEAR(ax, 3.0, 1e-3) << m;
    EXPECT_NEAR(bx, 2.0, 1e-3) << m;
  }
  const CommandRun r = run("rect 0 0 1 1 0 ; circle 5 0 1\n", nullptr, tool::Answer::boundary);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.at(0).find("error: the boundary distance covers circles and ellipses"), std::string::npos);
}

// A named method answers its own pairs; a line of another pair is refused, naming the line and the
// pair, and the lines around it are answered.
TEST(QueryCommand, MethodRefusesPairsItDoesNotCover) {
  const std::string lines =
      "ellipse 0 0 2 1 0 ; ellipse 5 0 2 1 0.3\nrect 0 0 1 1 0 ; circle 5 0 1\n"
      "circle 0 0 1 ; ellipse 4 0 2 1 0\n";
  const CommandRun solid = run(lines, "polynomial");
  EXPECT_EQ(solid.status, 2);
  ASSERT_EQ(solid.out.size(), 3u);
  EXPECT_EQ(solid.out[0].substr(0, 2), "0 ");
  EXPECT_EQ(solid.out[1], "error: --method polynomial measures two ellipses; this line is rect ; circle");
  EXPECT_EQ(solid.out[2], "error: --method polynomial measures two ellipses; this line is circle ; ellipse");
  EXPECT_EQ(solid.err,
            "line 2: --method polynomial measures two ellipses; this line is rect ; circle\n"
            "line 3: --method polynomial measures two ellipses; this line is circle ; ellipse\n");
  const CommandRun boundary = run(lines, "gradient", tool::Answer::boundary);
  EXPECT_EQ(boundary.out[1].rfind("error: --method gradient measures two ellipses, or a circle and an ellipse", 0), 0u);
  EXPECT_EQ(boundary.out[2].substr(0, 2), "0 ");
  const CommandRun overlap =
      run("ellipse 0 0 2 1 0 ; rect 1 0 1 1 0\nchain 2 0 0 0 -2 0 -3 0 ; ellipse 0 3 1 1 0\n", "minkowski");
  EXPECT_EQ(overlap.out[0].substr(0, 2), "1 ");
  EXPECT_EQ(overlap.out[1], "error: --method minkowski tests a rect and an ellipse; this line is chain ; ellipse");
  tool::QueryOptions options;
  tool::apply_method("closest-features", options);
  options.answer = tool::Answer::contact;
  EXPECT_THROW(tool::check_options(options), tool::ParseError);
  options.answer = tool::Answer::boundary;
  EXPECT_NO_THROW(tool::check_options(options));
  options.answer = tool::Answer::area;
  EXPECT_THROW(tool::check_options(options), tool::ParseError);
}

// The numbers of an answer line; empty when it does not hold N of them.
template <std::size_t N>
std::optional<std::array<double, N>> numbers_of(const std::string& text) {
  std::istringstream line(text);
  std::array<double, N> got{};
  for (double& x : got) line >> x;
  if (!line) return std::nullopt;
  return got;
}

// --contact: one pair of every kind with a signed distance known in closed form (the overlap along
// an axis of symmetry), points included; a bad line still gets its error in place.
TEST(QueryCommand, ContactLinesForEveryPair) {
  const std::string input =
      "circle 0 0 1 ; circle 1.5 0 1\n"
      "rect 0 0 1 1 0 ; circle 0 1.5 1\n"
      "rect 0 0 1 1 0 ; rect 2.5 0 0.25 0.25 0.78539816339744828\n"
      "rect 0 0 1 1 0 ; ellipse 0 1.75 2 1 0\n"
      "circle 0 0 1 ; ellipse 2.5 0 2 1 0\n"
      "ellipse 0 0 2 1 0 ; ellipse 3 0 2 1 0\n"
      "circle 0 0 -1 ; circle 0 0 1\n";
  const CommandRun r = run(input, nullptr, tool::Answer::contact);
  EXPECT_EQ(r.status, 2);
  const std::vector<std::array<double, 7>> expected = {{-0.5, 1, 0, 1, 0, 0.5, 0},
                                                       {-0.5, 0, 1, 0, 1, 0, 0.5},
                                                       {1.5 - std::sqrt(0.125), 1, 0, 1, 0, 2.5 - std::sqrt(0.125), 0},
                                                       {-0.25, 0, 1, 0, 1, 0, 0.75},
                                                       {-0.5, 1, 0, 1, 0, 0.5, 0},
                                                       {-1, 1, 0, 2, 0, 1, 0}};
  ASSERT_EQ(r.out.size(), expected.size() + 1);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const auto got = numbers_of<7>(r.out[k]);
    ASSERT_TRUE(got) << r.out[k];
    for (std::size_t i = 0; i < 7; ++i) EXPECT_NEAR((*got)[i], expected[k][i], 1e-15) << r.out[k];
  }
  EXPECT_NE(r.out.back().find("error: circle radius must be positive"), std::string::npos) << r.out.back();
}

// Time-of-impact lines: exact first contacts (a circle closing a gap of 8 at 20 per step, a bullet
// through a wall, a needle turning acos(0.22) into a circle), a miss, a start in overlap, and the
// bad lines: a motion without --toi, a motion with two numbers, a NaN velocity.
TEST(QueryCommand, TimeOfImpactLines) {
  const std::string input =
      "circle 0 0 1 ; circle 10 0 1 @ -20 0 0\n"
      "rect 0 0 0.005 1 0 ; circle -1000 0.3 0.001 @ 2000 0 0\n"
      "rect 0 0 1 0.01 0 @ 0 0 100 ; circle 0 0.5 0.1\n"
      "circle 0 0 1 ; circle 3 0 1 @ 1 0 0\n"
      "ellipse 0 0 2 1 0.3 ; circle 1 0 1 @ 5 0 0\n"
      "circle 0 0 1 @ 1 0 ; circle 1 0 1\n"
      "circle 0 0 1 @ nan 0 0 ; circle 5 0 1\n";
  const CommandRun r = run(input, nullptr, tool::Answer::toi);
  EXPECT_EQ(r.status, 2);
  ASSERT_EQ(r.out.size(), 7u);
  const std::array<double, 5> times = {0.4, (1000 - 0.005 - 0.001) / 2000, std::acos(0.22) / 100, 1.0, 0.0};
  const std::array<int, 5> hits = {1, 1, 1, 0, 1};
  for (std::size_t k = 0; k < times.size(); ++k) {
    const auto got = numbers_of<6>(r.out[k]);
    ASSERT_TRUE(got) << r.out[k];
    EXPECT_EQ((*got)[0], hits[k]) << r.out[k];
    EXPECT_LE((*got)[1], times[k] + 1e-15) << r.out[k];
    EXPECT_GE((*got)[1], times[k] - 1e-9) << r.out[k];
    EXPECT_NEAR(Vec2((*got)[2], (*got)[3]).norm(), 1.0, 1e-15) << r.out[k];
  }
  EXPECT_NE(r.out[5].find("error: a motion takes 3 numbers (vx vy w) after '@', got 2"), std::string::npos) << r.out[5];
  EXPECT_NE(r.out[6].find("error: A velocity x must be finite"), std::string::npos) << r.out[6];
  const CommandRun plain = run("circle 0 0 1 ; circle 3 0 1 @ 1 0 0\n");
  EXPECT_EQ(plain.status, 2);
  ASSERT_EQ(plain.out.size(), 1u);
  EXPECT_NE(plain.out[0].find("error: a motion ('@ vx vy w') needs --toi"), std::string::npos) << plain.out[0];
}

// --area: the overlap's area, centroid and IoU, on constructions whose answer is known: two unit
// circles a radius apart share 2 pi / 3 - sqrt(3) / 2 about (0.5, 0); two squares half over each
// other share half of each, a third of their union; touching boxes share nothing. A chain or a
// segment has no area.
TEST(QueryCommand, AreaWritesTheOverlap) {
  const CommandRun r =
      run("circle 0 0 1 ; circle 1 0 1\nrect 0 0 1 1 0 ; rect 1 0 1 1 0\nrect 0 0 1 1 0 ; rect 2 0 1 1 0\n"
          "chain 2 0 0 0 -2 0 -3 0 ; circle 0 0 1\nsegment 0 0 1 0 ; circle 0 0 1\n",
          nullptr, tool::Answer::area);
  EXPECT_EQ(r.status, 2);
  ASSERT_EQ(r.out.size(), 5u);
  const double lens = 2 * std::numbers::pi / 3 - std::sqrt(3.0) / 2;
  const std::vector<std::array<double, 4>> expected = {
      {lens, 0.5, 0, lens / (2 * std::numbers::pi - lens)}, {2, 0.5, 0, 1.0 / 3}, {0, 0, 0, 0}};
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const auto got = numbers_of<4>(r.out[k]);
    ASSERT_TRUE(got) << r.out[k];
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR((*got)[i], expected[k][i], 4e-16) << r.out[k];
  }
  EXPECT_EQ(r.out[3], "error: a chain segment has no area: --area takes two solid shapes");
  EXPECT_EQ(r.out[4].rfind("error: a segment has no area", 0), 0u) << r.out[4];
}

}  // namespace
}  // namespace collide2d
