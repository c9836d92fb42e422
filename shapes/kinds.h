// Private: the registry of shape kinds. Each kind has one entry, Kind<T>, and the list Kinds holds
// them in rank order; what the library and its tools know of a kind beyond its geometry is there:
// - its word in the query grammar, the scene format, the Python arrays and messages;
// - its number in the replay and wire formats, fixed for ever and never reused;
// - its row: the numbers the query grammar and the Python arrays write it with, and the shape
//   made from them (a polygon, whose vertices vary in number, has its own grammar instead);
// - its fields in the scene format, besides its centre;
// - its sizes in the replay and wire formats (sizes(), outline()), and the shape made of them at a
//   centre and angle (made());
// - the order of two shapes of it in a pair, by key (or its own precedes()), so that the pair's
//   kernel takes them one way whichever way the caller gave them.
// Its geometry (validate, aabb, support, contains, reach_of) is declared in shapes.h and defined in
// its own file, shapes/<word>.cpp; a kind must have each (ShapeKind, below). What follows from the
// entries is derived from them at compile time: the rank, the grammar's text, and with the pair table
// (narrowphase/pairs.h) every dispatch over pairs.
#pragma once

#include <collide2d/shapes.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace collide2d::detail {

// What a shape is apart from where (its centre and angle), as the replay and wire formats write it:
// two sizes, and a polygon's outline of vertices too (outline(); made() takes it, the others none).
using Sizes = std::array<double, 2>;
using Outline = std::span<const Vec2>;

// A kind's entry (below); a type with none is no kind.
template <class T>
struct Kind;

// What a shape must have to be a kind: its entry, and its geometry for the generic code.
template <class T>
concept ShapeKind = requires(const T& s, const Vec2& d) {
  Kind<T>::word;
  Kind<T>::number;
  validate(s);
  aabb(s);
  support(s, d);
  contains(s, d);
};

// The numbers a kind of fixed row is written with: their names, and the shape made from them.
template <std::size_t N>
using RowNames = std::array<std::string_view, N>;

template <>
struct Kind<Circle> {
  static constexpr std::string_view word = "circle";
  static constexpr std::uint32_t number = 0;
  static constexpr RowNames<3> row{"cx", "cy", "r"};
  static Circle from_row(const double* v) { return {Vec2(v[0], v[1]), v[2]}; }
  static constexpr std::array<std::string_view, 1> fields{"radius"};
  // The order of two circles in a pair (precedes()): by key.
  static std::array<double, 3> key(const Circle& c) { return {c.center.x(), c.center.y(), c.radius}; }
  static std::array<double, 2> sizes(const Circle& c) { return {c.radius, 0.0}; }
  static Circle made(const Vec2& center, double, const Sizes& s, Outline) { return {center, s[0]}; }
};

template <>
struct Kind<Ellipse> {
  static constexpr std::string_view word = "ellipse";
  static constexpr std::uint32_t number = 1;
  static constexpr RowNames<5> row{"cx", "cy", "a", "b", "theta"};
  static Ellipse from_row(const double* v) { return {Vec2(v[0], v[1]), v[2], v[3], v[4]}; }
  static constexpr std::array<std::string_view, 3> fields{"a", "b", "angle"};
  static std::array<double, 5> key(const Ellipse& e) { return {e.center.x(), e.center.y(), e.a, e.b, e.angle}; }
  static std::array<double, 2> sizes(const Ellipse& e) { return {e.a, e.b}; }
  static Ellipse made(const Vec2& center, double angle, const Sizes& s, Outline) { return {center, s[0], s[1], angle}; }
};

template <>
struct Kind<Rect> {
  static constexpr std::string_view word = "rect";
  static constexpr std::uint32_t number = 2;
  static constexpr RowNames<5> row{"cx", "cy", "hx", "hy", "theta"};
  static Rect from_row(const double* v) { return {Vec2(v[0], v[1]), Vec2(v[2], v[3]), v[4]}; }
  static constexpr std::array<std::string_view, 2> fields{"half_extents", "angle"};
  static std::array<double, 5> key(const Rect& r) {
    return {r.center.x(), r.center.y(), r.half_extents.x(), r.half_extents.y(), r.angle};
  }
  static std::array<double, 2> sizes(const Rect& r) { return {r.half_extents.x(), r.half_extents.y()}; }
  static Rect made(const Vec2& center, double angle, const Sizes& s, Outline) {
    return {center, Vec2(s[0], s[1]), angle};
  }
};

