// The batched circle–ellipse and rectangle–circle contacts (batch.h) against the one-off kernels,
// bit for bit in every field, on every SIMD target Highway compiled that this CPU runs: the
// hard-case families, the cases the lanes hand back to the one-off kernels (axis cases, corners a
// denormal away), the cases' ties, half a million random candidate pairs each in batches of ragged
// lengths; and lists of different lengths refused.
#include "batch_testing.h"
#include "hard_cases.h"
#include "tools/random.h"

#include <collide2d/batch.h>
#include <collide2d/kernels.h>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

namespace collide2d::testing {
namespace {

bool same_bits(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }
bool same_bits(const Vec2& x, const Vec2& y) { return same_bits(x.x(), y.x()) && same_bits(x.y(), y.y()); }

bool same_bits(const Contact& x, const Contact& y) {
  const ContactPoint &p = x.manifold[0], &q = y.manifold[0];
  return same_bits(x.separation, y.separation) && same_bits(x.normal, y.normal) && same_bits(x.point_a, y.point_a) &&
         same_bits(x.point_b, y.point_b) && x.manifold_size == y.manifold_size && same_bits(p.point_a, q.point_a) &&
         same_bits(p.point_b, q.point_b) && same_bits(p.separation, q.separation) && p.id == q.id &&
         x.evaluations == y.evaluations;
}

// The batch on [start, start + count) of the pairs, and the one-off kernel on pair k.
void batch(const Pairs<Circle, Ellipse>& p, std::size_t start, std::size_t count, std::vector<Contact>& out) {
  contact_circle_ellipse(std::span(p.a).subspan(start, count), std::span(p.b).subspan(start, count),
                         std::span(p.b_orientations).subspan(start, count), out);
}
Contact one_off(const Pairs<Circle, Ellipse>& p, std::size_t k) {
  return contact_circle_ellipse(p.a[k], p.b[k], p.b_orientations[k]);
}
void batch(const Pairs<Rect, Circle>& p, std::size_t start, std::size_t count, std::vector<Contact>& out) {
  contact_rect_circle(std::span(p.a).subspan(start, count), std::span(p.a_orientations).subspan(start, count),
                      std::span(p.b).subspan(start, count), out);
}
Contact one_off(const Pairs<Rect, Circle>& p, std::size_t k) {
  return contact_rect_circle(p.a[k], p.a_orientations[k], p.b[k]);
}

// Runs the batch on [start, start + count) and compares each contact with the one-off kernel's;
// returns the number of mismatches (the first few also reported).
template <class A, class B>
int mismatches(const Pairs<A, B>& p, std::size_t start, std::size_t count, const char* target) {
  std::vector<Contact> out(count);
  batch(p, start, count, out);
  int wrong = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t k = start + i;
    const Contact one = one_off(p, k);
    if (same_bits(out[i], one)) continue;
    if (++wrong <= 5) {
      ADD_FAILURE() << target << ": pair " << k << " batch separation " << out[i].separation << ", one-off "
                    << one.separation << ": " << describe(p.a[k]) << " ; " << describe(p.b[k]);
    }
  }
  return wrong;
}

// The pairs in batches of 1 to 600, so that chunks end everywhere in a vector: no mismatch on any
// target.
template <class A, class B>
void expect_ragged_batches_match(const Pairs<A, B>& p) {
  std::mt19937_64 lengths(5);
  on_every_target([&](const char* target) {
    int wrong = 0;
    for (std::size_t start = 0; start < p.size();) {
      const std::size_t count = std::min<std::size_t>(1 + lengths() % 600, p.size() - start);
      wrong += mismatches(p, start, count, target);
      start += count;
    }
    EXPECT_EQ(wrong, 0) << target;
  });
}

// Circles whose centres lie in the ellipse's frame on an axis, within 1e-60 of one, exactly on the
// curve, and at the centre: the cases the lanes leave to distance_point_ellipse's closed forms.
Pairs<Circle, Ellipse> axis_cases() {
  Pairs<Circle, Ellipse> p;
  for (const Ellipse& e : {Ellipse{{1, 2}, 2, 0.5, 0}, Ellipse{{1, 2}, 0.5, 2, 0}, Ellipse{{1, 2}, 1, 1, 0}}) {
    for (const Vec2& offset : {Vec2(0, 0), Vec2(1.5, 0), Vec2(-3, 0), Vec2(0, 0.25), Vec2(0, -3), Vec2(0.5, 1e-60),
                               Vec2(1e-70, 0.25), Vec2(e.a, 0), Vec2(0, e.b), Vec2(0.6 * e.a, 0.8 * e.b)}) {
      for (const double radius : {0.1, 1.0, 5.0}) p.add(Circle{e.center + offset, radius}, e);
    }
  }
  return p;
}

TEST(ContactBatch, HardCasesAndAxisCasesMatchTheOneOffKernel) {
  Pairs<Circle, Ellipse> p = axis_cases();
  for (const Family& f : standard_families(Kind::circle, Kind::ellipse)) {
    for (const Case& c : family_cases(f)) p.add(c);
  }
  std::printf("%zu pairs\n", p.size());
  on_every_target([&](const char* target) { EXPECT_EQ(mismatches(p, 0, p.size(), target), 0) << target; });
}

// Candidate pairs, half of them placed at a small gap (either sign) along a random direction,
// ellipses to aspect 1e6, in batches of 1 to 600 pairs so that chunks end everywhere in a vector.
TEST(ContactBatch, RandomCandidatePairsMatchTheOneOffKernel) {
  std::mt19937_64 rng(31);
  const tool::Uniform u(0.0, 1.0);
  Pairs<Circle, Ellipse> p;
  while (p.size() < 500'000) {
    const double ey = 4 * u(rng);
    Ellipse e{Vec2(4 * u(rng), ey), 0.05 + u(rng), 0, 7 * u(rng)};
    e.b = e.a / std::pow(10.0, 6 * u(rng));
    const double cy = 4 * u(rng);
    Circle c{Vec2(4 * u(rng), cy), 0.05 + u(rng)};
    if (p.size() % 2 == 1) {
      const double sine = std::sin(7 * u(rng));
      const Vec2 n(std::cos(7 * u(rng)), sine);
      const double side = u(rng) - 0.5;
      const double gap = side * std::pow(10.0, -16 * u(rng));
      c.center = support(e, n) + (gap + c.radius) * n;
    }
    if (intersects(aabb(c), aabb(e))) p.add(c, e);
  }
  expect_ragged_batches_match(p);
}

// Circles at a rectangle's centre, on its faces and corners, at equal depth below two faces, a
// hair beyond a corner (at scale 1e-160 its squared distance is no normal double: left to the
// one-off kernel), at scales 1e-160 to 1e40, turned and not.
Pairs<Rect, Circle> rect_circle_cases() {
  Pairs<Rect, Circle> p;
  for (const double scale : {1e-160, 1e-40, 1.0, 1e40}) {
    for (const double angle : {0.0, 0.3, 4.0}) {
      const Rect r{{scale, -2 * scale}, {2 * scale, scale}, angle};
      const Orientation o = Orientation::of(angle);
      const auto at = [&](double x, double y) { return Vec2(r.center + Vec2(o.c * x - o.s * y, o.s * x + o.c * y)); };
      const double h = 2 * scale, k = scale;
      for (const Vec2& local :
           {Vec2(0, 0), Vec2(h, 0), Vec2(0, -k), Vec2(h, k), Vec2(-h, -k), Vec2(h - k, 0), Vec2(h + 1e-310, k + 1e-310),
            Vec2(h * (1 + 1e-15), k * (1 + 1e-15)), Vec2(3 * h, 0.5 * k), Vec2(-0.5 * h, -3 * k), Vec2(3 * h, 3 * k)}) {
        for (const double radius : {0.5 * scale, 4 * scale}) p.add(r, Circle{at(local.x(), local.y()), radius});
      }
    }
  }
  return p;
}

TEST(ContactBatch, RectCircleCasesMatchTheOneOffKernel) {
  Pairs<Rect, Circle> p = rect_circle_cases();
  for (const Family& f : standard_families(Kind::rect, Kind::circle)) {
    for (const Case& c : family_cases(f)) p.add(c);
  }
  std::printf("%zu pairs\n", p.size());
  on_every_target([&](const char* target) { EXPECT_EQ(mismatches(p, 0, p.size(), target), 0) << target; });
}

// Candidate pairs of rectangles of aspect up to 1e6 and circles, half of them with the circle's
// centre near the rectangle's boundary (corners included), in batches of ragged lengths.
TEST(ContactBatch, RandomRectCirclePairsMatchTheOneOffKernel) {
  std::mt19937_64 rng(37);
  const tool::Uniform u(0.0, 1.0);
  Pairs<Rect, Circle> p;
  while (p.size() < 500'000) {
    const double w = 0.05 + u(rng);
    const double ry = 4 * u(rng);
    const Vec2 rc(4 * u(rng), ry);
    Rect r{rc, Vec2(w, w / std::pow(10.0, 6 * u(rng))), 7 * u(rng)};
    const double cy = 4 * u(rng);
    Circle c{Vec2(4 * u(rng), cy), 0.05 + u(rng)};
    if (p.size() % 2 == 1) {
      const Orientation o = Orientation::of(r.angle);
      const double sign = 2 * std::round(u(rng)) - 1;
      const double x = r.half_extents.x() * sign * (1 + (u(rng) - 0.5) * 1e-12);
      const double y = r.half_extents.y() * (2 * u(rng) - 1);
      const Vec2 local = p.size() % 4 == 1 ? Vec2(x, y) : Vec2(x, r.half_extents.y() + (u(rng) - 0.5) * 1e-12);
      c.center = r.center + Vec2(o.c * local.x() - o.s * local.y(), o.s * local.x() + o.c * local.y());
    }
    if (intersects(aabb(r), aabb(c))) p.add(r, c);
  }
  expect_ragged_batches_match(p);
}

TEST(ContactBatch, ListsOfDifferentLengthsAreRefusedBeforeAnyWrite) {
  const std::vector<Circle> circles{Circle{{0, 0}, 1}, Circle{{5, 0}, 1}};
  const std::vector<Ellipse> ellipses{Ellipse{{1.5, 0}, 1, 0.5, 0}, Ellipse{{1.5, 0}, 1, 0.5, 0}};
  const std::vector<Orientation> orientations(2);
  std::vector<Contact> out(3);
  out[0].separation = 7;
  try {
    contact_circle_ellipse(circles, ellipses, orientations, out);
    ADD_FAILURE() << "three contacts for two pairs were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "contact_circle_ellipse: the lists differ in length (2, 2, 2 pairs in, 3 contacts out)");
  }
  EXPECT_EQ(out[0].separation, 7);
  contact_circle_ellipse(circles, ellipses, orientations, std::span(out).first(2));
  // The first circle's centre is 0.5 beyond the ellipse's left end, the second 2.5 beyond its right.
  EXPECT_EQ(out[0].separation, -0.5);
  EXPECT_EQ(out[1].separation, 1.5);
  contact_circle_ellipse(std::span<const Circle>{}, {}, {}, {});  // nothing to do, and nothing touched
  const std::vector<Rect> rects{Rect{{0, 0}, {1, 1}, 0}};
  try {
    contact_rect_circle(rects, orientations, circles, out);
    ADD_FAILURE() << "lists of different lengths were taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "contact_rect_circle: the lists differ in length (1, 2, 2 pairs in, 3 contacts out)");
  }
  EXPECT_EQ(out[0].separation, -0.5);
}

}  // namespace
}  // namespace collide2d::testing
