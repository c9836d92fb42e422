// collide2d shapes: solid circles, ellipses and oriented rectangles in double precision.
//
// Shapes are plain value structs (no virtuals, no pointers). All angles are in radians, measured
// counter-clockwise from +x. A shape describes the closed solid region: boundary points belong to it.
//
// Validity: every field finite, every size strictly positive, and magnitudes a double can square and
// cube: sizes from 1e-50 to 1e50 and centre coordinates within +-1e50 (so no ratio of lengths in a
// query exceeds about 1e100, and no square or cube of one overflows). Kernels in narrowphase/ assume
// valid shapes; the dispatch in narrowphase/query.h, the World and the command line validate first.
#pragma once

#include <Eigen/Core>

#include <stdexcept>
#include <string>
#include <variant>

namespace collide2d {

using Vec2 = Eigen::Vector2d;

inline constexpr double kMaxMagnitude = 1e50;  // largest size or |centre coordinate| accepted
inline constexpr double kMinSize = 1e-50;      // smallest size accepted

struct Circle {
  Vec2 center = Vec2::Zero();
  double radius = 1.0;
};

// a is the semi-axis along the direction `angle`, b the one perpendicular to it (either may be larger).
struct Ellipse {
  Vec2 center = Vec2::Zero();
  double a = 1.0;
  double b = 1.0;
  double angle = 0.0;
};

// half_extents.x() lies along the direction `angle`, half_extents.y() perpendicular to it.
struct Rect {
  Vec2 center = Vec2::Zero();
  Vec2 half_extents = Vec2::Ones();
  double angle = 0.0;
};

using Shape = std::variant<Circle, Ellipse, Rect>;

struct Aabb {
  Vec2 min = Vec2::Zero();
  Vec2 max = Vec2::Zero();
};

// The cosine and sine of a shape's angle. Kernels that accept one skip evaluating them (most of the
// 38 ns of a rectangle–ellipse overlap test go to them) for callers that keep each pose's
// orientation between queries. It must be Orientation::of(shape.angle).
struct Orientation {
  double c = 1.0;
  double s = 0.0;
  static Orientation of(double angle);
};

// Thrown for a shape that breaks the validity rule; the message names the offending field.
class InvalidShape : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Throws InvalidShape("<what> <field> <rule> (got <value>)"), the form of every validation message
// ("ellipse a must be positive (got -1)"), for the checks of other modules to share.
[[noreturn]] void reject(const char* what, const char* field, double value, const char* rule);

void validate(const Circle& c);
void validate(const Ellipse& e);
void validate(const Rect& r);
void validate(const Shape& s);
// A query point: finite and within the coordinate range; the message calls it `what` ("point x ...").
void validate_point(const Vec2& p, const char* what);
// A query box: both corners valid points ("box min x ...") and min <= max on each axis. A box may
// have no width or height (a segment or a point).
void validate(const Aabb& box);

// The word used for the shape on the command line and in messages: "circle", "ellipse", "rect".
const char* shape_name(const Shape& s);

// The centre of any shape, and its angle (0 for a circle).
Vec2 center_of(const Shape& s);
double angle_of(const Shape& s);
// The distance from the centre to the shape's farthest point: the radius, the major semi-axis, the
// half diagonal.
double reach_of(const Shape& s);

// Whether two closed boxes share a point.
bool intersects(const Aabb& p, const Aabb& q);
// Whether the closed box `outer` holds all of `inner`.
bool encloses(const Aabb& outer, const Aabb& inner);

// The tightest axis-aligned box around the shape, grown by a few ulps of its coordinates so that
// rounding never puts a point of the shape outside it.
Aabb aabb(const Circle& c);
Aabb aabb(const Ellipse& e);
Aabb aabb(const Rect& r);
Aabb aabb(const Shape& s);
// The same box, given Orientation::of(angle_of(s)) (callers that keep it: the World).
Aabb aabb(const Shape& s, const Orientation& orientation);

// A point of the shape farthest in direction d (d need not be unit length; d = 0 gives the centre
// for circles and ellipses, and a corner for rectangles). On a rectangle edge facing d exactly, the
// corner with the larger coordinate along the other axis is returned.
Vec2 support(const Circle& c, const Vec2& d);
Vec2 support(const Ellipse& e, const Vec2& d);
Vec2 support(const Rect& r, const Vec2& d);
Vec2 support(const Shape& s, const Vec2& d);

// Whether p lies in the closed solid shape.
bool contains(const Circle& c, const Vec2& p);
bool contains(const Ellipse& e, const Vec2& p);
bool contains(const Rect& r, const Vec2& p);
bool contains(const Shape& s, const Vec2& p);

}  // namespace collide2d