template <>
struct Kind<Capsule> {
  static constexpr std::string_view word = "capsule";
  static constexpr std::uint32_t number = 3;
  static constexpr RowNames<5> row{"cx", "cy", "h", "r", "theta"};
  static Capsule from_row(const double* v) { return {Vec2(v[0], v[1]), v[2], v[3], v[4]}; }
  static constexpr std::array<std::string_view, 3> fields{"half_length", "radius", "angle"};
  static std::array<double, 5> key(const Capsule& c) {
    return {c.center.x(), c.center.y(), c.half_length, c.radius, c.angle};
  }
  static std::array<double, 2> sizes(const Capsule& c) { return {c.half_length, c.radius}; }
  static Capsule made(const Vec2& center, double angle, const Sizes& s, Outline) { return {center, s[0], s[1], angle}; }
};

template <>
struct Kind<ConvexPolygon> {
  static constexpr std::string_view word = "polygon";
  static constexpr std::uint32_t number = 4;
  // 3 to 8 vertices counter-clockwise in its own frame, after its pose and radius.
  static constexpr std::string_view grammar = "cx cy theta r x0 y0 x1 y1 x2 y2 ...";
  static constexpr std::array<std::string_view, 3> fields{"vertices", "radius", "angle"};
  // Its pose, then its outline's radius, count and vertices (never its address, which would order a
  // replay differently): the outline is read only where the poses tie, as copies of one polygon do.
  static bool precedes(const ConvexPolygon& p, const ConvexPolygon& q) {
    const auto pose = [](const ConvexPolygon& x) { return std::array<double, 3>{x.center.x(), x.center.y(), x.angle}; };
    if (pose(p) != pose(q)) return pose(p) < pose(q);
    const auto outline = [](const ConvexPolygon& x) {
      std::array<double, 2 + 2 * kMaxPolygonVertices> k{x.radius(), static_cast<double>(x.count())};
      for (int i = 0; i < x.count(); ++i) k[2 + 2 * i] = x.vertices()[i].x(), k[3 + 2 * i] = x.vertices()[i].y();
      return k;
    };
    return outline(p) < outline(q);
  }
  static std::array<double, 2> sizes(const ConvexPolygon& p) { return {p.radius(), 0.0}; }
  static std::span<const Vec2> outline(const ConvexPolygon& p) { return p.vertices(); }
  static ConvexPolygon made(const Vec2& center, double angle, const Sizes& s, Outline vertices) {
    return ConvexPolygon::of(vertices, s[0]).at(center, angle);
  }
};

// Level geometry: on static bodies only; no centre of its own in the formats users write, its two
// points place it.
template <>
struct Kind<Segment> {
  static constexpr std::string_view word = "segment";
  static constexpr std::uint32_t number = 5;
  static constexpr RowNames<4> row{"x1", "y1", "x2", "y2"};
  static Segment from_row(const double* v) { return Segment::between(Vec2(v[0], v[1]), Vec2(v[2], v[3])); }
  static constexpr std::array<std::string_view, 1> fields{"points"};
  static std::array<double, 5> key(const Segment& s) {
    return {s.center.x(), s.center.y(), s.end.x(), s.end.y(), s.angle};
  }
  static std::array<double, 2> sizes(const Segment& s) { return {s.end.x(), s.end.y()}; }
  static Segment made(const Vec2& center, double angle, const Sizes& s, Outline) {
    return {center, Vec2(s[0], s[1]), angle};
  }
  static constexpr bool level_geometry = true;  // on static bodies only
};

