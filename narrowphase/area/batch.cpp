// The area queries in bulk: pair by pair, the N x M problem through a tree of boxes, and
// non-maximum suppression.
#include <collide2d/aabb_tree.h>
#include <collide2d/area.h>
#include <collide2d/query.h>

#include "narrowphase/area/measures.h"
#include "narrowphase/area/overlap_rect_rect.h"
#include "narrowphase/dispatch.h"
#include "narrowphase/shared/frames/rect_pair_frame.h"
#include "shapes/kinds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace collide2d {
namespace {

// Checks a solid; the message of a bad one starts with where it is, which `where()` names only then.
template <class Where>
void require_area(const Shape& s, Where where) {
  try {
    area(s);
  } catch (const InvalidShape& e) {
    throw InvalidShape(where() + ": " + e.what());
  }
}

void require_all(std::span<const Shape> shapes, const char* which) {
  for (std::size_t i = 0; i < shapes.size(); ++i)
    require_area(shapes[i], [&] { return std::string(which) + "[" + std::to_string(i) + "]"; });
}

void require_pairs(std::span<const Shape> a, std::span<const Shape> b, std::size_t out) {
  if (a.size() != b.size() || a.size() != out) {
    throw std::invalid_argument("a has " + std::to_string(a.size()) + " shapes, b " + std::to_string(b.size()) +
                                " and out " + std::to_string(out) + ": a batch needs as many of each");
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    require_area(a[i], [i] { return "pair " + std::to_string(i) + ", a"; });
    require_area(b[i], [i] { return "pair " + std::to_string(i) + ", b"; });
  }
}

void require_fraction(double x, const char* what) {
  if (!(x >= 0 && x <= 1))
    throw std::invalid_argument(std::string(what) + " must lie in [0, 1] (got " + std::to_string(x) + ")");
}

// A tree of the shapes' boxes, each with its index.
AabbTree tree_of(std::span<const Shape> shapes) {
  std::vector<Aabb> boxes(shapes.size());
  std::transform(shapes.begin(), shapes.end(), boxes.begin(), [](const Shape& s) { return aabb(s); });
  return AabbTree(boxes);
}

// The two rectangles in the rank order the one-off IoU takes them in (narrowphase/dispatch.h).
std::pair<const Rect*, const Rect*> ranked(const Shape& a, const Shape& b) {
  auto order = [](const Rect& x, const Rect& y, bool) { return std::pair(&x, &y); };
  return detail::kinds_in_rank_order<detail::Kinds>(std::get<Rect>(a), std::get<Rect>(b), order);
}

// The IoU of the pairs `which`, each two rectangles, their areas found a chunk at a time in vectors.
void rect_ious(std::span<const Shape> a, std::span<const Shape> b, std::span<const std::size_t> which,
               std::span<double> out) {
  using Chunk = detail::Chunk<8>;
  const auto chunk = std::make_unique<Chunk>();
  std::array<double, Chunk::kPairs> areas;
  std::array<std::pair<const Rect*, const Rect*>, Chunk::kPairs> pairs;
  for (std::size_t start = 0; start < which.size(); start += Chunk::kPairs) {
    const std::size_t count = std::min(Chunk::kPairs, which.size() - start);
    detail::fill_chunk(*chunk, start, count, [&](std::size_t k) {
      const auto [x, y] = pairs[k - start] = ranked(a[which[k]], b[which[k]]);
      return detail::rect_rect_lanes(*x, Orientation::of(x->angle), *y, Orientation::of(y->angle));
    });
    detail::areas::rect_rect_areas(*chunk, count, areas.data());
    for (std::size_t k = 0; k < count; ++k)
      out[which[start + k]] = detail::areas::rect_iou(*pairs[k].first, *pairs[k].second, areas[k]);
  }
}

}  // namespace

void overlap_areas(std::span<const Shape> a, std::span<const Shape> b, std::span<OverlapArea> out) {
  require_pairs(a, b, out.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = detail::areas::overlap_of(a[i], b[i]);
}

void ious(std::span<const Shape> a, std::span<const Shape> b, std::span<double> out) {
  require_pairs(a, b, out.size());
  std::vector<std::size_t> rects;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::holds_alternative<Rect>(a[i]) && std::holds_alternative<Rect>(b[i]))
      rects.push_back(i);
    else
      out[i] = detail::areas::iou_of(a[i], b[i]);
  }
  rect_ious(a, b, rects, out);
}

std::vector<IouPair> iou_pairs(std::span<const Shape> a, std::span<const Shape> b, double min_iou) {
  require_fraction(min_iou, "min_iou");
  require_all(a, "a");
  require_all(b, "b");
  const AabbTree tree = tree_of(b);
  std::vector<IouPair> out;
  std::vector<std::uint32_t> met;
  for (std::size_t i = 0; i < a.size(); ++i) {
    met.clear();
    tree.query(aabb(a[i]), [&met](std::uint32_t j) { met.push_back(j); });
    std::sort(met.begin(), met.end());
    for (const std::uint32_t j : met) {
      const double x = detail::areas::iou_of(a[i], b[j]);
      if (x > 0 && x >= min_iou) out.push_back({static_cast<std::uint32_t>(i), j, x});
    }
  }
  return out;
}

std::vector<std::uint32_t> nms(std::span<const Shape> shapes, std::span<const double> scores, double iou_threshold,
                               std::span<const std::int64_t> labels) {
  require_fraction(iou_threshold, "iou_threshold");
  if (scores.size() != shapes.size() || (!labels.empty() && labels.size() != shapes.size())) {
    throw std::invalid_argument("nms takes a score" + std::string(labels.empty() ? "" : " and a label") +
                                " for each of the " + std::to_string(shapes.size()) + " shapes");
  }
  for (std::size_t i = 0; i < scores.size(); ++i) {
    if (std::isnan(scores[i])) throw std::invalid_argument("scores[" + std::to_string(i) + "] is NaN");
  }
  require_all(shapes, "shapes");
  std::vector<std::uint32_t> order(shapes.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) { return scores[i] > scores[j]; });
  std::vector<std::uint32_t> rank(shapes.size());
  for (std::size_t r = 0; r < order.size(); ++r) rank[order[r]] = static_cast<std::uint32_t>(r);
  const AabbTree tree = tree_of(shapes);
  std::vector<bool> suppressed(shapes.size(), false);
  std::vector<std::uint32_t> kept;
  for (const std::uint32_t i : order) {
    if (suppressed[i]) continue;
    kept.push_back(i);
    tree.query(aabb(shapes[i]), [&](std::uint32_t j) {
      if (rank[j] <= rank[i] || suppressed[j] || (!labels.empty() && labels[j] != labels[i])) return;
      if (detail::areas::iou_of(shapes[i], shapes[j]) > iou_threshold) suppressed[j] = true;
    });
  }
  return kept;
}

}  // namespace collide2d
