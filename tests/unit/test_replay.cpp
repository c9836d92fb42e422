// The Recorder against docs/replay-format.md: a decoder written from that page reads back, frame by
// frame, what the World held when each frame was recorded (its shapes, their float32 poses and
// broad-phase boxes, the candidate, overlapping and sensor pairs, the proximity pairs, contacts and
// impacts, the frame's counts and the character movers), through bodies added and removed, a filter
// changed, and shapes of every kind.
#include <collide2d/chain.h>
#include <collide2d/mover.h>
#include <collide2d/replay.h>
#include <collide2d/world.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace collide2d {
namespace {

using ShapeKey = std::pair<std::uint32_t, std::uint32_t>;  // a shape id: index, generation
using PairKey = std::pair<ShapeKey, ShapeKey>;

// What the World held at a frame, as the format keeps it.
struct Expected {
  std::map<ShapeKey, std::array<float, 7>> shapes;  // pose (x, y, angle), then broad box
  std::set<PairKey> candidates, overlapping, sensing;
  std::size_t proximity = 0, contacts = 0, impacts = 0;
  std::vector<float> impact_times;
  std::array<std::uint32_t, 7> counts{};
  // Each mover's kind, centre, angle, ground flag and normal, and its planes' point, normal and
  // separation, as float32.
  std::vector<std::vector<float>> movers;
};

std::vector<float> mover_floats(const MoverRecord& m) {
  std::vector<float> v{static_cast<float>(m.shape.index()),        static_cast<float>(center_of(m.shape).x()),
                       static_cast<float>(center_of(m.shape).y()), static_cast<float>(angle_of(m.shape)),
                       m.ground.on_ground ? 1.0f : 0.0f,           static_cast<float>(m.ground.normal.x()),
                       static_cast<float>(m.ground.normal.y())};
  for (const MoverPlane& p : m.planes) {
    for (const double x : {p.point.x(), p.point.y(), p.normal.x(), p.normal.y(), p.separation})
      v.push_back(static_cast<float>(x));
  }
  return v;
}

ShapeKey key(ShapeId id) { return {id.index, id.generation}; }

Expected expected_of(const World& world) {
  Expected e;
  for (const BodyId body : world.bodies()) {
    for (const ShapeId id : world.shapes(body)) {
      const Shape& s = world.shape(id);
      const Aabb box = world.broad_box(id);
      e.shapes[key(id)] = {static_cast<float>(center_of(s).x()), static_cast<float>(center_of(s).y()),
                           static_cast<float>(angle_of(s)),      static_cast<float>(box.min.x()),
                           static_cast<float>(box.min.y()),      static_cast<float>(box.max.x()),
                           static_cast<float>(box.max.y())};
    }
  }
  for (const ShapePair& p : world.candidates()) e.candidates.insert({key(p.shape_a), key(p.shape_b)});
  for (const ShapePair& p : world.overlapping()) e.overlapping.insert({key(p.shape_a), key(p.shape_b)});
  for (const SensorPair& p : world.sensing()) e.sensing.insert({key(p.sensor_shape), key(p.visitor_shape)});
  e.proximity = world.proximity().size();
  e.contacts = world.contacts().size();
  e.impacts = world.impacts().size();
  for (const Impact& i : world.impacts()) e.impact_times.push_back(static_cast<float>(i.t));
  const FrameStats& s = world.last_frame();
  e.counts = {static_cast<std::uint32_t>(s.candidates),  static_cast<std::uint32_t>(s.filtered),
              static_cast<std::uint32_t>(s.overlapping), static_cast<std::uint32_t>(s.proximity),
              static_cast<std::uint32_t>(s.contacts),    static_cast<std::uint32_t>(s.impacts),
              static_cast<std::uint32_t>(s.sensing)};
  return e;
}

// A reader of little-endian words, failing the test where it runs past its bytes.
class Reader {
 public:
  explicit Reader(std::string bytes) : bytes_(std::move(bytes)) {}
  std::uint32_t u32() {
    if (at_ + 4 > bytes_.size()) {
      ADD_FAILURE() << "read past the end";
      return 0;
    }
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes_[at_ + k])) << (8 * k);
    at_ += 4;
    return v;
  }
  std::uint64_t u64() {
    const std::uint64_t lo = u32();
    return lo | static_cast<std::uint64_t>(u32()) << 32;
  }
  float f32() { return std::bit_cast<float>(u32()); }
  unsigned char byte() { return static_cast<unsigned char>(bytes_.at(at_++)); }
  void skip(std::size_t n) { at_ += n; }
  bool done() const { return at_ == bytes_.size(); }

 private:
  std::string bytes_;
  std::size_t at_ = 0;
};

