// Contacts (signed distance, normal, deepest or closest points) against the 50-digit reference's
// signed distance, an independent scan of the dual function, on the hard-case families of every
// pair and on deep overlaps; against known answers where the construction gives one; and the
// properties a solver relies on.
#include "contact_testing.h"
#include "hard_cases.h"
#include "mp_reference.h"

#include <collide2d/kernels.h>
#include <collide2d/query.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace collide2d::testing {
namespace {

using testing::expect_same_contact;

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

double ulps_of(const Vec2& p) { return 8 * kU * std::max(std::abs(p.x()), std::abs(p.y())); }

struct Worst {
  double separation = 0;  // / scale
  double normal = 0;      // rad, where the maximiser is unique and |separation| > 1e-9 size
  double points = 0;      // / scale, beyond the points' coordinate rounding
  double known = 0;       // (|separation - nominal gap| - its rounding) / scale on shallow contacts
  int normals = 0;
  int evaluations = 0;
};

// A case's description for failure messages, its size (the larger shape's largest half-size) and
// its scale (also the centre distance): errors are measured against the scale.
struct Measures {
  std::string what;
  double size;
  double scale;
};

Measures measures_of(const Family& f, const Case& c, int k) {
  const double size = std::max(half_size(c.a), half_size(c.b));
  return {f.name + " case " + std::to_string(k) + ": " + describe(c.a) + " ; " + describe(c.b), size,
          std::max(size, (center_of(c.b) - center_of(c.a)).norm())};
}

class ContactFamilies : public ::testing::TestWithParam<ContactFamily> {};

TEST_P(ContactFamilies, MatchReference) {
  const Family& f = GetParam().family;
  Family small = f;
  small.cases = GetParam().cases;
  Worst worst;
  int k = 0;
  for (const Case& c : family_cases(small)) {
    const auto [what, size, scale] = measures_of(f, c, k++);
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
      EXPECT_LE(turn, 1e-10) << what << " normal (" << got.normal.transpose() << ") reference ("
                             << ref_normal.transpose() << ")";
    }

    const double ulps = ulps_of(got.point_a) + ulps_of(got.point_b);
    const double along = std::abs((got.point_b - got.point_a - got.separation * got.normal).norm()) - ulps;
    const double off_a = static_cast<double>(reference::distance_to(c.a, reference::to_mp(got.point_a))) - ulps;
    const double off_b = static_cast<double>(reference::distance_to(c.b, reference::to_mp(got.point_b))) - ulps;
    worst.points = std::max({worst.points, along / scale, off_a / scale, off_b / scale});
    EXPECT_LE(along, 16 * kU * scale) << what << " point_b - point_a != separation * normal";
    EXPECT_LE(off_a, 16 * kU * scale) << what << " point_a is off A";
    EXPECT_LE(off_b, 16 * kU * scale) << what << " point_b is off B";

    // A guess moves only where the climb starts: from near the normal, and from its opposite.
    const double c3 = std::cos(0.3), s3 = std::sin(0.3);
    for (const Vec2& guess :
         {Vec2(c3 * ref_normal.x() - s3 * ref_normal.y(), s3 * ref_normal.x() + c3 * ref_normal.y()),
          Vec2(-ref_normal)}) {
      ContactOptions from;
      from.guess = guess;
      const Contact guessed = contact(c.a, c.b, from);
      EXPECT_LE(std::abs(guessed.separation - ref_sep) / scale, 8 * kU)
          << what << " from the guess (" << guess.transpose() << "): " << guessed.separation << " reference "
          << ref_sep;
      EXPECT_LE(guessed.evaluations, 1000) << what << " support evaluations from a guess";
    }

    const Contact back = contact(c.b, c.a);
    EXPECT_EQ(back.separation, got.separation) << what << " swapped";
    // Shapes of one kind and one centre are dispatched in one order both ways, and -n maximises s
    // as well as n (s(-n) = s(n) when the centres coincide).
    if (center_of(c.a) != center_of(c.b)) EXPECT_EQ(back.normal, Vec2(-got.normal)) << what << " swapped normal";
  }
  std::printf(
      "[contact] %-44s worst separation %.1f u  points %.1f u  known gap %.1f u  normal %.1e rad (%d)  evals <= %d\n",
      f.name.c_str(), worst.separation / kU, worst.points / kU, worst.known / kU, worst.normal, worst.normals,
      worst.evaluations);
}

