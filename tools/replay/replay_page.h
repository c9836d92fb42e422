// The replay page: tools/replay/replay.html with a replay (include/collide2d/replay.h) embedded,
// compressed with zlib and written in base64, which the page inflates with the browser's own
// DecompressionStream. One file, no network.
#pragma once

#include <iosfwd>
#include <stdexcept>
#include <string_view>

namespace collide2d::tool {

class ReplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws ReplayError where `replay` is not a replay (no C2DR header).
void write_replay_page(std::string_view replay, std::ostream& out);

}  // namespace collide2d::tool
