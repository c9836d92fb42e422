// The shapes as immutable value classes, checked as the C++ shapes are (a bad one raises ValueError
// naming the field), and the results the queries return.
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

template <class S>
S checked(S shape) {
  validate(shape);
  return shape;
}

}  // namespace

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
  py::class_<OverlapArea>(m, "OverlapArea",
                          "area of A & B, its centroid, the boundaries' crossings and, with two, the chord\n"
                          "from where A's boundary enters B to where it leaves.")
      .def_readonly("area", &OverlapArea::area)
      .def_property_readonly("centroid", [](const OverlapArea& o) { return tuple(o.centroid); })
      .def_readonly("crossings", &OverlapArea::crossings)
      .def_property_readonly("chord",
                             [](const OverlapArea& o) { return py::make_tuple(tuple(o.chord[0]), tuple(o.chord[1])); });
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

}  // namespace collide2d::python
