// collide2d_report: speed against error of every ellipse-ellipse distance method and of the contact
// depth (bench/report.h).
// Not installed: it links Box2D and the 50-digit reference, which the library and the collide2d
// command do not.
//   collide2d_report [--json FILE] [--pairs N]
#include "bench/report.h"
#include "tools/cli_args.h"

#include <iostream>
#include <string>
#include <string_view>

namespace {

constexpr const char* kUsage =
    "usage: collide2d_report [--json FILE] [--pairs N]\n"
    "  Times every ellipse-ellipse distance method (robust, gradient, polynomial, Box2D on\n"
    "  inscribed and circumscribed 8- to 256-gons) on N separated pairs (default 200) and\n"
    "  measures its error against 50-digit arithmetic; prints a table. Then the contact\n"
    "  depth of N overlapping pairs: collide2d's contact() against Box2D's manifold on\n"
    "  inscribed and circumscribed 5- to 8-gons (a second table). --json writes both as JSON.\n";

int report(int argc, char** argv) {
  collide2d::report::ReportOptions options;
  std::string json_path;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--json") {
      json_path = collide2d::cli::value_of(i, argc, argv);
    } else if (arg == "--pairs") {
      options.pairs = collide2d::cli::positive_count(arg, collide2d::cli::value_of(i, argc, argv));
    } else {
      throw collide2d::cli::UsageError("unknown argument '" + std::string(arg) + "'");
    }
  }
  const auto distance = collide2d::report::measure_methods(options);
  collide2d::report::print_report(
      distance, "ellipse-ellipse distance, " + std::to_string(options.pairs) + " separated pairs", options, std::cout);
  std::cout << '\n';
  const auto contact = collide2d::report::measure_contact_methods(options);
  collide2d::report::print_report(
      contact, "ellipse-ellipse contact depth, " + std::to_string(options.pairs) + " overlapping pairs", options,
      std::cout);
  collide2d::cli::write_file(json_path, "measurements", [&](std::ostream& out) {
    collide2d::report::write_report_json(distance, contact, options, out);
  });
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return collide2d::cli::run_main(argc, argv, "collide2d_report", kUsage, [&] { return report(argc, argv); });
}
