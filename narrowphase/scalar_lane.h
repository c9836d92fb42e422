// Private: one pair as a "lane" of width one. The lane-generic kernels (the *-inl.h files) are
// written with the names Highway gives its operations; these overloads give the same names to
// double values and bool masks, found by ordinary lookup, while Highway's own are found on its
// vector types by argument-dependent lookup. One template then serves the one-off kernel and the
// batch (overlap_batch.cpp), with the same IEEE operations in the same order.
#pragma once

#include <algorithm>
#include <cmath>

namespace collide2d::detail {

struct Scalar {};
inline double Set(Scalar, double x) { return x; }
inline double Abs(double x) { return std::abs(x); }
inline double Max(double x, double y) { return std::max(x, y); }
inline double Min(double x, double y) { return std::min(x, y); }
inline double Sqrt(double x) { return std::sqrt(x); }
inline double Neg(double x) { return -x; }
inline bool And(bool x, bool y) { return x && y; }
inline bool Or(bool x, bool y) { return x || y; }
inline bool AndNot(bool not_x, bool y) { return !not_x && y; }
inline bool AllTrue(Scalar, bool m) { return m; }

}  // namespace collide2d::detail
