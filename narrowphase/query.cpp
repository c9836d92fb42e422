#include "narrowphase/query.h"

#include "narrowphase/distance_rect_ellipse.h"
#include "narrowphase/distance_rect_rect.h"
#include "narrowphase/overlap_circle_circle.h"
#include "narrowphase/overlap_circle_ellipse.h"
#include "narrowphase/overlap_rect_circle.h"
#include "narrowphase/overlap_rect_rect.h"

#include <array>
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

// A total order on shapes of one kind. Same-kind pairs are put in this order before the kernel runs,
// so that swapping A and B swaps the result exactly, bit for bit, whatever frame the kernel uses.
std::array<double, 3> key(const Circle& c) { return {c.center.x(), c.center.y(), c.radius}; }
std::array<double, 5> key(const Ellipse& e) { return {e.center.x(), e.center.y(), e.a, e.b, e.angle}; }
std::array<double, 5> key(const Rect& r) {
  return {r.center.x(), r.center.y(), r.half_extents.x(), r.half_extents.y(), r.angle};
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

// Calls kernel(x, y, swapped) with the pair in kernel order: by rank across kinds, by key within one.
template <class Kernel>
auto in_kernel_order(const Shape& a, const Shape& b, Kernel kernel) {
  return std::visit(
      [&kernel](const auto& x, const auto& y) {
        using X = std::decay_t<decltype(x)>;
        using Y = std::decay_t<decltype(y)>;
        if constexpr (rank<X>() < rank<Y>()) {
          return kernel(x, y, false);
        } else if constexpr (rank<X>() > rank<Y>()) {
          return kernel(y, x, true);
        } else {
          return key(y) < key(x) ? kernel(y, x, true) : kernel(x, y, false);
        }
      },
      a, b);
}

}  // namespace

bool overlaps(const Shape& a, const Shape& b, const OverlapOptions& options) {
  validate(a);
  validate(b);
  return in_kernel_order(a, b, [&options](const auto& x, const auto& y, bool) { return overlap_kernel(x, y, options); });
}

DistanceResult distance(const Shape& a, const Shape& b) {
  validate(a);
  validate(b);
  return in_kernel_order(a, b, [](const auto& x, const auto& y, bool swapped) {
    const DistanceResult r = distance_kernel(x, y);
    return swapped ? r.swapped() : r;
  });
}

}  // namespace collide2d
