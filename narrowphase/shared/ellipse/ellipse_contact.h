// Private: the overlap decision for two ellipses with what it found on the way, shared by the
// overlap test and the distance queries.
#pragma once

#include "narrowphase/shared/ellipse/ellipse_pair.h"

#include <collide2d/shapes.h>
#include <optional>

namespace collide2d::detail {

struct EllipseContact {
  bool overlap = false;
  Vec2 direction = Vec2::UnitX();  // separated: a direction n (A towards B) with s(n) > 0
  Vec2 witness = Vec2::Zero();     // overlap: a world point in both shapes (to rounding)
  int iterations = 0;              // GJK support evaluations, both precisions
};

// With `double_verdict`, stops after the double pass and stores its verdict there (`uncertain` when
// it could not decide; the returned contact is then only a guess). `pair` is EllipsePair::of(a, b),
// built here unless the bounding circles already decide (it costs two sines and cosines), and kept
// for callers that go on to a distance. With `verdict_only` the witness and direction are not
// wanted, and a certain overlap found on the segment between the centres ends the test there.
EllipseContact ellipse_contact(const Ellipse& a, const Ellipse& b, std::optional<EllipsePair<double>>& pair,
                               FilterVerdict* double_verdict = nullptr, bool verdict_only = false);

}  // namespace collide2d::detail
