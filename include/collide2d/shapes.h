/// @file
/// Shapes: solid circles, ellipses, oriented rectangles, capsules and convex polygons, and segments,
/// in double precision.
///
/// Shapes are plain value structs (no virtuals); a convex polygon shares its immutable outline among
/// its copies. Angles are in radians, counter-clockwise from +x. A shape is the closed solid region:
/// its boundary belongs to it.
///
/// Validity: every field finite, every size (a segment's length too) in [1e-50, 1e50], every centre
/// coordinate, every polygon vertex and a segment's end within +-1e50. In that range no ratio of lengths in a query
/// exceeds about 1e100, so no square or cube of one overflows. The queries of query.h, the World and the command line
/// validate their shapes; the kernels of kernels.h and batch.h trust them.
#pragma once

#include <Eigen/Core>

#include <array>
#include <memory>
#include <span>
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

/// A solid capsule: the segment of half length `half_length` through the centre along the direction
/// `angle`, grown by `radius` (a rounded segment, Box2D's capsule posed by centre and angle). A capsule
/// of no length is a circle: use Circle.
struct Capsule {
  Vec2 center = Vec2::Zero();
  double half_length = 1.0;
  double radius = 0.5;
  double angle = 0.0;
};

/// A segment: the points `center` and center + R(angle) end, with no thickness (Box2D's b2Segment).
/// Its first point is the origin of its frame, as a polygon's centre is of its outline, so that its
/// second point follows from the first by a difference that is exact wherever the two lie within a
/// factor 2 of each other (Sterbenz): far from the world's origin the segment stays exact at its own
/// scale. Level geometry: the World takes it on static bodies only.
struct Segment {
  Vec2 center = Vec2::Zero();  ///< the first point
  Vec2 end = Vec2::UnitX();    ///< the second point, in the segment's frame
  double angle = 0.0;

  /// The segment from point1 to point2, unturned: end = point2 - point1.
  static Segment between(const Vec2& point1, const Vec2& point2) { return {point1, point2 - point1, 0.0}; }
  /// Its two points in the world.
  Vec2 point1() const { return center; }
  Vec2 point2() const;
};

/// The most vertices a convex polygon has (Box2D's cap): its outline stays inline, 2 x 8 points.
inline constexpr int kMaxPolygonVertices = 8;

/// The outline of a convex polygon in its own frame, immutable once ConvexPolygon's makers built it.
/// They check it: 3 to 8 vertices counter-clockwise, strictly convex (each vertex strictly left of
/// every edge it is not on, beyond the rounding of the orientation test), each edge's outward unit
/// normal, and a rounding radius (0, or a size) that grows the polygon into a rounded one.
struct PolygonOutline {
  int count = 0;
  double radius = 0.0;
  double reach = 0.0;  ///< the largest |vertex| plus the radius: the farthest point from the origin
  /// The radius of a disc about the origin within the solid, or -1 where the core lacks the origin.
  /// The distance to the nearest face's line, plus the radius.
  double inner = -1.0;
  /// Each edge's outward unit normal, and past the count copies of the first.
  /// normals[i] is the normal of the edge from vertices[i] to vertices[(i + 1) % count].
  std::array<Vec2, kMaxPolygonVertices> normals{};
  /// offsets[i] = normals[i].dot(vertices[i]): face i's line is {p : normals[i].dot(p) = offsets[i]}.
  std::array<double, kMaxPolygonVertices> offsets{};
  /// The vertices, and past the count copies of the first (so that every slot is a vertex).
  std::array<Vec2, kMaxPolygonVertices> vertices{};
  double area = 0.0;             ///< of the rounded solid
  Vec2 centroid = Vec2::Zero();  ///< of the rounded solid, in the polygon's frame

  /// The vertices, counter-clockwise.
  std::span<const Vec2> points() const { return {vertices.data(), static_cast<std::size_t>(count)}; }
};

/// A solid convex polygon, possibly rounded, posed by its centre and angle: the centre is the origin
/// of the outline's frame (not moved to the centroid) and the outline turns by `angle` about it. The
/// outline is shared, immutable, among copies, so that a polygon costs a Shape no more than a
/// rectangle does; make one with the functions below, which validate it.
struct ConvexPolygon {
  Vec2 center = Vec2::Zero();
  double angle = 0.0;
  /// The outline; the default is the square of half side 1 (the default Rect's).
  std::shared_ptr<const PolygonOutline> outline = square();

  /// The polygon with these vertices, counter-clockwise, as given (exact: no weld, no reordering),
  /// rounded by `radius`. Throws InvalidShape for fewer than 3 or more than 8 vertices, a coordinate
  /// that is not finite or beyond +-1e50, a radius that is neither 0 nor a size, vertices clockwise,
  /// not strictly convex (a vertex on the line of two others, to the orientation test's rounding),
  /// or a polygon smaller than 1e-50 across, naming the vertex and the rule.
  static ConvexPolygon of(std::span<const Vec2> vertices, double radius = 0.0);
  /// The convex hull of the points, rounded by `radius`: points closer than `weld` times the points'
  /// extent to a kept vertex, or to the line of its two neighbours, are dropped first (the extent is
  /// the larger side of their bounding box, so that the weld scales with the polygon). Throws
  /// InvalidShape as of(), and for points that are all collinear or more than 8 on the hull.
  static ConvexPolygon hull(std::span<const Vec2> points, double radius = 0.0, double weld = 1e-9);
  /// The rectangle of half extents hx, hy about the centre, rounded by `radius`.
  /// Box2D's box and rounded box: the rounded box reaches hx + radius along x.
  static ConvexPolygon box(double hx, double hy, double radius = 0.0);
  /// The regular polygon of `count` vertices, rounded by `radius`.
  /// Its vertices lie on the circle of radius `circumradius` about the centre, vertex 0 on +x.
  static ConvexPolygon regular(int count, double circumradius, double radius = 0.0);

