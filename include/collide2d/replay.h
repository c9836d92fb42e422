/// @file
/// Recording a World frame by frame into a replay, which `collide2d replay` turns into a page that
/// plays it back in a browser (docs/replay.md):
///
///   Recorder recorder;
///   for (int frame = 0; frame < 600; ++frame) {
///     // ... move the bodies ...
///     world.update();
///     recorder.record(world);
///   }
///   std::ofstream out("game.c2dr", std::ios::binary);
///   recorder.write(out);
///
/// Each frame keeps the shapes (their sizes once, their poses every frame as float32), the broad
/// phase's boxes and candidate pairs, the overlapping and proximity pairs, the contacts, the
/// impacts, the sensors' visitors, the frame's statistics and the character movers the caller
/// passes (mover.h). The format (docs/replay-format.md) stores what changed between frames, so
/// that a long run compresses well.
#pragma once

#include <collide2d/mover.h>
#include <collide2d/world.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <ostream>
#include <span>
#include <vector>

namespace collide2d {

/// A character mover as a replay shows it: where move() left it, its ground, and the planes of
/// the surfaces it touches there (World::collide_mover()).
struct MoverRecord {
  Shape shape;
  Ground ground{};
  std::vector<MoverPlane> planes;
};

/// Records a World frame by frame into a replay (the file comment).
class Recorder {
 public:
  /// A recorder of no frames yet; it moves, and is not copied.
  Recorder();
  ~Recorder();
  Recorder(Recorder&&) noexcept;
  Recorder& operator=(Recorder&&) noexcept;

  /// Records the world as its last update left it, and the frame's character movers.
  /// Call it right after update(), before any shape is removed, and after the movers moved.
  void record(const World& world, std::span<const MoverRecord> movers = {});
  /// The frames recorded.
  std::size_t frames() const;
  /// Writes the replay: every frame recorded so far.
  void write(std::ostream& out) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace collide2d
