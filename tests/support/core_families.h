// Families of pairs of core shapes for the tests (rectangles, convex polygons sharp and rounded, capsules,
// segments and circles against each other and against ellipses): B placed against A at a known gap along a
// random direction, on near-tangent, deep, sliver, far-off and extreme-scale families.
#pragma once

#include <collide2d/shapes.h>

#include <algorithm>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace collide2d::testing {

// polygon: 3 to 8 vertices; triangle and octagon: 3 and 8; kinked: a polygon with a vertex 1e-12
// of the size off the line of its neighbours; needle: a capsule of radius 1e-9 of its half length;
// stub: a capsule of half length 1e-9 of its radius; segment: a segment of half length the size.
enum class Form { rect, polygon, rounded, capsule, circle, ellipse, triangle, octagon, kinked, needle, stub, segment };
const char* name_of(Form k);

// The core forms held in a ConvexPolygon and in a Capsule.
inline constexpr Form kPolygonKinds[] = {Form::polygon, Form::rounded, Form::triangle, Form::octagon, Form::kinked};
inline constexpr Form kCapsuleKinds[] = {Form::capsule, Form::needle, Form::stub};
inline bool is_one_of(std::span<const Form> kinds, Form k) {
  return std::find(kinds.begin(), kinds.end(), k) != kinds.end();
}

// Where B meets A: at A's support point along a random direction (a polygon's vertex, almost
// surely); at a random point of one of A's faces, against B's support point there (a vertex on a
// face, a curve tangent to it); or face to face, B turned so that one of its faces lies along one of
// A's, the two overlapping along it. Where A or B has no face, B meets A along a random direction.
enum class Touch { any, face, parallel };

// A random shape of the kind about the origin, of size about `size` (its longest half-size) and
// aspect up to `aspect`: a polygon has 3 to 8 vertices on an ellipse of that aspect, a rounded one
// a radius of up to its thin half-size.
Shape random_shape(Form kind, double size, double aspect, std::mt19937_64& rng);

struct CoreFamily {
  std::string name;
  Form a, b;
  double size = 1.0;
  double offset = 0.0;
  double aspect = 4.0;
  std::vector<double> deltas;  // of the size: B's support point that far along A's
  int cases = 24;
  Touch touch = Touch::any;
};

void PrintTo(const CoreFamily& f, std::ostream* os);

// Every pair of a core kind A with a core kind or an ellipse B (not circle–circle or
// circle–ellipse, which have families of their own, nor segment–segment, which never pair in a
// World): touching at gaps of +-1e-3 ... 1e-12 and 0 of the size, deep, slivers (aspect 1e6), far
// off (1e9), small (1e-6) and large (1e6); faces touching curves, vertices and capsules' sides at
// those gaps, and parallel faces (a capsule lying on a segment); the degenerate kinds (triangles,
// octagons, kinked polygons, needles and stubs) touching at those gaps.
std::vector<CoreFamily> core_families();

struct CoreCase {
  Shape a, b;
  double delta;  // the nominal gap
};

// B placed so that its support point along -n lies at A's along n plus delta n (delta in units of
// the size), n chosen as the family's touch says: for delta >= 0 the pair's distance is delta, to
// the rounding of B's centre.
std::vector<CoreCase> cases_of(const CoreFamily& f);

}  // namespace collide2d::testing
