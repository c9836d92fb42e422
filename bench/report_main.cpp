// collide2d_report: speed against error of every ellipse-ellipse distance method and of the contact
// depth (bench/report.h).
// Not installed: it links Box2D and the 50-digit reference, which the library and the collide2d
// command do not.
//   collide2d_report [--json FILE] [--html FILE] [--pairs N]
#include "bench/report.h"
#include "tools/cli_args.h"

#include <iostream>
#include <string>
#include <string_view>
#include <vector>

namespace {

constexpr const char* kUsage =
    "usage: collide2d_report [--json FILE] [--html FILE] [--pairs N]\n"
    "  Times every ellipse-ellipse distance method (robust, gradient, polynomial, Box2D on\n"
    "  inscribed and circumscribed 8- to 256-gons) on N separated pairs (default 200) and\n"
    "  measures its error against 50-digit arithmetic; prints a table. Then the contact\n"
    "  depth of N overlapping pairs of each kind with an ellipse (rect, circle, ellipse,\n"
    "  polygon, capsule, segment): collide2d's contact, one pair at a time, batched and to\n"
    "  tolerances of 1e-1 to 1e-12 of the size, against Box2D 2.4.1's manifold on inscribed\n"
    "  and circumscribed 5- to 8- and 16-gons and, in a build given Box2D v3's source, v3's on\n"
    "  inscribed 5- to 8-gons (a table each, with the normal's and the point's errors).\n"
    "  --json writes all as JSON; --html as a page, the plot of speed against error\n"
    "  interactive beside the tables.\n";

int report(int argc, char** argv) {
  collide2d::report::ReportOptions options;
  std::string json_path, html_path;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--json") {
      json_path = collide2d::cli::value_of(i, argc, argv);
    } else if (arg == "--html") {
      html_path = collide2d::cli::value_of(i, argc, argv);
    } else if (arg == "--pairs") {
      options.pairs = collide2d::cli::positive_count(arg, collide2d::cli::value_of(i, argc, argv));
    } else {
      throw collide2d::cli::UsageError("unknown argument '" + std::string(arg) + "'");
    }
  }
  collide2d::cli::check_writable({json_path, html_path});
  const auto distance = collide2d::report::measure_methods(options);
  collide2d::report::print_report(
      distance, "ellipse-ellipse distance, " + std::to_string(options.pairs) + " separated pairs", options, std::cout);
  std::cout << '\n';
  const auto contact = collide2d::report::measure_contact_methods(options);
  for (const char* pair :
       {"rect-ellipse", "circle-ellipse", "ellipse-ellipse", "polygon-ellipse", "capsule-ellipse", "segment-ellipse"}) {
    std::vector<collide2d::report::MethodResult> rows;
    for (const auto& r : contact) {
      if (r.pair == pair) rows.push_back(r);
    }
    std::cout << '\n';
    collide2d::report::print_report(
        rows, std::string(pair) + " contact depth, " + std::to_string(options.pairs) + " overlapping pairs", options,
        std::cout);
  }
  collide2d::cli::write_file(json_path, "measurements", [&](std::ostream& out) {
    collide2d::report::write_report_json(distance, contact, options, out);
  });
  collide2d::cli::write_file(html_path, "report page", [&](std::ostream& out) {
    collide2d::report::write_report_html(distance, contact, options, out);
  });
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return collide2d::cli::run_main(argc, argv, "collide2d_report", kUsage, [&] { return report(argc, argv); });
}
