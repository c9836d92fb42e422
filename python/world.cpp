// The World: bodies moved from Python or from arrays, updated with the GIL released, and its pairs,
// events, contacts and impacts as NumPy arrays.
#include "python/module.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

namespace collide2d::python {

namespace {

using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

// An array's shape as NumPy writes it: "(3,)", "(3, 2)".
std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) text += (d > 0 ? ", " : "") + std::to_string(a.shape(d));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

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
  return id_pairs(
      records, [](const auto& r) { return r.a; }, [](const auto& r) { return r.b; });
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
  // Every row is checked before any body moves, so that a refusal leaves the World as it was.
  void set_poses(const py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>& ids, const Rows& centres,
                 const Rows& angles) {
    if (ids.ndim() != 1) throw py::value_error("set_poses: ids must be an (n,) array, got shape " + shape_text(ids));
    const py::ssize_t n = ids.shape(0);
    const std::string for_ids = " array for the n = " + std::to_string(n) + " ids, got shape ";
    if (centres.ndim() != 2 || centres.shape(0) != n || centres.shape(1) != 2) {
      throw py::value_error("set_poses: centres must be an (n, 2)" + for_ids + shape_text(centres));
    }
    if (angles.ndim() != 1 || angles.shape(0) != n) {
      throw py::value_error("set_poses: angles must be an (n,)" + for_ids + shape_text(angles));
    }
    const auto id = ids.unchecked<1>();
    const auto centre = centres.unchecked<2>();
    const auto angle = angles.unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) {
      try {
        (void)world_.pose(body_of(id(i)));
        validate_point({centre(i, 0), centre(i, 1)}, "centre");
        if (!std::isfinite(angle(i)))
          throw std::invalid_argument("angle " + std::to_string(angle(i)) + " must be finite");
      } catch (const std::exception& e) {
        throw py::value_error("set_poses row " + std::to_string(i) + ": " + e.what());
      }
    }
    for (py::ssize_t i = 0; i < n; ++i) world_.move_to(body_of(id(i)), {centre(i, 0), centre(i, 1)}, angle(i));
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
  py::class_<RayHit>(m, "BodyRayHit",
                     "What World.ray_cast() hits: the body, the distance along the ray, point and normal.")
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
  py::class_<MoverPlane>(m, "MoverPlane",
                         "A surface a mover touches (World.collide_mover()): the body, its user id, the surface's\n"
                         "nearest point (deepest, overlapping), the normal towards the mover, the separation.")
      .def_property_readonly("body", [](const MoverPlane& p) { return id_of(p.body); })
      .def_readonly("user_id", &MoverPlane::user_id)
      .def_property_readonly("point", [](const MoverPlane& p) { return tuple(p.point); })
      .def_property_readonly("normal", [](const MoverPlane& p) { return tuple(p.normal); })
      .def_readonly("separation", &MoverPlane::separation);
  py::class_<Ground>(m, "Ground",
                     "Where a mover stands (MoveResult.ground): on_ground, the floor's normal, body and user id.")
      .def(py::init<>())
      .def_readonly("on_ground", &Ground::on_ground)
      .def_property_readonly("normal", [](const Ground& g) { return tuple(g.normal); })
      .def_property_readonly("body", [](const Ground& g) { return id_of(g.body); })
      .def_readonly("user_id", &Ground::user_id);
  py::class_<MoveResult>(m, "MoveResult",
                         "What World.move() did: the mover's new centre, its clipped velocity, its ground, the\n"
                         "iterations of collide, solve and cast, and whether its last cast stopped at a surface.")
      .def_property_readonly("position", [](const MoveResult& r) { return tuple(r.position); })
      .def_property_readonly("velocity", [](const MoveResult& r) { return tuple(r.velocity); })
      .def_readonly("ground", &MoveResult::ground)
      .def_readonly("iterations", &MoveResult::iterations)
      .def_readonly("blocked", &MoveResult::blocked);
}

using Bodies = py::class_<PyWorld>;

