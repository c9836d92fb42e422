#include "examples/settle/settle.h"

#include <collide2d/area.h>
#include <collide2d/world.h>
#include "tools/random.h"
#include "tools/scene/svg_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>
#include <random>
#include <sstream>
#include <tuple>
#include <type_traits>
#include <utility>

namespace collide2d::settle {
namespace {

constexpr double kGravity = 9.81;
constexpr double kDamping = 0.3;   // each contact's dashpot, as a fraction of critical damping
constexpr double kFriction = 0.5;  // Coulomb coefficient
constexpr double kWall = 1.0;      // wall thickness
constexpr double kLargest = 0.4;   // the largest half-extent of a body
constexpr double kDrag = 1.0;      // a light drag on every body (per second), which hastens the rest
constexpr double kCell = 2 * kLargest + 0.05;

// A body's motion; its shape and pose live in the World.
struct Body {
  Vec2 velocity = Vec2::Zero();
  double spin = 0.0;
  double mass = 0.0;  // 0: a wall, which never moves
  double inertia = 0.0;
  BodyId id{};
};

// The tangential spring of one contact point, kept from step to step while the same features of
// the same pair touch (the World's contacts are sorted by pair, and a rectangle manifold's points
// carry feature ids): what gives the pile static friction, so that it rests instead of creeping.
struct Spring {
  std::uint32_t a;
  std::uint32_t b;
  std::uint32_t id;
  Vec2 stretch;
  auto key() const { return std::tie(a, b, id); }
};

// The moment of inertia of the uniform solid about its centre, per unit mass.
double inertia_per_mass(const Shape& s) {
  if (const auto* c = std::get_if<Circle>(&s)) return c->radius * c->radius / 2;
  if (const auto* e = std::get_if<Ellipse>(&s)) return (e->a * e->a + e->b * e->b) / 4;
  const Vec2& h = std::get<Rect>(s).half_extents;
  return (h.x() * h.x() + h.y() * h.y()) / 3;
}

double smallest_half_size(const Shape& s) {
  if (const auto* c = std::get_if<Circle>(&s)) return c->radius;
  if (const auto* e = std::get_if<Ellipse>(&s)) return std::min(e->a, e->b);
  return std::get<Rect>(s).half_extents.minCoeff();
}

Shape random_shape(std::mt19937_64& rng, int kind, const Vec2& center) {
  const auto uniform = [&rng](double lo, double hi) { return tool::uniform(rng, lo, hi); };
  const double size = uniform(kLargest / 2, kLargest), aspect = uniform(1.0, 2.0),
               angle = uniform(0.0, 2 * std::numbers::pi);
  switch (kind % 3) {
    case 0:
      return Circle{center, size};
    case 1:
      return Ellipse{center, size, size / aspect, angle};
    default:
      return Rect{center, Vec2(size, size / aspect), angle};
  }
}

// The pile's weight on its bottom contacts, about that of a column as tall as the pile packed solid
// and two of the widest bodies wide, presses them 0.2% of the smallest half-size deep: five times
// below the 1% the example promises.
double stiffness_for(double total_area, double width, double smallest) {
  const double load = kGravity * (total_area / width) * 2 * kLargest;
  return load / (0.002 * smallest);
}

Vec2 cross(double w, const Vec2& r) { return {-w * r.y(), w * r.x()}; }
double cross(const Vec2& r, const Vec2& f) { return r.x() * f.y() - r.y() * f.x(); }

class Pile {
 public:
  Pile(const SettleOptions& options) : world_({.fat_margin = 0.02, .contacts = true}), width_(options.width) {
    std::mt19937_64 rng(options.seed);
    const int columns = std::max(1, static_cast<int>(width_ / kCell));
    double total_area = 0.0;
    smallest_ = kLargest;
    for (int k = 0; k < options.bodies; ++k) {
      const Vec2 cell(kCell * (k % columns + 0.5), kCell * (k / columns + 0.5));
      const Vec2 jitter(tool::uniform(rng, -0.02, 0.02), 0.0);
      const Shape shape = random_shape(rng, k, Vec2(cell + jitter));
      Body& b = bodies_.emplace_back();
      b.mass = area(shape);  // its mass at density 1
      b.inertia = b.mass * inertia_per_mass(shape);
      BodyDef def;
      def.user_id = bodies_.size() - 1;
      b.id = world_.add(shape, def);
      total_area += b.mass;
      smallest_ = std::min(smallest_, smallest_half_size(shape));
    }
    height_ = kCell * (options.bodies / columns + 2);
    for (const Rect& wall : {Rect{Vec2(width_ / 2, -kWall / 2), Vec2(width_ / 2 + kWall, kWall / 2), 0.0},
                             Rect{Vec2(-kWall / 2, height_ / 2), Vec2(kWall / 2, height_ / 2), 0.0},
                             Rect{Vec2(width_ + kWall / 2, height_ / 2), Vec2(kWall / 2, height_ / 2), 0.0}}) {
      BodyDef def;  // walls never move: static bodies, never paired with each other
      def.user_id = bodies_.size();
      def.is_static = true;
      bodies_.emplace_back().id = world_.add(wall, def);
    }
    stiffness_ = stiffness_for(total_area, width_, smallest_);
    // 0.15 sqrt(m / k) for the lightest body: a body pressed by several contacts, their lever arms
    // turning it, vibrates several times faster than one contact alone (at twelve steps to a
    // contact's period, a wedged box's rocking grew until it moved at 0.36 rad/s).
    double lightest = bodies_.front().mass;
    for (const Body& b : bodies_) {
      if (b.mass > 0) lightest = std::min(lightest, b.mass);
    }
    step_ = 0.15 * std::sqrt(lightest / stiffness_);
  }

