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
}

}  // namespace collide2d::python
