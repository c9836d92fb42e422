// Chain fuzzer: a chain segment (a segment and two ghost points) against a shape of any moving kind,
// and a polyline through chain_segments(). Invalid input must be refused with InvalidShape. For
// valid input: the contact is empty where the shape lies behind (in_front false); otherwise an empty
// contact has an infinite separation, and a contact has finite points, a unit normal on the
// segment's front (its dot with the segment's normal positive) and, where the segment's own contact
// is apart, a separation of at least that distance (to 1e-9 of the scale); where the chain admits
// the segment's own contact, it is that contact to the bit. A ray from behind the segment misses it.
// A polyline's chain segments are each valid.
#include <collide2d/chain.h>
#include <collide2d/kernels.h>
#include <collide2d/ray_cast.h>
#include "fuzz_input.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

using namespace collide2d;

using fuzz::check;
using fuzz::fail;

bool valid(const ChainSegment& s) {
  try {
    validate(s);
    return true;
  } catch (const InvalidShape&) {
    return false;
  }
}

void check_polyline(fuzz::Input& in) {
  const int count = in.byte() % 8;
  const bool loop = in.byte() & 1;
  std::vector<Vec2> points;
  for (int k = 0; k < count; ++k) points.push_back(in.point());
  try {
    for (const ChainSegment& s : chain_segments(points, loop)) check(valid(s), "a polyline's chain segments valid");
  } catch (const InvalidShape&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Input in(data, size);
  ChainSegment chain{in.segment(), Vec2::Zero(), Vec2::Zero()};
  chain.ghost1 = in.point();
  chain.ghost2 = in.point();
  const Shape b = in.shape(fuzz::Kind::all);
  check_polyline(in);
  if (!valid(chain) || !fuzz::valid(b)) {
    try {
      contact(chain, b);
      fail("an invalid chain segment or shape was accepted");
    } catch (const InvalidShape&) {
    }
    return 0;
  }
  const Contact c = contact(chain, b);
  if (!in_front(chain, b)) check(c.empty(), "no contact from behind");
  if (c.empty()) {
    check(c.separation == HUGE_VAL, "an empty chain contact's separation infinite");
  } else {
    check(std::isfinite(c.separation) && c.point_a.allFinite() && c.point_b.allFinite(), "contact finite");
    check(std::abs(c.normal.norm() - 1) <= 1e-12, "contact normal unit");
    // On the segment's front, or in the cone of the convex vertex it leans towards (which may reach
    // past the segment's direction).
    const Vec2 end = chain.segment.end, in = -chain.ghost1, out = chain.ghost2 - end;
    const Orientation o = Orientation::of(chain.segment.angle);
    const Vec2 n(o.c * c.normal.x() + o.s * c.normal.y(), -o.s * c.normal.x() + o.c * c.normal.y());  // in its frame
    const Vec2 e = end.normalized();
    const bool convex1 = in.x() * end.y() - in.y() * end.x() > 0, convex2 = end.x() * out.y() - end.y() * out.x() > 0;
    const bool convex = (n.dot(e) <= 1e-12 && convex1) || (n.dot(e) >= -1e-12 && convex2);
    check(convex || n.dot(Vec2(e.y(), -e.x())) > -1e-12, "contact normal on the segment's front");
    const Contact own = contact(chain.segment, b);
    const double reach = std::max({fuzz::extent(chain.segment), fuzz::extent(b), 1e-300});
    if (own.separation > 0) check(c.separation >= own.separation - 1e-9 * reach, "no nearer than the segment");
    if (c.normal == own.normal) {
      check(c.separation == own.separation && c.point_a == own.point_a && c.point_b == own.point_b,
            "an admitted contact is the segment's own");
    }
  }
  const Vec2 origin = in.point();
  const Vec2 direction = in.point();
  if (origin.allFinite() && origin.cwiseAbs().maxCoeff() <= kMaxMagnitude && direction.allFinite() &&
      direction.norm() > 0 && std::isfinite(direction.norm())) {
    const Vec2 unit = direction / direction.norm();
    const auto hit = ray_cast(chain, origin, unit, 1e300);
    const Vec2 start = chain.segment.center;
    const Orientation o = Orientation::of(chain.segment.angle);
    const Vec2 end(o.c * chain.segment.end.x() - o.s * chain.segment.end.y(),
                   o.s * chain.segment.end.x() + o.c * chain.segment.end.y());
    if (Vec2(end.y(), -end.x()).dot(origin - start) < 0 && end.norm() > 0) {
      // Behind by more than the rounding of the side test.
      const double side = Vec2(end.y(), -end.x()).normalized().dot(origin - start);
      if (side < -1e-9 * std::max(reach_of(chain.segment), (origin - start).norm()))
        check(!hit, "a ray from behind misses");
    }
  }
  return 0;
}
