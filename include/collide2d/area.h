/// @file
/// Areas: the area of a solid shape, and the exact area, centroid and IoU of the overlap of two.
///
/// The overlap of two convex solids is convex; its boundary is made of the two shapes' edges and
/// arcs (circular on circles, capsules and rounded polygons, elliptic on ellipses) between the
/// points where their boundaries cross. Its area and centroid come from Green's theorem over that
/// boundary, each arc by the area between it and its chord, so that no curve is approximated by a
/// polygon. docs/overlap-area.md gives the method and the accuracy the tests assert.
///
/// Every function here validates its shapes and throws InvalidShape for NaN, infinity or a size out
/// of range, and for a segment, which has no area.
#pragma once

#include <collide2d/shapes.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace collide2d {

/// The area of the solid shape (a rounded polygon's and a capsule's rounding included).
double area(const Shape& s);

/// The overlap of two solids. Solids that share no open region (apart, or touching) overlap with
/// area 0, centroid at A's centre and no crossings.
struct OverlapArea {
  double area = 0.0;
  Vec2 centroid = Vec2::Zero();  ///< of the overlap, in the world frame
  /// How many points the two boundaries cross at: 0 when the solids are apart or one holds the
  /// other, 2 when they cross once in and once out, at most twice the pieces (edges and arcs) of the
  /// shape with fewer (an ellipse and a rectangle cross 8 times at most).
  int crossings = 0;
  /// Where there are exactly two crossings, the chord between them (the DEM models' contact line):
  /// A's boundary enters B at chord[0] and leaves it at chord[1].
  std::array<Vec2, 2> chord{Vec2::Zero(), Vec2::Zero()};
};

/// The area and centroid of A ∩ B. Symmetric to the bit: overlap_area(b, a) gives the same area
/// and centroid, and the chord reversed.
OverlapArea overlap_area(const Shape& a, const Shape& b);

/// Intersection over union, |A ∩ B| / |A ∪ B|, in [0, 1].
double iou(const Shape& a, const Shape& b);
/// |A ∆ B| / |A ∪ B|, which is 1 - IoU, in [0, 1]: 0 for equal shapes, 1 for shapes that share no
/// open region. It keeps its own digits however near identical the shapes are, taking the overlap
/// again in double-double below 1/2; docs/overlap-area.md gives the accuracy of each pair.
double iou_distance(const Shape& a, const Shape& b);
/// Intersection over the first, |A ∩ B| / |A| (mmcv's "iof" mode), in [0, 1].
double iof(const Shape& a, const Shape& b);

/// overlap_area() and iou() in bulk, pair i being a[i] with b[i].
/// Every shape is checked before any result is written: a bad one throws InvalidShape naming its
/// pair ("pair 7, b: ..."), and spans of different lengths std::invalid_argument, leaving `out` as
/// it was.
void overlap_areas(std::span<const Shape> a, std::span<const Shape> b, std::span<OverlapArea> out);
void ious(std::span<const Shape> a, std::span<const Shape> b, std::span<double> out);

/// A pair of an N x M problem: a's index, b's, and their IoU.
struct IouPair {
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  double iou = 0.0;
};

/// The pairs of a shape of `a` and one of `b` with IoU above 0 and at least `min_iou`.
/// Sorted by a's index and then b's. Only pairs whose bounding boxes meet are measured (b's boxes in
/// a tree, aabb_tree.h), so that sparse overlaps cost time and memory in proportion to the pairs
/// found, not to N x M. Throws as the batches do, and std::invalid_argument for a min_iou outside
/// [0, 1].
std::vector<IouPair> iou_pairs(std::span<const Shape> a, std::span<const Shape> b, double min_iou = 0.0);

/// Greedy non-maximum suppression: the indices of the shapes kept, in order of score.
/// The shapes go highest score first, equal scores by index; each one is kept unless a kept one
/// overlaps it with IoU above `iou_threshold` (strictly, as detectron2 and torchvision do). With
/// labels, only shapes of one label suppress each other. Throws std::invalid_argument for scores or
/// labels of another length than the shapes, a score that is NaN, or a threshold outside [0, 1], and
/// InvalidShape naming a bad shape's index.
std::vector<std::uint32_t> nms(std::span<const Shape> shapes, std::span<const double> scores, double iou_threshold,
                               std::span<const std::int64_t> labels = {});

}  // namespace collide2d