INSTANTIATE_TEST_SUITE_P(Families, ContactFamilies, ::testing::ValuesIn(contact_families()),
                         [](const auto& info) { return name_of(info.param); });

// What a solver relies on, over the cases of every family: apart, the separation is the distance;
// its sign is the overlap verdict; moving B by -separation * normal leaves the pair touching; a
// rigid motion of both keeps the separation. Tolerances: the rounding of the moved input (an ulp
// of each centre coordinate, of the angle times the size) plus 16 u of the scale.
TEST(ContactProperties, HoldOnEveryFamily) {
  int apart = 0, pushed = 0;
  double worst_push = 0, worst_motion = 0;  // as fractions of their bounds
  for (const ContactFamily& cf : contact_families()) {
    Family f = cf.family;
    f.cases = 12;
    int k = 0;
    for (const Case& c : family_cases(f)) {
      const auto [what, size, scale] = measures_of(f, c, k++);
      const Contact got = contact(c.a, c.b);
      if (got.separation > 1e-10 * size) {
        ++apart;
        EXPECT_NEAR(got.separation, distance(c.a, c.b).distance, 8 * kU * scale) << what;
      }
      if (std::abs(got.separation) > 1e-10 * size) EXPECT_EQ(overlaps(c.a, c.b), got.separation < 0) << what;

      const Shape b = moved(c.b, 0.0, -got.separation * got.normal);
      const double rounding = 4 * kU * center_of(b).cwiseAbs().sum() + 16 * kU * scale;
      const Contact touching = contact(c.a, b);
      const double push = std::abs(touching.separation);
      // Touching, s flips sign around 0 from one direction to the next: a climb that changed its step
      // limit with the sign ran on (to 2^31 evaluations under UBSan; 196 s in Release).
      EXPECT_LE(touching.evaluations, 1000) << what << " pushed out";
      worst_push = std::max(worst_push, push / rounding);
      EXPECT_LE(push, rounding) << what << " pushed out by " << got.separation;
      ++pushed;

      const Vec2 shift(3.0, -2.0);
      const Contact turned = contact(moved(c.a, 0.7, shift), moved(c.b, 0.7, shift));
      const double motion = std::abs(turned.separation - got.separation);
      const double reach = center_of(c.a).norm() + center_of(c.b).norm() + shift.norm();
      const double motion_bound = 16 * kU * (reach + 8 * size) + 16 * kU * scale;
      worst_motion = std::max(worst_motion, motion / motion_bound);
      EXPECT_LE(motion, motion_bound) << what;
    }
  }
  std::printf(
      "[contact] properties: %d pairs apart; %d pushed out, worst %.2f of the bound; rigid motion worst %.2f of it\n",
      apart, pushed, worst_push, worst_motion);
}

// The kernels with orientations kept against the same kernels computing them, on every family:
// the same contact bit for bit (Orientation::of is the kernels' own rotation).
using KernelPair = std::optional<std::pair<Contact, Contact>>;
template <class A, class B>
KernelPair both_ways(const A&, const B&) {
  return std::nullopt;
}
KernelPair both_ways(const Rect& a, const Rect& b) {
  return std::pair{contact_rect_rect(a, b),
                   contact_rect_rect(a, Orientation::of(a.angle), b, Orientation::of(b.angle))};
}
KernelPair both_ways(const Rect& a, const Circle& b) {
  return std::pair{contact_rect_circle(a, b), contact_rect_circle(a, Orientation::of(a.angle), b)};
}
KernelPair both_ways(const Rect& a, const Ellipse& b) {
  return std::pair{contact_rect_ellipse(a, b),
                   contact_rect_ellipse(a, Orientation::of(a.angle), b, Orientation::of(b.angle))};
}
KernelPair both_ways(const Circle& a, const Ellipse& b) {
  return std::pair{contact_circle_ellipse(a, b), contact_circle_ellipse(a, b, Orientation::of(b.angle))};
}
KernelPair both_ways(const Ellipse& a, const Ellipse& b) {
  return std::pair{contact_ellipse_ellipse(a, b),
                   contact_ellipse_ellipse(a, Orientation::of(a.angle), b, Orientation::of(b.angle))};
}

