// Fuzz-input helpers: reads numbers and choices from the fuzzer's bytes, and builds shapes from them
// with magnitudes anywhere in double range (extremes and denormals included), so that validation
// and the kernels both get exercised.
#pragma once

#include <collide2d/shapes.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>

namespace collide2d::fuzz {

// `any`: a circle, an ellipse or a rectangle, as the bytes choose (the corpora were written so);
// `cored`: a capsule or a polygon; `all`: any of those five; `segment`: a segment.
enum class Kind { circle, ellipse, rect, any, capsule, polygon, cored, all, segment };

class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  bool empty() const { return pos_ >= size_; }
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }

  // Raw 8 bytes as a double half of the time (any bit pattern: NaN, infinity, denormals), otherwise
  // a tame value from one byte (-8 ... 8 in steps) so that shapes often meet.
  double number() {
    if (byte() & 1) {
      std::uint64_t bits = 0;  // little-endian, as the corpora were written
      for (int k = 0; k < 8; ++k) bits |= std::uint64_t{byte()} << (8 * k);
      double value;
      std::memcpy(&value, &bits, sizeof value);  // std::bit_cast, which Emscripten 3.1's library lacks
      return value;
    }
    return (static_cast<int>(byte()) - 128) / 16.0;
  }
  double size() {
    const double x = number();
    return x < 0 ? -x : x;
  }

  // A shape of the given kind, or of the kind the bytes choose. The choice byte is read either way,
  // so that one input decodes to the same numbers in every fuzzer and the corpora can be shared.
  // Each read in its own statement: the order of evaluation of function arguments differs between
  // compilers, and a crash found with clang must decode the same with g++.
  Shape shape(Kind wanted = Kind::any) {
    if (wanted == Kind::cored || wanted == Kind::all) {
      const int chosen = byte() % (wanted == Kind::cored ? 2 : 5);
      constexpr Kind kinds[] = {Kind::capsule, Kind::polygon, Kind::circle, Kind::ellipse, Kind::rect};
      return shape(kinds[chosen]);
    }
    if (wanted == Kind::capsule) return capsule();
    if (wanted == Kind::polygon) return polygon();
    if (wanted == Kind::segment) return segment();
    const double x = number();
    const double y = number();
    const int chosen = byte() % 3;
    const int kind = wanted == Kind::any ? chosen : static_cast<int>(wanted);
    const double u = size();
    const double v = kind == 0 ? 0.0 : size();
    const double angle = kind == 0 ? 0.0 : number();
    if (kind == 0) return Circle{Vec2(x, y), u};
    if (kind == 1) return Ellipse{Vec2(x, y), u, v, angle};
    return Rect{Vec2(x, y), Vec2(u, v), angle};
  }
  Capsule capsule() {
    const Vec2 c = point();
    const double h = size();
    const double r = size();
    return {c, h, r, number()};
  }
  // 3 to 8 vertices on an ellipse, each within a quarter step of its regular place (a convex polygon
  // unless the numbers are extreme), rounded half the time; one that ConvexPolygon::of refuses has
  // no outline, and validate() refuses it.
  ConvexPolygon polygon() {
    const Vec2 c = point();
    const double angle = number();
    const double a = size();
    const double b = size();
    const int n = 3 + byte() % 6;
    std::array<Vec2, kMaxPolygonVertices> v;
    for (int k = 0; k < n; ++k) {
      const double t = (k + (static_cast<int>(byte()) - 128) / 512.0) * 6.283185307179586 / n;
      const Orientation o = Orientation::of(t);  // the library's cosine and sine, the same everywhere
      v[k] = Vec2(a * o.c, b * o.s);
    }
    const double radius = byte() & 1 ? size() : 0.0;
    try {
      return ConvexPolygon::of(std::span<const Vec2>(v.data(), static_cast<std::size_t>(n)), radius).at(c, angle);
    } catch (const InvalidShape&) {
      return {c, angle, nullptr};
    }
  }
  // Its first point, its second in its frame, and its angle.
  Segment segment() {
    const Vec2 first = point();
    const Vec2 end = point();
    return {first, end, number()};
  }
  Vec2 point() {
    const double x = number();
    return {x, number()};
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// The largest coordinate of the shape's box: the scale its rounding errors are relative to.
inline double extent(const Shape& s) {
  const Aabb b = aabb(s);
  return std::max(b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff());
}

// Aborts naming the property that failed, so that the fuzzer keeps the input.
[[noreturn]] inline void fail(const char* what) {
  std::fprintf(stderr, "property failed: %s\n", what);
  std::abort();
}
inline void check(bool ok, const char* what) {
  if (!ok) fail(what);
}

// Whether the shape passes validation (the fuzzers check the properties on valid shapes only).
inline bool valid(const Shape& s) {
  try {
    validate(s);
    return true;
  } catch (const InvalidShape&) {
    return false;
  }
}

}  // namespace collide2d::fuzz
