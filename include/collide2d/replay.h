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
/// impacts, the sensors' visitors and the frame's statistics. The format (docs/replay-format.md)
/// stores what changed between frames, so that a long run compresses well.
#pragma once

#include <collide2d/world.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <ostream>

namespace collide2d {

/// Records a World frame by frame into a replay (the file comment).
class Recorder {
 public:
  /// A recorder of no frames yet; it moves, and is not copied.
  Recorder();
  ~Recorder();
  Recorder(Recorder&&) noexcept;
  Recorder& operator=(Recorder&&) noexcept;

  /// Records the world as its last update left it.
  /// Call it right after update(), before any shape is removed.
  void record(const World& world);
  /// The frames recorded.
  std::size_t frames() const;
  /// Writes the replay: every frame recorded so far.
  void write(std::ostream& out) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace collide2d
