#include "tools/scene/svg_shape.h"

#include <cmath>
#include <numbers>
#include <ostream>
#include <type_traits>

namespace collide2d::tool {
namespace {

// In (-180, 180]: a scene's angles grow without bound as bodies turn.
double degrees(double radians) {
  const double d = std::remainder(radians * 180.0 / std::numbers::pi, 360.0);
  return d == -180.0 ? 180.0 : d;
}

}  // namespace

void svg_shape(std::ostream& out, const Shape& s, const char* css) {
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        const double cx = x.center.x(), cy = x.center.y();
        if constexpr (std::is_same_v<T, Circle>) {
          out << "<circle class=\"" << css << "\" cx=\"" << cx << "\" cy=\"" << cy << "\" r=\"" << x.radius << "\"/>\n";
        } else if constexpr (std::is_same_v<T, Ellipse>) {
          out << "<ellipse class=\"" << css << "\" cx=\"" << cx << "\" cy=\"" << cy << "\" rx=\"" << x.a << "\" ry=\""
              << x.b << "\" transform=\"rotate(" << degrees(x.angle) << ' ' << cx << ' ' << cy << ")\"/>\n";
        } else {
          out << "<rect class=\"" << css << "\" x=\"" << cx - x.half_extents.x() << "\" y=\"" << cy - x.half_extents.y()
              << "\" width=\"" << 2 * x.half_extents.x() << "\" height=\"" << 2 * x.half_extents.y()
              << "\" transform=\"rotate(" << degrees(x.angle) << ' ' << cx << ' ' << cy << ")\"/>\n";
        }
      },
      s);
}

}  // namespace collide2d::tool