  double step() const { return step_; }
  double width() const { return width_; }
  double smallest() const { return smallest_; }

  // One step: contacts from the World at the current poses, forces, then velocities and poses.
  // Returns the deepest penetration among the contacts.
  double advance() {
    world_.update();
    forces_.assign(bodies_.size(), Vec2::Zero());
    torques_.assign(bodies_.size(), 0.0);
    for (std::size_t i = 0; i < bodies_.size(); ++i) forces_[i] = Vec2(0, -kGravity * bodies_[i].mass);
    double deepest = 0.0;
    springs_.swap(previous_);
    springs_.clear();
    for (const BodyContact& c : world_.contacts()) {
      const std::size_t i = world_.user_id(c.a), j = world_.user_id(c.b);
      if (bodies_[i].mass == 0 && bodies_[j].mass == 0) continue;  // wall on wall
      deepest = std::max(deepest, -c.contact.separation);
      for (const ContactPoint& p : c.contact.points()) {
        if (p.separation < 0) push({c.a.index, c.b.index, p.id, Vec2::Zero()}, i, j, c.contact.normal, p);
      }
    }
    // By pair the contacts come sorted; within a rectangle pair the points come deepest first.
    std::sort(springs_.begin(), springs_.end(), [](const Spring& x, const Spring& y) { return x.key() < y.key(); });
    const double drag = 1.0 / (1.0 + kDrag * step_);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      Body& b = bodies_[i];
      if (b.mass == 0) continue;
      b.velocity = drag * (b.velocity + forces_[i] / b.mass * step_);
      b.spin = drag * (b.spin + torques_[i] / b.inertia * step_);
      world_.move_by(b.id, b.velocity * step_, b.spin * step_);
    }
    return deepest;
  }

  // The fastest point speed of any body: |v| + |w| times its reach.
  double max_speed() const {
    double fastest = 0.0;
    for (const Body& b : bodies_) fastest = std::max(fastest, b.velocity.norm() + std::abs(b.spin) * kLargest * 1.5);
    return fastest;
  }

  SettleResult result() const {
    SettleResult r;
    r.width = width_;
    r.smallest = smallest_;
    for (const Body& b : bodies_) (b.mass > 0 ? r.shapes : r.walls).push_back(world_.shape(b.id));
    const double tolerance = 0.01 * smallest_;
    for (const Shape& s : r.shapes) {
      const Aabb box = aabb(s);
      r.outside += box.min.x() < -tolerance || box.max.x() > width_ + tolerance || box.min.y() < -tolerance;
    }
    return r;
  }

