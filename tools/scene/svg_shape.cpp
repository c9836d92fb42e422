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

// The outline in the polygon's frame: each vertex's arc of the radius (counter-clockwise, sweep 1
// in the scene's y-up frame) and each face moved out by it; the core alone when sharp.
void polygon_path(std::ostream& out, const ConvexPolygon& p, const char* css) {
  const PolygonOutline& o = *p.outline;
  const double r = o.radius;
  const auto point = [&](const Vec2& q) { out << q.x() << ' ' << q.y(); };
  out << "<path class=\"" << css << "\" d=\"M ";
  point(o.vertices[0] + r * o.normals[o.count - 1]);
  for (int i = 0; i < o.count; ++i) {
    if (r > 0) {
      out << " A " << r << ' ' << r << " 0 0 1 ";
      point(o.vertices[i] + r * o.normals[i]);
    }
    out << " L ";
    point(o.vertices[(i + 1) % o.count] + r * o.normals[i]);
  }
  out << " Z\" transform=\"translate(" << p.center.x() << ' ' << p.center.y() << ") rotate(" << degrees(p.angle)
      << ")\"/>\n";
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
        } else if constexpr (std::is_same_v<T, Rect>) {
          out << "<rect class=\"" << css << "\" x=\"" << cx - x.half_extents.x() << "\" y=\"" << cy - x.half_extents.y()
              << "\" width=\"" << 2 * x.half_extents.x() << "\" height=\"" << 2 * x.half_extents.y()
              << "\" transform=\"rotate(" << degrees(x.angle) << ' ' << cx << ' ' << cy << ")\"/>\n";
        } else if constexpr (std::is_same_v<T, Segment>) {
          const Vec2 to = x.point2();
          out << "<line class=\"" << css << "\" x1=\"" << cx << "\" y1=\"" << cy << "\" x2=\"" << to.x() << "\" y2=\""
              << to.y() << "\"/>\n";
        } else if constexpr (std::is_same_v<T, Capsule>) {
          const double h = x.half_length, r = x.radius;
          out << "<rect class=\"" << css << "\" x=\"" << cx - h - r << "\" y=\"" << cy - r << "\" width=\""
              << 2 * (h + r) << "\" height=\"" << 2 * r << "\" rx=\"" << r << "\" transform=\"rotate("
              << degrees(x.angle) << ' ' << cx << ' ' << cy << ")\"/>\n";
        } else {
          polygon_path(out, x, css);
        }
      },
      s);
}

}  // namespace collide2d::tool