// The document's "changes of a sorted list", applied to `list`.
template <class T, class Read>
void apply_changes(Reader& r, std::set<T>& list, Read read) {
  const std::uint32_t gained = r.u32(), lost = r.u32();
  std::vector<T> g, l;
  for (std::uint32_t k = 0; k < gained; ++k) g.push_back(read());
  for (std::uint32_t k = 0; k < lost; ++k) l.push_back(read());
  EXPECT_TRUE(std::is_sorted(g.begin(), g.end()) && std::is_sorted(l.begin(), l.end()));
  for (const T& x : l) EXPECT_EQ(list.erase(x), 1u) << "a lost item was not there";
  for (const T& x : g) EXPECT_TRUE(list.insert(x).second) << "a gained item was there";
}

// Reads a replay and checks each frame against `frames`.
void expect_replay(const std::string& bytes, const std::vector<Expected>& frames) {
  Reader head(bytes);
  ASSERT_EQ(bytes.substr(0, 4), "C2DR");
  head.skip(4);
  ASSERT_EQ(head.u32(), 2u);
  ASSERT_EQ(head.u32(), frames.size());
  const std::uint32_t entry_count = head.u32();
  std::array<std::uint32_t, 12> sizes{};
  for (auto& s : sizes) s = head.u32();
  std::size_t at = 20 + 4 * 11;
  std::vector<Reader> parts;
  for (const std::uint32_t s : sizes) {
    ASSERT_LE(at + s, bytes.size());
    parts.emplace_back(bytes.substr(at, s));
    at += s;
  }
  ASSERT_EQ(at, bytes.size());
  // The table: each entry's shape id; the rest read past by the document's layout.
  Reader& table = parts[0];
  std::vector<ShapeKey> shape_of;
  for (std::uint32_t e = 0; e < entry_count; ++e) {
    const std::uint32_t index = table.u32(), generation = table.u32();
    shape_of.push_back({index, generation});
    table.skip(8 + 16);
    const std::uint32_t kind = table.u32(), flags = table.u32();
    table.skip(16 + 4 + 8);
    if (kind == 4) table.skip(8 * table.u32());
    if (flags & 8) table.skip(16);
  }
  EXPECT_TRUE(table.done());
  Reader &live_r = parts[1], &poses_r = parts[2], &boxes_r = parts[3], &cand_r = parts[4], &over_r = parts[5],
         &near_r = parts[6], &touch_r = parts[7], &hit_r = parts[8], &sense_r = parts[9], &stats_r = parts[10],
         &movers_r = parts[11];
  std::set<std::uint32_t> live;
  std::set<std::pair<std::uint32_t, std::uint32_t>> candidates, overlapping, sensing;
  std::vector<std::array<std::uint32_t, 7>> last(entry_count, std::array<std::uint32_t, 7>{}), before_last = last;
  const auto pair = [](Reader& r) {
    return [&r] {
      const std::uint32_t a = r.u32();
      return std::pair(a, r.u32());
    };
  };
  const auto as_shapes = [&](const auto& pairs) {
    std::set<PairKey> out;
    for (const auto& [a, b] : pairs) out.insert({shape_of[a], shape_of[b]});
    return out;
  };
  for (std::size_t f = 0; f < frames.size(); ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    const Expected& x = frames[f];
    apply_changes(live_r, live, [&] { return live_r.u32(); });
    // Poses and boxes: the live entries' words as zigzagged residuals from their predictions (a
    // pose's 2 w1 - w0, a box's w1), in four byte planes.
    const auto planes = [&](Reader& r, int width, int first, bool linear) {
      const std::size_t n = live.size() * static_cast<std::size_t>(width);
      std::vector<std::uint32_t> zigzag(n, 0);
      for (int plane = 0; plane < 4; ++plane) {
        for (std::size_t k = 0; k < n; ++k) zigzag[k] |= static_cast<std::uint32_t>(r.byte()) << (8 * plane);
      }
      std::size_t k = 0;
      for (const std::uint32_t e : live) {
        for (int w = first; w < first + width; ++w, ++k) {
          const std::uint32_t d = zigzag[k] >> 1 ^ (0u - (zigzag[k] & 1u));
          const std::uint32_t predicted = linear ? 2 * last[e][w] - before_last[e][w] : last[e][w];
          before_last[e][w] = last[e][w];
          last[e][w] = predicted + d;
        }
      }
    };
    planes(poses_r, 3, 0, true);
    planes(boxes_r, 4, 3, false);
    std::map<ShapeKey, std::array<float, 7>> shapes;
    for (const std::uint32_t e : live) {
      std::array<float, 7> v;
      for (int w = 0; w < 7; ++w) v[w] = std::bit_cast<float>(last[e][w]);
      shapes[shape_of[e]] = v;
    }
    EXPECT_EQ(shapes, x.shapes);
    apply_changes(cand_r, candidates, pair(cand_r));
    apply_changes(over_r, overlapping, pair(over_r));
    EXPECT_EQ(as_shapes(candidates), x.candidates);
    EXPECT_EQ(as_shapes(overlapping), x.overlapping);
    const std::uint32_t near = near_r.u32();
    EXPECT_EQ(near, x.proximity);
    near_r.skip(near * 28u);
    const std::uint32_t touching = touch_r.u32();
    EXPECT_EQ(touching, x.contacts);
    for (std::uint32_t k = 0; k < touching; ++k) {
      touch_r.skip(8 + 4 + 4 + 8 + 16);
      touch_r.skip(touch_r.u32() * 24u);
    }
    const std::uint32_t hits = hit_r.u32();
    ASSERT_EQ(hits, x.impacts);
    for (std::uint32_t k = 0; k < hits; ++k) {
      hit_r.skip(8);
      EXPECT_EQ(hit_r.f32(), x.impact_times[k]);
      hit_r.skip(16);
    }
    apply_changes(sense_r, sensing, pair(sense_r));
    EXPECT_EQ(as_shapes(sensing), x.sensing);
    std::array<std::uint32_t, 7> counts;
    for (auto& c : counts) c = stats_r.u32();
    EXPECT_EQ(counts, x.counts);
    stats_r.skip(8);
    // Movers: the kind's registry number is the Shape's alternative index (shapes/kinds.h).
    std::vector<std::vector<float>> movers(movers_r.u32());
    for (std::vector<float>& m : movers) {
      const std::uint32_t kind = movers_r.u32();
      m.push_back(static_cast<float>(kind));
      movers_r.skip(8);
      if (kind == 4) movers_r.skip(8 * movers_r.u32());
      for (int k = 0; k < 3; ++k) m.push_back(movers_r.f32());
      m.push_back(static_cast<float>(movers_r.u32()));
      for (int k = 0; k < 2; ++k) m.push_back(movers_r.f32());
      const std::uint32_t planes = movers_r.u32();
      for (std::uint32_t k = 0; k < 5 * planes; ++k) m.push_back(movers_r.f32());
    }
    EXPECT_EQ(movers, x.movers);
  }
  for (const Reader& r : parts) EXPECT_TRUE(r.done());
}

