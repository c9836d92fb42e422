// The mover's planes (mover.h): the translation nearest a target that respects them, and the
// velocity clipped by them. Both are the same small problem, the nearest point to a vector of the
// set its planes allow, which projected Gauss-Seidel sweeps (E. Catto's b2SolvePlanes) approach
// one plane at a time: a sweep that moves nothing more than rounding ends them. Sweeps converge
// slowly where two planes meet at a narrow angle, so the planes found pushing are then made to hold
// exactly: at most two of them fix the translation in the plane, and the result is kept where every
// plane's condition checks out to rounding.
#include <collide2d/mover.h>

#include "engine/internal.h"
#include "shapes/internal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide2d {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr int kMaxSweeps = 64;

// A plane as the solver reads it: a translation d respects it where n.d >= offset, and it pushes
// at most `limit`.
struct Plane {
  Vec2 n;
  double offset, limit;
};

void validate(const Vec2& v, std::span<const CollisionPlane> planes, const char* what) {
  if (!std::isfinite(v.x()) || !std::isfinite(v.y())) {
    detail::require_finite(v.x(), (std::string(what) + " x").c_str());
    detail::require_finite(v.y(), (std::string(what) + " y").c_str());
  }
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const CollisionPlane& p = planes[i];
    const bool valid = std::isfinite(p.normal.x()) && std::isfinite(p.normal.y()) && std::isfinite(p.offset) &&
                       std::abs(p.normal.squaredNorm() - 1.0) <= 1e-12 && p.push_limit >= 0.0;
    if (valid) continue;  // names are built for a refusal only: a mover solves planes every frame
    const std::string name = "plane " + std::to_string(i);
    detail::require_finite(p.normal.x(), (name + " normal x").c_str());
    detail::require_finite(p.normal.y(), (name + " normal y").c_str());
    detail::require_finite(p.offset, (name + " offset").c_str());
    if (!(std::abs(p.normal.squaredNorm() - 1.0) <= 1e-12)) {
      throw std::invalid_argument(name + " normal must be of unit length (got length " +
                                  detail::shortest(p.normal.norm()) + ')');
    }
    throw std::invalid_argument(name + " push limit must not be negative (got " + detail::shortest(p.push_limit) + ')');
  }
}

// Room for the pushes: on the stack for the few planes a mover touches.
class Pushes {
 public:
  explicit Pushes(std::size_t count) {
    if (count > local_.size()) heap_.resize(count);
  }
  double* data() { return heap_.empty() ? local_.data() : heap_.data(); }

 private:
  std::array<double, 32> local_{};
  std::vector<double> heap_;
};

// The size rounding is relative to: the target's and the offsets' largest magnitude.
template <class At>
double scale_of(const Vec2& target, int count, At at) {
  double scale = target.cwiseAbs().maxCoeff();
  for (int i = 0; i < count; ++i) scale = std::max(scale, std::abs(at(i).offset));
  return scale;
}

// Whether plane p's push e lies strictly between 0 and its limit: the plane holds exactly.
bool free_push(double e, const Plane& p) { return e > 0.0 && e < p.limit; }
// Whether it pushes all it may.
bool at_limit(double e, const Plane& p) { return e > 0.0 && e == p.limit; }

// The translation where planes `first` and `second` hold exactly (-1: none; a second needs a
// first), each plane at its limit after the sweeps pushing its limit and every other nothing, with
// each plane's push, where it meets every plane's condition within `slack`: a push within its
// range, a plane that pushes less than its limit respected, one that pushes its limit not. Else
// nothing is written and the result is false.
template <class At>
bool exact_with(const Vec2& target, int count, At at, double slack, int first, int second, double* push, Vec2& delta) {
  Vec2 base = target;
  for (int i = 0; i < count; ++i) {
    const Plane p = at(i);
    if (i != first && i != second && at_limit(push[i], p)) base += p.limit * p.n;
  }
  std::array<double, 2> lambda{0.0, 0.0};
  Vec2 d = base;
  if (second >= 0) {
    const Plane pi = at(first), pj = at(second);
    const double det = detail::cross(pi.n, pj.n);
    if (!(std::abs(det) > 1e-8)) return false;  // too ill-conditioned a crossing to take
    d = Vec2((pi.offset * pj.n.y() - pj.offset * pi.n.y()) / det, (pi.n.x() * pj.offset - pj.n.x() * pi.offset) / det);
    lambda = {detail::cross(Vec2(d - base), pj.n) / det, detail::cross(pi.n, Vec2(d - base)) / det};
  } else if (first >= 0) {
    const Plane p = at(first);
    lambda[0] = (p.offset - p.n.dot(base)) / p.n.squaredNorm();
    d = base + lambda[0] * p.n;
  }
  // Each plane's push there: the two that hold theirs, those at their limit it, the rest none.
  const auto push_of = [&](int i, const Plane& p) {
    return i == first ? lambda[0] : i == second ? lambda[1] : at_limit(push[i], p) ? p.limit : 0.0;
  };
  for (int i = 0; i < count; ++i) {
    const Plane p = at(i);
    const double e = push_of(i, p);
    const double gap = p.n.dot(d) - p.offset;
    const bool full = e >= p.limit;
    const bool in_range = e >= -slack && e <= p.limit + slack;
    const bool respected = full || gap >= -slack;
    const bool wanted = !(full && p.limit > 0.0) || gap <= slack;
    if (!(in_range && respected && wanted)) return false;
  }
  for (int i = 0; i < count; ++i) {
    const Plane p = at(i);
    push[i] = std::clamp(push_of(i, p), 0.0, p.limit);
  }
  delta = d;
  return true;
}

