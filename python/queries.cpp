// The pair queries, each one call into the library, so that the results are the C++ results bit for
// bit.
#include "python/module.h"

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

namespace collide2d::python {

namespace {

// The planes of a Python list, and each plane's push written back into its object.
std::vector<CollisionPlane> planes_of(const py::list& planes) {
  std::vector<CollisionPlane> out;
  for (const py::handle p : planes) out.push_back(p.cast<CollisionPlane>());
  return out;
}

void add_planes(py::module_& m) {
  py::class_<CollisionPlane>(m, "CollisionPlane",
                             "A surface a mover touches as a plane: a translation d respects it where\n"
                             "normal . d >= offset; push_limit for soft surfaces; push written by solve_planes().")
      .def(py::init([](const Pair& normal, double offset, double push_limit, bool clip_velocity) {
             return CollisionPlane{vec(normal), offset, push_limit, clip_velocity};
           }),
           py::arg("normal"), py::arg("offset") = 0.0, py::arg("push_limit") = std::numeric_limits<double>::infinity(),
           py::arg("clip_velocity") = true)
      .def_property_readonly("normal", [](const CollisionPlane& p) { return tuple(p.normal); })
      .def_readonly("offset", &CollisionPlane::offset)
      .def_readonly("push_limit", &CollisionPlane::push_limit)
      .def_readonly("clip_velocity", &CollisionPlane::clip_velocity)
      .def_readonly("push", &CollisionPlane::push);
  m.def(
      "solve_planes",
      [](const Pair& target, const py::list& planes) {
        std::vector<CollisionPlane> solved = planes_of(planes);
        const PlaneSolution s = solve_planes(vec(target), solved);
        for (std::size_t i = 0; i < solved.size(); ++i) planes[i].cast<CollisionPlane&>().push = solved[i].push;
        return tuple(s.delta);
      },
      py::arg("target_delta"), py::arg("planes"),
      "The translation nearest target_delta that the planes allow; each plane's push is written.");
  m.def(
      "clip_vector", [](const Pair& v, const py::list& planes) { return tuple(clip_vector(vec(v), planes_of(planes))); },
      py::arg("v"), py::arg("planes"),
      "The velocity with its components into the planes that pushed and clip velocity removed.");
}

}  // namespace

void add_queries(py::module_& m) {
  m.def("overlaps", py::overload_cast<const Shape&, const Shape&>(&overlaps), py::arg("a"), py::arg("b"),
        "Whether the solids overlap (touching counts).");
  m.def("distance", py::overload_cast<const Shape&, const Shape&>(&distance), py::arg("a"), py::arg("b"),
        "The distance between the solids and their closest points.");
  m.def("boundary_distance", &boundary_distance, py::arg("a"), py::arg("b"),
        "The distance between the boundary curves of two circles or ellipses (nested ones give their gap).");
  m.def(
      "contact",
      [](const Shape& a, const Shape& b, double max_separation, double margin, double tolerance) {
        return contact(a, b,
                       ContactOptions{.margin = margin, .max_separation = max_separation, .tolerance = tolerance});
      },
      py::arg("a"), py::arg("b"), py::arg("max_separation") = std::numeric_limits<double>::infinity(),
      py::arg("margin") = 0.0, py::arg("tolerance") = 0.0,
      "The signed distance, normal from A to B, deepest points and manifold; within `tolerance` of\n"
      "the exact ones for a pair with an ellipse.");
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
  m.def("area", &area, py::arg("shape"), "The area of the solid (a segment has none).");
  m.def("overlap_area", &overlap_area, py::arg("a"), py::arg("b"),
        "The area and centroid of the solids' overlap, exactly (0 where they are apart or touch).");
  m.def("iou", &iou, py::arg("a"), py::arg("b"), "Intersection over union, |A & B| / |A | B|.");
  m.def("iou_distance", &iou_distance, py::arg("a"), py::arg("b"),
        "|A ^ B| / |A | B|, which is 1 - IoU, keeping its own digits however near identical the shapes are.");
  m.def("iof", &iof, py::arg("a"), py::arg("b"), "Intersection over the first, |A & B| / |A|.");
  add_planes(m);
}

}  // namespace collide2d::python
