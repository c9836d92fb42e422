// The area queries in bulk: the batches against the single calls, iou_pairs against every pair
// measured one by one, nms against a greedy pass over every pair, and their refusals.
#include "core_families.h"

#include <collide2d/area.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide2d {
namespace {

using testing::Form;

// n shapes of every solid kind, scattered over a square of side `spread`.
std::vector<Shape> scattered(int n, double spread, std::mt19937_64& rng) {
  constexpr Form kinds[] = {Form::rect, Form::polygon, Form::rounded, Form::capsule, Form::circle, Form::ellipse};
  std::uniform_real_distribution<double> at(0, spread);
  std::vector<Shape> out;
  for (int i = 0; i < n; ++i)
    out.push_back(moved_to(testing::random_shape(kinds[i % 6], 1.0, 3.0, rng), Vec2(at(rng), at(rng))));
  return out;
}

TEST(AreaBatch, EqualsTheSingleCalls) {
  std::mt19937_64 rng(70);
  const std::vector<Shape> a = scattered(300, 3, rng), b = scattered(300, 3, rng);
  std::vector<OverlapArea> areas(a.size());
  std::vector<double> values(a.size());
  overlap_areas(a, b, areas);
  ious(a, b, values);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const OverlapArea one = overlap_area(a[i], b[i]);
    EXPECT_EQ(areas[i].area, one.area) << i;
    EXPECT_EQ(areas[i].centroid, one.centroid) << i;
    EXPECT_EQ(values[i], iou(a[i], b[i])) << i;
  }
}

TEST(AreaBatch, RefusesBeforeWriting) {
  std::vector<Shape> a(4, Rect{}), b(4, Circle{});
  b[3] = Circle{Vec2::Zero(), -1.0};
  std::vector<double> out(4, 7.0);
  try {
    ious(a, b, out);
    ADD_FAILURE() << "a negative radius passed";
  } catch (const InvalidShape& e) {
    EXPECT_NE(std::string(e.what()).find("pair 3, b"), std::string::npos) << e.what();
  }
  EXPECT_EQ(out, std::vector<double>(4, 7.0));
  std::vector<OverlapArea> short_out(3);
  EXPECT_THROW(overlap_areas(a, a, short_out), std::invalid_argument);
  EXPECT_THROW(iou_pairs(a, b), InvalidShape);
  EXPECT_THROW(iou_pairs(a, a, 1.5), std::invalid_argument);
}

// Every pair with IoU above 0 and at least min_iou, found by measuring all N x M.
std::vector<IouPair> all_pairs(const std::vector<Shape>& a, const std::vector<Shape>& b, double min_iou) {
  std::vector<IouPair> out;
  for (std::uint32_t i = 0; i < a.size(); ++i) {
    for (std::uint32_t j = 0; j < b.size(); ++j) {
      const double x = iou(a[i], b[j]);
      if (x > 0 && x >= min_iou) out.push_back({i, j, x});
    }
  }
  return out;
}

TEST(AreaBatch, IouPairsFindsEveryOverlappingPair) {
  std::mt19937_64 rng(71);
  const std::vector<Shape> a = scattered(200, 30, rng), b = scattered(150, 30, rng);
  for (const double min_iou : {0.0, 0.2}) {
    const std::vector<IouPair> got = iou_pairs(a, b, min_iou), want = all_pairs(a, b, min_iou);
    ASSERT_EQ(got.size(), want.size()) << min_iou;
    EXPECT_GT(want.size(), 20u);
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_EQ(got[k].a, want[k].a);
      EXPECT_EQ(got[k].b, want[k].b);
      EXPECT_EQ(got[k].iou, want[k].iou);
    }
  }
}

// Greedy suppression over every pair, in the order of a plain sort by (score descending, index).
std::vector<std::uint32_t> greedy(const std::vector<Shape>& s, const std::vector<double>& scores, double threshold,
                                  const std::vector<std::int64_t>& labels) {
  std::vector<std::uint32_t> order(s.size());
  for (std::uint32_t i = 0; i < s.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t i, std::uint32_t j) { return scores[i] != scores[j] ? scores[i] > scores[j] : i < j; });
  std::vector<std::uint32_t> kept;
  for (const std::uint32_t i : order) {
    const bool beaten = std::any_of(kept.begin(), kept.end(), [&](std::uint32_t k) {
      return (labels.empty() || labels[k] == labels[i]) && iou(s[k], s[i]) > threshold;
    });
    if (!beaten) kept.push_back(i);
  }
  return kept;
}

TEST(AreaBatch, NmsEqualsTheGreedyPass) {
  std::mt19937_64 rng(72);
  const std::vector<Shape> boxes = scattered(400, 12, rng);
  std::uniform_int_distribution<int> score(0, 20), label(0, 2);  // few scores: many ties
  std::vector<double> scores;
  std::vector<std::int64_t> labels;
  for (std::size_t i = 0; i < boxes.size(); ++i) scores.push_back(score(rng) / 20.0), labels.push_back(label(rng));
  for (const double threshold : {0.0, 0.1, 0.5}) {
    const std::vector<std::uint32_t> plain = nms(boxes, scores, threshold);
    EXPECT_EQ(plain, greedy(boxes, scores, threshold, {})) << threshold;
    EXPECT_EQ(nms(boxes, scores, threshold, labels), greedy(boxes, scores, threshold, labels)) << threshold;
    EXPECT_LT(plain.size(), boxes.size());
  }
}

// Two equal boxes: IoU 1, which a threshold of 1 keeps (strictly above) and any lower suppresses.
TEST(AreaBatch, NmsSuppressesStrictlyAbove) {
  const std::vector<Shape> twins(2, Rect{});
  const std::vector<double> scores{0.5, 0.5};
  EXPECT_EQ(nms(twins, scores, 1.0), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(nms(twins, scores, 0.99), (std::vector<std::uint32_t>{0}));
  EXPECT_THROW(nms(twins, std::vector<double>{0.5}, 0.5), std::invalid_argument);
  EXPECT_THROW(nms(twins, std::vector<double>{0.5, std::nan("")}, 0.5), std::invalid_argument);
  EXPECT_THROW(nms(twins, scores, -0.1), std::invalid_argument);
}

}  // namespace
}  // namespace collide2d
