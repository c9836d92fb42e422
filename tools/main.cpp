// collide2d: the command line.
//   collide2d query [--method NAME]... [--boundary | --contact | --toi | --area] < queries   (query_command.h)
//   collide2d run [scene.json] [--svg FILE] [--html FILE] [--replay FILE] [--frames N] [--threads N]
//       (scene_run.h)
//   collide2d replay FILE.c2dr --html FILE                       (replay_page.h)
// It links the library and the JSON reader only; the speed-against-error report, which needs Box2D
// and the 50-digit reference, is bench/collide2d_report.
#include "tools/cli_args.h"
#include "tools/query_command.h"
#include "tools/replay/replay_page.h"
#include "tools/scene/scene_run.h"
#ifdef COLLIDE2D_WITH_MPI
#include "tools/scene/distributed_run.h"
#endif

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>

namespace {

const std::string kQueryUsage =
    "usage: collide2d query [--method NAME]... [--boundary | --contact | --toi | --area]\n"
    "  Reads '<shapeA> ; <shapeB>' lines from stdin, a shape being one of\n" +
    collide2d::tool::shape_grammar("    ") +
    "  (angles in radians), and shape A also chain gx1 gy1 x1 y1 x2 y2 gx2 gy2, a chain\n"
    "  segment between its neighbours' far points; it writes 'overlap distance ax ay bx by'\n"
    "  per line (errors as 'error: <reason>').\n"
    "  --method minkowski|closest-features|all-features\n"
    "      the rectangle-ellipse overlap test (default minkowski, the kernel; the others are\n"
    "      reference methods in plain double)\n"
    "  --method robust|gradient|polynomial\n"
    "      the ellipse-ellipse distance solver (default robust, the kernel; gradient and\n"
    "      polynomial are reference methods, to measure it; with --boundary, a circle and an\n"
    "      ellipse too). With a method named, a line of a pair it does not cover is an error\n"
    "  --boundary  distance and closest points between the boundary curves instead of the\n"
    "      solids (circles and ellipses; nested shapes give their gap)\n"
    "  --contact   writes 'separation nx ny ax ay bx by' instead: the signed distance (minus\n"
    "      the penetration depth when the solids overlap), the unit normal from A to B, and\n"
    "      the deepest points (the closest points when apart)\n"
    "  --toi       reads '<shapeA> @ vx vy w ; <shapeB> @ vx vy w' (velocity and turn per\n"
    "      step; a shape without '@' is at rest) and writes 'hit t nx ny px py': hit 1 and\n"
    "      the first time of contact in [0, 1] (0 if they overlap at the start), or hit 0\n"
    "      and t 1; the normal from A to B and the midpoint of the closest points at t\n"
    "  --area      writes 'area cx cy iou' instead: the exact area of the overlap, its\n"
    "      centroid (A's centre where they share no area) and the intersection over union\n";

constexpr const char* kRunUsage =
    "usage: collide2d run [scene.json] [--svg FILE] [--html FILE] [--replay FILE] [--frames N] [--threads N]\n"
    "  Runs the scene (default: a built-in scene of 4000 moving circles, ellipses and\n"
    "  rectangles on two layers that never pair, 8 continuous bullets, a static level (a\n"
    "  chain cave with a hilly floor, slopes and rocks), and 4 static sensors) through\n"
    "  the broad phase (sweep and prune for moving bodies, a tree for static ones) and\n"
    "  the narrow phase, frame by frame, then prints what they found (bullets: their\n"
    "  impacts within each frame; the pairs the filters drop; each sensor's contents)\n"
    "  and how long it took. --svg draws the last frame; --html writes a page that\n"
    "  replays every frame in a browser; --replay writes the recording itself (a .c2dr\n"
    "  file, as a Recorder writes one); --frames overrides the scene's frame count;\n"
    "  --threads the World's update threads (default: every hardware thread).\n";

constexpr const char* kReplayUsage =
    "usage: collide2d replay FILE.c2dr --html FILE\n"
    "  Writes the page that replays a recording (collide2d run --replay, or a program's\n"
    "  own Recorder) in a browser: one file, the recording inside it.\n";

constexpr const char* kReportNote =
    "The speed-against-error report of the ellipse distance methods is a separate program\n"
    "of the build tree, bench/collide2d_report (it links Box2D; not installed).\n";

const std::string kUsage = kQueryUsage + "\n" + kRunUsage + "\n" + kReplayUsage + "\n" + kReportNote;

// `collide2d <command> --help` (or -h) anywhere among its arguments.
bool wants_help(int argc, char** argv) {
  for (int i = 2; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--help" || std::string_view(argv[i]) == "-h") return true;
  }
  return false;
}

int query(int argc, char** argv) {
  if (wants_help(argc, argv)) {
    std::cout << kQueryUsage;
    return 0;
  }
  collide2d::tool::QueryOptions options;
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--method") {
      if (i + 1 == argc) throw collide2d::cli::UsageError("--method needs a name");
      try {
        collide2d::tool::apply_method(argv[++i], options);
      } catch (const collide2d::tool::ParseError& e) {
        throw collide2d::cli::UsageError(e.what());
      }
    } else if (arg == "--boundary" || arg == "--contact" || arg == "--toi" || arg == "--area") {
      using collide2d::tool::Answer;
      const Answer chosen = arg == "--boundary"  ? Answer::boundary
                            : arg == "--contact" ? Answer::contact
                            : arg == "--toi"     ? Answer::toi
                                                 : Answer::area;
      if (options.answer != Answer::distance && options.answer != chosen) {
        throw collide2d::cli::UsageError("--boundary, --contact, --toi and --area cannot be combined");
      }
      options.answer = chosen;
    } else {
      throw collide2d::cli::UsageError("unknown argument '" + std::string(arg) + "'");
    }
  }
  try {
    collide2d::tool::check_options(options);
  } catch (const collide2d::tool::ParseError& e) {
    throw collide2d::cli::UsageError(e.what());
  }
  std::ios::sync_with_stdio(false);
  return collide2d::tool::run_query(std::cin, std::cout, std::cerr, options);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw collide2d::tool::SceneError("cannot read '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

#ifdef COLLIDE2D_WITH_MPI
// Under mpirun (Open MPI names the rank count in the environment): every rank runs the scene, rank
// 0 prints.
int run_on_ranks(collide2d::tool::Scene scene, unsigned threads, const std::string& title) {
  MPI_Init(nullptr, nullptr);
  struct Finalize {
    ~Finalize() { MPI_Finalize(); }
  } finalize;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) std::cout << title << std::flush;
  const collide2d::tool::RunSummary summary =
      collide2d::tool::run_distributed(std::move(scene), MPI_COMM_WORLD, threads, rank == 0 ? &std::cerr : nullptr);
  if (rank == 0) collide2d::tool::print_summary(summary, std::cout);
  return 0;
}
#endif

