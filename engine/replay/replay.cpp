// The replay format (docs/replay-format.md): a table of the shapes' fixed forms, then one section
// per kind of record, each holding every frame in turn, so that like data lies together for the
// compressor. What changes little between frames (the live shapes, the candidate and overlapping
// pairs, the sensors' visitors) is stored as what changed. The poses and the broad-phase boxes are
// float32 bits taken as integers, which run evenly where the value does (within one binade): each
// is stored as its difference from a prediction (a pose's: its last two continued in a line; a
// box's: its last), split into byte planes, so that a shape moving steadily or standing still has
// its high bytes zero.
#include <collide2d/replay.h>

#include "shapes/internal.h"
#include "shapes/kinds.h"

#include <algorithm>
#include <array>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace collide2d {
namespace {

using Bytes = std::vector<std::uint8_t>;
using Pair = std::pair<std::uint32_t, std::uint32_t>;  // two entries of the table
constexpr std::uint32_t kNone = ~std::uint32_t{0};
constexpr std::uint32_t kVersion = 2;

// The sections, in the order they are written after the table.
enum Section : std::size_t {
  live,
  poses,
  boxes,
  candidates,
  overlapping,
  proximity,
  contacts,
  impacts,
  sensing,
  stats,
  movers
};
constexpr std::size_t kSections = 11;

void put(Bytes& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
}
void put(Bytes& out, std::uint64_t v) {
  put(out, static_cast<std::uint32_t>(v));
  put(out, static_cast<std::uint32_t>(v >> 32));
}
void put(Bytes& out, float v) { put(out, detail::bit_copy<std::uint32_t>(v)); }
void put(Bytes& out, double v) { put(out, static_cast<float>(v)); }
void put(Bytes& out, const Vec2& v) {
  put(out, v.x());
  put(out, v.y());
}
void put(Bytes& out, const Pair& p) {
  put(out, p.first);
  put(out, p.second);
}

// A shape's sizes, its pose left out (shapes/kinds.h): two numbers, then a polygon's vertices in its
// own frame.
void put_sizes(Bytes& out, const Shape& s) {
  detail::with_kind(s, [&](const auto& x, auto kind) {
    using K = decltype(kind);
    const detail::Sizes sizes = K::sizes(x);
    put(out, Vec2(sizes[0], sizes[1]));
    if constexpr (requires { K::outline(x); }) {
      put(out, static_cast<std::uint32_t>(K::outline(x).size()));
      for (const Vec2& v : K::outline(x)) put(out, v);
    }
  });
}

// What a shape is, apart from where: the table's entry for it while this stays the same.
Bytes form_of(const World& world, BodyId body, ShapeId id) {
  Bytes out;
  put(out, id.index);
  put(out, id.generation);
  put(out, body.index);
  put(out, body.generation);
  put(out, world.user_id(body));
  put(out, world.user_id(id));
  const Shape& shape = world.shape(id);
  const std::optional<ChainSegment> chain = world.chain_segment(id);
  const std::uint32_t flags = (world.is_static(body) ? 1u : 0u) | (world.is_sensor(id) ? 2u : 0u) |
                              (world.is_continuous(body) ? 4u : 0u) | (chain ? 8u : 0u);
  put(out, detail::kind_number(shape));  // the registry's number (shapes/kinds.h)
  put(out, flags);
  const Filter& filter = world.filter(id);
  put(out, filter.category);
  put(out, filter.mask);
  put(out, static_cast<std::uint32_t>(filter.group));
  put_sizes(out, shape);
  if (chain) {
    put(out, chain->ghost1);
    put(out, chain->ghost2);
  }
  return out;
}

// A shape's pose words: its centre (a segment's first point) and angle.
std::array<std::uint32_t, 3> pose_words(const Shape& s) {
  const Vec2 c = center_of(s);
  return {detail::bit_copy<std::uint32_t>(static_cast<float>(c.x())),
          detail::bit_copy<std::uint32_t>(static_cast<float>(c.y())),
          detail::bit_copy<std::uint32_t>(static_cast<float>(angle_of(s)))};
}
std::array<std::uint32_t, 4> box_words(const Aabb& b) {
  return {detail::bit_copy<std::uint32_t>(static_cast<float>(b.min.x())),
          detail::bit_copy<std::uint32_t>(static_cast<float>(b.min.y())),
          detail::bit_copy<std::uint32_t>(static_cast<float>(b.max.x())),
          detail::bit_copy<std::uint32_t>(static_cast<float>(b.max.y()))};
}

// A word's difference from its prediction as an integer (wrapping), zigzagged so that a small
// difference either way has zero high bytes.
std::uint32_t residual(std::uint32_t word, std::uint32_t predicted) {
  const auto d = static_cast<std::int32_t>(word - predicted);
  return static_cast<std::uint32_t>(d) << 1 ^ static_cast<std::uint32_t>(d >> 31);
}

// The words' bytes, plane by plane: every word's lowest byte, then every word's next.
void put_planes(Bytes& out, const std::vector<std::uint32_t>& words) {
  for (int plane = 0; plane < 4; ++plane) {
    for (const std::uint32_t w : words) out.push_back(static_cast<std::uint8_t>(w >> (8 * plane)));
  }
}

// What `now` gained and lost since `before` (both sorted): the count gained, the count lost, then
// the items gained and those lost, each in order.
template <class T>
void put_changes(Bytes& out, const std::vector<T>& before, const std::vector<T>& now) {
  std::vector<T> gained, lost;
  std::set_difference(now.begin(), now.end(), before.begin(), before.end(), std::back_inserter(gained));
  std::set_difference(before.begin(), before.end(), now.begin(), now.end(), std::back_inserter(lost));
  put(out, static_cast<std::uint32_t>(gained.size()));
  put(out, static_cast<std::uint32_t>(lost.size()));
  for (const T& x : gained) put(out, x);
  for (const T& x : lost) put(out, x);
}

}  // namespace

