// Query-line fuzzer: any bytes as `collide2d query` input, answered for distances, for times of
// impact and for overlap areas. Every line must be answered or refused with an `error:` line
// (ParseError, InvalidShape), never crash; answers carry six finite numbers (a distance 0 exactly
// when overlapping; a time in [0, 1], 1 on a miss), an area's four (the area not negative, the IoU
// in [0, 1]), and the output keeps one line per query line.
#include "tools/query_command.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

// Checks one mode's output against the input's query count; aborts on any breach.
void check(const std::string& text, collide2d::tool::Answer mode) {
  std::istringstream in(text);
  std::ostringstream out, err;
  collide2d::tool::QueryOptions options;
  options.answer = mode;
  const int status = collide2d::tool::run_query(in, out, err, options);
  if (status != 0 && status != 2) std::abort();
  std::size_t queries = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first != std::string::npos && line[first] != '#') ++queries;
  }
  const bool toi = mode == collide2d::tool::Answer::toi;
  std::size_t answers = 0;
  std::istringstream produced(out.str());
  for (std::string line; std::getline(produced, line); ++answers) {
    if (line.rfind("error: ", 0) == 0) continue;
    std::istringstream fields(line);
    if (mode == collide2d::tool::Answer::area) {  // area cx cy iou: finite, the area not negative, iou in [0, 1]
      double area = -1, cx = 0, cy = 0, iou = -1;
      fields >> area >> cx >> cy >> iou;
      if (!fields || !(area >= 0) || !std::isfinite(area) || !std::isfinite(cx) || !std::isfinite(cy) ||
          !(iou >= 0 && iou <= 1))
        std::abort();
      continue;
    }
    int hit = -1;
    double v[5];
    fields >> hit >> v[0] >> v[1] >> v[2] >> v[3] >> v[4];
    if (!fields || (hit != 0 && hit != 1)) std::abort();
    for (const double x : v) {
      if (!std::isfinite(x)) std::abort();
    }
    if (toi ? (v[0] < 0 || v[0] > 1 || (hit == 0 && v[0] != 1)) : (v[0] == 0) != (hit == 1)) std::abort();
  }
  if (answers != queries) {
    std::fprintf(stderr, "%zu answers for %zu queries\n", answers, queries);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), std::min<std::size_t>(size, 4096));
  check(text, collide2d::tool::Answer::distance);
  check(text, collide2d::tool::Answer::toi);
  check(text, collide2d::tool::Answer::area);
  return 0;
}
