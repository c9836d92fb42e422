// settle: drops ellipses, rectangles and circles into a box and writes an SVG of the settled pile
// (examples/settle/settle.h).
//   settle [--bodies N] [--width W] [--seed S] [--svg FILE]
#include "examples/settle/settle.h"
#include "tools/cli_args.h"

#include <iostream>
#include <string>
#include <string_view>

namespace {

constexpr const char* kUsage =
    "usage: settle [--bodies N] [--width W] [--seed S] [--svg FILE]\n"
    "  Drops N bodies (default 2000: ellipses, rectangles and circles) into a box W wide\n"
    "  (default 40) under gravity, pushes overlapping ones apart with a spring-dashpot on\n"
    "  their exact penetration depth, runs until they rest, and prints what it found;\n"
    "  --svg draws the pile.\n";

int run(int argc, char** argv) {
  collide2d::settle::SettleOptions options;
  std::string svg_path;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--bodies") {
      options.bodies = collide2d::cli::positive_count(arg, collide2d::cli::value_of(i, argc, argv));
    } else if (arg == "--width") {
      options.width = collide2d::cli::positive_count(arg, collide2d::cli::value_of(i, argc, argv));
    } else if (arg == "--seed") {
      options.seed =
          static_cast<unsigned>(collide2d::cli::positive_count(arg, collide2d::cli::value_of(i, argc, argv)));
    } else if (arg == "--svg") {
      svg_path = collide2d::cli::value_of(i, argc, argv);
    } else {
      throw collide2d::cli::UsageError("unknown argument '" + std::string(arg) + "'");
    }
  }
  collide2d::cli::check_writable({svg_path});
  const collide2d::settle::SettleResult r = collide2d::settle::settle(options, &std::cerr);
  std::cout << r.shapes.size() << " bodies, " << (r.at_rest ? "at rest" : "still moving") << " after " << r.seconds
            << " s (" << r.steps << " steps); fastest " << r.max_speed << "; deepest contact " << r.max_penetration
            << " = " << r.max_penetration / r.smallest * 100 << "% of the smallest half-size " << r.smallest << "; "
            << r.outside << " outside the box\n";
  collide2d::cli::write_file(svg_path, "pile",
                             [&r](std::ostream& out) { collide2d::settle::write_settle_svg(r, out); });
  return r.at_rest && r.outside == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return collide2d::cli::run_main(argc, argv, "settle", kUsage, [&] { return run(argc, argv); });
}
