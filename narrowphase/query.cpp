#include "narrowphase/query.h"

#include "narrowphase/distance_rect_ellipse.h"
#include "narrowphase/distance_rect_rect.h"
#include "narrowphase/overlap_circle_circle.h"
#include "narrowphase/overlap_circle_ellipse.h"
#include "narrowphase/overlap_rect_circle.h"
#include "narrowphase/overlap_rect_rect.h"

#include <type_traits>

namespace collide2d {
namespace {

// The order in which kernels take their shapes.
template <class T>
constexpr int rank() {
  if constexpr (std::is_same_v<T, Rect>) return 0;
  if constexpr (std::is_same_v<T, Circle>) return 1;
  return 2;
}

[[noreturn]] void unsupported(const char* pair) {
  throw UnsupportedPair(std::string(pair) + " is not supported yet");
}

bool overlap_kernel(const Rect& a, const Rect& b, const OverlapOptions&) { return overlap_rect_rect(a, b); }
bool overlap_kernel(const Rect& a, const Circle& b, const OverlapOptions&) { return overlap_rect_circle(a, b); }
bool overlap_kernel(const Rect& a, const Ellipse& b, const OverlapOptions& o) {
  return overlap_rect_ellipse(a, b, o.rect_ellipse);
}
bool overlap_kernel(const Circle& a, const Circle& b, const OverlapOptions&) { return overlap_circle_circle(a, b); }
bool overlap_kernel(const Circle& a, const Ellipse& b, const OverlapOptions&) {
  return overlap_circle_ellipse(a, b);
}
bool overlap_kernel(const Ellipse&, const Ellipse&, const OverlapOptions&) { unsupported("ellipse-ellipse overlap"); }

DistanceResult distance_kernel(const Rect& a, const Rect& b) { return distance_rect_rect(a, b); }
DistanceResult distance_kernel(const Rect& a, const Circle& b) { return distance_rect_circle(a, b); }
DistanceResult distance_kernel(const Rect& a, const Ellipse& b) { return distance_rect_ellipse(a, b); }
DistanceResult distance_kernel(const Circle& a, const Circle& b) { return distance_circle_circle(a, b); }
DistanceResult distance_kernel(const Circle& a, const Ellipse& b) { return distance_circle_ellipse(a, b); }
DistanceResult distance_kernel(const Ellipse&, const Ellipse&) { unsupported("ellipse-ellipse distance"); }

}  // namespace

bool overlaps(const Shape& a, const Shape& b, const OverlapOptions& options) {
  validate(a);
  validate(b);
  return std::visit(
      [&options](const auto& x, const auto& y) {
        if constexpr (rank<std::decay_t<decltype(x)>>() <= rank<std::decay_t<decltype(y)>>()) {
          return overlap_kernel(x, y, options);
        } else {
          return overlap_kernel(y, x, options);
        }
      },
      a, b);
}

DistanceResult distance(const Shape& a, const Shape& b) {
  validate(a);
  validate(b);
  return std::visit(
      [](const auto& x, const auto& y) {
        if constexpr (rank<std::decay_t<decltype(x)>>() <= rank<std::decay_t<decltype(y)>>()) {
          return distance_kernel(x, y);
        } else {
          return distance_kernel(y, x).swapped();
        }
      },
      a, b);
}

}  // namespace collide2d