struct Recorder::State {
  std::uint32_t frames = 0;
  Bytes table;
  std::uint32_t entries = 0;
  // By ShapeId::index: the shape's generation, its entry, and the form that entry holds.
  struct Current {
    std::uint32_t generation = 0;
    std::uint32_t entry = kNone;
    Bytes form;
  };
  std::vector<Current> by_shape;
  // By entry: the pose and box words last written, and those before them.
  std::vector<std::array<std::uint32_t, 7>> last, before_last;
  // The last frame's live entries and pairs, sorted.
  std::vector<std::uint32_t> live;
  std::vector<Pair> candidates, overlapping, sensing;
  std::array<Bytes, kSections> sections;

  // The shape's entry, a new one where the shape is new or its form changed.
  std::uint32_t entry_of(const World& world, BodyId body, ShapeId id) {
    if (id.index >= by_shape.size()) by_shape.resize(id.index + 1);
    Current& c = by_shape[id.index];
    Bytes form = form_of(world, body, id);
    if (c.entry == kNone || c.generation != id.generation || c.form != form) {
      table.insert(table.end(), form.begin(), form.end());
      c = {id.generation, entries++, std::move(form)};
      last.push_back({});
      before_last.push_back({});
    }
    return c.entry;
  }
  std::uint32_t entry(ShapeId id) const { return by_shape[id.index].entry; }
  template <class Record>
  Pair pair_of(const Record& r) const {
    return {entry(r.shape_a), entry(r.shape_b)};
  }

  void record_shapes(const World& world);
  void record_pairs(const World& world);
  void record_stats(const FrameStats& s);
  void record_movers(std::span<const MoverRecord> movers);
};

void Recorder::State::record_shapes(const World& world) {
  std::vector<std::pair<std::uint32_t, ShapeId>> now;
  for (const BodyId body : world.bodies()) {
    for (const ShapeId id : world.shapes(body)) now.emplace_back(entry_of(world, body, id), id);
  }
  std::sort(now.begin(), now.end());
  std::vector<std::uint32_t> entries_now;
  std::vector<std::uint32_t> pose_bits, box_bits;
  for (const auto& [e, id] : now) {
    entries_now.push_back(e);
    const auto p = pose_words(world.shape(id));
    const auto b = box_words(world.broad_box(id));
    std::array<std::uint32_t, 7> words;
    std::copy(p.begin(), p.end(), words.begin());
    std::copy(b.begin(), b.end(), words.begin() + 3);
    for (int k = 0; k < 7; ++k) {
      const std::uint32_t w1 = last[e][k], w0 = before_last[e][k];
      const std::uint32_t predicted = k < 3 ? 2 * w1 - w0 : w1;
      (k < 3 ? pose_bits : box_bits).push_back(residual(words[k], predicted));
      before_last[e][k] = w1, last[e][k] = words[k];
    }
  }
  put_changes(sections[Section::live], live, entries_now);
  put_planes(sections[Section::poses], pose_bits);
  put_planes(sections[Section::boxes], box_bits);
  live = std::move(entries_now);
}

