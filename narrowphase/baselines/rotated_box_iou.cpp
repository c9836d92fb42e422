#include "narrowphase/baselines/rotated_box_iou.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace collide2d::baselines {
namespace {

struct P {
  double x = 0, y = 0;
};
P operator-(P a, P b) { return {a.x - b.x, a.y - b.y}; }
P operator+(P a, P b) { return {a.x + b.x, a.y + b.y}; }
P operator*(double k, P a) { return {k * a.x, k * a.y}; }
double dot(P a, P b) { return a.x * b.x + a.y * b.y; }
double cross(P a, P b) { return a.x * b.y - a.y * b.x; }

// The method's fixed tolerances: edges nearer parallel than this determinant are skipped, and a
// corner counts as inside within this much of the other box's projections.
constexpr double kParallel = 1e-14;
constexpr double kInside = 1e-6;

std::array<P, 4> corners(const Rect& r, P shift) {
  const double c = std::cos(r.angle), s = std::sin(r.angle), hx = r.half_extents.x(), hy = r.half_extents.y();
  const P o{r.center.x() - shift.x, r.center.y() - shift.y};
  return {P{o.x - c * hx + s * hy, o.y - s * hx - c * hy}, P{o.x + c * hx + s * hy, o.y + s * hx - c * hy},
          P{o.x + c * hx - s * hy, o.y + s * hx + c * hy}, P{o.x - c * hx - s * hy, o.y - s * hx + c * hy}};
}

// The crossings of the two boxes' edges, and the corners of each inside the other.
int overlap_points(const std::array<P, 4>& a, const std::array<P, 4>& b, std::array<P, 24>& out) {
  int n = 0;
  for (int i = 0; i < 4; ++i) {
    const P ea = a[(i + 1) % 4] - a[i];
    for (int j = 0; j < 4; ++j) {
      const P eb = b[(j + 1) % 4] - b[j];
      const double det = cross(eb, ea);
      if (std::abs(det) <= kParallel) continue;
      const P d = b[j] - a[i];
      const double t = cross(eb, d) / det, u = cross(ea, d) / det;
      if (t >= 0 && t <= 1 && u >= 0 && u <= 1) out[n++] = a[i] + t * ea;
    }
  }
  const auto inside = [&](const std::array<P, 4>& box, P p) {
    const P ab = box[1] - box[0], ad = box[3] - box[0], ap = p - box[0];
    const double along = dot(ab, ap), across = dot(ad, ap);
    return along >= -kInside && along <= dot(ab, ab) + kInside && across >= -kInside && across <= dot(ad, ad) + kInside;
  };
  for (const P& p : a)
    if (inside(b, p)) out[n++] = p;
  for (const P& p : b)
    if (inside(a, p)) out[n++] = p;
  return n;
}

// Graham's scan from the lowest point: the rest sorted by angle about it (nearer first on a tie),
// then kept while they turn left.
int hull(std::array<P, 24>& p, int n) {
  std::swap(p[0], *std::min_element(p.begin(), p.begin() + n,
                                    [](P a, P b) { return a.y < b.y || (a.y == b.y && a.x < b.x); }));
  const P start = p[0];
  for (int i = 0; i < n; ++i) p[i] = p[i] - start;
  std::sort(p.begin() + 1, p.begin() + n, [](P a, P b) {
    const double turn = cross(a, b);
    return turn > 0 || (turn == 0 && dot(a, a) < dot(b, b));
  });
  int k = 1;
  while (k < n && dot(p[k], p[k]) <= 1e-8) ++k;  // points on the start
  if (k == n) return 1;
  p[1] = p[k];
  int m = 2;
  for (int i = k + 1; i < n; ++i) {
    while (m > 1 && cross(p[m - 1] - p[m - 2], p[i] - p[m - 2]) <= 0) --m;
    p[m++] = p[i];
  }
  return m;
}

}  // namespace

double rotated_box_iou(const Rect& a, const Rect& b) {
  const double area_a = 4 * a.half_extents.x() * a.half_extents.y(),
               area_b = 4 * b.half_extents.x() * b.half_extents.y();
  if (area_a < 1e-14 || area_b < 1e-14) return 0;
  const P shift{(a.center.x() + b.center.x()) / 2, (a.center.y() + b.center.y()) / 2};
  std::array<P, 24> points;
  const int n = overlap_points(corners(a, shift), corners(b, shift), points);
  if (n <= 2) return 0;
  const int m = hull(points, n);
  double twice = 0;
  for (int i = 1; i + 1 < m; ++i) twice += std::abs(cross(points[i], points[i + 1]));
  const double overlap = twice / 2;
  return overlap / (area_a + area_b - overlap);
}

}  // namespace collide2d::baselines
