// Narrow-phase fuzzer, built once per kernel family (tests/fuzz/CMakeLists.txt): COLLIDE2D_FUZZ_FIRST
// and COLLIDE2D_FUZZ_SECOND name the kinds of the two shapes, `any` letting the bytes choose.
// Invalid shapes must be refused with InvalidShape; for valid ones the answers must be finite, the
// overlap verdict must match the distance (0 exactly when overlapping) and the batched test's
// verdict; swapping A and B must swap the result exactly, and moving both
// shapes by one rigid motion must keep the distance (to 1e-9 of the scale). The contact must be
// finite with a unit normal, its separation the distance when apart and at most 0 when
// overlapping (to 1e-9 of the scale), the same both ways with the normal reversed, and its search
// certified within its cap of support evaluations.
#include <collide2d/batch.h>
#include <collide2d/kernels.h>
#include <collide2d/query.h>
#include "fuzz_input.h"
#include "narrowphase/internal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <type_traits>

namespace {

using namespace collide2d;

using fuzz::check;
using fuzz::fail;

Shape moved(const Shape& s, double c, double sn, const Vec2& t) {
  return std::visit(
      [&](auto x) -> Shape {
        x.center = Vec2(c * x.center.x() - sn * x.center.y(), sn * x.center.x() + c * x.center.y()) + t;
        if constexpr (!std::is_same_v<decltype(x), Circle>) x.angle += std::atan2(sn, c);
        return x;
      },
      s);
}

// The batched test's verdict on the pair as a list of one, in kernel order.
bool batched(const Shape& a, const Shape& b) {
  return std::visit(
      [&](const auto& x, const auto& y) {
        using X = std::decay_t<decltype(x)>;
        using Y = std::decay_t<decltype(y)>;
        if constexpr (!detail::batched<X, Y>) {
          return overlaps(a, b);  // no batch takes the kind
        } else if constexpr (detail::rank<X>() > detail::rank<Y>()) {
          return batched(b, a);
        } else {
          const Orientation ox = Orientation::of(angle_of(x)), oy = Orientation::of(angle_of(y));
          std::uint8_t verdict = 2;
          detail::overlap_batch<X, Y>(std::span(&x, 1), std::span(&ox, 1), std::span(&y, 1), std::span(&oy, 1),
                                      std::span(&verdict, 1));
          return verdict == 1;
        }
      },
      a, b);
}

// The batched circle–ellipse contact of a circle and an ellipse as a list of one: the one-off
// contact's numbers.
void check_batched_contact(const Shape& a, const Shape& b) {
  const Circle* circle = std::get_if<Circle>(&a);
  const Ellipse* ellipse = std::get_if<Ellipse>(&b);
  if (circle == nullptr || ellipse == nullptr) return;
  const Orientation o = Orientation::of(ellipse->angle);
  Contact batch;
  contact_circle_ellipse(std::span(circle, 1), std::span(ellipse, 1), std::span(&o, 1), std::span(&batch, 1));
  const Contact one = contact_circle_ellipse(*circle, *ellipse, o);
  check(batch.separation == one.separation && batch.normal == one.normal && batch.point_a == one.point_a &&
            batch.point_b == one.point_b,
        "batched contact the one-off contact");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input in(data, size);
  const Shape a = in.shape(fuzz::Kind::COLLIDE2D_FUZZ_FIRST);
  const Shape b = in.shape(fuzz::Kind::COLLIDE2D_FUZZ_SECOND);
  if (!fuzz::valid(a) || !fuzz::valid(b)) {
    try {
      distance(a, b);
      fail("an invalid shape was accepted");
    } catch (const InvalidShape&) {
    }
    return 0;
  }
  const bool hit = overlaps(a, b);
  const DistanceResult d = distance(a, b);
  check(std::isfinite(d.distance) && d.distance >= 0, "distance finite and non-negative");
  check(d.point_a.allFinite() && d.point_b.allFinite(), "closest points finite");
  check(d.overlapping == hit && (d.distance == 0) == hit, "distance 0 exactly when overlapping");
  check(hit == overlaps(b, a), "overlap symmetric");
  check(batched(a, b) == hit, "batched overlap the one-off verdict");
  const DistanceResult back = distance(b, a);
  check(back.distance == d.distance && back.point_a == d.point_b, "distance symmetric");
  const double reach = std::max({fuzz::extent(a), fuzz::extent(b), 1e-300});
  const Contact c = contact(a, b);
  check(std::isfinite(c.separation) && c.point_a.allFinite() && c.point_b.allFinite(), "contact finite");
  check(std::abs(c.normal.norm() - 1) <= 1e-12, "contact normal unit");
  check(hit ? c.separation <= 1e-9 * reach : std::abs(c.separation - d.distance) <= 1e-9 * reach,
        "contact separation is the distance apart and not positive overlapping");
  const Contact c_back = contact(b, a);
  check(c_back.separation == c.separation && (c_back.normal == -c.normal || center_of(a) == center_of(b)),
        "contact symmetric");
  check(c.evaluations < 4096, "contact search certified within its cap");
  check_batched_contact(a, b);
  check_batched_contact(b, a);
  const auto curved = [](const Shape& s) {
    return std::holds_alternative<Circle>(s) || std::holds_alternative<Ellipse>(s);
  };
  if (curved(a) && curved(b)) {
    const DistanceResult g = boundary_distance(a, b);
    check(std::isfinite(g.distance) && g.distance >= 0 && g.point_a.allFinite(), "boundary distance finite");
    check(boundary_distance(b, a).distance == g.distance, "boundary distance symmetric");
  }
  // Invariance under a rigid motion, where the motion keeps the shapes in range and adding the turn
  // to the shapes' angles is exact to 1e-13 (beyond |angle| 1e3 the sum loses the turn's digits).
  const double angle = in.number();
  const Vec2 shift = in.point();
  const bool tame = std::abs(angle) < 1e3 && std::abs(angle_of(a)) < 1e3 && std::abs(angle_of(b)) < 1e3;
  if (tame && shift.allFinite() && shift.norm() < 1e6 && fuzz::extent(a) < 1e6 && fuzz::extent(b) < 1e6) {
    const double c = std::cos(angle), sn = std::sin(angle);
    const Shape ma = moved(a, c, sn, shift), mb = moved(b, c, sn, shift);
    if (fuzz::valid(ma) && fuzz::valid(mb)) {
      const double scale = std::max({fuzz::extent(a), fuzz::extent(b), shift.norm(), 1e-300});
      check(std::abs(distance(ma, mb).distance - d.distance) <= 1e-9 * scale, "distance invariant under rigid motion");
    }
  }
  return 0;
}
