// The array forms of the pair queries: NumPy arrays of shapes of one kind a row, the GIL released,
// through the batched kernels where the pair of kinds has one.
#include "python/module.h"

#include <collide2d/area.h>

#include "narrowphase/internal.h"
#include "shapes/kinds.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <optional>
#include <tuple>
#include <span>
#include <string>
#include <type_traits>
#include <variant>
#include <utility>
#include <vector>

namespace collide2d::python {

namespace {

using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The kinds an array holds, one shape a row in its row of the query grammar (shapes/kinds.h): every
// kind with a row of fixed length but level geometry.
template <class S>
struct KindTag {
  using type = S;
};
template <class Tags>
struct VariantOf;
template <class... Tags>
struct VariantOf<std::tuple<Tags...>> {
  using type = std::variant<Tags...>;
};
template <class... S>
using RowKinds = typename VariantOf<decltype(std::tuple_cat(
    std::declval<std::conditional_t<detail::HasRow<S> && !detail::level_geometry<S>(), std::tuple<KindTag<S>>,
                                    std::tuple<>>>()...))>::type;
template <class List>
struct ArrayKindsOf;
template <class... S>
struct ArrayKindsOf<detail::KindList<S...>> {
  using type = RowKinds<S...>;
};
using AnyKind = ArrayKindsOf<detail::Kinds>::type;

// Each kind's text, `what`, by its number, joined: "circle, ellipse, rect or capsule",
// "circle (cx cy r), ...".
template <class What>
std::string each_kind(const char* last, What what) {
  std::vector<std::pair<std::uint32_t, std::string>> texts;
  [&]<class... Tags>(std::variant<Tags...>*) {
    (texts.emplace_back(detail::Kind<typename Tags::type>::number, what(Tags{})), ...);
  }(static_cast<AnyKind*>(nullptr));
  std::sort(texts.begin(), texts.end());
  std::string out;
  for (std::size_t k = 0; k < texts.size(); ++k) {
    out += (k == 0 ? "" : k + 1 == texts.size() ? last : ", ") + texts[k].second;
  }
  return out;
}
std::string kind_words() {
  return each_kind(" or ", [](auto tag) { return std::string(detail::Kind<typename decltype(tag)::type>::word); });
}
std::string kind_rows() {
  return each_kind(", ", [](auto tag) {
    using S = typename decltype(tag)::type;
    return std::string(detail::Kind<S>::word) + " (" + std::string(detail::grammar_of<S>()) + ")";
  });
}

AnyKind kind_of(const std::string& name) {
  std::optional<AnyKind> found;
  [&]<class... Tags>(std::variant<Tags...>*) {
    ((name == detail::Kind<typename Tags::type>::word ? void(found = Tags{}) : void()), ...);
  }(static_cast<AnyKind*>(nullptr));
  if (!found) throw py::value_error("unknown shape kind '" + name + "' (" + kind_words() + ")");
  return *found;
}

// Throws where the array is not (n, k) for the kind's k columns.
template <class S>
void check_columns(const char* which, const Rows& rows) {
  constexpr auto columns = static_cast<py::ssize_t>(detail::Kind<S>::row.size());
  if (rows.ndim() != 2 || rows.shape(1) != columns) {
    throw py::value_error(std::string(which) + ": " + std::string(detail::Kind<S>::word) + " rows need an (n, " +
                          std::to_string(columns) + ") array (" + std::string(detail::grammar_of<S>()) + ")");
  }
}

// Row i of an array as a checked shape; the error names the array and the row.
template <class S>
S checked_row(const char* which, const Rows& rows, py::ssize_t i) {
  S shape = detail::Kind<S>::from_row(rows.data() + i * rows.shape(1));  // c_style rows
  try {
    validate(shape);
  } catch (const InvalidShape& e) {
    throw py::value_error(std::string(which) + "[" + std::to_string(i) + "]: " + e.what());
  }
  return shape;
}

// Storage the thread keeps from call to call (`slot` 0 for a, 1 for b), so that a large array does
// not take fresh pages from the system on every call.
template <class T>
T& kept(int slot) {
  thread_local std::array<T, 2> storage;
  return storage[static_cast<std::size_t>(slot)];
}

// The rows of an (n, k) array as shapes of one kind, each checked, in the thread's kept storage.
const std::vector<Shape>& shapes_of(const char* which, const std::string& kind_name, const Rows& rows, int slot) {
  std::vector<Shape>& out = kept<std::vector<Shape>>(slot);
  out.clear();
  std::visit(
      [&](auto tag) {
        using S = typename decltype(tag)::type;
        check_columns<S>(which, rows);
        out.reserve(static_cast<std::size_t>(rows.shape(0)));
        for (py::ssize_t i = 0; i < rows.shape(0); ++i) out.push_back(checked_row<S>(which, rows, i));
      },
      kind_of(kind_name));
  return out;
}

void check_lengths(std::size_t a, std::size_t b) {
  if (a != b) {
    throw py::value_error("a has " + std::to_string(a) + " rows and b " + std::to_string(b) +
                          ": pairs need as many of each");
  }
}

struct PairLists {
  const std::vector<Shape>& a;
  const std::vector<Shape>& b;
};

// Rotated boxes in a detector's rows, (cx, cy, w, h, angle), as rect rows (cx, cy, hx, hy, theta):
// detectron2's angle in degrees, mmcv's in radians. Whether the angle turns clockwise (mmcv's flag)
// mirrors every box alike and leaves every area and IoU as it is.
Rows rect_rows(const Rows& rows, const std::string& format) {
  if (format == "collide2d") return rows;
  double to_radians = 1;
  if (format == "detectron2")
    to_radians = std::numbers::pi / 180;
  else if (format != "mmcv")
    throw py::value_error("unknown box_format '" + format + "' (collide2d, detectron2 or mmcv)");
  if (rows.ndim() != 2 || rows.shape(1) != 5)
    throw py::value_error(format + " boxes need an (n, 5) array (cx cy w h angle)");
  Rows out({rows.shape(0), py::ssize_t{5}});
  auto in = rows.unchecked<2>();
  auto o = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
    o(i, 0) = in(i, 0), o(i, 1) = in(i, 1), o(i, 2) = in(i, 2) / 2, o(i, 3) = in(i, 3) / 2;
    o(i, 4) = in(i, 4) * to_radians;
  }
  return out;
}

const std::vector<Shape>& solids_of(const char* which, const std::string& kind, const Rows& rows,
                                    const std::string& format, int slot) {
  if (format != "collide2d" && kind != "rect")
    throw py::value_error("box_format '" + format + "' is for rect rows, not " + kind);
  return shapes_of(which, kind, rect_rows(rows, format), slot);
}

PairLists pair_lists(const std::string& a_kind, const Rows& a, const std::string& b_kind, const Rows& b,
                     const std::string& format = "collide2d") {
  PairLists p{solids_of("a", a_kind, a, format, 0), solids_of("b", b_kind, b, format, 1)};
  check_lengths(p.a.size(), p.b.size());
  return p;
}

py::array_t<double> points(std::size_t n) { return py::array_t<double>({static_cast<py::ssize_t>(n), py::ssize_t{2}}); }

// One query over every pair, the GIL released: out(i, result) for each.
template <class Query, class Out>
void each_pair(const PairLists& p, Query query, Out out) {
  py::gil_scoped_release released;
  for (std::size_t i = 0; i < p.a.size(); ++i) out(i, query(p.a[i], p.b[i]));
}

// An array's rows as checked shapes of one kind and their orientations, as the batches take them,
// in storage kept by the thread from call to call (`slot` 0 for a, 1 for b), so that a large array
// does not take fresh pages from the system on every call.
template <class S>
struct Typed {
  std::vector<S>& shapes;
  std::vector<Orientation>& orientations;
  Typed(const char* which, const Rows& rows, int slot)
      : shapes(kept<std::vector<S>>(slot)), orientations(kept<std::vector<Orientation>>(slot)) {
    shapes.clear();
    orientations.clear();
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
      shapes.push_back(checked_row<S>(which, rows, i));
      if constexpr (requires { shapes.back().angle; }) {
        orientations.push_back(Orientation::of(shapes.back().angle));
      } else {
        orientations.push_back(Orientation{});  // a kind with no angle (a circle) has none to read
      }
    }
  }
};