void add_world_bodies(Bodies& c) {
  c.def(py::init(
            [](double fat_margin, double proximity_margin, bool contacts, double speculative_margin, unsigned threads,
               double contact_tolerance, bool overlap_areas) {
              return std::make_unique<PyWorld>(WorldOptions{
                  fat_margin, proximity_margin, contacts, speculative_margin, threads, contact_tolerance, overlap_areas});
            }),
        py::kw_only(), py::arg("fat_margin") = 0.0, py::arg("proximity_margin") = 0.0, py::arg("contacts") = false,
        py::arg("speculative_margin") = 0.0, py::arg("threads") = 0u, py::arg("contact_tolerance") = 0.0,
        py::arg("overlap_areas") = false,
        "fat_margin: how far a shape may move before the broad phase looks again; proximity_margin > 0:\n"
        "report pairs apart by less than it; contacts: a contact for every overlapping pair;\n"
        "speculative_margin: contacts also for pairs apart by less than it; threads: 0 for the\n"
        "hardware's count; contact_tolerance: how far a contact with an ellipse may be off (0: exact);\n"
        "overlap_areas: the overlap's area and centroid with each touching contact and each sensor visit.");
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
      py::arg("shape"), py::kw_only(), py::arg("center") = py::none(), py::arg("angle") = 0.0, py::arg("user_id") = 0,
      py::arg("category") = 1, py::arg("mask") = ~std::uint64_t{0}, py::arg("group") = 0, py::arg("static") = false,
      py::arg("sensor") = false, py::arg("continuous") = false,
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
      "set_static", [](PyWorld& w, std::uint64_t id, bool on) { w.world().set_static(body_of(id), on); }, py::arg("id"),
      py::arg("static") = true, "Makes a body level geometry (never pairs with a static body) or moving again.");
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
  c.def(
      "state_hash", [](PyWorld& w) { return w.world().state_hash(); },
      "A 64-bit digest of the bodies and the last update's results, the same on every machine (docs/world.md).");
}

