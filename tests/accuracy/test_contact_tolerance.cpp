// Contacts to a tolerance (ContactOptions::tolerance) against the 50-digit reference's signed
// distance, on the hard-case families of every pair with an ellipse (a circle, an ellipse or a
// rectangle; the core families' polygons, capsules and segments) and on deep overlaps: at
// each tolerance from 1e-2 to 1e-12 of the size, the separation and both deepest points within the
// tolerance of the reference, the normal within tolerance / size rad, and the verdict overlaps()'s.
#include "contact_testing.h"
#include "core_families.h"
#include "hard_cases.h"
#include "mp_reference.h"

#include <collide2d/chain.h>
#include <collide2d/query.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide2d::testing {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;
constexpr double kTolerances[] = {1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12};

std::vector<Family> tolerance_families() {
  std::vector<Family> out;
  for (const Kind a : {Kind::circle, Kind::ellipse, Kind::rect}) {
    for (Family f : standard_families(a, Kind::ellipse)) {
      f.cases = 16;
      out.push_back(f);
    }
    // Deep overlaps: B pushed into A by 0.1 ... 1.5 of the larger size, needles crossing.
    for (const double aspect : {1.0, 1e2}) {
      Family f = standard_families(a, Kind::ellipse).front();
      f.name = f.name.substr(0, f.name.find(' ') + 1) + (aspect == 1 ? "deep" : "deep needles");
      f.aspect_min = aspect;
      f.aspect_max = 2 * aspect;
      f.deltas = {-0.1, -0.5, -0.9, -0.99, -1.5};
      f.cases = 16;
      f.seed = 41 + static_cast<std::uint64_t>(aspect);
      out.push_back(f);
    }
  }
  return out;
}

Vec2 to_double(const reference::Point& p) { return {static_cast<double>(p.x), static_cast<double>(p.y)}; }
double off_by(const Vec2& got, const reference::Point& want) {
  return static_cast<double>(hypot(reference::Real(got.x()) - want.x, reference::Real(got.y()) - want.y));
}

// The worst of each error over a family, as a fraction of what the tolerance allows.
struct Worst {
  double separation = 0, normal = 0, points = 0;
  int normals = 0, points_checked = 0;
};

struct Pair {
  Shape a, b;
};