// overlaps() of every pair into `out`, the GIL released: through the batched kernels where the
// kinds have one (in either order: overlap is symmetric), else one pair at a time.
template <class A, class B>
void overlaps_into(const Typed<A>& x, const Typed<B>& y, std::span<std::uint8_t> out) {
  py::gil_scoped_release released;
  if constexpr (!detail::batched<A, B>) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = overlaps(Shape(x.shapes[i]), Shape(y.shapes[i])) ? 1 : 0;
  } else if constexpr (detail::rank<A>() <= detail::rank<B>()) {
    detail::overlap_batch<A, B>(x.shapes, x.orientations, y.shapes, y.orientations, out);
  } else {
    detail::overlap_batch<B, A>(y.shapes, y.orientations, x.shapes, x.orientations, out);
  }
}

py::array_t<bool> overlaps_arrays(const std::string& a_kind, const Rows& a, const std::string& b_kind, const Rows& b) {
  py::array_t<bool> out;
  std::visit(
      [&](auto tag_a, auto tag_b) {
        using A = typename decltype(tag_a)::type;
        using B = typename decltype(tag_b)::type;
        check_columns<A>("a", a);
        check_columns<B>("b", b);
        check_lengths(static_cast<std::size_t>(a.shape(0)), static_cast<std::size_t>(b.shape(0)));
        out = py::array_t<bool>(a.shape(0));
        // A bool array's bytes, 0 or 1, are the batches' verdicts.
        const std::span<std::uint8_t> verdicts(reinterpret_cast<std::uint8_t*>(out.mutable_data()),
                                               static_cast<std::size_t>(a.shape(0)));
        const Typed<A> x("a", a, 0);
        const Typed<B> y("b", b, 1);
        overlaps_into(x, y, verdicts);
      },
      kind_of(a_kind), kind_of(b_kind));
  return out;
}

