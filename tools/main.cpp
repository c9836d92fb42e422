// collide2d: the command line.
//   collide2d query [--method NAME]... [--boundary] < queries     (see query_command.h)
//   collide2d run [scene.json] [--svg FILE] [--frames N]          (see run_command.h, scene.h)
//   collide2d report [--svg FILE] [--pairs N]                      (see report_command.h)
#include "tools/query_command.h"
#include "tools/report_command.h"
#include "tools/run_command.h"

#include <charconv>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
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
    "      solids (circles and ellipses; nested shapes give their gap)\n"
    "\n"
    "usage: collide2d run [scene.json] [--svg FILE] [--frames N]\n"
    "  Runs the scene (default: a built-in scene of 4000 moving circles, ellipses and\n"
    "  rectangles) through the sweep-and-prune broad phase and the narrow phase, frame by\n"
    "  frame, then prints what they found and how long they took. --svg draws the last\n"
    "  frame; --frames overrides the scene's frame count.\n"
    "\n"
    "usage: collide2d report [--svg FILE] [--pairs N]\n"
    "  Times every ellipse-ellipse distance method (robust, gradient, polynomial, Box2D on\n"
    "  inscribed and circumscribed 8- to 256-gons) on N separated pairs (default 200) and\n"
    "  measures its error against 50-digit arithmetic; prints a table, --svg plots it.\n";

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

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw collide2d::tool::SceneError("cannot read '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int positive_count(std::string_view option, std::string_view word) {
  int n = 0;
  const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), n);
  if (ec != std::errc() || ptr != word.data() + word.size() || n < 1) {
    throw collide2d::tool::ParseError(std::string(option) + " needs a positive integer, got '" + std::string(word) + "'");
  }
  return n;
}

// Options that take a value: returns it, or throws when it is missing.
const char* value_of(int& i, int argc, char** argv) {
  if (i + 1 == argc) throw collide2d::tool::ParseError(std::string(argv[i]) + " needs a value");
  return argv[++i];
}

// Writes an SVG with `draw` when a path was given, and says where.
template <class Draw>
void write_svg_file(const std::string& path, const char* what, Draw draw) {
  if (path.empty()) return;
  std::ofstream out(path);
  draw(out);
  if (!out) throw collide2d::tool::ParseError("cannot write '" + path + "'");
  std::cout << what << ": " << path << '\n';
}

int run(int argc, char** argv) {
  std::string scene_path, svg_path;
  int frames = 0;
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--svg") {
      svg_path = value_of(i, argc, argv);
    } else if (arg == "--frames") {
      frames = positive_count(arg, value_of(i, argc, argv));
    } else if (!arg.starts_with("--") && scene_path.empty()) {
      scene_path = arg;
    } else {
      throw collide2d::tool::ParseError("unknown argument '" + std::string(arg) + "'");
    }
  }
  collide2d::tool::Scene scene =
      scene_path.empty() ? collide2d::tool::default_scene() : collide2d::tool::parse_scene(read_file(scene_path));
  if (frames > 0) scene.frames = frames;
  std::cout << "scene " << (scene_path.empty() ? "built-in" : scene_path) << ": " << scene.bodies.size() << " bodies, "
            << scene.frames << " frames\n";
  collide2d::tool::SceneRun runner(std::move(scene));
  const collide2d::tool::RunSummary summary = runner.run(&std::cerr);
  collide2d::tool::print_summary(summary, std::cout);
  write_svg_file(svg_path, "picture of the last frame", [&runner](std::ostream& out) { collide2d::tool::write_svg(runner, out); });
  return 0;
}

int report(int argc, char** argv) {
  collide2d::tool::ReportOptions options;
  std::string svg_path;
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--svg") {
      svg_path = value_of(i, argc, argv);
    } else if (arg == "--pairs") {
      options.pairs = positive_count(arg, value_of(i, argc, argv));
    } else {
      throw collide2d::tool::ParseError("unknown argument '" + std::string(arg) + "'");
    }
  }
  const auto results = collide2d::tool::measure_methods(options);
  collide2d::tool::print_report(results, options, std::cout);
  write_svg_file(svg_path, "plot", [&results](std::ostream& out) { collide2d::tool::write_report_svg(results, out); });
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::cout << kUsage;
    return 0;
  }
  const bool is_query = argc >= 2 && std::strcmp(argv[1], "query") == 0;
  const bool is_run = argc >= 2 && std::strcmp(argv[1], "run") == 0;
  const bool is_report = argc >= 2 && std::strcmp(argv[1], "report") == 0;
  if (!is_query && !is_run && !is_report) {
    std::cerr << kUsage;
    return 2;
  }
  try {
    if (is_report) return report(argc, argv);
    return is_query ? query(argc, argv) : run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "collide2d: " << e.what() << '\n' << kUsage;
    return 2;
  }
}