// Every case of a family at every tolerance, against the 50-digit reference; one summary line.
void check_cases(const std::string& family, const std::vector<Pair>& pairs) {
  Worst worst;
  std::vector<double> evaluations(std::size(kTolerances), 0.0);
  int k = 0;
  for (const Pair& c : pairs) {
    const std::string what = family + " case " + std::to_string(k++) + ": " + describe(c.a) + " ; " + describe(c.b);
    const double size = std::max(reach_of(c.a), reach_of(c.b));
    const double scale = std::max(size, (center_of(c.b) - center_of(c.a)).norm());
    const reference::SignedDistance ref = reference::signed_distance(c.a, c.b);
    const double ref_sep = static_cast<double>(ref.separation);
    const bool overlapping = overlaps(c.a, c.b);
    // Normals and points where the maximiser is unique and sharp enough that the exact contact's
    // own (its rounding of s', 64 u scale, over the curvature) is far below the smallest tolerance.
    const bool unique = ref.runner_up < ref.separation - 1e-9 * scale;
    const bool sharp = 64 * kU * scale / static_cast<double>(ref.curvature) <= 1e-14;
    const reference::Point n = ref.normal, minus_n{-n.x, -n.y};
    // A face's support set has no one point: that shape's point goes unchecked.
    const std::optional<reference::Point> pa = reference::support_point(c.a, n);
    const std::optional<reference::Point> pb = reference::support_point(c.b, minus_n);
    for (std::size_t t = 0; t < std::size(kTolerances); ++t) {
      const double tolerance = kTolerances[t] * size;
      const Contact got = contact(c.a, c.b, {.tolerance = tolerance});
      const std::string at = what + " at tolerance " + std::to_string(kTolerances[t]) + " size";
      evaluations[t] += got.evaluations;
      EXPECT_EQ(got.separation <= 0, overlapping) << at << ": separation " << got.separation;
      // The reference is exact for the double input; the kernel's own rounding is a few u scale.
      const double slack = 8 * kU * scale;
      const double sep_error = std::abs(got.separation - ref_sep);
      worst.separation = std::max(worst.separation, sep_error / (tolerance + slack));
      EXPECT_LE(sep_error, tolerance + slack) << at << ": separation " << got.separation << " reference " << ref_sep;
      const Vec2 along = got.point_b - got.point_a - got.separation * got.normal;
      EXPECT_LE(along.norm(), slack + 8 * kU * (got.point_a.norm() + got.point_b.norm()))
          << at << ": point_b - point_a != separation * normal";
      if (!unique || !sharp) continue;
      const double turn = angle_between(got.normal, to_double(n));
      const double allowed_turn = tolerance / size + 4 * kU;
      worst.normal = std::max(worst.normal, turn / allowed_turn);
      ++worst.normals;
      EXPECT_LE(turn, allowed_turn) << at << ": normal (" << got.normal.transpose() << ") reference ("
                                    << to_double(n).transpose() << ")";
      // The points' own rounding: a few u of their coordinates and of the scale.
      const double point_slack = slack + 8 * kU * (got.point_a.cwiseAbs().sum() + got.point_b.cwiseAbs().sum());
      const double point_error = std::max(pa ? off_by(got.point_a, *pa) : 0.0, pb ? off_by(got.point_b, *pb) : 0.0);
      worst.points = std::max(worst.points, point_error / (tolerance + point_slack));
      ++worst.points_checked;
      EXPECT_LE(point_error, tolerance + point_slack)
          << at << ": points (" << got.point_a.transpose() << ") (" << got.point_b.transpose() << ")";
    }
  }
  std::printf("[tolerance] %-40s of the allowed: separation %.2f normal %.2f (%d) points %.2f (%d); evaluations",
              family.c_str(), worst.separation, worst.normal, worst.normals, worst.points, worst.points_checked);
  for (const double e : evaluations) std::printf(" %.1f", e / std::max<double>(pairs.size(), 1));
  std::printf("\n");
}

class ToleranceFamilies : public ::testing::TestWithParam<Family> {};

TEST_P(ToleranceFamilies, StayWithinTheTolerance) {
  std::vector<Pair> pairs;
  for (const Case& c : family_cases(GetParam())) pairs.push_back({c.a, c.b});
  check_cases(GetParam().name, pairs);
}

INSTANTIATE_TEST_SUITE_P(Families, ToleranceFamilies, ::testing::ValuesIn(tolerance_families()),
                         [](const auto& info) { return test_name(info.param); });

// The pairs of a core shape (polygons sharp, rounded and degenerate, capsules, segments; a
// rectangle through its own kernel) with an ellipse, on every core family that has one.
std::vector<CoreFamily> core_ellipse_families() {
  std::vector<CoreFamily> out;
  for (CoreFamily f : core_families()) {
    if (f.b != Form::ellipse) continue;
    f.cases = std::min(f.cases, 12);  // the reference scans are the cost; test_core_pairs runs them all
    out.push_back(f);
  }
  return out;
}

class ToleranceCoreFamilies : public ::testing::TestWithParam<CoreFamily> {};

TEST_P(ToleranceCoreFamilies, StayWithinTheTolerance) {
  std::vector<Pair> pairs;
  for (const CoreCase& c : cases_of(GetParam())) pairs.push_back({c.a, c.b});
  check_cases(GetParam().name, pairs);
}

INSTANTIATE_TEST_SUITE_P(Families, ToleranceCoreFamilies, ::testing::ValuesIn(core_ellipse_families()),
                         [](const auto& info) { return info.param.name; });