py::dict distance_arrays(const std::string& a_kind, const Rows& a, const std::string& b_kind, const Rows& b) {
  const PairLists p = pair_lists(a_kind, a, b_kind, b);
  const auto n = static_cast<py::ssize_t>(p.a.size());
  py::array_t<bool> overlapping(n);
  py::array_t<double> distances(n);
  py::array_t<double> pa = points(p.a.size()), pb = points(p.a.size());
  auto o = overlapping.mutable_unchecked<1>();
  auto d = distances.mutable_unchecked<1>();
  auto ua = pa.mutable_unchecked<2>(), ub = pb.mutable_unchecked<2>();
  each_pair(p, [](const Shape& x, const Shape& y) { return distance(x, y); },
            [&](std::size_t k, const DistanceResult& r) {
              const auto i = static_cast<py::ssize_t>(k);
              o(i) = r.overlapping, d(i) = r.distance;
              ua(i, 0) = r.point_a.x(), ua(i, 1) = r.point_a.y(), ub(i, 0) = r.point_b.x(), ub(i, 1) = r.point_b.y();
            });
  return py::dict(py::arg("overlapping") = overlapping, py::arg("distance") = distances, py::arg("point_a") = pa,
                  py::arg("point_b") = pb);
}

py::dict contact_arrays(const std::string& a_kind, const Rows& a, const std::string& b_kind, const Rows& b) {
  const PairLists p = pair_lists(a_kind, a, b_kind, b);
  const auto n = static_cast<py::ssize_t>(p.a.size());
  py::array_t<double> separations(n);
  py::array_t<double> normals = points(p.a.size()), pa = points(p.a.size()), pb = points(p.a.size());
  auto s = separations.mutable_unchecked<1>();
  auto un = normals.mutable_unchecked<2>(), ua = pa.mutable_unchecked<2>(), ub = pb.mutable_unchecked<2>();
  each_pair(p, [](const Shape& x, const Shape& y) { return contact(x, y); },
            [&](std::size_t k, const Contact& c) {
              const auto i = static_cast<py::ssize_t>(k);
              s(i) = c.separation;
              un(i, 0) = c.normal.x(), un(i, 1) = c.normal.y();
              ua(i, 0) = c.point_a.x(), ua(i, 1) = c.point_a.y(), ub(i, 0) = c.point_b.x(), ub(i, 1) = c.point_b.y();
            });
  return py::dict(py::arg("separation") = separations, py::arg("normal") = normals, py::arg("point_a") = pa,
                  py::arg("point_b") = pb);
}