 private:
  // The spring-dashpot normal force of one overlapping contact point, and a tangential
  // spring-dashpot (two sevenths as stiff) whose stretch is kept while the point lasts, capped by
  // Coulomb's law: on b along the normal, on a against it. Each point has the full spring: sharing
  // it among a rectangle manifold's points made a rocking box's stiffness jump as a corner lifted
  // and landed, which pumped the rocking instead of damping it.
  void push(Spring spring, std::size_t i, std::size_t j, const Vec2& normal, const ContactPoint& p) {
    const Body& a = bodies_[i];
    const Body& b = bodies_[j];
    const Vec2 at = 0.5 * (p.point_a + p.point_b);
    const Vec2 ra = at - center_of(world_.shape(a.id)), rb = at - center_of(world_.shape(b.id));
    const Vec2 relative = b.velocity + cross(b.spin, rb) - a.velocity - cross(a.spin, ra);
    const double approach = relative.dot(normal);
    const double mass = a.mass == 0 ? b.mass : b.mass == 0 ? a.mass : a.mass * b.mass / (a.mass + b.mass);
    const double k = stiffness_, kt = 2.0 / 7.0 * k;
    const double damping = 2 * kDamping * std::sqrt(k * mass), damping_t = 2 * kDamping * std::sqrt(kt * mass);
    const double push = std::max(0.0, -k * p.separation - damping * approach);
    const Vec2 slide = relative - approach * normal;
    const auto kept = std::lower_bound(previous_.begin(), previous_.end(), spring,
                                       [](const Spring& x, const Spring& y) { return x.key() < y.key(); });
    if (kept != previous_.end() && kept->key() == spring.key())
      spring.stretch = kept->stretch - kept->stretch.dot(normal) * normal;
    spring.stretch += slide * step_;
    Vec2 friction = -kt * spring.stretch - damping_t * slide;
    const double limit = kFriction * push;
    if (friction.norm() > limit) {  // sliding: the spring holds what Coulomb allows
      friction *= limit / friction.norm();
      spring.stretch = -(friction + damping_t * slide) / kt;
    }
    springs_.push_back(spring);
    const Vec2 force = push * normal + friction;
    forces_[j] += force;
    forces_[i] -= force;
    torques_[j] += cross(rb, force);
    torques_[i] -= cross(ra, force);
  }

  World world_;
  std::vector<Body> bodies_;
  std::vector<Vec2> forces_;
  std::vector<double> torques_;
  std::vector<Spring> springs_;  // this step's, sorted by pair and feature
  std::vector<Spring> previous_;
  double width_;
  double height_ = 0.0;
  double smallest_ = 0.0;
  double stiffness_ = 0.0;
  double step_ = 0.0;
};

}  // namespace

SettleResult settle(const SettleOptions& options, std::ostream* progress) {
  Pile pile(options);
  double t = 0.0, rest = 0.0, deepest = 0.0, next_report = 1.0;
  int steps = 0;
  while (t < options.max_seconds && rest < options.rest_seconds) {
    deepest = pile.advance();
    t += pile.step();
    ++steps;
    rest = pile.max_speed() < options.rest_speed ? rest + pile.step() : 0.0;
    if (progress && t >= next_report) {
      *progress << "  t = " << t << " s: fastest " << pile.max_speed() << ", deepest contact " << deepest << '\n';
      next_report += 1.0;
    }
  }
  SettleResult r = pile.result();
  r.seconds = t;
  r.steps = steps;
  r.at_rest = rest >= options.rest_seconds;
  r.max_speed = pile.max_speed();
  r.max_penetration = pile.advance();  // the contacts where the bodies came to rest
  return r;
}

// Strokes in the pile's units, not non-scaling pixels: renderers without vector-effect (rsvg) drew
// them half a unit wide, wider than the bodies. The caption fits the width at 0.6 em a character.
void write_settle_svg(const SettleResult& r, std::ostream& out) {
  double top = kWall;
  for (const Shape& s : r.shapes) top = std::max(top, aabb(s).max.y());
  top += kWall;
  std::ostringstream caption;
  caption << r.shapes.size() << " bodies at rest after " << r.seconds << " s (" << r.steps
          << " steps); deepest contact " << r.max_penetration / r.smallest * 100 << "% of the smallest half-size";
  const double left = -kWall, right = r.width + kWall, bottom = -kWall;
  const double w = right - left,
               font = std::min(0.98 * w / (0.6 * static_cast<double>(caption.str().size())), 0.025 * w);
  const double h = top - bottom + 2 * font;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << left << ' ' << -top << ' ' << w << ' ' << h
      << "\" width=\"1000\" height=\"" << static_cast<int>(1000 * h / w) << "\">\n"
      << "<style>.body{fill:#9db4cc;stroke:#34495e;stroke-width:0.02}.wall{fill:#566573}text{font-family:sans-serif}</"
         "style>\n"
      << "<g transform=\"scale(1,-1)\">\n";
  for (const Shape& s : r.walls) tool::svg_shape(out, s, "wall");
  for (const Shape& s : r.shapes) tool::svg_shape(out, s, "body");
  out << "</g>\n<text x=\"" << left + 0.01 * w << "\" y=\"" << -bottom + 1.5 * font << "\" font-size=\"" << font
      << "\">" << caption.str() << "</text>\n</svg>\n";
}

}  // namespace collide2d::settle
