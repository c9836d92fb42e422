// Families of flat pairs for the tests (rectangles, convex polygons sharp and rounded, capsules and
// circles against each other and against ellipses): B placed against A at a known gap along a
// random direction, on near-tangent, deep, sliver, far-off and extreme-scale families.
#pragma once

#include <collide2d/shapes.h>

#include <random>
#include <string>
#include <vector>

namespace collide2d::testing {

enum class Flat { rect, polygon, rounded, capsule, circle, ellipse };
const char* name_of(Flat k);

// A random shape of the kind about the origin, of size about `size` (its longest half-size) and
// aspect up to `aspect`: a polygon has 3 to 8 vertices on an ellipse of that aspect, a rounded one
// a radius of up to its thin half-size.
Shape random_shape(Flat kind, double size, double aspect, std::mt19937_64& rng);

struct FlatFamily {
  std::string name;
  Flat a, b;
  double size = 1.0;
  double offset = 0.0;
  double aspect = 4.0;
  std::vector<double> deltas;  // of the size: B's support point that far along A's
  int cases = 24;
};

void PrintTo(const FlatFamily& f, std::ostream* os);

// Every pair of a flat kind A with a flat kind or an ellipse B (not circle–circle or
// circle–ellipse, which have families of their own): touching at gaps of +-1e-3 ... 1e-12 and 0 of
// the size, deep, slivers (aspect 1e6), far off (1e9), small (1e-6) and large (1e6).
std::vector<FlatFamily> flat_families();

struct FlatCase {
  Shape a, b;
  double delta;  // the nominal gap
};

// B placed so that its support point along -n lies at A's along n plus delta n (delta in units of
// the size): for delta >= 0 the pair's distance is delta, to the rounding of B's centre.
std::vector<FlatCase> cases_of(const FlatFamily& f);

}  // namespace collide2d::testing