// A library call on shapes already checked, the GIL released; its refusals come out as ValueError.
template <class Call>
auto released(Call call) {
  py::gil_scoped_release unlocked;
  try {
    return call();
  } catch (const std::invalid_argument& e) {  // InvalidShape too
    throw py::value_error(e.what());
  }
}

py::dict overlap_area_arrays(const std::string& a_kind, const Rows& a, const std::string& b_kind, const Rows& b,
                             const std::string& box_format) {
  const PairLists p = pair_lists(a_kind, a, b_kind, b, box_format);
  std::vector<OverlapArea>& results = kept<std::vector<OverlapArea>>(0);
  results.resize(p.a.size());
  released([&] { overlap_areas(p.a, p.b, results); });
  const auto n = static_cast<py::ssize_t>(p.a.size());
  py::array_t<double> areas(n), centroids = points(p.a.size());
  py::array_t<std::int32_t> crossings(n);
  auto ar = areas.mutable_unchecked<1>();
  auto c = centroids.mutable_unchecked<2>();
  auto x = crossings.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const OverlapArea& r = results[static_cast<std::size_t>(i)];
    ar(i) = r.area, c(i, 0) = r.centroid.x(), c(i, 1) = r.centroid.y(), x(i) = r.crossings;
  }
  return py::dict(py::arg("area") = areas, py::arg("centroid") = centroids, py::arg("crossings") = crossings);
}

py::array_t<double> iou_arrays(const std::string& a_kind, const Rows& a, const std::string& b_kind, const Rows& b,
                               const std::string& mode, const std::string& box_format) {
  double (*measure)(const Shape&, const Shape&) = nullptr;
  if (mode == "iou") measure = &iou;
  if (mode == "iof") measure = &iof;
  if (mode == "distance") measure = &iou_distance;
  if (!measure) throw py::value_error("unknown mode '" + mode + "' (iou, iof or distance)");
  const PairLists p = pair_lists(a_kind, a, b_kind, b, box_format);
  py::array_t<double> out(static_cast<py::ssize_t>(p.a.size()));
  const std::span<double> values(out.mutable_data(), p.a.size());
  released([&] {
    if (measure == &iou) return ious(p.a, p.b, values);  // the batch
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = measure(p.a[i], p.b[i]);
  });
  return out;
}

py::dict iou_matrix(const std::string& a_kind, const Rows& a, const std::string& b_kind, const Rows& b, double min_iou,
                    const std::string& box_format) {
  const std::vector<Shape>&x = solids_of("a", a_kind, a, box_format, 0), &y = solids_of("b", b_kind, b, box_format, 1);
  const std::vector<IouPair> pairs = released([&] { return iou_pairs(x, y, min_iou); });
  const auto n = static_cast<py::ssize_t>(pairs.size());
  py::array_t<std::int64_t> i(n), j(n);
  py::array_t<double> values(n);
  auto ui = i.mutable_unchecked<1>(), uj = j.mutable_unchecked<1>();
  auto uv = values.mutable_unchecked<1>();
  for (py::ssize_t k = 0; k < n; ++k) {
    const IouPair& p = pairs[static_cast<std::size_t>(k)];
    ui(k) = p.a, uj(k) = p.b, uv(k) = p.iou;
  }
  return py::dict(py::arg("i") = i, py::arg("j") = j, py::arg("iou") = values);
}

