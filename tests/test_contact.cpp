// Contacts (signed distance, normal, deepest or closest points) against the 50-digit reference's
// signed distance, an independent scan of the dual function, on the hard-case families of every
// pair and on deep overlaps; against known answers where the construction gives one; and the
// properties a solver relies on.
#include "hard_cases.h"
#include "mp_reference.h"

#include "narrowphase/query.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace collide2d::testing {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

struct ContactFamily {
  Family family;
  int cases = 40;
};

void PrintTo(const ContactFamily& f, std::ostream* os) { *os << f.family.name; }

std::vector<ContactFamily> contact_families() {
  std::vector<ContactFamily> out;
  const Kind kinds[] = {Kind::rect, Kind::circle, Kind::ellipse};
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      for (const Family& f : standard_families(kinds[i], kinds[j])) out.push_back({f});
      // Deep overlaps: B pushed into A by 0.1 ... 1.5 of the larger size, so that one shape is nearly
      // through the other; with needles, crossings.
      for (const double aspect : {1.0, 1e2, 1e4, 1e6}) {
        if (kinds[i] == Kind::circle && kinds[j] == Kind::circle && aspect > 1) continue;
        char name[64];
        std::snprintf(name, sizeof name, "deep aspect %.0e", aspect);
        Family f = standard_families(kinds[i], kinds[j]).front();
        f.name = f.name.substr(0, f.name.find(' ') + 1) + name;
        f.aspect_min = aspect;
        f.aspect_max = 2 * aspect;
        f.deltas = {-0.1, -0.5, -0.9, -0.99, -1.5};
        f.seed = 31 + static_cast<std::uint64_t>(std::log10(aspect));
        out.push_back({f});
      }
    }
  }
  return out;
}

std::string name_of(const ContactFamily& f) { return test_name(f.family); }

double angle_between(const Vec2& u, const Vec2& v) { return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v)); }

double ulps_of(const Vec2& p) { return 8 * kU * std::max(std::abs(p.x()), std::abs(p.y())); }

struct Worst {
  double separation = 0;  // / scale
  double normal = 0;      // rad, where the maximiser is unique and |separation| > 1e-9 size
  double points = 0;      // / scale, beyond the points' coordinate rounding
  double known = 0;       // (|separation - nominal gap| - its rounding) / scale on shallow contacts
  int normals = 0;
  int evaluations = 0;
};

class ContactFamilies : public ::testing::TestWithParam<ContactFamily> {};

TEST_P(ContactFamilies, MatchReference) {
  const Family& f = GetParam().family;
  Family small = f;
  small.cases = GetParam().cases;
  Worst worst;
  int k = 0;
  for (const Case& c : family_cases(small)) {
    const std::string what = f.name + " case " + std::to_string(k++) + ": " + describe(c.a) + " ; " + describe(c.b);
    const double size = std::max(half_size(c.a), half_size(c.b));
    const double scale = std::max(size, (center_of(c.b) - center_of(c.a)).norm());
    const Contact got = contact(c.a, c.b);
    const reference::SignedDistance ref = reference::signed_distance(c.a, c.b);
    const double ref_sep = static_cast<double>(ref.separation);
    const double err = std::abs(got.separation - ref_sep) / scale;
    worst.separation = std::max(worst.separation, err);
    EXPECT_LE(err, 8 * kU) << what << " separation " << got.separation << " reference " << ref_sep;
    worst.evaluations = std::max(worst.evaluations, got.evaluations);
    EXPECT_LE(got.evaluations, 1000) << what << " support evaluations";

    // The construction's own answer: a shallow contact along a common normal, where s has its
    // maximum (apart: the separating line; overlapping: a stationary point of s where s'' =
    // -(gap + rho_A + rho_B) < 0, which two rectangles' corners, rho = 0, do not make).
    const bool both_rects = std::holds_alternative<Rect>(c.a) && std::holds_alternative<Rect>(c.b);
    // Needles are left out: at their tips rho_A + rho_B can be below the overlap.
    const bool curved_enough = f.aspect_max <= 4 && !both_rects;
    if (f.placement == Placement::touching && std::abs(c.delta) <= 1e-3 * size && (c.delta >= 0 || curved_enough)) {
      const double rho = 16 * kU * (std::abs(f.offset) + 4 * size);
      worst.known = std::max(worst.known, (std::abs(got.separation - c.delta) - rho) / scale);
      EXPECT_LE(std::abs(got.separation - c.delta), rho + 8 * kU * scale) << what << " nominal gap " << c.delta;
    }

    const Vec2 ref_normal(static_cast<double>(ref.normal.x), static_cast<double>(ref.normal.y));
    // The normal where the maximiser is unique, the contact clear of touching, and the maximum
    // sharp enough for the target: s' is known to its rounding, 64 u scale, which moves a maximum
    // of curvature k by 64 u scale / k (a needle's tip against a corner: k is the tip's radius).
    const bool unique = ref.runner_up < ref.separation - 1e-9 * scale;
    const double curvature = static_cast<double>(ref.curvature);
    if (unique && std::abs(ref_sep) > 1e-9 * size && 64 * kU * scale / curvature <= 1e-10) {
      const double turn = angle_between(got.normal, ref_normal);
      worst.normal = std::max(worst.normal, turn);
      ++worst.normals;
      EXPECT_LE(turn, 1e-10) << what << " normal (" << got.normal.transpose() << ") reference (" << ref_normal.transpose() << ")";
    }

    const double ulps = ulps_of(got.point_a) + ulps_of(got.point_b);
    const double along = std::abs((got.point_b - got.point_a - got.separation * got.normal).norm()) - ulps;
    const double off_a = static_cast<double>(reference::distance_to(c.a, reference::to_mp(got.point_a))) - ulps;
    const double off_b = static_cast<double>(reference::distance_to(c.b, reference::to_mp(got.point_b))) - ulps;
    worst.points = std::max({worst.points, along / scale, off_a / scale, off_b / scale});
    EXPECT_LE(along, 16 * kU * scale) << what << " point_b - point_a != separation * normal";
    EXPECT_LE(off_a, 16 * kU * scale) << what << " point_a is off A";
    EXPECT_LE(off_b, 16 * kU * scale) << what << " point_b is off B";

    const Contact back = contact(c.b, c.a);
    EXPECT_EQ(back.separation, got.separation) << what << " swapped";
    // Shapes of one kind and one centre are dispatched in one order both ways, and -n maximises s
    // as well as n (s(-n) = s(n) when the centres coincide).
    if (center_of(c.a) != center_of(c.b)) EXPECT_EQ(back.normal, Vec2(-got.normal)) << what << " swapped normal";
  }
  std::printf("[contact] %-44s worst separation %.1f u  points %.1f u  known gap %.1f u  normal %.1e rad (%d)  evals <= %d\n",
              f.name.c_str(), worst.separation / kU, worst.points / kU, worst.known / kU, worst.normal, worst.normals,
              worst.evaluations);
}

INSTANTIATE_TEST_SUITE_P(Families, ContactFamilies, ::testing::ValuesIn(contact_families()),
                         [](const auto& info) { return name_of(info.param); });

}  // namespace
}  // namespace collide2d::testing
