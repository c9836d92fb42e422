// A small discrete-element program on top of the World and its contacts: ellipses, rectangles and
// circles dropped into a box under gravity until they settle. Not a physics engine: each contact
// pushes with the standard DEM law, a linear spring on the penetration depth with a dashpot on its
// rate (Cundall and Strack), a tangential spring capped by Coulomb friction, and a light drag; the
// bodies move by symplectic Euler.
//
//   SettleResult r = settle({.bodies = 2000});
//   write_settle_svg(r, out);
//
// Units: lengths in the bodies' sizes (largest half-extents 0.2 to 0.4), density 1, g = 9.81. The
// spring is stiff enough that the pile's weight presses no contact deeper than a small fraction of
// the smallest body (stiffness_for), and the step is 0.15 sqrt(m / k) for the lightest body.
#pragma once

#include <collide2d/shapes.h>

#include <iosfwd>
#include <vector>

namespace collide2d::settle {

struct SettleOptions {
  int bodies = 2000;
  double width = 40.0;  // inside width of the box; its floor is y = 0
  unsigned seed = 1;
  double max_seconds = 20.0;   // simulated time at most
  double rest_speed = 1e-2;    // at rest: no body faster than this (sizes per second) ...
  double rest_seconds = 0.25;  // ... for this long
};

struct SettleResult {
  std::vector<Shape> shapes;  // the bodies where they came to rest
  std::vector<Shape> walls;   // floor, left and right wall
  double width = 0.0;
  double seconds = 0.0;  // simulated
  int steps = 0;
  bool at_rest = false;
  double max_speed = 0.0;        // at the end
  double max_penetration = 0.0;  // deepest contact at the end (minus the least separation)
  double smallest = 0.0;         // the smallest half-size of any body (a circle's radius, a semi-axis)
  int outside = 0;               // bodies not within the box's walls and above its floor
};

SettleResult settle(const SettleOptions& options, std::ostream* progress = nullptr);

// The settled pile, the walls, and a caption with the numbers above.
void write_settle_svg(const SettleResult& result, std::ostream& out);

}  // namespace collide2d::settle
