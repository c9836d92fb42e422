#include "tools/replay/replay_page.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace collide2d::tool {

extern const char kReplayPage[];

namespace {

constexpr std::string_view kPlaceholder = "%%REPLAY%%";

std::vector<unsigned char> deflated(std::string_view bytes) {
  uLongf size = compressBound(static_cast<uLong>(bytes.size()));
  std::vector<unsigned char> out(size);
  const int status = compress2(out.data(), &size, reinterpret_cast<const Bytef*>(bytes.data()),
                               static_cast<uLong>(bytes.size()), Z_DEFAULT_COMPRESSION);
  if (status != Z_OK) throw ReplayError("zlib could not compress the replay (status " + std::to_string(status) + ")");
  out.resize(size);
  return out;
}

void write_base64(const std::vector<unsigned char>& bytes, std::ostream& out) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = static_cast<std::uint32_t>(bytes[i]) << 16;
    if (n > 1) v |= static_cast<std::uint32_t>(bytes[i + 1]) << 8;
    if (n > 2) v |= bytes[i + 2];
    for (std::size_t k = 0; k < 4; ++k) text.push_back(k <= n ? kDigits[(v >> (18 - 6 * k)) & 63] : '=');
  }
  out << text;
}

}  // namespace

void write_replay_page(std::string_view replay, std::ostream& out) {
  if (!replay.starts_with("C2DR")) throw ReplayError("not a collide2d replay: it does not start with C2DR");
  const std::string_view page = kReplayPage;
  const std::size_t at = page.find(kPlaceholder);
  out << page.substr(0, at);
  write_base64(deflated(replay), out);
  out << page.substr(at + kPlaceholder.size());
}

}  // namespace collide2d::tool