// Kinds in rank order: a pair of two kinds goes to its kernel in this order (the lower rank as A).
template <ShapeKind... Ts>
struct KindList {
  static constexpr std::size_t size = sizeof...(Ts);
  template <class T>
  static constexpr int rank() {
    int at = 0, found = -1;
    ((std::is_same_v<T, Ts> ? found = at : 0, ++at), ...);
    return found;
  }
  // f.template operator()<T>() for each kind, in rank order.
  template <class F>
  static constexpr void each(F&& f) {
    (f.template operator()<Ts>(), ...);
  }
  // The kinds' words by number, joined by ", " and, before `last` (or else the last kind's), "or":
  // "circle, ellipse, rect, capsule, polygon, segment or chain".
  static std::string words(std::string_view last = {}) {
    std::array<std::pair<std::uint32_t, std::string_view>, size> by_number{{{Kind<Ts>::number, Kind<Ts>::word}...}};
    std::sort(by_number.begin(), by_number.end());
    std::string out;
    for (std::size_t k = 0; k < size; ++k) {
      const bool final = last.empty() && k + 1 == size;
      out += k == 0 ? "" : final ? " or " : ", ";
      out += by_number[k].second;
    }
    if (!last.empty()) out += std::string(" or ") + std::string(last);
    return out;
  }
  // Whether no two kinds of the list share a number: the formats tell kinds apart by them.
  static constexpr bool numbers_distinct() {
    const std::array<std::uint32_t, size> numbers{Kind<Ts>::number...};
    for (std::size_t i = 0; i < size; ++i) {
      for (std::size_t j = i + 1; j < size; ++j) {
        if (numbers[i] == numbers[j]) return false;
      }
    }
    return true;
  }
};

// The library's kinds: core shapes first, as they take the curved ones in their frames.
using Kinds = KindList<Rect, ConvexPolygon, Capsule, Segment, Circle, Ellipse>;
static_assert(Kinds::numbers_distinct(), "two kinds share a number of the replay and wire formats");

template <class T>
constexpr int rank() {
  return Kinds::rank<T>();
}

// Whether x comes before y, the order in which kernels take two shapes of one kind, so that swapping
// A and B swaps the result exactly, bit for bit, whatever frame the kernel uses.
template <class T>
bool precedes(const T& x, const T& y) {
  if constexpr (requires { Kind<T>::precedes(x, y); }) {
    return Kind<T>::precedes(x, y);
  } else {
    return Kind<T>::key(x) < Kind<T>::key(y);
  }
}

// Whether the kind is written as a row of fixed length.
template <class T>
concept HasRow = requires {
  Kind<T>::row;
};

// A row's names, spaced, as characters and their count.
template <class T>
inline constexpr auto kRowText = [] {
  std::array<char, 64> out{};
  std::size_t n = 0;
  for (const std::string_view name : Kind<T>::row) {
    if (n > 0) out[n++] = ' ';
    for (const char c : name) out[n++] = c;
  }
  return std::pair(out, n);
}();

// The kind's numbers in the query grammar, spaced: "cx cy a b theta".
template <class T>
constexpr std::string_view grammar_of() {
  if constexpr (HasRow<T>) {
    return {kRowText<T>.first.data(), kRowText<T>.second};
  } else {
    return Kind<T>::grammar;
  }
}

// The entry of the kind a shape holds.
template <class F>
decltype(auto) with_kind(const Shape& s, F&& f) {
  return std::visit([&f](const auto& x) -> decltype(auto) { return f(x, Kind<std::decay_t<decltype(x)>>{}); }, s);
}

// Whether the kind is level geometry, which the World takes on static bodies only.
template <class T>
constexpr bool level_geometry() {
  if constexpr (requires { Kind<T>::level_geometry; }) {
    return Kind<T>::level_geometry;
  } else {
    return false;
  }
}
inline bool is_level_geometry(const Shape& s) {
  return with_kind(s, [](const auto& x, auto) { return level_geometry<std::decay_t<decltype(x)>>(); });
}

// The number of the kind a shape holds.
inline std::uint32_t kind_number(const Shape& s) {
  return with_kind(s, [](const auto&, auto kind) { return decltype(kind)::number; });
}

// The shape of the kind numbered `number` with these sizes and outline, at a centre and angle.
// Throws std::invalid_argument for a number no kind has.
inline Shape made(std::uint32_t number, const Vec2& center, double angle, const Sizes& sizes, Outline outline) {
  std::optional<Shape> shape;
  Kinds::each([&]<class T>() {
    if (Kind<T>::number == number) shape = Kind<T>::made(center, angle, sizes, outline);
  });
  if (!shape) throw std::invalid_argument("no shape kind is numbered " + std::to_string(number));
  return *shape;
}

}  // namespace collide2d::detail