// The translation the planes pushing below their limit after the sweeps fix, holding exactly: the
// best conditioned two of them, else the one pushing most. Where the sweeps have not found which
// hold, every plane alone and every two are tried, and none.
template <class At>
void make_exact(const Vec2& target, int count, At at, double slack, double* push, Vec2& delta) {
  int most = -1, first = -1, second = -1;
  double best = 0.0;
  for (int i = 0; i < count; ++i) {
    if (!free_push(push[i], at(i))) continue;
    if (most < 0 || push[i] > push[most]) most = i;
    for (int j = 0; j < i; ++j) {
      const double c = std::abs(detail::cross(at(i).n, at(j).n));
      if (free_push(push[j], at(j)) && c > best) first = j, second = i, best = c;
    }
  }
  if (second >= 0 && exact_with(target, count, at, slack, first, second, push, delta)) return;
  if (exact_with(target, count, at, slack, most, -1, push, delta)) return;
  if (most >= 0 && exact_with(target, count, at, slack, -1, -1, push, delta)) return;
  for (int i = 0; i < count; ++i) {
    for (int j = -1; j < i; ++j) {
      if (exact_with(target, count, at, slack, i, j < 0 ? -1 : j, push, delta)) return;
    }
  }
}

// The nearest translation to `target` that the planes allow, each plane's push into `push`.
template <class At>
PlaneSolution solve(const Vec2& target, int count, At at, double* push) {
  std::fill(push, push + count, 0.0);
  const double scale = scale_of(target, count, at);
  PlaneSolution out{target, 0};
  while (out.iterations < kMaxSweeps) {
    ++out.iterations;
    double moved = 0.0;
    for (int i = 0; i < count; ++i) {
      const Plane p = at(i);
      const double before = push[i];
      push[i] = std::clamp(before + (p.offset - p.n.dot(out.delta)), 0.0, p.limit);
      out.delta += (push[i] - before) * p.n;
      moved += std::abs(push[i] - before);
    }
    if (moved <= 4 * kEps * scale) break;
  }
  const double slack = 64 * kEps * std::max(scale, out.delta.cwiseAbs().maxCoeff());
  make_exact(target, count, at, slack, push, out.delta);
  return out;
}

}  // namespace

PlaneSolution solve_planes(const Vec2& target_delta, std::span<CollisionPlane> planes) {
  validate(target_delta, planes, "target delta");
  Pushes push(planes.size());
  const auto at = [&](int i) {
    const CollisionPlane& p = planes[static_cast<std::size_t>(i)];
    return Plane{p.normal, p.offset, p.push_limit};
  };
  const PlaneSolution s = solve(target_delta, static_cast<int>(planes.size()), at, push.data());
  for (std::size_t i = 0; i < planes.size(); ++i) planes[i].push = push.data()[i];
  return s;
}

Vec2 clip_vector(const Vec2& v, std::span<const CollisionPlane> planes) {
  validate(v, planes, "vector");
  Pushes push(planes.size());
  // A plane that does not clip is one that may push nothing and asks for nothing.
  const auto at = [&](int i) {
    const CollisionPlane& p = planes[static_cast<std::size_t>(i)];
    const bool clips = p.push > 0.0 && p.clip_velocity;
    return Plane{p.normal, 0.0, clips ? std::numeric_limits<double>::infinity() : 0.0};
  };
  return solve(v, static_cast<int>(planes.size()), at, push.data()).delta;
}

}  // namespace collide2d