void add_world_pairs(Bodies& c) {
  c.def(
      "overlapping", [](PyWorld& w) { return body_pairs(w.world().body_overlapping()); },
      "The overlapping pairs of bodies, sorted: a (m, 2) uint64 array.");
  c.def(
      "began", [](PyWorld& w) { return body_pairs(w.world().body_began()); }, "Pairs that began at the update.");
  c.def(
      "ended", [](PyWorld& w) { return body_pairs(w.world().body_ended()); }, "Pairs that ended at the update.");
  const auto visits = [](const std::vector<SensorVisit>& pairs) {
    return id_pairs(
        pairs, [](const SensorVisit& p) { return p.sensor; }, [](const SensorVisit& p) { return p.visitor; });
  };
  c.def(
      "sensing", [=](PyWorld& w) { return visits(w.world().body_sensing()); },
      "(sensor, visitor) pairs of bodies: a sensor and a body with a solid shape inside it, a row per sensor shape.");
  c.def(
      "sensing_areas",
      [=](PyWorld& w) {
        const auto& r = w.world().body_sensing();
        return py::dict(py::arg("pairs") = visits(r),
                        py::arg("area") = column(r, 1, [](const SensorVisit& v, double* o) { o[0] = v.area; }),
                        py::arg("centroid") = column(r, 2, [](const SensorVisit& v, double* o) { put(o, v.centroid); }));
      },
      "With overlap_areas on, the rows of sensing() with how much of each visitor lies inside the sensor\n"
      "shape: pairs (m, 2), area (m, 1), centroid (m, 2) (its shapes' overlaps summed).");
  c.def(
      "sensor_began", [=](PyWorld& w) { return visits(w.world().body_sensor_began()); },
      "(sensor, visitor) pairs that began at the update: the visitor's first shape entered.");
  c.def(
      "sensor_ended", [=](PyWorld& w) { return visits(w.world().body_sensor_ended()); },
      "(sensor, visitor) pairs that ended at the update: the visitor's last shape left.");
  c.def(
      "proximity",
      [](PyWorld& w) {
        const auto& r = w.world().proximity();
        return py::dict(
            py::arg("pairs") = body_pairs(r),
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
            py::arg("point_b") = column(r, 2, [](const BodyContact& c, double* o) { put(o, c.contact.point_b); }),
            py::arg("area") = column(r, 1, [](const BodyContact& c, double* o) { o[0] = c.overlap.area; }),
            py::arg("centroid") = column(r, 2, [](const BodyContact& c, double* o) { put(o, c.overlap.centroid); }));
      },
      "With contacts on: pairs (m, 2), separation (m, 1), normal, point_a, point_b (m, 2); with\n"
      "overlap_areas on also each touching pair's overlap: area (m, 1), centroid (m, 2) (zero otherwise).");
  c.def(
      "contacts_of",
      [](PyWorld& w, std::uint64_t body) {
        const BodyId id = body_of(body);
        const std::span<const std::uint32_t> found = w.world().contacts_of(id);
        const auto& all = w.world().contacts();
        py::array_t<std::int64_t> index(static_cast<py::ssize_t>(found.size()));
        py::array_t<std::uint64_t> other(static_cast<py::ssize_t>(found.size()));
        py::array_t<double> normal({static_cast<py::ssize_t>(found.size()), py::ssize_t{2}});
        for (std::size_t k = 0; k < found.size(); ++k) {
          const BodyContact& c = all[found[k]];
          index.mutable_data()[k] = found[k];
          other.mutable_data()[k] = id_of(c.a == id ? c.b : c.a);
          put(normal.mutable_data() + 2 * k, normal_from(c, id));
        }
        return py::dict(py::arg("index") = index, py::arg("other") = other, py::arg("normal") = normal);
      },
      py::arg("body"),
      "With contacts on: the body's contacts, found without a scan: index (k,), their rows of contacts();\n"
      "other (k,), the other bodies; normal (k, 2), pointing away from this body.");
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

// The mover's query from Python's keywords: the skin, the filter and the mover's own body.
MoverQuery mover_query(double skin, std::optional<std::uint64_t> own_body, std::uint64_t cat, std::uint64_t msk) {
  return {skin, {cat, msk}, own_body ? std::optional<BodyId>(body_of(*own_body)) : std::nullopt};
}

void add_world_movers(Bodies& c) {
  const auto [kw, category, mask] = query_filter_args();
  const auto skin = py::arg("skin") = 0.01;
  const auto own_body = py::arg("own_body") = py::none();
  c.def(
      "add_chain",
      [](PyWorld& w, const std::vector<Pair>& points, bool loop, std::uint64_t user_id, std::uint64_t cat,
         std::uint64_t msk, std::int32_t group) {
        std::vector<Vec2> at;
        for (const Pair& p : points) at.push_back(vec(p));
        return id_of(w.world().add_chain(at, loop, {user_id, {cat, msk, group}}));
      },
      py::arg("points"), kw, py::arg("loop") = false, py::arg("user_id") = 0, py::arg("category") = 1,
      py::arg("mask") = ~std::uint64_t{0}, py::arg("group") = 0,
      "Adds a chain, a static body of one-sided segments (collide2d.h's chain.h): a loop closes on its\n"
      "first point; an open chain takes its first and last points as ghosts only. Returns its id.");
  c.def(
      "cast_mover",
      [](PyWorld& w, const Shape& shape, const Pair& translation, double skin, std::optional<std::uint64_t> own,
         std::uint64_t cat, std::uint64_t msk) {
        return w.world().cast_mover(shape, vec(translation), mover_query(skin, own, cat, msk));
      },
      py::arg("shape"), py::arg("translation"), kw, skin, own_body, category, mask,
      "The fraction of translation the mover can move before it comes nearer a surface than the\n"
      "smaller of the skin and its starting separation (docs/movers.md).");
  c.def(
      "collide_mover",
      [](PyWorld& w, const Shape& shape, double skin, std::optional<std::uint64_t> own, std::uint64_t cat,
         std::uint64_t msk) { return w.world().collide_mover(shape, mover_query(skin, own, cat, msk)); },
      py::arg("shape"), kw, skin, own_body, category, mask,
      "The surfaces within the skin of the mover or overlapping it, as MoverPlanes, by body.");
  c.def(
      "displacement",
      [](PyWorld& w, std::uint64_t id, const Pair& point) {
        return tuple(w.world().displacement(body_of(id), vec(point)));
      },
      py::arg("id"), py::arg("point"), "How far the body's motion over the last update carried the point.");
  c.def(
      "move",
      [](PyWorld& w, const Shape& shape, const Pair& velocity, double dt, const Ground& ground, double skin,
         std::optional<std::uint64_t> own, std::uint64_t cat, std::uint64_t msk, double max_slope, double step_height,
         double snap_distance, const Pair& up, int max_iterations, std::uint64_t soft_categories,
         double soft_push_limit) {
        const MoverOptions options{mover_query(skin, own, cat, msk), max_slope,       step_height,    snap_distance,
                                   vec(up),                          max_iterations, soft_categories, soft_push_limit};
        return move(w.world(), shape, vec(velocity), dt, options, ground);
      },
      py::arg("shape"), py::arg("velocity"), py::arg("dt"), py::arg("ground") = Ground{}, kw, skin, own_body,
      category, mask, py::arg("max_slope") = MoverOptions{}.max_slope, py::arg("step_height") = 0.0,
      py::arg("snap_distance") = 0.0, py::arg("up") = Pair{0.0, 1.0}, py::arg("max_iterations") = 5,
      py::arg("soft_categories") = 0, py::arg("soft_push_limit") = 0.0,
      "Moves a character by velocity * dt as move() in C++ does (docs/movers.md) and returns a\n"
      "MoveResult; ground is the last move's, so that it rides a body that moved.");
}

}  // namespace

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
  add_world_movers(c);
}

}  // namespace collide2d::python
