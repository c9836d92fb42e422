// The batched overlap tests (batch.h, overlap_pairs.h) against the one-off tests, verdict for verdict, on
// every SIMD target Highway compiled that this CPU runs: the hard-case families (rounding-level
// gaps included, where the rectangle–ellipse batch must hand pairs to the fallback), two million
// random rectangle–ellipse, a million rectangle–rectangle and half a million of each circle pair's
// and of ellipse pairs' candidate pairs in batches of ragged lengths, and lists of different
// lengths refused.
#include "batch_testing.h"
#include "core_families.h"
#include "hard_cases.h"

#include <collide2d/batch.h>
#include <collide2d/kernels.h>
#include <collide2d/query.h>
#include "narrowphase/batch/overlap_pairs.h"
#include "narrowphase/overlap/overlap_rect_ellipse.h"
#include "narrowphase/shared/lanes.h"
#include "tools/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/disc_filter-inl.h"
#include "narrowphase/overlap/overlap_ellipse_ellipse-inl.h"
#include "narrowphase/shared/cores/least_quadratic-inl.h"
}  // namespace detail

namespace testing {
namespace {

// The batched test, and the one-off test with orientations kept (query.h), for each pair kind.
template <class A, class B>
void batch(const Pairs<A, B>& p, std::size_t start, std::size_t count, std::span<std::uint8_t> out) {
  detail::overlap_batch<A, B>(std::span(p.a).subspan(start, count), std::span(p.a_orientations).subspan(start, count),
                              std::span(p.b).subspan(start, count), std::span(p.b_orientations).subspan(start, count),
                              out);
}
template <class A, class B>
bool one_off(const Pairs<A, B>& p, std::size_t k) {
  return overlaps(p.a[k], p.a_orientations[k], p.b[k], p.b_orientations[k]);
}

// Runs the batch on [start, start + count) and compares each verdict with the one-off kernel's;
// returns the number of mismatches (each also reported).
template <class A, class B>
int mismatches(const Pairs<A, B>& p, std::size_t start, std::size_t count, const char* target) {
  std::vector<std::uint8_t> out(count, 7);
  batch(p, start, count, out);
  int wrong = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t k = start + i;
    const bool one = one_off(p, k);
    if (out[i] == (one ? 1 : 0)) continue;
    if (++wrong <= 5) {
      ADD_FAILURE() << target << ": pair " << k << " batch " << int(out[i]) << ", one-off " << one << ": "
                    << describe(p.a[k]) << " ; " << describe(p.b[k]);
    }
  }
  return wrong;
}

// The same in batches of 1 to 600 pairs, so that chunks end everywhere in a vector and the padding
// is exercised.
template <class A, class B>
int mismatches_in_ragged_batches(const Pairs<A, B>& p, const char* target) {
  std::mt19937_64 lengths(5);
  int wrong = 0;
  for (std::size_t start = 0; start < p.size();) {
    const std::size_t count = std::min<std::size_t>(1 + lengths() % 600, p.size() - start);
    wrong += mismatches(p, start, count, target);
    start += count;
  }
  return wrong;
}

TEST(OverlapBatch, HardCaseFamiliesMatchTheOneOffKernel) {
  std::vector<Family> families = standard_families(Kind::rect, Kind::ellipse);
  for (const double aspect : {1.0, 1e3, 1e6}) {
    Family rounding{.name = "rounding", .a = Kind::rect, .b = Kind::ellipse, .cases = 280};
    rounding.aspect_min = aspect;
    rounding.aspect_max = 4 * aspect;
    rounding.deltas = {0.0, 1e-14, -1e-14, 1e-15, -1e-15, 1e-16, -1e-16};
    families.push_back(rounding);
  }
  Pairs<Rect, Ellipse> p;
  for (const Family& f : families) {
    for (const Case& c : family_cases(f)) p.add(c);
  }
  int uncertain = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    uncertain += detail::overlap_rect_ellipse_filter(p.a[k], p.b[k]) == detail::FilterVerdict::uncertain;
  }
  std::printf("%zu hard-case pairs, %d of them uncertain for the filter\n", p.size(), uncertain);
  EXPECT_GT(uncertain, 500) << "the families must send pairs to the fallback";
  on_every_target([&](const char* target) { EXPECT_EQ(mismatches(p, 0, p.size(), target), 0) << target; });
}

