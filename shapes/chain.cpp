#include <collide2d/chain.h>

#include "shapes/internal.h"

#include <string>

namespace collide2d {
namespace {

using detail::cross;

// Whether the chain turns a half turn at a vertex: the edge in and the edge out in line, opposed.
bool folds_back(const Vec2& in, const Vec2& out) { return cross(in, out) == 0.0 && in.dot(out) < 0.0; }

[[noreturn]] void refuse(const std::string& message) { throw InvalidShape(message); }

void require_points(std::size_t count, bool loop) {
  if (loop && count < 3) refuse("a chain loop needs at least 3 points (got " + std::to_string(count) + ")");
  if (!loop && count < 4) {
    refuse("an open chain needs at least 4 points, its first and last ghosts only (got " + std::to_string(count) + ")");
  }
}

}  // namespace

void validate(const ChainSegment& s) {
  validate(s.segment);
  validate_point(s.ghost1, "chain segment ghost1");
  validate_point(s.ghost2, "chain segment ghost2");
  if (s.ghost1 == Vec2::Zero()) refuse("chain segment ghost1 must differ from point1");
  if (s.ghost2 == s.segment.end) refuse("chain segment ghost2 must differ from point2");
  if (folds_back(-s.ghost1, s.segment.end)) refuse("chain segment folds back on itself at point1");
  if (folds_back(s.segment.end, s.ghost2 - s.segment.end)) refuse("chain segment folds back on itself at point2");
}

std::vector<ChainSegment> chain_segments(std::span<const Vec2> points, bool loop) {
  require_points(points.size(), loop);
  const std::size_t n = points.size();
  for (std::size_t k = 0; k < n; ++k) validate_point(points[k], ("chain point " + std::to_string(k)).c_str());
  const auto at = [&](std::size_t k) -> const Vec2& { return points[k % n]; };
  const std::size_t edges = loop ? n : n - 1;
  for (std::size_t k = 0; k < edges; ++k) {
    if (at(k) == at(k + 1))
      refuse("chain point " + std::to_string((k + 1) % n) + " repeats point " + std::to_string(k));
  }
  const std::size_t first = loop ? 0 : 1, count = loop ? n : n - 3;
  std::vector<ChainSegment> out;
  out.reserve(count);
  for (std::size_t k = first; k < first + count; ++k) {
    const ChainSegment s = ChainSegment::of(at(k + n - 1), at(k), at(k + 1), at(k + 2));
    try {
      validate(s);
    } catch (const InvalidShape& e) {
      refuse("chain segment from point " + std::to_string(k % n) + ": " + e.what());
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace collide2d
