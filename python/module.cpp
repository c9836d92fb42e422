// The Python module `collide2d` (docs/python.md): the shapes as immutable value classes, checked as
// the C++ shapes are, the pair queries and their array forms, and the World, each one call into the
// library, so that the results are the C++ results bit for bit. Points and vectors go in as any pair
// of numbers and come out as tuples.
#include "python/module.h"

PYBIND11_MODULE(collide2d, m) {
  m.doc() = "collide2d: exact 2D collision detection between circles, ellipses, rectangles, capsules,\n"
            "convex polygons and segments (docs/python.md).";
  // InvalidShape is a std::invalid_argument, which pybind11 raises as ValueError; so is a pair a query
  // does not take.
  pybind11::register_exception<collide2d::UnsupportedPair>(m, "UnsupportedPair", PyExc_ValueError);
  collide2d::python::add_shapes(m);
  collide2d::python::add_results(m);
  collide2d::python::add_queries(m);
  collide2d::python::add_arrays(m);
  collide2d::python::add_world(m);
  m.attr("__version__") = COLLIDE2D_VERSION_STRING;
}