// Rectangle pairs of the hard-case families (touching at gaps down to 1e-12 of the size, inside,
// identical, mirrored), each also with B turned by a few ulps.
TEST(OverlapBatch, HardCaseRectanglePairsMatchTheOneOffKernel) {
  Pairs<Rect, Rect> p;
  for (const Family& f : standard_families(Kind::rect, Kind::rect)) {
    for (const Case& c : family_cases(f)) {
      Rect b = std::get<Rect>(c.b);
      p.add(std::get<Rect>(c.a), b);
      b.angle = std::nextafter(std::nextafter(b.angle, 10.0), 10.0);
      p.add(std::get<Rect>(c.a), b);
    }
  }
  // The fuzzer's pair: a rectangle 2.4e35 wide whose corner rounds onto a small one's; the verdict
  // depends on whose frame the test runs in, so the batch must take the dispatcher's order, either
  // way round.
  const Rect huge{
      {2.4173705217460969e+35, 2.4173705217460969e+35}, {2.4173705217460969e+35, 2.4173705217460969e+35}, 0};
  const Rect small{{-8, -8}, {8, 8}, -8};
  ASSERT_NE(overlap_rect_rect(huge, small), overlap_rect_rect(small, huge))
      << "the pair no longer tells the orders apart";
  p.add(huge, small);
  p.add(small, huge);
  std::printf("%zu hard-case rectangle pairs\n", p.size());
  on_every_target([&](const char* target) { EXPECT_EQ(mismatches(p, 0, p.size(), target), 0) << target; });
}

// The hard cases of the circle pairs: touching at gaps down to 1e-12 of the size (where the
// circle–ellipse test leaves pairs to the root), nested, concentric, at the evolute's cusps.
template <class A, class B>
void check_hard_cases(Kind a, Kind b) {
  Pairs<A, B> p;
  for (const Family& f : standard_families(a, b)) {
    for (const Case& c : family_cases(f)) p.add(c);
  }
  std::printf("%zu hard-case pairs\n", p.size());
  on_every_target([&](const char* target) { EXPECT_EQ(mismatches(p, 0, p.size(), target), 0) << target; });
}

TEST(OverlapBatch, HardCaseCirclePairsMatchTheOneOffKernel) {
  // Two circles at the rounding level of touching, where (n - ra) - rb and (n - rb) - ra round to
  // opposite signs: the batch must take the dispatcher's order, either way round.
  const Circle big{{0, 0}, 43.430986838512901}, small{{43.433120300761729, 0}, 0.0021334622488282024};
  ASSERT_NE(overlap_circle_circle(big, small), overlap_circle_circle(small, big))
      << "the pair no longer tells the orders apart";
  Pairs<Circle, Circle> both_ways;
  both_ways.add(big, small);
  both_ways.add(small, big);
  on_every_target([&](const char* target) { EXPECT_EQ(mismatches(both_ways, 0, 2, target), 0) << target; });
  check_hard_cases<Circle, Circle>(Kind::circle, Kind::circle);
  check_hard_cases<Rect, Circle>(Kind::rect, Kind::circle);
  check_hard_cases<Circle, Ellipse>(Kind::circle, Kind::ellipse);
}

// Ellipse pairs of the hard-case families (touching at gaps down to 1e-12 of the size, needles to
// aspect 1e6, offsets to 1e9, nested, identical), where the algebraic test must leave pairs to the
// one-off kernel's GJK.
TEST(OverlapBatch, HardCaseEllipsePairsMatchTheOneOffKernel) {
  Pairs<Ellipse, Ellipse> p;
  for (const Family& f : standard_families(Kind::ellipse, Kind::ellipse)) {
    for (const Case& c : family_cases(f)) p.add(c);
  }
  int uncertain = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto v = detail::ellipse_cubic_verdicts(
        detail::Scalar{}, detail::ellipse_ellipse_lanes(p.a[k], p.a_orientations[k], p.b[k], p.b_orientations[k]));
    uncertain += !v.separated && !v.overlap;
  }
  std::printf("%zu hard-case ellipse pairs, %d of them uncertain for the algebraic test\n", p.size(), uncertain);
  EXPECT_GT(uncertain, 100) << "the families must send pairs to the one-off kernel";
  on_every_target([&](const char* target) { EXPECT_EQ(mismatches(p, 0, p.size(), target), 0) << target; });
}

