// The replay page's writer: the page is replay.html with the replay inside, zlib-compressed in
// base64, which inflates back to the replay's bytes; a file that is not a replay is refused.
#include "tools/replay/replay_page.h"

#include <collide2d/replay.h>
#include <collide2d/world.h>

#include <gtest/gtest.h>
#include <zlib.h>

#include <sstream>
#include <string>
#include <vector>

namespace collide2d::tool {
namespace {

std::vector<unsigned char> from_base64(const std::string& text) {
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> out;
  std::uint32_t bits = 0;
  int held = 0;
  for (const char c : text) {
    if (c == '=') break;
    const std::size_t v = digits.find(c);
    EXPECT_NE(v, std::string::npos) << "not a base64 digit: " << int(c);
    bits = bits << 6 | static_cast<std::uint32_t>(v);
    held += 6;
    if (held >= 8) {
      held -= 8;
      out.push_back(static_cast<unsigned char>(bits >> held));
    }
  }
  return out;
}

std::string inflated(const std::vector<unsigned char>& bytes, std::size_t size) {
  std::string out(size, '\0');
  uLongf length = static_cast<uLongf>(size);
  EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(out.data()), &length, bytes.data(), static_cast<uLong>(bytes.size())),
            Z_OK);
  out.resize(length);
  return out;
}

TEST(ReplayPage, HoldsTheReplayInflatedBackToItsBytes) {
  World world;
  world.add(Circle{{0, 0}, 1});
  world.add(Rect{{1, 0}, {1, 1}, 0.5});
  Recorder recorder;
  for (int f = 0; f < 5; ++f) {
    world.update();
    recorder.record(world);
  }
  std::ostringstream replay;
  recorder.write(replay);
  std::ostringstream page;
  write_replay_page(replay.str(), page);
  const std::string html = page.str();
  EXPECT_TRUE(html.starts_with("<!doctype html>"));
  EXPECT_EQ(html.find("%%REPLAY%%"), std::string::npos);
  const std::string open = "<script id=\"replay-data\" type=\"application/octet-stream\">";
  const std::size_t from = html.find(open) + open.size(), to = html.find("</script>", from);
  ASSERT_NE(to, std::string::npos);
  EXPECT_EQ(inflated(from_base64(html.substr(from, to - from)), replay.str().size()), replay.str());
  EXPECT_TRUE(html.ends_with("</html>\n"));
}

TEST(ReplayPage, RefusesWhatIsNotAReplay) {
  std::ostringstream page;
  try {
    write_replay_page("{\"frames\": 1}", page);
    ADD_FAILURE() << "a JSON file was taken for a replay";
  } catch (const ReplayError& e) {
    EXPECT_STREQ(e.what(), "not a collide2d replay: it does not start with C2DR");
  }
  EXPECT_TRUE(page.str().empty());
}

}  // namespace
}  // namespace collide2d::tool