void Recorder::State::record_pairs(const World& world) {
  const auto sorted_pairs = [&](const auto& records) {
    std::vector<Pair> out;
    for (const auto& r : records) out.push_back(pair_of(r));
    std::sort(out.begin(), out.end());
    return out;
  };
  std::vector<Pair> c = sorted_pairs(world.candidates()), o = sorted_pairs(world.overlapping());
  std::vector<Pair> s;
  for (const SensorPair& p : world.sensing()) s.emplace_back(entry(p.sensor_shape), entry(p.visitor_shape));
  std::sort(s.begin(), s.end());
  put_changes(sections[Section::candidates], candidates, c);
  put_changes(sections[Section::overlapping], overlapping, o);
  put_changes(sections[Section::sensing], sensing, s);
  candidates = std::move(c), overlapping = std::move(o), sensing = std::move(s);

  Bytes& near = sections[Section::proximity];
  put(near, static_cast<std::uint32_t>(world.proximity().size()));
  for (const Proximity& p : world.proximity()) {
    put(near, pair_of(p));
    put(near, p.result.distance);
    put(near, p.result.point_a);
    put(near, p.result.point_b);
  }
  Bytes& touch = sections[Section::contacts];
  put(touch, static_cast<std::uint32_t>(world.contacts().size()));
  for (const BodyContact& bc : world.contacts()) {
    put(touch, pair_of(bc));
    put(touch, bc.touching ? 1u : 0u);
    put(touch, bc.contact.separation);
    put(touch, bc.contact.normal);
    put(touch, bc.contact.point_a);
    put(touch, bc.contact.point_b);
    put(touch, static_cast<std::uint32_t>(bc.contact.points().size()));
    for (const ContactPoint& m : bc.contact.points()) {
      put(touch, m.point_a);
      put(touch, m.point_b);
      put(touch, m.separation);
      put(touch, m.id);
    }
  }
  Bytes& hit = sections[Section::impacts];
  put(hit, static_cast<std::uint32_t>(world.impacts().size()));
  for (const Impact& i : world.impacts()) {
    put(hit, pair_of(i));
    put(hit, i.t);
    put(hit, i.point);
    put(hit, i.normal);
  }
}

void Recorder::State::record_stats(const FrameStats& s) {
  Bytes& out = sections[Section::stats];
  for (const std::size_t n : {s.candidates, s.filtered, s.overlapping, s.proximity, s.contacts, s.impacts, s.sensing})
    put(out, static_cast<std::uint32_t>(n));
  put(out, s.broad_seconds * 1e3);
  put(out, s.narrow_seconds * 1e3);
}

// Each mover whole, every frame: its kind and sizes, its pose, its ground, its planes.
void Recorder::State::record_movers(std::span<const MoverRecord> movers) {
  Bytes& out = sections[Section::movers];
  put(out, static_cast<std::uint32_t>(movers.size()));
  for (const MoverRecord& m : movers) {
    put(out, detail::kind_number(m.shape));
    put_sizes(out, m.shape);
    put(out, center_of(m.shape));
    put(out, angle_of(m.shape));
    put(out, m.ground.on_ground ? 1u : 0u);
    put(out, m.ground.normal);
    put(out, static_cast<std::uint32_t>(m.planes.size()));
    for (const MoverPlane& p : m.planes) {
      put(out, p.point);
      put(out, p.normal);
      put(out, p.separation);
    }
  }
}

Recorder::Recorder() : state_(std::make_unique<State>()) {}
Recorder::~Recorder() = default;
Recorder::Recorder(Recorder&&) noexcept = default;
Recorder& Recorder::operator=(Recorder&&) noexcept = default;

void Recorder::record(const World& world, std::span<const MoverRecord> movers) {
  state_->record_shapes(world);
  state_->record_pairs(world);
  state_->record_stats(world.last_frame());
  state_->record_movers(movers);
  ++state_->frames;
}

std::size_t Recorder::frames() const { return state_->frames; }

void Recorder::write(std::ostream& out) const {
  Bytes head{'C', '2', 'D', 'R'};
  put(head, kVersion);
  put(head, state_->frames);
  put(head, state_->entries);
  put(head, static_cast<std::uint32_t>(state_->table.size()));
  for (const Bytes& s : state_->sections) put(head, static_cast<std::uint32_t>(s.size()));
  const auto write_bytes = [&out](const Bytes& b) {
    out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
  };
  write_bytes(head);
  write_bytes(state_->table);
  for (const Bytes& s : state_->sections) write_bytes(s);
}

}  // namespace collide2d