// Candidate pairs as a broad phase hands them over, half of them placed at a small gap (either
// sign) along a random direction, needles to aspect 1e6, in batches of ragged lengths.
TEST(OverlapBatch, RandomCandidatePairsMatchTheOneOffKernel) {
  std::mt19937_64 rng(29);
  const tool::Uniform u(0.0, 1.0);
  Pairs<Rect, Ellipse> with_ellipses;
  Pairs<Rect, Rect> rects;
  Pairs<Circle, Circle> circles;
  Pairs<Rect, Circle> rect_circles;
  Pairs<Circle, Ellipse> circle_ellipses;
  Pairs<Ellipse, Ellipse> ellipses;
  while (with_ellipses.size() < 1'000'000) {
    const double aspect = std::pow(10.0, 6 * u(rng));
    const double ry = 4 * u(rng);
    const Vec2 rc(4 * u(rng), ry);
    const double height = 0.05 + u(rng);
    const Rect r{rc, Vec2(0.05 + u(rng), height), 7 * u(rng)};
    const double ey = 4 * u(rng);
    Ellipse e{Vec2(4 * u(rng), ey), 0.05 + u(rng), 0, 7 * u(rng)};
    e.b = e.a / aspect;
    Rect s{e.center, Vec2(e.a, e.b), e.angle};
    Circle c{e.center, e.a}, d{r.center, 0.05 + u(rng)};
    Ellipse f{r.center, 0.05 + u(rng), 0, 7 * u(rng)};
    f.b = f.a / std::pow(10.0, 3 * u(rng));
    if (with_ellipses.size() % 2 == 1) {
      const double sine = std::sin(7 * u(rng));
      const Vec2 n(std::cos(7 * u(rng)), sine);
      const double side = u(rng) - 0.5;
      const double gap = side * std::pow(10.0, -16 * u(rng));
      e.center = support(r, n) + gap * n - support(e, Vec2(-n));
      s.center = support(r, n) + gap * n - support(s, Vec2(-n));
      c.center = support(r, n) + gap * n - support(c, Vec2(-n));
      d.center = support(e, n) + gap * n - support(d, Vec2(-n));
      f.center = support(e, n) + gap * n - support(f, Vec2(-n));
    }
    if (intersects(aabb(r), aabb(e))) with_ellipses.add(r, e);
    if (rects.size() < 500'000 && intersects(aabb(r), aabb(s))) rects.add(r, s);
    if (rect_circles.size() < 250'000 && intersects(aabb(r), aabb(c))) rect_circles.add(r, c);
    if (circles.size() < 250'000 && intersects(aabb(d), aabb(c))) circles.add(d, c);
    if (circle_ellipses.size() < 250'000 && intersects(aabb(d), aabb(e))) circle_ellipses.add(d, e);
    if (ellipses.size() < 250'000 && intersects(aabb(e), aabb(f))) ellipses.add(e, f);
  }
  on_every_target([&](const char* target) {
    EXPECT_EQ(mismatches_in_ragged_batches(with_ellipses, target), 0) << target;
    EXPECT_EQ(mismatches_in_ragged_batches(rects, target), 0) << target;
    EXPECT_EQ(mismatches_in_ragged_batches(circles, target), 0) << target;
    EXPECT_EQ(mismatches_in_ragged_batches(rect_circles, target), 0) << target;
    EXPECT_EQ(mismatches_in_ragged_batches(circle_ellipses, target), 0) << target;
    EXPECT_EQ(mismatches_in_ragged_batches(ellipses, target), 0) << target;
  });
}

// Whether the vector kernels leave the pair to the exact test: the disc test, then against an
// ellipse or a circle the least quadratic.
template <class A, class B>
bool left_uncertain(const Pairs<A, B>& p, std::size_t k) {
  const detail::PairRef<A, B> pair{p.a[k], p.a_orientations[k], p.b[k], p.b_orientations[k]};
  const auto discs = detail::disc_verdicts(detail::Scalar{}, detail::disc_lanes_of(pair));
  if (discs.separated || discs.overlap) return false;
  if constexpr (requires { detail::lanes_of(pair); }) {
    const auto v = detail::core_ellipse_verdicts(detail::Scalar{}, detail::lanes_of(pair));
    return !v.separated && !v.overlap;
  }
  return true;
}

// A core shape of the kinds `as` against one of the kinds `bs`: the core families (touching at gaps
// of +-1e-3 to 1e-12 of the size and 0, deep, slivers of aspect 1e6, far off, tiny and huge), and
// candidate pairs at random sizes, half of them at a gap of either sign down to 1e-16 along a random
// direction.
template <class A, class B>
void check_cores(std::span<const Form> as, std::span<const Form> bs) {
  Pairs<A, B> p;
  for (CoreFamily f : core_families()) {
    if (!is_one_of(as, f.a) || !is_one_of(bs, f.b)) continue;
    f.cases = 240;
    for (const CoreCase& c : cases_of(f)) p.add(std::get<A>(c.a), std::get<B>(c.b));
  }
  const std::size_t family_pairs = p.size();
  std::mt19937_64 rng(37);
  const tool::Uniform u(0.0, 1.0);
  for (std::size_t k = 0; p.size() < family_pairs + 300'000; ++k) {
    const auto random = [&](std::span<const Form> kinds) {
      const double aspect = std::pow(10.0, 3 * u(rng));
      return random_shape(*(kinds.begin() + k % kinds.size()), 0.05 + u(rng), aspect, rng);
    };
    const Shape a = random(as);
    Shape b = random(bs);
    const double sine = std::sin(7 * u(rng));
    const Vec2 n(std::cos(7 * u(rng)), sine);
    const double side = u(rng) - 0.5;
    const double gap = k % 2 == 0 ? side * std::pow(10.0, -16 * u(rng)) : 4 * side;
    std::get<B>(b).center = support(a, n) + gap * n - support(b, Vec2(-n));
    if (intersects(aabb(a), aabb(b))) p.add(std::get<A>(a), std::get<B>(b));
  }
  int uncertain = 0;
  for (std::size_t k = 0; k < p.size(); ++k) uncertain += left_uncertain(p, k);
  std::printf("%zu pairs, %d of them left to the exact test\n", p.size(), uncertain);
  EXPECT_GT(uncertain, 1000) << "the pairs must go to the exact test";
  on_every_target([&](const char* target) { EXPECT_EQ(mismatches_in_ragged_batches(p, target), 0) << target; });
}

constexpr Form kEllipse[] = {Form::ellipse};
constexpr Form kCircle[] = {Form::circle};

TEST(OverlapBatch, PolygonEllipsePairsMatchTheOneOffKernel) {
  check_cores<ConvexPolygon, Ellipse>(testing::kPolygonKinds, kEllipse);
}
TEST(OverlapBatch, CapsuleEllipsePairsMatchTheOneOffKernel) {
  check_cores<Capsule, Ellipse>(testing::kCapsuleKinds, kEllipse);
}
TEST(OverlapBatch, PolygonCirclePairsMatchTheOneOffKernel) {
  check_cores<ConvexPolygon, Circle>(testing::kPolygonKinds, kCircle);
}
TEST(OverlapBatch, CapsuleCirclePairsMatchTheOneOffKernel) {
  check_cores<Capsule, Circle>(testing::kCapsuleKinds, kCircle);
}
TEST(OverlapBatch, PolygonPairsMatchTheOneOffKernel) {
  check_cores<ConvexPolygon, ConvexPolygon>(testing::kPolygonKinds, testing::kPolygonKinds);
}

TEST(OverlapBatch, ListsOfDifferentLengthsAreRefusedBeforeAnyWrite) {
  Pairs<Rect, Ellipse> p;
  p.add(Rect{{0, 0}, {1, 1}, 0}, Ellipse{{1.5, 0}, 1, 0.5, 0});
  p.add(Rect{{0, 0}, {1, 1}, 0}, Ellipse{{5, 0}, 1, 0.5, 0});
  std::vector<std::uint8_t> out(3, 7);
  try {
    overlap_rect_ellipse(p.a, p.a_orientations, p.b, p.b_orientations, out);
    ADD_FAILURE() << "three verdicts for two pairs were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "overlap_rect_ellipse: the lists differ in length (2, 2, 2, 2 pairs in, 3 verdicts out)");
  }
  EXPECT_EQ(out, std::vector<std::uint8_t>(3, 7));
  const std::vector<Rect> rects{Rect{{0, 0}, {1, 1}, 0}, Rect{{2.5, 0}, {1, 1}, 0}};
  try {
    overlap_rect_rect(rects, std::span(p.a_orientations).first(1), rects, p.b_orientations, std::span(out).first(2));
    ADD_FAILURE() << "one orientation for two rectangles was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "overlap_rect_rect: the lists differ in length (2, 1, 2, 2 pairs in, 2 verdicts out)");
  }
  EXPECT_EQ(out, std::vector<std::uint8_t>(3, 7));
  out.resize(2);
  overlap_rect_ellipse(p.a, p.a_orientations, p.b, p.b_orientations, out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{1, 0}));
  // Rectangles 2.5 apart with half widths 1: the first pair is one rectangle twice, the second apart.
  const std::vector<Rect> firsts{rects[0], rects[0]};
  overlap_rect_rect(firsts, p.a_orientations, rects, p.b_orientations, out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{1, 0}));
  overlap_rect_ellipse({}, {}, {}, {}, {});  // nothing to do, and nothing touched
  overlap_rect_rect({}, {}, {}, {}, {});
  const std::vector<Circle> discs{Circle{{0, 0}, 1}, Circle{{3, 0}, 1}};
  EXPECT_THROW(overlap_circle_circle(discs, std::span(discs).first(1), std::span(out).first(2)), std::invalid_argument);
  overlap_circle_circle(discs, std::vector<Circle>{Circle{{1.5, 0}, 1}, Circle{{0, 0}, 1}}, out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{1, 0}));
}

}  // namespace
}  // namespace testing
}  // namespace collide2d
