// collide2d: the command line. `collide2d query [--method NAME]... [--boundary] < queries`
// (see query_command.h).
#include "tools/query_command.h"

#include <cstring>
#include <iostream>
#include <string_view>

namespace {

constexpr const char* kUsage =
    "usage: collide2d query [--method NAME]... [--boundary]\n"
    "  Reads '<shapeA> ; <shapeB>' lines from stdin, a shape being\n"
    "    circle cx cy r | ellipse cx cy a b theta | rect cx cy hx hy theta   (radians)\n"
    "  and writes 'overlap distance ax ay bx by' per line (errors as 'error: <reason>').\n"
    "  --method minkowski|closest-features|all-features\n"
    "      the rectangle-ellipse overlap test (default minkowski)\n"
    "  --method robust|gradient|polynomial\n"
    "      the ellipse-ellipse distance solver (default robust; gradient and polynomial are\n"
    "      the seed baselines)\n"
    "  --boundary  distance and closest points between the boundary curves instead of the\n"
    "      solids (circles and ellipses; nested shapes give their gap)\n";

int query(int argc, char** argv) {
  collide2d::tool::QueryOptions options;
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--method") {
      if (i + 1 == argc) throw collide2d::tool::ParseError("--method needs a name");
      collide2d::tool::apply_method(argv[++i], options);
    } else if (arg == "--boundary") {
      options.boundary = true;
    } else {
      throw collide2d::tool::ParseError("unknown argument '" + std::string(arg) + "'");
    }
  }
  std::ios::sync_with_stdio(false);
  return collide2d::tool::run_query(std::cin, std::cout, std::cerr, options);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::cout << kUsage;
    return 0;
  }
  if (argc < 2 || std::strcmp(argv[1], "query") != 0) {
    std::cerr << kUsage;
    return 2;
  }
  try {
    return query(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "collide2d: " << e.what() << '\n' << kUsage;
    return 2;
  }
}