using Labels = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
using Scores = py::array_t<double, py::array::c_style | py::array::forcecast>;

py::array_t<std::int64_t> non_maximum_suppression(const Rows& rows, const Scores& scores, double iou_threshold,
                                                  const std::optional<Labels>& labels, const std::string& kind,
                                                  const std::string& box_format) {
  const std::vector<Shape>& shapes = solids_of("rows", kind, rows, box_format, 0);
  const std::span<const double> s(scores.data(), static_cast<std::size_t>(scores.size()));
  std::span<const std::int64_t> l;
  if (labels) l = {labels->data(), static_cast<std::size_t>(labels->size())};
  const std::vector<std::uint32_t> kept = released([&] { return nms(shapes, s, iou_threshold, l); });
  return py::array_t<std::int64_t>(static_cast<py::ssize_t>(kept.size()), std::vector<std::int64_t>(kept.begin(), kept.end()).data());
}

}  // namespace

void add_arrays(py::module_& m) {
  const std::string kinds = "\n\nShapes of one kind a row: " + kind_rows() + "; row i of a with row i of b.";
  m.def("overlaps_arrays", &overlaps_arrays, py::arg("a_kind"), py::arg("a"), py::arg("b_kind"), py::arg("b"),
        ("overlaps() of every pair: a bool array." + kinds).c_str());
  m.def("distance_arrays", &distance_arrays, py::arg("a_kind"), py::arg("a"), py::arg("b_kind"), py::arg("b"),
        (std::string("distance() of every pair: a dict of arrays overlapping (n,), distance (n,), point_a\n"
                     "and point_b (n, 2).") +
         kinds)
            .c_str());
  m.def("contact_arrays", &contact_arrays, py::arg("a_kind"), py::arg("a"), py::arg("b_kind"), py::arg("b"),
        (std::string("contact() of every pair: a dict of arrays separation (n,), normal, point_a and\n"
                     "point_b (n, 2).") +
         kinds)
            .c_str());
  const std::string boxes =
      "\n\nbox_format: 'collide2d' (the rows above), or rotated boxes as (n, 5) rows cx cy w h angle,\n"
      "'detectron2' (angle in degrees) or 'mmcv' (radians), for rect rows.";
  m.def("overlap_area_arrays", &overlap_area_arrays, py::arg("a_kind"), py::arg("a"), py::arg("b_kind"), py::arg("b"),
        py::kw_only(), py::arg("box_format") = "collide2d",
        (std::string("overlap_area() of every pair: a dict of arrays area (n,), centroid (n, 2) and\n"
                     "crossings (n,).") +
         kinds + boxes)
            .c_str());
  m.def("iou_arrays", &iou_arrays, py::arg("a_kind"), py::arg("a"), py::arg("b_kind"), py::arg("b"), py::kw_only(),
        py::arg("mode") = "iou", py::arg("box_format") = "collide2d",
        ("iou() of every pair, or iof() with mode='iof', iou_distance() with mode='distance'." + kinds + boxes)
            .c_str());
  m.def("iou_matrix", &iou_matrix, py::arg("a_kind"), py::arg("a"), py::arg("b_kind"), py::arg("b"),
        py::arg("min_iou") = 0.0, py::kw_only(), py::arg("box_format") = "collide2d",
        (std::string("Every pair (i, j) of a row of a and a row of b with IoU above 0 and at least min_iou, as\n"
                     "a dict of arrays i, j and iou sorted by i then j; only pairs whose boxes meet are measured.") +
         boxes)
            .c_str());
  m.def("nms", &non_maximum_suppression, py::arg("rows"), py::arg("scores"), py::arg("iou_threshold"),
        py::arg("labels") = py::none(), py::kw_only(), py::arg("kind") = "rect", py::arg("box_format") = "collide2d",
        (std::string("Greedy non-maximum suppression: the indices kept, highest score first (equal scores by\n"
                     "index); a row is dropped when a kept one of its label has IoU strictly above the threshold.") +
         boxes)
            .c_str());
}

}  // namespace collide2d::python