int run(int argc, char** argv) {
  if (wants_help(argc, argv)) {
    std::cout << kRunUsage;
    return 0;
  }
  std::string scene_path, svg_path, html_path, replay_path;
  int frames = 0;
  unsigned threads = 0;
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--svg") {
      svg_path = collide2d::cli::value_of(i, argc, argv);
    } else if (arg == "--html") {
      html_path = collide2d::cli::value_of(i, argc, argv);
    } else if (arg == "--replay") {
      replay_path = collide2d::cli::value_of(i, argc, argv);
    } else if (arg == "--frames") {
      frames = collide2d::cli::positive_count(arg, collide2d::cli::value_of(i, argc, argv));
    } else if (arg == "--threads") {
      threads = static_cast<unsigned>(collide2d::cli::positive_count(arg, collide2d::cli::value_of(i, argc, argv)));
    } else if (!arg.starts_with("--") && scene_path.empty()) {
      scene_path = arg;
    } else {
      throw collide2d::cli::UsageError("unknown argument '" + std::string(arg) + "'");
    }
  }
  collide2d::cli::check_writable({svg_path, html_path, replay_path});
  collide2d::tool::Scene scene =
      scene_path.empty() ? collide2d::tool::default_scene() : collide2d::tool::parse_scene(read_file(scene_path));
  if (frames > 0) scene.frames = frames;
  std::ostringstream title;
  title << "scene " << (scene_path.empty() ? "built-in" : scene_path) << ": " << scene.bodies.size() << " bodies, "
        << scene.frames << " frames\n";
#ifdef COLLIDE2D_WITH_MPI
  if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr) {
    if (!svg_path.empty() || !html_path.empty() || !replay_path.empty()) {
      throw collide2d::cli::UsageError("--svg, --html and --replay draw one process's World: run without mpirun");
    }
    return run_on_ranks(std::move(scene), threads, title.str());
  }
#endif
  std::cout << title.str();
  collide2d::tool::SceneRun runner(std::move(scene), threads);
  collide2d::Recorder recorder;
  const bool records = !html_path.empty() || !replay_path.empty();
  const collide2d::tool::RunSummary summary = runner.run(&std::cerr, records ? &recorder : nullptr);
  collide2d::tool::print_summary(summary, std::cout);
  collide2d::cli::write_file(svg_path, "picture of the last frame",
                             [&runner](std::ostream& out) { collide2d::tool::write_svg(runner, out); });
  collide2d::cli::write_file(replay_path, "recording", [&recorder](std::ostream& out) { recorder.write(out); });
  collide2d::cli::write_file(html_path, "replay page", [&recorder](std::ostream& out) {
    std::ostringstream bytes;
    recorder.write(bytes);
    collide2d::tool::write_replay_page(bytes.str(), out);
  });
  return 0;
}

int replay(int argc, char** argv) {
  if (wants_help(argc, argv)) {
    std::cout << kReplayUsage;
    return 0;
  }
  std::string input, html_path;
  for (int i = 2; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--html") {
      html_path = collide2d::cli::value_of(i, argc, argv);
    } else if (!arg.starts_with("--") && input.empty()) {
      input = arg;
    } else {
      throw collide2d::cli::UsageError("unknown argument '" + std::string(arg) + "'");
    }
  }
  if (input.empty()) throw collide2d::cli::UsageError("replay needs a recording (a .c2dr file)");
  if (html_path.empty()) throw collide2d::cli::UsageError("replay needs --html FILE, the page to write");
  collide2d::cli::check_writable({html_path});
  const std::string bytes = read_file(input);
  collide2d::cli::write_file(html_path, "replay page",
                             [&bytes](std::ostream& out) { collide2d::tool::write_replay_page(bytes, out); });
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return collide2d::cli::run_main(argc, argv, "collide2d", kUsage.c_str(), [&] {
    const std::string_view command = argc >= 2 ? argv[1] : "";
    if (command == "query") return query(argc, argv);
    if (command == "run") return run(argc, argv);
    if (command == "replay") return replay(argc, argv);
    throw collide2d::cli::UsageError(command.empty() ? "no command given"
                                                     : "unknown command '" + std::string(command) + "'");
  });
}
