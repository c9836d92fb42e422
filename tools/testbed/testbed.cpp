// The testbed's WebAssembly module (built by scripts/wasm.sh with Emscripten): a query line of the
// command line's grammar in (tools/query_command.h), the answers out, for tools/testbed/testbed.html.
// The page shows `collide2d query`'s own lines, so that what it shows is what the command prints
// (to the last bits of the sine and cosine, which WebAssembly's libm may round differently).
#include "tools/query_command.h"

#include <collide2d/query.h>

#include <cstdio>
#include <exception>
#include <string>

namespace {

std::string number(double x) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%.17g", x + 0.0);
  return digits;
}

std::string point(const collide2d::Vec2& p) { return "[" + number(p.x()) + "," + number(p.y()) + "]"; }

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// The line's answer in every mode the command has for it, as its lines, and the contact's manifold.
std::string answers(const collide2d::tool::QueryLine& q) {
  using collide2d::tool::Answer;
  collide2d::tool::QueryOptions options;
  std::string json = "{\"ok\":true";
  if (q.moving) {
    options.answer = Answer::toi;
    json += ",\"toi\":" + quoted(collide2d::tool::answer(q, options));
    collide2d::tool::QueryLine still = q;
    still.moving = false;
    still.a_motion = still.b_motion = {};
    return json + ",\"still\":" + answers(still) + "}";
  }
  options.answer = Answer::distance;
  json += ",\"distance\":" + quoted(collide2d::tool::answer(q, options));
  options.answer = Answer::contact;
  json += ",\"contact\":" + quoted(collide2d::tool::answer(q, options));
  const collide2d::Contact c = q.chain ? collide2d::contact(*q.chain, q.b) : collide2d::contact(q.a, q.b);
  json += ",\"manifold\":[";
  for (const collide2d::ContactPoint& m : c.points()) {
    if (json.back() != '[') json += ',';
    json += "{\"a\":" + point(m.point_a) + ",\"b\":" + point(m.point_b) + ",\"separation\":" + number(m.separation) +
            ",\"id\":" + std::to_string(m.id) + "}";
  }
  return json + "]}";
}

}  // namespace

// JSON: {"ok": true, "distance": LINE, "contact": LINE, "manifold": [...]} for a line without a motion;
// {"ok": true, "toi": LINE, "still": {...}} with one (the answers at rest under "still");
// {"ok": false, "error": TEXT} for a line the command refuses. The text lives until the next call.
extern "C" const char* testbed_answer(const char* line) {
  static std::string out;
  try {
    const auto q = collide2d::tool::parse_query_line(line);
    out = q ? answers(*q) : "{\"ok\":false,\"error\":\"an empty line\"}";
  } catch (const std::exception& e) {
    out = "{\"ok\":false,\"error\":" + quoted(e.what()) + "}";
  }
  return out.c_str();
}