TEST(Recorder, WritesWhatTheWorldHeldFrameByFrame) {
  World world({.fat_margin = 0.1, .proximity_margin = 0.5, .contacts = true});
  std::vector<BodyId> moving = {
      world.add(Circle{{0, 0}, 0.5}),
      world.add(Ellipse{{1.5, 0.2}, 0.8, 0.3, 0.4}),
      world.add(Rect{{-1.2, 0.5}, {0.4, 0.2}, 0.3}),
      world.add(Capsule{{0.3, 1.4}, 0.5, 0.2, 1.0}),
      world.add(ConvexPolygon::regular(5, 0.6, 0.05).at({-0.5, -1.3}, 0.2)),
  };
  world.add(Rect{{0, -3}, {6, 0.5}, 0.0}, {.is_static = true});
  world.add(Circle{{2.5, 2.5}, 1.0}, {.is_static = true, .sensor = true});
  world.add_chain(std::vector<Vec2>{{6, -2}, {6, 4}, {-6, 4}, {-6, -2}}, false);
  const BodyId bullet = world.add(Circle{{-5, 3}, 0.05});
  world.set_continuous(bullet);
  // Two characters falling onto the floor and walking: a capsule and a polygon.
  std::vector<MoverRecord> movers{{Capsule{{-2, 0}, 0.3, 0.2, 1.5}}, {ConvexPolygon::regular(6, 0.4).at({2, 0}, 0.1)}};
  std::vector<Vec2> velocity(movers.size(), Vec2::Zero());
  Recorder recorder;
  std::vector<Expected> frames;
  for (int f = 0; f < 40; ++f) {
    for (std::size_t k = 0; k < moving.size(); ++k) {
      const double t = 0.1 * f + static_cast<double>(k);
      if (world.contains(moving[k])) world.move_by(moving[k], {0.08 * std::cos(t), 0.08 * std::sin(t)}, 0.05);
    }
    world.move_by(bullet, {0.3, -0.4});
    if (f == 10) world.remove(moving[1]);
    if (f == 15) moving[1] = world.add(Circle{{1, 1}, 0.3});
    if (f == 20) world.set_filter(moving[2], Filter{.category = 2, .mask = 2});
    world.update();
    for (std::size_t k = 0; k < movers.size(); ++k) {
      MoverRecord& m = movers[k];
      velocity[k] += Vec2(k == 0 ? 0.5 : -0.5, -1.0);
      const MoveResult r = move(world, m.shape, velocity[k], 0.1, {}, m.ground);
      m.shape = moved_to(m.shape, r.position);
      m.ground = r.ground;
      m.planes = world.collide_mover(m.shape);
      velocity[k] = r.velocity;
    }
    recorder.record(world, movers);
    frames.push_back(expected_of(world));
    for (const MoverRecord& m : movers) frames.back().movers.push_back(mover_floats(m));
  }
  EXPECT_EQ(recorder.frames(), 40u);
  const auto landed = [](const Expected& e) { return e.movers[0][4] == 1.0f && e.movers[1][4] == 1.0f; };
  EXPECT_TRUE(landed(frames.back()));  // the movers reached the floor and stand on it
  const auto total = [&](auto member) {
    std::size_t n = 0;
    for (const Expected& e : frames) n += (e.*member).size();
    return n;
  };
  // The run has something of each to record.
  EXPECT_GT(total(&Expected::overlapping), 0u);
  EXPECT_GT(total(&Expected::sensing), 0u);
  EXPECT_GT(total(&Expected::impact_times), 0u);
  std::ostringstream out;
  recorder.write(out);
  expect_replay(out.str(), frames);
}

TEST(Recorder, WritesNoFramesAsAHeaderAlone) {
  Recorder recorder;
  std::ostringstream out;
  recorder.write(out);
  expect_replay(out.str(), {});
  EXPECT_EQ(out.str().size(), 64u);
}

}  // namespace
}  // namespace collide2d
