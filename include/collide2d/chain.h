/// @file
/// Chains: level geometry of one-sided segments that a body slides along without catching on the
/// vertex between two of them (Box2D v3's b2ChainSegment and its ghost vertices).
///
/// A chain segment is a segment that knows the far points of its neighbours (its ghosts): ghost1,
/// point1, point2, ghost2 in the chain's order. It collides from its right, the side of point2 -
/// point1 turned clockwise, as in Box2D v3: a loop of points counter-clockwise is a solid island, a
/// loop clockwise the inside of a cave, and a floor runs from right to left. A vertex is convex where
/// the chain turns left (towards its solid side) and concave where it turns right or runs straight on.
///
/// Its contact with a shape (the chain segment A, the shape B; contact() in query.h) is the segment's
/// under three rules:
/// - one-sided: none where the shape's centre (a polygon's centroid) lies behind the segment's line
///   and behind the line of each convex neighbour;
/// - shared vertices: at a convex vertex the segment and its neighbour split the plane between them
///   by separating axes: none where the shape lies farther from the neighbour's line than from the
///   segment's (by more than the rounding of the pair's scale, so that on the bisector both report);
/// - smooth: the normal is the segment's, or lies in a convex vertex's cone between the two faces'
///   normals. Any other (a corner of the shape catching a vertex, a shape pushed in deeper than its
///   way out along the segment's normal) gives way to the segment's normal held fixed: the shape's
///   deepest points over the segment; none where no point of it lies over the segment, or where
///   the shape is apart and its points over the segment lie behind it.
/// Overlap, distance, proximity and queries see the segment's geometry, from either side.
#pragma once

#include <collide2d/shapes.h>

#include <span>
#include <vector>

namespace collide2d {

/// A segment of a chain: the segment and its neighbours' far points, in the segment's frame (as its
/// `end`: relative to its first point, turned with it), so that they keep their place as the chain
/// is posed.
struct ChainSegment {
  Segment segment;
  Vec2 ghost1 = Vec2(-1, 0);  ///< the point before point1
  Vec2 ghost2 = Vec2(2, 0);   ///< the point after point2

  /// The chain segment from point1 to point2 between ghost1 and ghost2, in the world, unturned.
  static ChainSegment of(const Vec2& ghost1, const Vec2& point1, const Vec2& point2, const Vec2& ghost2) {
    return {Segment::between(point1, point2), ghost1 - point1, ghost2 - point1};
  }
};

/// Throws InvalidShape unless the chain segment is valid.
/// Valid: the segment is, and each ghost is a valid point apart from the segment's point next to it
/// and not folded back onto the segment (the chain turning a half turn).
void validate(const ChainSegment& s);

/// The chain segments of a polyline, in the world: a loop of 3 or more points closes on its first
/// point, one segment per point; an open chain of 4 or more points takes its first and last points
/// as ghosts only (as b2ChainDef does), count - 3 segments from points[1] to points[count - 2].
/// Throws InvalidShape, naming the point and the rule, for too few points, a point that is not
/// finite or beyond +-1e50, a point repeated next to itself, or a chain that folds back on itself
/// at a point. A loop that crosses itself is not detected.
std::vector<ChainSegment> chain_segments(std::span<const Vec2> points, bool loop);

/// Whether the one-sided rule lets the shape collide with the chain segment: its centre (a polygon's
/// centroid) lies on the line or in front of it or of a convex neighbour's.
bool in_front(const ChainSegment& s, const Shape& shape);

}  // namespace collide2d
