// A shape as one SVG element (circle, rotated ellipse or rotated rect) with a CSS class, in world
// coordinates; callers flip y with the viewBox. Shared by `collide2d run` and examples/settle.
#pragma once

#include <collide2d/shapes.h>

#include <iosfwd>

namespace collide2d::tool {

void svg_shape(std::ostream& out, const Shape& s, const char* css);

}  // namespace collide2d::tool