// Tolerance 0 is the exact contact, bit for bit, and any tolerance leaves the pairs without an
// ellipse alone.
TEST(ContactTolerance, ZeroIsTheExactContactAndPairsWithoutAnEllipseIgnoreIt) {
  const Shape shapes[] = {Circle{{0.3, 0.1}, 0.7},
                          Ellipse{{1.2, -0.4}, 1.5, 0.4, 0.3},
                          Rect{{-0.5, 0.9}, {0.8, 0.3}, 1.1},
                          Ellipse{{0.1, 0.2}, 0.9, 0.2, -1.0},
                          ConvexPolygon::regular(5, 0.6, 0.1).at(Vec2(0.9, 0.6), 0.4),
                          Capsule{{-0.2, -0.3}, 0.7, 0.25, 2.0},
                          Segment::between({0.4, -0.9}, {1.1, 0.5})};
  for (const Shape& a : shapes) {
    for (const Shape& b : shapes) {
      const Contact exact = contact(a, b), zero = contact(a, b, {.tolerance = 0.0});
      EXPECT_EQ(exact.separation, zero.separation);
      EXPECT_EQ(exact.normal, zero.normal);
      EXPECT_EQ(exact.point_a, zero.point_a);
      EXPECT_EQ(exact.point_b, zero.point_b);
      if (std::holds_alternative<Ellipse>(a) || std::holds_alternative<Ellipse>(b)) continue;
      const Contact loose = contact(a, b, {.tolerance = 0.1});
      EXPECT_EQ(exact.separation, loose.separation);
      EXPECT_EQ(exact.normal, loose.normal);
    }
  }
}

// Chain segments (one-sided, smooth at their vertices) against ellipses grazing and sunk into a
// zigzag: at every tolerance, the contact within it of the exact chain contact (itself within a few
// ulps of the 50-digit reference, test_chain_families), with the exact one's verdict.
TEST(ContactTolerance, ChainSegmentsTakeIt) {
  const std::vector<Vec2> points{{-4, 0}, {-2, 0.5}, {0, -0.3}, {2, 0.8}, {4, 0}};
  const std::vector<ChainSegment> chain = chain_segments(points, false);
  std::mt19937_64 rng(57);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int apart = 0, overlapping = 0;
  for (int k = 0; k < 1000; ++k) {
    const double a = 0.2 + 0.8 * u(rng), b = a / std::pow(10.0, u(rng));
    const Vec2 centre(-3 + 6 * u(rng), -1 + 2.5 * u(rng));
    const Ellipse e{centre, a, b, 6.3 * u(rng)};
    for (const ChainSegment& s : chain) {
      const Contact exact = contact(s, e);
      if (exact.empty()) continue;  // behind the segment
      const double size = std::max(reach_of(s.segment), reach_of(e));
      const double scale = std::max(size, (e.center - s.segment.center).norm());
      for (const double fraction : kTolerances) {
        const double tolerance = fraction * size;
        const Contact got = contact(s, e, {.tolerance = tolerance});
        const std::string at =
            describe(e) + " on segment " + std::to_string(&s - chain.data()) + " at " + std::to_string(fraction);
        const double slack = 8 * kU * scale;
        EXPECT_EQ(got.separation <= 0, exact.separation <= 0) << at;
        EXPECT_LE(std::abs(got.separation - exact.separation), tolerance + slack) << at;
        EXPECT_LE(angle_between(got.normal, exact.normal), fraction + 4 * kU) << at;
        EXPECT_LE((got.point_a - exact.point_a).norm(), tolerance + slack) << at;
        EXPECT_LE((got.point_b - exact.point_b).norm(), tolerance + slack) << at;
      }
      ++(exact.separation <= 0 ? overlapping : apart);
    }
  }
  EXPECT_GT(apart, 100);
  EXPECT_GT(overlapping, 100);
}

TEST(ContactTolerance, BadTolerancesAreRefused) {
  const Shape a = Circle{{0, 0}, 1}, b = Ellipse{{3, 0}, 1, 0.5, 0};
  for (const double bad : {-1e-3, std::nan(""), HUGE_VAL}) {
    try {
      contact(a, b, {.tolerance = bad});
      ADD_FAILURE() << "tolerance " << bad << " was taken";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("contact tolerance must be finite and not negative"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace collide2d::testing
