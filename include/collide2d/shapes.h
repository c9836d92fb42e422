/// @file
/// Shapes: solid circles, ellipses and oriented rectangles in double precision.
///
/// Shapes are plain value structs (no virtuals, no pointers). Angles are in radians,
/// counter-clockwise from +x. A shape is the closed solid region: its boundary belongs to it.
///
/// Validity: every field finite, every size in [1e-50, 1e50], every centre coordinate within
/// +-1e50. In that range no ratio of lengths in a query exceeds about 1e100, so no square or cube of
/// one overflows. The queries of query.h, the World and the command line validate their shapes; the
/// kernels of kernels.h and batch.h trust them.
#pragma once

#include <Eigen/Core>

#include <stdexcept>
#include <variant>

namespace collide2d {

/// A point or vector of the plane.
using Vec2 = Eigen::Vector2d;

/// The largest size or |centre coordinate| accepted.
inline constexpr double kMaxMagnitude = 1e50;
/// The smallest size accepted.
inline constexpr double kMinSize = 1e-50;

/// A solid disc.
struct Circle {
  Vec2 center = Vec2::Zero();
  double radius = 1.0;
};

/// A solid ellipse: semi-axis `a` along the direction `angle`, `b` across it (either may be longer).
struct Ellipse {
  Vec2 center = Vec2::Zero();
  double a = 1.0;
  double b = 1.0;
  double angle = 0.0;
};

/// A solid rectangle: half_extents.x() along the direction `angle`, half_extents.y() across it.
struct Rect {
  Vec2 center = Vec2::Zero();
  Vec2 half_extents = Vec2::Ones();
  double angle = 0.0;
};

/// Any shape.
using Shape = std::variant<Circle, Ellipse, Rect>;

/// A closed axis-aligned box; min <= max on each axis. A box may have no width or height.
struct Aabb {
  Vec2 min = Vec2::Zero();
  Vec2 max = Vec2::Zero();
};

/// The cosine and sine of a shape's angle, kept by callers that query a pose many times (as Box2D
/// keeps b2Rot). Kernels that take one skip evaluating them; it must be Orientation::of(angle).
struct Orientation {
  double c = 1.0;
  double s = 0.0;
  /// {cos(angle), sin(angle)}, the values every kernel computes from the angle itself.
  static Orientation of(double angle);
};

/// Thrown for a shape, point or box that breaks the validity rule. The message names the shape, the
/// field, the rule and the value: "ellipse b must be positive (got -1)".
class InvalidShape : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Throws InvalidShape unless the shape is valid (see the file comment).
void validate(const Circle& c);
void validate(const Ellipse& e);
void validate(const Rect& r);
void validate(const Shape& s);
/// Throws InvalidShape unless both coordinates are finite and within +-1e50; the message calls the
/// point `what` ("ray origin x ...").
void validate_point(const Vec2& p, const char* what);
/// Throws InvalidShape unless both corners are valid points and min <= max on each axis.
void validate(const Aabb& box);

/// "circle", "ellipse" or "rect": the word of the command line and of error messages.
const char* shape_name(const Shape& s);

/// The centre of any shape.
Vec2 center_of(const Shape& s);
/// The angle of an ellipse or rectangle; 0 for a circle.
double angle_of(const Shape& s);
/// The distance from the centre to the farthest point: the radius, the longer semi-axis, the half
/// diagonal.
double reach_of(const Shape& s);

/// Whether two closed boxes share a point.
bool intersects(const Aabb& p, const Aabb& q);
/// Whether the closed box `outer` holds all of `inner`.
bool encloses(const Aabb& outer, const Aabb& inner);

/// The tightest axis-aligned box around the shape, grown by a few ulps of its coordinates so that
/// no point of the shape, as any kernel rounds it, lies outside.
Aabb aabb(const Circle& c);
Aabb aabb(const Ellipse& e);
Aabb aabb(const Rect& r);
Aabb aabb(const Shape& s);
/// The same box, given Orientation::of(angle_of(s)).
Aabb aabb(const Shape& s, const Orientation& orientation);

/// A point of the shape farthest in direction d (any length). d = 0 gives the centre of a circle or
/// ellipse and a corner of a rectangle. On a rectangle face facing d exactly, the corner with the
/// larger coordinate along the other axis.
Vec2 support(const Circle& c, const Vec2& d);
Vec2 support(const Ellipse& e, const Vec2& d);
Vec2 support(const Rect& r, const Vec2& d);
Vec2 support(const Shape& s, const Vec2& d);

/// Whether p lies in the closed solid shape.
bool contains(const Circle& c, const Vec2& p);
bool contains(const Ellipse& e, const Vec2& p);
bool contains(const Rect& r, const Vec2& p);
bool contains(const Shape& s, const Vec2& p);

}  // namespace collide2d