  /// The same outline, posed at `center` and `angle`.
  ConvexPolygon at(const Vec2& center, double angle = 0.0) const { return {center, angle, outline}; }
  /// The number of vertices, the vertices in the polygon's frame, and the rounding radius.
  int count() const { return outline->count; }
  std::span<const Vec2> vertices() const { return outline->points(); }
  double radius() const { return outline->radius; }
  /// The area of the (rounded) solid and its centroid in the world frame.
  double area() const { return outline->area; }
  Vec2 centroid() const;

 private:
  static std::shared_ptr<const PolygonOutline> square();
};

/// Any shape.
using Shape = std::variant<Circle, Ellipse, Rect, Capsule, ConvexPolygon, Segment>;

/// A closed axis-aligned box; min <= max on each axis. A box may have no width or height.
struct Aabb {
  Vec2 min = Vec2::Zero();
  Vec2 max = Vec2::Zero();
};

/// The cosine and sine of a shape's angle, kept by callers that query a pose many times.
/// As Box2D keeps b2Rot. Kernels that take one skip evaluating them; it must be Orientation::of(angle).
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

/// Throws InvalidShape unless the shape is valid (see the file comment). A polygon's outline was
/// checked when it was made: its pose is checked here.
void validate(const Circle& c);
void validate(const Ellipse& e);
void validate(const Rect& r);
void validate(const Capsule& c);
void validate(const Segment& s);
void validate(const ConvexPolygon& p);
void validate(const Shape& s);
/// Throws InvalidShape unless both coordinates are finite and within +-1e50; the message calls the
/// point `what` ("ray origin x ...").
void validate_point(const Vec2& p, const char* what);
/// Throws InvalidShape unless both corners are valid points and min <= max on each axis.
void validate(const Aabb& box);

/// "circle", "ellipse", "rect", "capsule", "polygon" or "segment": the word of the command line and
/// of error messages.
const char* shape_name(const Shape& s);

/// The centre of any shape (a segment's first point).
Vec2 center_of(const Shape& s);
/// The same shape with its centre at `center`, turned as it is.
Shape moved_to(const Shape& s, const Vec2& center);
/// The angle of an ellipse, rectangle, capsule, polygon or segment; 0 for a circle.
double angle_of(const Shape& s);
/// The distance from the centre to the farthest point: the radius, the longer semi-axis, the half
/// diagonal, the half length plus the radius, a polygon's farthest vertex plus its radius, a segment's
/// length.
double reach_of(const Shape& s);

/// Whether two closed boxes share a point.
bool intersects(const Aabb& p, const Aabb& q);
/// Whether the closed box `outer` holds all of `inner`.
bool encloses(const Aabb& outer, const Aabb& inner);

/// The tightest axis-aligned box around the shape, grown by a few ulps of its coordinates.
/// Grown so that no point of the shape, as any kernel rounds it, lies outside.
Aabb aabb(const Circle& c);
Aabb aabb(const Ellipse& e);
Aabb aabb(const Rect& r);
Aabb aabb(const Capsule& c);
Aabb aabb(const Segment& s);
Aabb aabb(const ConvexPolygon& p);
Aabb aabb(const Shape& s);
/// The same box, given Orientation::of(angle_of(s)).
Aabb aabb(const Shape& s, const Orientation& orientation);

/// A point of the shape farthest in direction d (any length). d = 0 gives the centre of a circle or
/// ellipse and a corner of a rectangle. On a rectangle face facing d exactly, the corner with the
/// larger coordinate along the other axis.
Vec2 support(const Circle& c, const Vec2& d);
Vec2 support(const Ellipse& e, const Vec2& d);
Vec2 support(const Rect& r, const Vec2& d);
/// A capsule's: the segment's end along d (the end at +half_length on a tie) plus radius d / |d|. A
/// polygon's: its vertex farthest along d (the first counter-clockwise from vertex 0 on a tie) plus
/// radius d / |d|. A segment's: its point farthest along d (the second on a tie).
Vec2 support(const Capsule& c, const Vec2& d);
Vec2 support(const Segment& s, const Vec2& d);
Vec2 support(const ConvexPolygon& p, const Vec2& d);
Vec2 support(const Shape& s, const Vec2& d);
/// The same point, given Orientation::of(angle_of(s)).
Vec2 support(const Shape& s, const Orientation& orientation, const Vec2& d);

/// Whether p lies in the closed solid shape.
bool contains(const Circle& c, const Vec2& p);
bool contains(const Ellipse& e, const Vec2& p);
bool contains(const Rect& r, const Vec2& p);
bool contains(const Capsule& c, const Vec2& p);
bool contains(const Segment& s, const Vec2& p);
bool contains(const ConvexPolygon& poly, const Vec2& p);
bool contains(const Shape& s, const Vec2& p);

}  // namespace collide2d
