// Private to the Python module (docs/python.md): what its parts share. Each part adds its own names
// to the module: the shapes and results (shapes.cpp), the pair queries (queries.cpp), their array
// forms (arrays.cpp) and the World (world.cpp); module.cpp makes the module of them.
#pragma once

#include <collide2d/collide2d.h>

#include <pybind11/pybind11.h>

#include <array>
#include <string>

namespace collide2d::python {

namespace py = pybind11;

// A point or vector as Python gives it: any pair of numbers.
using Pair = std::array<double, 2>;

inline Vec2 vec(const Pair& p) { return {p[0], p[1]}; }
inline py::tuple tuple(const Vec2& v) { return py::make_tuple(v.x(), v.y()); }

// A number and a point as Python writes them, for the shapes' repr.
inline std::string number(double x) { return py::repr(py::float_(x)).cast<std::string>(); }
// Appended piece by piece: GCC 12 warns falsely of an overlapping copy in "(" + std::string&&
// (its bug 105329).
inline std::string point(const Vec2& v) {
  std::string out = "(";
  out += number(v.x());
  out += ", ";
  out += number(v.y());
  out += ")";
  return out;
}

void add_shapes(py::module_& m);
void add_results(py::module_& m);
void add_queries(py::module_& m);
void add_arrays(py::module_& m);
void add_world(py::module_& m);

}  // namespace collide2d::python
