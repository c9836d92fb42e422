// The `collide2d query` command as a library, so that tests drive it without a process.
//
// Input: one query a line, `<shapeA> ; <shapeB>`, each shape one of
//   circle cx cy r | ellipse cx cy a b theta | rect cx cy hx hy theta     (theta in radians)
//   capsule cx cy h r theta | polygon cx cy theta r x0 y0 ... | segment x1 y1 x2 y2
// and shape A also `chain gx1 gy1 x1 y1 x2 y2 gx2 gy2`, a chain segment (chain.h): its contact
// follows the chain's rules (`none` where they give none) and so does its time of impact (a miss
// from behind); its overlap and distance are its segment's.
// Blank lines and lines starting with '#' are skipped (they produce no output).
// Output: one line per query, `overlap distance ax ay bx by` (overlap 1/0 for the solids; distance 0
// when they overlap; a and b the closest points, a common point when overlapping), numbers in %.17g
// so they round-trip. With Answer::boundary, distance and points are those of the boundary curves
// (circles and ellipses only; a rectangle gives an error line). With Answer::contact, the line is
// `separation nx ny ax ay bx by`: the signed distance (minus the penetration depth when the solids
// overlap), the unit normal from A to B and the deepest (or closest) points (Contact in query.h).
// With Answer::toi, either shape may carry a motion over one step, `<shape> @ vx vy w` (velocity
// of the centre and turn in radians, per step; at rest without it), and the line is
// `hit t nx ny px py` (time_of_impact.h): hit 1 and t the first time of contact (0 when
// they overlap at the start; when the iteration stalls, the time up to which they certainly do not
// touch, still hit 1, so that nothing tunnels), or hit 0 and t 1 for a miss; the normal from A to B
// and the midpoint of the closest points at t (for a miss, at the last time evaluated). A motion on
// a line without Answer::toi is an error. With Answer::area, the line is `area cx cy iou`: the
// area of the overlap, its centroid (A's centre when the area is 0) and the intersection over
// union (area.h); a chain segment or a segment, which have no area, give an error line.
// A malformed or invalid line prints `error: <reason>` in its place and `line N: <reason>` on the
// error stream; processing goes on.
#pragma once

#include <collide2d/area.h>
#include <collide2d/chain.h>
#include <collide2d/query.h>
#include <collide2d/time_of_impact.h>

#include "narrowphase/baselines/baselines.h"

#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace collide2d::tool {

// Thrown for a line that does not follow the grammar; the message says what is wrong.
class ParseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct QueryLine {
  Shape a;
  Shape b;
  Motion a_motion;
  Motion b_motion;
  bool moving = false;  // a motion was written
  // A is this chain segment (`chain ...`): its contact and time of impact follow the chain's rules,
  // its overlap and distance are its segment's (`a`).
  std::optional<ChainSegment> chain{};
};

// The shapes of the grammar, three to a line, each line after `indent`: "circle cx cy r | ...".
std::string shape_grammar(std::string_view indent);

// nullopt for blank and comment lines. Throws ParseError or InvalidShape.
std::optional<QueryLine> parse_query_line(std::string_view line);

enum class Answer { distance, boundary, contact, toi, area };

// A method named on the command line: its word, and the reference method it picks (nullopt: the
// kernel).
template <class Method>
struct NamedMethod {
  std::string_view word;
  std::optional<Method> method;
};

struct QueryOptions {
  // The method named for the rectangle–ellipse overlap, and for the ellipse distances (both solid
  // and boundary; a circle's boundary with an ellipse too): the kernel or a reference method
  // (narrowphase/baselines/baselines.h). A line of a pair the named method does not cover is an
  // error, not answered by another method.
  std::optional<NamedMethod<baselines::RectEllipseTest>> rect_ellipse;
  std::optional<NamedMethod<baselines::EllipseSolver>> ellipse;
  Answer answer = Answer::distance;
};

// Applies a method named on the command line: a rect–ellipse overlap test (minkowski, the kernel;
// closest-features, all-features) or an ellipse distance solver (robust, the kernel; gradient,
// polynomial). Throws ParseError for other names.
void apply_method(std::string_view name, QueryOptions& options);

// Throws ParseError when the options do not go together: a method with --contact or --toi.
void check_options(const QueryOptions& options);

// The output line for one query (without newline). Throws UnsupportedPair, and ParseError for a
// pair that the named method does not cover.
std::string answer(const QueryLine& q, const QueryOptions& options);

// Streams queries from `in` to `out`, reporting bad lines on `err`. Returns the exit status: 0 when
// every line was answered, 2 when any line was in error.
int run_query(std::istream& in, std::ostream& out, std::ostream& err, const QueryOptions& options);

}  // namespace collide2d::tool
