// The Python module `collide2d` (docs/python.md): the shapes as immutable value classes, checked as
// the C++ shapes are (a bad one raises ValueError naming the field), and the pair queries on them,
// each one call into the library, so that the results are the C++ results bit for bit. Points and
// vectors go in as any pair of numbers and come out as tuples.
#include <collide2d/collide2d.h>

#include "narrowphase/internal.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <tuple>
#include <span>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace py = pybind11;

namespace collide2d {
namespace {

using Pair = std::array<double, 2>;

Vec2 vec(const Pair& p) { return {p[0], p[1]}; }
py::tuple tuple(const Vec2& v) { return py::make_tuple(v.x(), v.y()); }

template <class S>
S checked(S shape) {
  validate(shape);
  return shape;
}

std::string number(double x) { return py::repr(py::float_(x)).cast<std::string>(); }
std::string point(const Vec2& v) { return "(" + number(v.x()) + ", " + number(v.y()) + ")"; }

void add_shapes(py::module_& m) {
  py::class_<Circle>(m, "Circle", "A circle: its centre and radius (> 0).")
      .def(py::init([](const Pair& center, double radius) { return checked(Circle{vec(center), radius}); }),
           py::arg("center"), py::arg("radius"))
      .def_property_readonly("center", [](const Circle& c) { return tuple(c.center); })
      .def_readonly("radius", &Circle::radius)
      .def("__repr__", [](const Circle& c) { return "Circle(" + point(c.center) + ", " + number(c.radius) + ")"; });
  py::class_<Ellipse>(m, "Ellipse", "An ellipse: its centre, semi-axes a (along angle) and b, and angle (radians).")
      .def(py::init([](const Pair& center, double a, double b, double angle) {
             return checked(Ellipse{vec(center), a, b, angle});
           }),
           py::arg("center"), py::arg("a"), py::arg("b"), py::arg("angle") = 0.0)
      .def_property_readonly("center", [](const Ellipse& e) { return tuple(e.center); })
      .def_readonly("a", &Ellipse::a)
      .def_readonly("b", &Ellipse::b)
      .def_readonly("angle", &Ellipse::angle)
      .def("__repr__", [](const Ellipse& e) {
        return "Ellipse(" + point(e.center) + ", " + number(e.a) + ", " + number(e.b) + ", " + number(e.angle) + ")";
      });
  py::class_<Rect>(m, "Rect", "A rectangle: its centre, half extents (along angle, and across) and angle.")
      .def(py::init([](const Pair& center, const Pair& half_extents, double angle) {
             return checked(Rect{vec(center), vec(half_extents), angle});
           }),
           py::arg("center"), py::arg("half_extents"), py::arg("angle") = 0.0)
      .def_property_readonly("center", [](const Rect& r) { return tuple(r.center); })
      .def_property_readonly("half_extents", [](const Rect& r) { return tuple(r.half_extents); })
      .def_readonly("angle", &Rect::angle)
      .def("__repr__", [](const Rect& r) {
        return "Rect(" + point(r.center) + ", " + point(r.half_extents) + ", " + number(r.angle) + ")";
      });
  py::class_<Capsule>(m, "Capsule", "A capsule: a segment of half_length along angle about its centre, grown by radius.")
      .def(py::init([](const Pair& center, double half_length, double radius, double angle) {
             return checked(Capsule{vec(center), half_length, radius, angle});
           }),
           py::arg("center"), py::arg("half_length"), py::arg("radius"), py::arg("angle") = 0.0)
      .def_property_readonly("center", [](const Capsule& c) { return tuple(c.center); })
      .def_readonly("half_length", &Capsule::half_length)
      .def_readonly("radius", &Capsule::radius)
      .def_readonly("angle", &Capsule::angle)
      .def("__repr__", [](const Capsule& c) {
        return "Capsule(" + point(c.center) + ", " + number(c.half_length) + ", " + number(c.radius) + ", " +
               number(c.angle) + ")";
      });
  py::class_<Segment>(m, "Segment", "A segment between two points (level geometry; no thickness).")
      .def(py::init([](const Pair& point1, const Pair& point2) {
             return checked(Segment::between(vec(point1), vec(point2)));
           }),
           py::arg("point1"), py::arg("point2"))
      .def_property_readonly("point1", [](const Segment& s) { return tuple(s.point1()); })
      .def_property_readonly("point2", [](const Segment& s) { return tuple(s.point2()); })
      .def("__repr__", [](const Segment& s) { return "Segment(" + point(s.point1()) + ", " + point(s.point2()) + ")"; });
  py::class_<ConvexPolygon>(m, "ConvexPolygon",
                            "A convex polygon: 3 to 8 vertices counter-clockwise about its centre, in its own\n"
                            "frame, rounded by radius, posed at center and angle.")
      .def(py::init([](const std::vector<Pair>& vertices, double radius, const Pair& center, double angle) {
             std::vector<Vec2> v;
             for (const Pair& p : vertices) v.push_back(vec(p));
             return checked(ConvexPolygon::of(v, radius).at(vec(center), angle));
           }),
           py::arg("vertices"), py::arg("radius") = 0.0, py::arg("center") = Pair{0.0, 0.0}, py::arg("angle") = 0.0)
      .def_property_readonly("center", [](const ConvexPolygon& p) { return tuple(p.center); })
      .def_readonly("angle", &ConvexPolygon::angle)
      .def_property_readonly("radius", &ConvexPolygon::radius)
      .def_property_readonly("vertices",
                             [](const ConvexPolygon& p) {
                               py::list out;
                               for (const Vec2& v : p.vertices()) out.append(tuple(v));
                               return out;
                             })
      .def("__repr__", [](const ConvexPolygon& p) {
        return "ConvexPolygon(" + std::to_string(p.count()) + " vertices, radius " + number(p.radius()) + ", at " +
               point(p.center) + ", " + number(p.angle) + ")";
      });
}

void add_results(py::module_& m) {
  py::class_<DistanceResult>(m, "DistanceResult",
                             "overlapping, distance (0 when they overlap), and the closest points (a common\n"
                             "point when they overlap).")
      .def_readonly("overlapping", &DistanceResult::overlapping)
      .def_readonly("distance", &DistanceResult::distance)
      .def_property_readonly("point_a", [](const DistanceResult& d) { return tuple(d.point_a); })
      .def_property_readonly("point_b", [](const DistanceResult& d) { return tuple(d.point_b); });
  py::class_<ContactPoint>(m, "ContactPoint", "A manifold point: on A, on B, its separation and feature id.")
      .def_property_readonly("point_a", [](const ContactPoint& c) { return tuple(c.point_a); })
      .def_property_readonly("point_b", [](const ContactPoint& c) { return tuple(c.point_b); })
      .def_readonly("separation", &ContactPoint::separation)
      .def_readonly("id", &ContactPoint::id);
  py::class_<Contact>(m, "Contact",
                      "separation (> 0 apart, < 0 minus the depth), the unit normal from A to B, the deepest\n"
                      "(or closest) points, and the manifold; empty beyond max_separation.")
      .def_readonly("separation", &Contact::separation)
      .def_property_readonly("normal", [](const Contact& c) { return tuple(c.normal); })
      .def_property_readonly("point_a", [](const Contact& c) { return tuple(c.point_a); })
      .def_property_readonly("point_b", [](const Contact& c) { return tuple(c.point_b); })
      .def_property_readonly("manifold",
                             [](const Contact& c) {
                               const auto points = c.points();
                               return std::vector<ContactPoint>(points.begin(), points.end());
                             })
      .def_property_readonly("empty", &Contact::empty);
  py::class_<TimeOfImpact>(m, "TimeOfImpact",
                           "status ('hit', 'miss', 'overlapping' or 'stalled'), the time t in [0, 1], the\n"
                           "normal from A to B and the contact point there.")
      .def_property_readonly("status",
                             [](const TimeOfImpact& r) {
                               constexpr const char* kNames[] = {"hit", "miss", "overlapping", "stalled"};
                               return std::string(kNames[static_cast<int>(r.status)]);
                             })
      .def_readonly("t", &TimeOfImpact::t)
      .def_property_readonly("normal", [](const TimeOfImpact& r) { return tuple(r.normal); })
      .def_property_readonly("point", [](const TimeOfImpact& r) { return tuple(r.point); })
      .def_readonly("iterations", &TimeOfImpact::iterations);
  py::class_<RayShapeHit>(m, "RayHit",
                          "distance along the ray, the point, and the outward normal there ((0, 0) when the\n"
                          "ray starts inside).")
      .def_readonly("distance", &RayShapeHit::distance)
      .def_property_readonly("point", [](const RayShapeHit& h) { return tuple(h.point); })
      .def_property_readonly("normal", [](const RayShapeHit& h) { return tuple(h.normal); });
}

void add_queries(py::module_& m) {
  m.def("overlaps", py::overload_cast<const Shape&, const Shape&>(&overlaps), py::arg("a"), py::arg("b"),
        "Whether the solids overlap (touching counts).");
  m.def("distance", py::overload_cast<const Shape&, const Shape&>(&distance), py::arg("a"), py::arg("b"),
        "The distance between the solids and their closest points.");
  m.def("boundary_distance", &boundary_distance, py::arg("a"), py::arg("b"),
        "The distance between the boundary curves of two circles or ellipses (nested ones give their gap).");
  m.def(
      "contact",
      [](const Shape& a, const Shape& b, double max_separation, double margin) {
        return contact(a, b, ContactOptions{.margin = margin, .max_separation = max_separation});
      },
      py::arg("a"), py::arg("b"), py::arg("max_separation") = std::numeric_limits<double>::infinity(),
      py::arg("margin") = 0.0, "The signed distance, normal from A to B, deepest points and manifold.");
  m.def(
      "time_of_impact",
      [](const Shape& a, const Shape& b, const Pair& a_velocity, double a_turn, const Pair& b_velocity, double b_turn) {
        return time_of_impact(a, Motion{vec(a_velocity), a_turn}, b, Motion{vec(b_velocity), b_turn});
      },
      py::arg("a"), py::arg("b"), py::arg("a_velocity") = Pair{0.0, 0.0}, py::arg("a_turn") = 0.0,
      py::arg("b_velocity") = Pair{0.0, 0.0}, py::arg("b_turn") = 0.0,
      "The first time in [0, 1] at which the shapes, moving by their velocities and turns over the\n"
      "step (per step, about their centres), touch.");
  m.def(
      "ray_cast",
      [](const Shape& shape, const Pair& origin, const Pair& direction, double max_distance) {
        return ray_cast(shape, vec(origin), vec(direction), max_distance);
      },
      py::arg("shape"), py::arg("origin"), py::arg("direction"),
      py::arg("max_distance") = std::numeric_limits<double>::infinity(),
      "The first point of the shape on origin + t direction, 0 <= t <= max_distance, or None.");
}

// ---- the array forms ----

using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The kinds an array holds, one shape a row, and their columns.
enum class Kind { circle, ellipse, rect, capsule };
struct KindInfo {
  const char* name;
  py::ssize_t columns;
  const char* order;
};
constexpr KindInfo kKinds[] = {{"circle", 3, "cx cy r"},
                               {"ellipse", 5, "cx cy a b theta"},
                               {"rect", 5, "cx cy hx hy theta"},
                               {"capsule", 5, "cx cy half_length radius theta"}};

Kind kind_of(const std::string& name) {
  for (int k = 0; k < 4; ++k) {
    if (name == kKinds[k].name) return static_cast<Kind>(k);
  }
  throw py::value_error("unknown shape kind '" + name + "' (circle, ellipse, rect or capsule)");
}

template <class S>
S from_row(const double* r) {
  if constexpr (std::is_same_v<S, Circle>) return Circle{{r[0], r[1]}, r[2]};
  if constexpr (std::is_same_v<S, Ellipse>) return Ellipse{{r[0], r[1]}, r[2], r[3], r[4]};
  if constexpr (std::is_same_v<S, Rect>) return Rect{{r[0], r[1]}, {r[2], r[3]}, r[4]};
  if constexpr (std::is_same_v<S, Capsule>) return Capsule{{r[0], r[1]}, r[2], r[3], r[4]};
}

template <class S>
struct KindTag {
  using type = S;
};
using AnyKind = std::variant<KindTag<Circle>, KindTag<Ellipse>, KindTag<Rect>, KindTag<Capsule>>;
AnyKind tag_of(Kind k) {
  switch (k) {
    case Kind::circle:
      return KindTag<Circle>{};
    case Kind::ellipse:
      return KindTag<Ellipse>{};
    case Kind::rect:
      return KindTag<Rect>{};
    default:
      return KindTag<Capsule>{};
  }
}

// Throws where the array is not (n, k) for the kind's k columns.
void check_columns(const char* which, Kind kind, const Rows& rows) {
  const KindInfo& info = kKinds[static_cast<int>(kind)];
  if (rows.ndim() != 2 || rows.shape(1) != info.columns) {
    throw py::value_error(std::string(which) + ": " + info.name + " rows need an (n, " +
                          std::to_string(info.columns) + ") array (" + info.order + ")");
  }
}

// Row i of an array as a checked shape; the error names the array and the row.
template <class S>
S checked_row(const char* which, const Rows& rows, py::ssize_t i) {
  S shape = from_row<S>(rows.data() + i * rows.shape(1));  // c_style rows
  try {
    validate(shape);
  } catch (const InvalidShape& e) {
    throw py::value_error(std::string(which) + "[" + std::to_string(i) + "]: " + e.what());
  }
  return shape;
}

// The rows of an (n, k) array as shapes of one kind, each checked.
std::vector<Shape> shapes_of(const char* which, const std::string& kind_name, const Rows& rows) {
  const Kind kind = kind_of(kind_name);
  check_columns(which, kind, rows);
  std::vector<Shape> out;
  out.reserve(static_cast<std::size_t>(rows.shape(0)));
  std::visit(
      [&](auto tag) {
        for (py::ssize_t i = 0; i < rows.shape(0); ++i) out.push_back(checked_row<typename decltype(tag)::type>(which, rows, i));
      },
      tag_of(kind));
  return out;
}

void check_lengths(std::size_t a, std::size_t b) {
  if (a != b) {
    throw py::value_error("a has " + std::to_string(a) + " rows and b " + std::to_string(b) +
                          ": pairs need as many of each");
  }
}

struct PairLists {
  std::vector<Shape> a, b;
};

PairLists pair_lists(const std::string& a_kind, const Rows& a, const std::string& b_kind, const Rows& b) {
  PairLists p{shapes_of("a", a_kind, a), shapes_of("b", b_kind, b)};
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

template <class T>
T& kept(int slot) {
  thread_local std::array<T, 2> storage;
  return storage[static_cast<std::size_t>(slot)];
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
      if constexpr (std::is_same_v<S, Circle>) {
        orientations.push_back(Orientation{});  // a circle's is not read
      } else {
        orientations.push_back(Orientation::of(shapes.back().angle));
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
  const Kind ka = kind_of(a_kind), kb = kind_of(b_kind);
  check_columns("a", ka, a);
  check_columns("b", kb, b);
  check_lengths(static_cast<std::size_t>(a.shape(0)), static_cast<std::size_t>(b.shape(0)));
  py::array_t<bool> out(a.shape(0));
  // A bool array's bytes, 0 or 1, are the batches' verdicts.
  const std::span<std::uint8_t> verdicts(reinterpret_cast<std::uint8_t*>(out.mutable_data()),
                                         static_cast<std::size_t>(a.shape(0)));
  std::visit(
      [&](auto tag_a, auto tag_b) {
        const Typed<typename decltype(tag_a)::type> x("a", a, 0);
        const Typed<typename decltype(tag_b)::type> y("b", b, 1);
        overlaps_into(x, y, verdicts);
      },
      tag_of(ka), tag_of(kb));
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

void add_arrays(py::module_& m) {
  const char* kinds = "\n\nShapes of one kind a row: circle (cx cy r), ellipse (cx cy a b theta), rect (cx cy hx hy\n"
                      "theta), capsule (cx cy half_length radius theta); row i of a with row i of b.";
  m.def("overlaps_arrays", &overlaps_arrays, py::arg("a_kind"), py::arg("a"), py::arg("b_kind"), py::arg("b"),
        (std::string("overlaps() of every pair: a bool array.") + kinds).c_str());
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
}

// ---- the World ----

// A body's id in Python: generation << 32 | index, one uint64.
std::uint64_t id_of(BodyId b) { return static_cast<std::uint64_t>(b.generation) << 32 | b.index; }
BodyId body_of(std::uint64_t id) { return {static_cast<std::uint32_t>(id), static_cast<std::uint32_t>(id >> 32)}; }

template <class Records, class A, class B>
py::array_t<std::uint64_t> id_pairs(const Records& records, A a, B b) {
  py::array_t<std::uint64_t> out({static_cast<py::ssize_t>(records.size()), py::ssize_t{2}});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t k = 0; k < records.size(); ++k) {
    const auto i = static_cast<py::ssize_t>(k);
    o(i, 0) = id_of(a(records[k])), o(i, 1) = id_of(b(records[k]));
  }
  return out;
}

template <class Records>
py::array_t<std::uint64_t> body_pairs(const Records& records) {
  return id_pairs(records, [](const auto& r) { return r.a; }, [](const auto& r) { return r.b; });
}

// Columns of doubles from the records: each `get` fills one row of `width`.
template <class Records, class Get>
py::array_t<double> column(const Records& records, py::ssize_t width, Get get) {
  py::array_t<double> out({static_cast<py::ssize_t>(records.size()), width});
  double* data = out.mutable_data();
  for (std::size_t k = 0; k < records.size(); ++k) get(records[k], data + static_cast<py::ssize_t>(k) * width);
  return out;
}
void put(double* row, const Vec2& v) { row[0] = v.x(), row[1] = v.y(); }

// The World and, beside it, what a Python pair predicate raised in a worker thread, raised again by
// update() once the update is over.
class PyWorld {
 public:
  explicit PyWorld(const WorldOptions& options) : world_(options) {}

  // One shape at its own pose, or several placed in the body's frame at `pose`.
  std::uint64_t add(const std::variant<Shape, std::vector<Shape>>& shapes, const std::optional<Pose>& pose,
                    const BodyDef& def, bool continuous) {
    const BodyId id = std::visit(
        [&](const auto& s) {
          if constexpr (std::is_same_v<std::decay_t<decltype(s)>, Shape>) {
            if (pose) throw py::value_error("a pose is for a list of shapes; one shape is placed by its own centre");
            return world_.add(s, def);
          } else {
            std::vector<ShapeDef> defs;
            for (const Shape& shape : s) defs.push_back({.shape = shape});
            return world_.add(pose.value_or(Pose{}), defs, def);
          }
        },
        shapes);
    if (continuous) world_.set_continuous(id);
    return id_of(id);
  }
  void set_poses(const py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>& ids, const Rows& centres,
                 const Rows& angles) {
    const py::ssize_t n = ids.size();
    if (ids.ndim() != 1 || centres.ndim() != 2 || centres.shape(0) != n || centres.shape(1) != 2 ||
        angles.ndim() != 1 || angles.shape(0) != n) {
      throw py::value_error("set_poses needs ids (n,), centres (n, 2) and angles (n,); got " + std::to_string(n) +
                            " ids");
    }
    const auto id = ids.unchecked<1>();
    const auto centre = centres.unchecked<2>();
    const auto angle = angles.unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) {
      try {
        world_.move_to(body_of(id(i)), {centre(i, 0), centre(i, 1)}, angle(i));
      } catch (const std::exception& e) {
        throw py::value_error("row " + std::to_string(i) + ": " + e.what());
      }
    }
  }
  void set_pair_predicate(py::object predicate) {
    if (predicate.is_none()) return world_.set_pair_predicate({});
    world_.set_pair_predicate([this, predicate](BodyId a, BodyId b) {
      py::gil_scoped_acquire held;
      if (raised_) return false;
      try {
        return predicate(id_of(a), id_of(b)).cast<bool>();
      } catch (py::error_already_set& e) {
        raised_ = std::make_unique<py::error_already_set>(std::move(e));
        return false;
      }
    });
  }
  void update() {
    {
      py::gil_scoped_release released;
      world_.update();
    }
    if (raised_) {
      const std::unique_ptr<py::error_already_set> error = std::move(raised_);
      throw *error;
    }
  }
  World& world() { return world_; }

 private:
  World world_;
  std::unique_ptr<py::error_already_set> raised_;
};

py::array_t<std::uint64_t> ids(const std::vector<BodyId>& bodies) {
  py::array_t<std::uint64_t> out(static_cast<py::ssize_t>(bodies.size()));
  for (std::size_t k = 0; k < bodies.size(); ++k) out.mutable_at(static_cast<py::ssize_t>(k)) = id_of(bodies[k]);
  return out;
}

// The keywords every query takes: the query's own filter, as Box2D v3's b2QueryFilter.
auto query_filter_args() {
  return std::make_tuple(py::kw_only(), py::arg("category") = std::uint64_t{1}, py::arg("mask") = ~std::uint64_t{0});
}

void add_world_hits(py::module_& m) {
  py::class_<RayHit>(m, "BodyRayHit", "What World.ray_cast() hits: the body, the distance along the ray, point and normal.")
      .def_property_readonly("body", [](const RayHit& h) { return id_of(h.body); })
      .def_readonly("distance", &RayHit::distance)
      .def_property_readonly("point", [](const RayHit& h) { return tuple(h.point); })
      .def_property_readonly("normal", [](const RayHit& h) { return tuple(h.normal); });
  py::class_<BodyCastHit>(m, "BodyCastHit",
                          "What World.cast() meets first: the body, the fraction of the translation, the point and\n"
                          "the body's outward normal there.")
      .def_property_readonly("body", [](const BodyCastHit& h) { return id_of(h.body); })
      .def_readonly("fraction", &BodyCastHit::fraction)
      .def_property_readonly("point", [](const BodyCastHit& h) { return tuple(h.point); })
      .def_property_readonly("normal", [](const BodyCastHit& h) { return tuple(h.normal); });
}

using Bodies = py::class_<PyWorld>;

void add_world_bodies(Bodies& c) {
  c.def(py::init([](double fat_margin, double proximity_margin, bool contacts, double speculative_margin,
                    unsigned threads) {
          return std::make_unique<PyWorld>(
              WorldOptions{fat_margin, proximity_margin, contacts, speculative_margin, threads});
        }),
        py::kw_only(), py::arg("fat_margin") = 0.0, py::arg("proximity_margin") = 0.0, py::arg("contacts") = false,
        py::arg("speculative_margin") = 0.0, py::arg("threads") = 0u,
        "fat_margin: how far a shape may move before the broad phase looks again; proximity_margin > 0:\n"
        "report pairs apart by less than it; contacts: a contact for every overlapping pair;\n"
        "speculative_margin: contacts also for pairs apart by less than it; threads: 0 for the\n"
        "hardware's count.");
  c.def(
      "add",
      [](PyWorld& w, const std::variant<Shape, std::vector<Shape>>& shapes, std::optional<Pair> center, double angle,
         std::uint64_t user_id, std::uint64_t category, std::uint64_t mask, std::int32_t group, bool is_static,
         bool sensor, bool continuous) {
        const std::optional<Pose> pose = center ? std::optional<Pose>(Pose{vec(*center), angle}) : std::nullopt;
        return w.add(shapes, pose,
                     {.user_id = user_id, .filter = {category, mask, group}, .is_static = is_static, .sensor = sensor},
                     continuous);
      },
      py::arg("shape"), py::kw_only(), py::arg("center") = py::none(), py::arg("angle") = 0.0,
      py::arg("user_id") = 0, py::arg("category") = 1, py::arg("mask") = ~std::uint64_t{0}, py::arg("group") = 0,
      py::arg("static") = false, py::arg("sensor") = false, py::arg("continuous") = false,
      "Adds a body and returns its id. One shape: the body's origin is the shape's centre and angle.\n"
      "A list of shapes: each placed in the body's frame, the body at center and angle. Two shapes pair\n"
      "when each one's category is in the other's mask, unless they share a group: positive, always;\n"
      "negative, never. A static body never pairs with a static one; a sensor reports in sensing();\n"
      "a continuous one sweeps from pose to pose and reports its first contact in impacts().");
  c.def(
      "move_to",
      [](PyWorld& w, std::uint64_t id, const Pair& center, double angle) {
        w.world().move_to(body_of(id), vec(center), angle);
      },
      py::arg("id"), py::arg("center"), py::arg("angle") = 0.0, "Moves a body (a continuous one sweeps there).");
  c.def("set_poses", &PyWorld::set_poses, py::arg("ids"), py::arg("centres"), py::arg("angles"),
        "move_to() for every row: ids (n,), centres (n, 2), angles (n,), in one call.");
  c.def(
      "remove", [](PyWorld& w, std::uint64_t id) { w.world().remove(body_of(id)); }, py::arg("id"),
      "Removes a body; its id goes stale (a later body may reuse the index, with a new generation).");
  c.def(
      "set_filter",
      [](PyWorld& w, std::uint64_t id, std::uint64_t category, std::uint64_t mask, std::int32_t group) {
        w.world().set_filter(body_of(id), Filter{category, mask, group});
      },
      py::arg("id"), py::arg("category") = 1, py::arg("mask") = ~std::uint64_t{0}, py::arg("group") = 0,
      "The filter of every shape of the body, from the next update.");
  c.def(
      "set_static", [](PyWorld& w, std::uint64_t id, bool on) { w.world().set_static(body_of(id), on); },
      py::arg("id"), py::arg("static") = true,
      "Makes a body level geometry (never pairs with a static body) or moving again.");
  c.def(
      "set_continuous", [](PyWorld& w, std::uint64_t id, bool on) { w.world().set_continuous(body_of(id), on); },
      py::arg("id"), py::arg("continuous") = true,
      "A continuous body sweeps from pose to pose and reports its first contact in the step in impacts().");
  c.def("update", &PyWorld::update,
        "Runs the broad and narrow phases (the GIL released; a Python pair predicate takes it).");
  c.def("set_pair_predicate", &PyWorld::set_pair_predicate, py::arg("predicate"),
        "predicate(a, b) -> bool for the candidate pairs that pass the filters, None for none; what it\n"
        "raises comes out of update().");
}

void add_world_reads(Bodies& c) {
  c.def("__len__", [](PyWorld& w) { return w.world().size(); });
  c.def(
      "__contains__", [](PyWorld& w, std::uint64_t id) { return w.world().contains(body_of(id)); }, py::arg("id"));
  c.def(
      "pose",
      [](PyWorld& w, std::uint64_t id) {
        const Pose p = w.world().pose(body_of(id));
        return py::make_tuple(tuple(p.position), p.angle);
      },
      py::arg("id"), "The body's origin and angle: ((x, y), angle).");
  c.def(
      "user_id", [](PyWorld& w, std::uint64_t id) { return w.world().user_id(body_of(id)); }, py::arg("id"),
      "The user id the body was added with.");
  c.def(
      "last_frame",
      [](PyWorld& w) {
        const FrameStats& f = w.world().last_frame();
        return py::dict(py::arg("candidates") = f.candidates, py::arg("filtered") = f.filtered,
                        py::arg("overlapping") = f.overlapping, py::arg("proximity") = f.proximity,
                        py::arg("contacts") = f.contacts, py::arg("impacts") = f.impacts,
                        py::arg("sensing") = f.sensing, py::arg("broad_seconds") = f.broad_seconds,
                        py::arg("narrow_seconds") = f.narrow_seconds);
      },
      "What the last update did: pair counts and the seconds of each phase.");
}

void add_world_pairs(Bodies& c) {
  c.def(
      "overlapping", [](PyWorld& w) { return body_pairs(w.world().body_overlapping()); },
      "The overlapping pairs of bodies, sorted: a (m, 2) uint64 array.");
  c.def(
      "began", [](PyWorld& w) { return body_pairs(w.world().body_began()); }, "Pairs that began at the update.");
  c.def(
      "ended", [](PyWorld& w) { return body_pairs(w.world().body_ended()); }, "Pairs that ended at the update.");
  const auto sensor_pairs = [](const std::vector<SensorPair>& pairs) {
    return id_pairs(
        pairs, [](const SensorPair& p) { return p.sensor; }, [](const SensorPair& p) { return p.visitor; });
  };
  c.def(
      "sensing", [=](PyWorld& w) { return sensor_pairs(w.world().sensing()); },
      "(sensor, visitor) pairs of bodies: a sensor and a solid body that overlaps it.");
  c.def(
      "sensor_began", [=](PyWorld& w) { return sensor_pairs(w.world().sensor_began()); },
      "(sensor, visitor) pairs that began at the update.");
  c.def(
      "sensor_ended", [=](PyWorld& w) { return sensor_pairs(w.world().sensor_ended()); },
      "(sensor, visitor) pairs that ended at the update.");
  c.def(
      "proximity",
      [](PyWorld& w) {
        const auto& r = w.world().proximity();
        return py::dict(py::arg("pairs") = body_pairs(r),
                        py::arg("distance") = column(r, 1, [](const Proximity& p, double* o) { o[0] = p.result.distance; }),
                        py::arg("point_a") = column(r, 2, [](const Proximity& p, double* o) { put(o, p.result.point_a); }),
                        py::arg("point_b") = column(r, 2, [](const Proximity& p, double* o) { put(o, p.result.point_b); }));
      },
      "Pairs apart by less than the proximity margin: pairs (m, 2), distance (m, 1), point_a, point_b.");
  c.def(
      "contacts",
      [](PyWorld& w) {
        const auto& r = w.world().contacts();
        return py::dict(
            py::arg("pairs") = body_pairs(r),
            py::arg("separation") = column(r, 1, [](const BodyContact& c, double* o) { o[0] = c.contact.separation; }),
            py::arg("normal") = column(r, 2, [](const BodyContact& c, double* o) { put(o, c.contact.normal); }),
            py::arg("point_a") = column(r, 2, [](const BodyContact& c, double* o) { put(o, c.contact.point_a); }),
            py::arg("point_b") = column(r, 2, [](const BodyContact& c, double* o) { put(o, c.contact.point_b); }));
      },
      "With contacts on: pairs (m, 2), separation (m, 1), normal, point_a, point_b (m, 2).");
  c.def(
      "impacts",
      [](PyWorld& w) {
        const auto& r = w.world().impacts();
        return py::dict(py::arg("pairs") = body_pairs(r),
                        py::arg("t") = column(r, 1, [](const Impact& i, double* o) { o[0] = i.t; }),
                        py::arg("point") = column(r, 2, [](const Impact& i, double* o) { put(o, i.point); }),
                        py::arg("normal") = column(r, 2, [](const Impact& i, double* o) { put(o, i.normal); }));
      },
      "Continuous bodies' first contacts in the step: pairs (m, 2), t (m, 1), point, normal (m, 2).");
}

// World.ray_cast() and ray_cast_all(), which take the same arguments.
template <class Cast>
void def_ray(Bodies& c, const char* name, Cast cast, const char* doc) {
  const auto [kw, category, mask] = query_filter_args();
  c.def(
      name,
      [cast](PyWorld& w, const Pair& origin, const Pair& direction, double max_distance, bool from_inside,
             std::uint64_t cat, std::uint64_t msk) {
        return cast(w.world(), vec(origin), vec(direction), max_distance, QueryFilter{cat, msk},
                    RayOptions{from_inside});
      },
      py::arg("origin"), py::arg("direction"), py::arg("max_distance") = std::numeric_limits<double>::infinity(), kw,
      py::arg("from_inside") = false, category, mask, doc);
}

void add_world_queries(Bodies& c) {
  const auto [kw, category, mask] = query_filter_args();
  c.def(
      "query",
      [](PyWorld& w, const Shape& shape, std::uint64_t cat, std::uint64_t msk) {
        return ids(w.world().overlapping(shape, {cat, msk}));
      },
      py::arg("shape"), kw, category, mask,
      "The bodies with a solid shape that overlaps the shape (and that the query's category and mask\n"
      "let through), as sorted uint64 ids. No update needed.");
  c.def(
      "query_box",
      [](PyWorld& w, const Pair& lower, const Pair& upper, std::uint64_t cat, std::uint64_t msk) {
        return ids(w.world().overlapping(Aabb{vec(lower), vec(upper)}, {cat, msk}));
      },
      py::arg("lower"), py::arg("upper"), kw, category, mask, "The bodies with a solid shape that meets the box.");
  c.def(
      "within",
      [](PyWorld& w, const std::variant<Pair, Shape>& from, double distance, std::uint64_t cat, std::uint64_t msk) {
        return ids(std::visit(
            [&](const auto& f) {
              if constexpr (std::is_same_v<std::decay_t<decltype(f)>, Pair>) {
                return w.world().within(vec(f), distance, {cat, msk});
              } else {
                return w.world().within(f, distance, {cat, msk});
              }
            },
            from));
      },
      py::arg("point_or_shape"), py::arg("distance"), kw, category, mask,
      "The bodies with a solid shape within distance (>= 0) of a point or a shape.");
  const auto ray = [](const World& world, const auto&... args) { return world.ray_cast(args...); };
  def_ray(c, "ray_cast", ray,
          "The first shape the ray from origin along direction meets within max_distance, or None (the\n"
          "lowest body on a tie). A shape that holds the origin is skipped unless from_inside.");
  const auto every = [](const World& world, const auto&... args) { return world.ray_cast_all(args...); };
  def_ray(c, "ray_cast_all", every, "Every shape the ray meets within max_distance, nearest first.");
  c.def(
      "cast",
      [](PyWorld& w, const Shape& shape, const Pair& translation, bool skip_initial_overlap, std::uint64_t cat,
         std::uint64_t msk) {
        return w.world().cast(shape, vec(translation), {cat, msk}, {skip_initial_overlap});
      },
      py::arg("shape"), py::arg("translation"), kw, py::arg("skip_initial_overlap") = false, category, mask,
      "The first shape the shape meets when moved by translation, or None; one it overlaps at the\n"
      "start is met at fraction 0 unless skip_initial_overlap.");
}

void add_world(py::module_& m) {
  add_world_hits(m);
  Bodies c(m, "World",
           "Bodies that move every frame, and their pairs frame by frame (the C++ World, docs/world.md).\n"
           "Body ids are uint64: generation << 32 | index. Move bodies, call update(), then read the\n"
           "pairs, events, contacts and impacts of that update as NumPy arrays (copies).");
  add_world_bodies(c);
  add_world_reads(c);
  add_world_pairs(c);
  add_world_queries(c);
}

}  // namespace
}  // namespace collide2d

PYBIND11_MODULE(collide2d, m) {
  m.doc() = "collide2d: exact 2D collision detection between circles, ellipses, rectangles, capsules,\n"
            "convex polygons and segments (docs/python.md).";
  // InvalidShape is a std::invalid_argument, which pybind11 raises as ValueError; so is a pair a query
  // does not take.
  py::register_exception<collide2d::UnsupportedPair>(m, "UnsupportedPair", PyExc_ValueError);
  collide2d::add_shapes(m);
  collide2d::add_results(m);
  collide2d::add_queries(m);
  collide2d::add_arrays(m);
  collide2d::add_world(m);
  m.attr("__version__") = COLLIDE2D_VERSION_STRING;
}