TEST(ContactOrientations, KeptGiveTheSameContact) {
  int compared = 0;
  for (const ContactFamily& cf : contact_families()) {
    Family f = cf.family;
    f.cases = 12;
    for (const Case& c : family_cases(f)) {
      const KernelPair got = std::visit([](const auto& a, const auto& b) { return both_ways(a, b); }, c.a, c.b);
      if (!got) continue;
      ++compared;
      const auto& [plain, kept] = *got;
      expect_same_contact(plain, kept, describe(c.a) + " ; " + describe(c.b));
    }
  }
  EXPECT_GT(compared, 500);
}

// The same for the queries over any pair (either order, shapes of one kind put in kernel order):
// the contact, and the overlap verdict (the World's narrow phase).
TEST(ContactOrientations, KeptByTheCallerGiveTheSameQuery) {
  int compared = 0, overlapping = 0;
  for (const ContactFamily& cf : contact_families()) {
    Family f = cf.family;
    f.cases = 6;
    for (const Case& c : family_cases(f)) {
      const Orientation oa = Orientation::of(angle_of(c.a)), ob = Orientation::of(angle_of(c.b));
      for (const bool swap : {false, true}) {
        const Shape& a = swap ? c.b : c.a;
        const Shape& b = swap ? c.a : c.b;
        expect_same_contact(contact(a, b), contact(a, swap ? ob : oa, b, swap ? oa : ob),
                            describe(a) + " ; " + describe(b));
        const bool overlap = overlaps(a, b);
        EXPECT_EQ(overlaps(a, swap ? ob : oa, b, swap ? oa : ob), overlap) << describe(a) + " ; " + describe(b);
        overlapping += overlap;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 500);
  EXPECT_GT(overlapping, 100);
  EXPECT_LT(overlapping, compared - 100);
  std::printf("[contact] orientations kept: %d pairs compared, %d of them overlapping\n", compared, overlapping);
}

// Box2D's manifold on the cases it exists for: a box resting on a box (two points, the overlap of
// the faces, each at the exact depth 1/128), the same box tilted (one point; both with a margin),
// the pair swapped (features renamed, normal reversed), the same features after a small motion
// (same ids), and two corners nearest while apart (a corner pair).
TEST(ContactManifold, RectanglesResting) {
  const Rect floor{{0, 0}, {2, 0.5}, 0};
  const Rect box{{0.25, 0.75 - 1.0 / 128}, {0.5, 0.25}, 0};
  const Contact c = contact(floor, box);
  EXPECT_EQ(c.separation, -1.0 / 128);
  EXPECT_EQ(c.normal, Vec2(0, 1));
  ASSERT_EQ(c.manifold_size, 2);
  double xs[2];
  for (int i = 0; i < 2; ++i) {
    const ContactPoint& p = c.manifold[static_cast<std::size_t>(i)];
    EXPECT_EQ(p.separation, -1.0 / 128);
    EXPECT_EQ(p.point_a.y(), 0.5);
    EXPECT_EQ(p.point_b.y(), 0.5 - 1.0 / 128);
    EXPECT_EQ(p.point_a.x(), p.point_b.x());
    EXPECT_EQ(feature_kind(p.id), FeatureKind::face_of_a);
    xs[i] = p.point_b.x();
  }
  EXPECT_EQ(std::min(xs[0], xs[1]), -0.25);
  EXPECT_EQ(std::max(xs[0], xs[1]), 0.75);
  // The floor's +y face (1) against the box's lower corners (0 and 1).
  const std::uint32_t ids[2] = {c.manifold[0].id, c.manifold[1].id};
  EXPECT_EQ(std::min(ids[0], ids[1]), feature_id(FeatureKind::face_of_a, 1, 0));
  EXPECT_EQ(std::max(ids[0], ids[1]), feature_id(FeatureKind::face_of_a, 1, 1));

  // Swapped, the faces still tie, and the box, now first, gives the reference face: its -y face (3)
  // against the floor's top face cut by its side planes (4 and 5).
  const Contact back = contact(box, floor);
  EXPECT_EQ(back.normal, Vec2(0, -1));
  EXPECT_EQ(back.separation, c.separation);
  ASSERT_EQ(back.manifold_size, 2);
  const std::uint32_t back_ids[2] = {back.manifold[0].id, back.manifold[1].id};
  EXPECT_EQ(std::min(back_ids[0], back_ids[1]), feature_id(FeatureKind::face_of_a, 3, 4));
  EXPECT_EQ(std::max(back_ids[0], back_ids[1]), feature_id(FeatureKind::face_of_a, 3, 5));
  // Turned by 1e-3, the box's face no longer ties with the floor's (the floor's far corners reach
  // 2e-3 deeper along the box's normal than the box's corners below the floor's face): the floor's
  // face is the reference either way, and the swapped ids are the swapped features.
  const Rect post{{0.25, 0.75 - 1.0 / 128}, {0.5, 0.25}, 1e-3};
  const Contact on_floor = contact(floor, post), swapped = contact(post, floor);
  ASSERT_EQ(on_floor.manifold_size, 2);
  ASSERT_EQ(swapped.manifold_size, 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(swapped.manifold[static_cast<std::size_t>(i)].id,
              swapped_feature(on_floor.manifold[static_cast<std::size_t>(i)].id));
    EXPECT_EQ(feature_kind(swapped.manifold[static_cast<std::size_t>(i)].id), FeatureKind::face_of_b);
  }

  Rect nudged = box;
  nudged.center += Vec2(0.01, -0.001);
  nudged.angle = 1e-3;
  const Contact later = contact(floor, nudged);
  ASSERT_EQ(later.manifold_size, 2);
  EXPECT_EQ(std::min(later.manifold[0].id, later.manifold[1].id), std::min(ids[0], ids[1]));
  EXPECT_EQ(std::max(later.manifold[0].id, later.manifold[1].id), std::max(ids[0], ids[1]));
  // Deepest first: turned counter-clockwise, the box's lower right corner rises.
  EXPECT_LT(later.manifold[0].separation, later.manifold[1].separation);
  EXPECT_EQ(later.manifold[0].separation, later.separation);

  Rect tilted = box;
  tilted.angle = 0.1;
  EXPECT_EQ(contact(floor, tilted).manifold_size, 1);
  EXPECT_EQ(contact(floor, tilted, {.margin = 0.2}).manifold_size, 2);

  const Rect corner{{3.5, 1.5}, {0.5, 0.5}, 0.0};  // (3, 1) is 1 from (2, 0.5) along x and 0.5 along y
  const Contact apart = contact(floor, corner);
  EXPECT_DOUBLE_EQ(apart.separation, std::sqrt(1.25));
  EXPECT_EQ(apart.manifold_size, 1);
  EXPECT_EQ(apart.manifold[0].id, feature_id(FeatureKind::corner_corner, 2, 0));
  EXPECT_NEAR((apart.normal - Vec2(1, 0.5) / std::sqrt(1.25)).norm(), 0, 1e-16);
}

// A box resting on a face of equal separation (its bottom face on a floor 20 long or on a box 4
// wide, turned by up to 1e-12 from parallel, at several angles), slid over 10,000 positions along
// it, keeps the floor's face as its reference, so its two feature ids, and its normal to the
// normal's rounding: the faces' separations tie up to rounding, and the kernel order of the two
// rectangles changes as the box passes the floor's centre, so without the preference for the face
// of the shape named first one or the other face became the reference.
TEST(ContactManifold, SlidingBoxKeepsItsFeatures) {
  int slides = 0;
  for (const double base : {0.0, 0.3, 1.1, 2.5}) {
    for (const double tilt : {0.0, 1e-13, -1e-13, 1e-12, -1e-12}) {
      for (const double floor_half : {10.0, 2.0}) {
        const Rect floor{{3, -2}, {floor_half, 0.5}, base};
        const Vec2 along(std::cos(base), std::sin(base)), up(-std::sin(base), std::cos(base));
        std::set<std::uint32_t> first_ids;
        Vec2 first_normal = Vec2::Zero();
        int flips = 0;
        double worst_turn = 0;
        for (int i = 0; i < 10000; ++i) {
          const double x = (floor_half - 0.501) * (2.0 * i / 9999 - 1);
          const Rect box{floor.center + x * along + (0.75 - 1.0 / 128) * up, {0.5, 0.25}, base + tilt};
          const Contact c = contact(floor, box);
          ASSERT_EQ(c.manifold_size, 2) << base << ' ' << tilt << ' ' << x;
          const std::set<std::uint32_t> ids{c.manifold[0].id, c.manifold[1].id};
          if (i == 0) {
            first_ids = ids;
            first_normal = c.normal;
          }
          flips += ids != first_ids;
          worst_turn = std::max(worst_turn, angle_between(c.normal, first_normal));
        }
        const std::string what =
            "base " + std::to_string(base) + " tilt " + std::to_string(tilt) + " floor " + std::to_string(floor_half);
        EXPECT_EQ(flips, 0) << what;
        EXPECT_EQ(feature_kind(*first_ids.begin()), FeatureKind::face_of_a) << what;
        EXPECT_LE(worst_turn, 4 * kU) << what;
        ++slides;
      }
    }
  }
  EXPECT_EQ(slides, 40);
}

// A face 6.9e20 long as the incident face of a face 16 wide: the cut points must land on the side
// planes (interpolated along the long face they would carry its rounding, 3.5e4, past the other
// plane, and the pair would be taken for two corners 3.5e20 apart). The distance is the gap between
// the parallel long sides.
TEST(ContactManifold, LongIncidentFaceClipsToAShortReferenceFace) {
  const Rect needle{{-3.8125, 10843966555981446}, {7.8125, 3.4621985169758506e+20}, -8};
  const Rect box{{-8, -8}, {8, 8}, -8};
  for (const bool swap : {false, true}) {
    const Contact c = swap ? contact(box, needle) : contact(needle, box);
    EXPECT_EQ(c.separation, distance(needle, box).distance) << swap;
    EXPECT_EQ(c.manifold_size, 2) << swap;
  }
}

// A box inside an ellipse 2.9e47 long of aspect 4,446: the bound on the ellipse's flat side (radius
// of curvature 1.3e51) must not drown in the rounding of that radius (the search would run to its
// cap of 4,096 evaluations).
TEST(ContactSearch, HugeFlatSideCertifiesWithinItsRounding) {
  const Rect box{{-2.25, -2.25}, {2.25, 2.25}, 8.5884776959808324e-275};
  const Ellipse needle{{8.3138050000613955e-275, 8.3138050000613955e-275},
                       6.419116461067246e+43,
                       2.8545232667078439e+47,
                       -13203.574554449877};
  const Contact c = contact(box, needle);
  EXPECT_LT(c.evaluations, 200);
  const double reference = static_cast<double>(reference::signed_distance(box, needle).separation);
  EXPECT_LE(std::abs(c.separation - reference), 8 * kU * 2.9e47);
}

// A needle's flat side (aspect 9,440) facing a rectangle 8,604 away: s has a peak far sharper than
// its surroundings, where plain Newton swings from side to side with steps of one size (every call
// would run its 200 iterations, the search its cap, and the separation fall 1.1e-3 short). The
// iteration bisects whenever a step would not halve the last.
TEST(ContactSearch, SharpPeakBesideAFarRectangle) {
  const Rect box{{-8, 4}, {6.375, 5.6875}, 2};
  const Ellipse needle{{-7.75, 8616.3496323525906}, 4.5, 0.00047666206976579019, 0};
  const Contact c = contact(box, needle);
  EXPECT_LT(c.evaluations, 100);
  EXPECT_NEAR(c.separation, distance(box, needle).distance, 8 * kU * 8620);
}

// Centres 1e-160 apart: their difference squares to a denormal, and a normal from norm() came out
// 1.00004 long (the fuzzer); centres a denormal or two apart gave normals 0.94 to 1.41 long. The circle pairs, nearly
// concentric (a rectangle's corner, at least 1e-50 from its centre, keeps differences beside it far above the
// denormals).
TEST(ContactNormal, UnitWhenTheCentresNearlyCoincide) {
  const Vec2 tiny(0, 1.1436311670790528e-160);
  const Shape pairs[][2] = {{Circle{{7.9375, 0}, 8}, Circle{Vec2(7.9375, 0) + tiny, 6.125}},
                            // a difference of one and two denormals: its rounded length, divided
                            // into it, gave a normal 1.118 long (the fuzzer)
                            {Circle{{0, 0}, 8}, Circle{{4.9406564584124654e-324, -9.8813129168249309e-324}, 6.125}},
                            {Circle{{0, 0}, 8}, Circle{{9.8813129168249309e-324, 9.8813129168249309e-324}, 6.125}},
                            {Circle{{0, 0}, 1}, Ellipse{tiny, 2, 1, 0}},
                            // the climb's start direction (the fuzzer: 1e-9 off unit length)
                            {Ellipse{{2.5278101602652375e-158, -8}, 8, 8, 5.5322820227311624e-222},
                             Ellipse{{5.4110079941854194e-312, -8}, 8, 8, -8}},
                            {Ellipse{{0, -8}, 8, 8, 3.8125}, Ellipse{{1.2598673968951787e-321, -8}, 8, 8, -8}}};
  for (const auto& pair : pairs) {
    const Contact c = contact(pair[0], pair[1]);
    EXPECT_NEAR(c.normal.norm(), 1.0, 4 * kU) << shape_name(pair[0]) << "-" << shape_name(pair[1]);
    // Concentric to within 1e-160: the depth is the two radii across, the ellipse's minor one.
    const double across = std::holds_alternative<Circle>(pair[1]) ? 14.125 : std::get<Ellipse>(pair[1]).b == 1 ? 2 : 16;
    EXPECT_NEAR(c.separation, -across, 8 * kU * 16);
  }
}

TEST(ContactManifold, CurvedPairsGiveOnePoint) {
  const Contact c = contact(Ellipse{{0, 0}, 2, 1, 0.3}, Rect{{1, 1.2}, {0.5, 0.25}, 0.2});
  EXPECT_EQ(c.manifold_size, 1);
  EXPECT_EQ(c.manifold[0].id, 0u);
  EXPECT_EQ(c.manifold[0].point_a, c.point_a);
  EXPECT_EQ(c.manifold[0].separation, c.separation);
}

TEST(ContactValidation, NamesTheBadField) {
  EXPECT_THROW(contact(Circle{{0, 0}, -1}, Circle{}), InvalidShape);
  EXPECT_THROW(contact(Rect{}, Ellipse{{0, std::nan("")}, 1, 1, 0}), InvalidShape);
  ContactOptions bad;
  bad.guess = Vec2(1, INFINITY);
  try {
    contact(Rect{}, Ellipse{{3, 0}, 1, 1, 0}, bad);
    ADD_FAILURE() << "an infinite guess was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "contact guess must be finite");
  }
}

}  // namespace
}  // namespace collide2d::testing
