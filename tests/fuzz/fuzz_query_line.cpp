// Query-line fuzzer: any bytes as `collide2d query` input. Every line must be answered or refused
// with an `error:` line (ParseError, InvalidShape), never crash; answers carry six finite numbers,
// and the output keeps one line per query line.
#include "tools/query_command.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), std::min<std::size_t>(size, 4096));
  std::istringstream in(text);
  std::ostringstream out, err;
  const int status = collide2d::tool::run_query(in, out, err, {});
  if (status != 0 && status != 2) std::abort();
  std::size_t queries = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first != std::string::npos && line[first] != '#') ++queries;
  }
  std::size_t answers = 0;
  std::istringstream produced(out.str());
  for (std::string line; std::getline(produced, line); ++answers) {
    if (line.rfind("error: ", 0) == 0) continue;
    std::istringstream fields(line);
    int hit = -1;
    double v[5];
    fields >> hit >> v[0] >> v[1] >> v[2] >> v[3] >> v[4];
    if (!fields || (hit != 0 && hit != 1)) std::abort();
    for (const double x : v) {
      if (!std::isfinite(x)) std::abort();
    }
    if ((v[0] == 0) != (hit == 1)) std::abort();
  }
  if (answers != queries) {
    std::fprintf(stderr, "%zu answers for %zu queries\n", answers, queries);
    std::abort();
  }
  return 0;
}
