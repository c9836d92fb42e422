// Command-line helpers shared by `collide2d` (tools/main.cpp) and `collide2d_report`
// (bench/report_main.cpp). A mistake in the arguments throws UsageError, which the mains turn into
// a message, the usage's synopsis and exit status 2.
#pragma once

#include <collide2d/version.h>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace collide2d::cli {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline int positive_count(std::string_view option, std::string_view word) {
  int n = 0;
  const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), n);
  if (ec != std::errc() || ptr != word.data() + word.size() || n < 1) {
    throw UsageError(std::string(option) + " needs a positive integer, got '" + std::string(word) + "'");
  }
  return n;
}

// The value after the option at argv[i] (and i moved past it), or UsageError when it is missing.
inline const char* value_of(int& i, int argc, char** argv) {
  if (i + 1 == argc) throw UsageError(std::string(argv[i]) + " needs a value");
  return argv[++i];
}

// Throws when a file cannot be written at one of `paths` (empty ones are skipped), so that a main
// refuses a bad output path before its work rather than after it. A file there is left as it is;
// none is left where there was none.
inline void check_writable(std::initializer_list<std::string_view> paths) {
  for (const std::string_view path : paths) {
    if (path.empty()) continue;
    const bool existed = std::filesystem::exists(path);
    if (!std::ofstream(std::string(path), std::ios::app)) {
      throw std::runtime_error("cannot write '" + std::string(path) + "'");
    }
    if (!existed) std::filesystem::remove(path);
  }
}

// Writes a file with `draw` when a path was given, and says where on stdout.
template <class Draw>
void write_file(const std::string& path, const char* what, Draw draw) {
  if (path.empty()) return;
  std::ofstream out(path);
  draw(out);
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
  std::cout << what << ": " << path << '\n';
}

// The body of a main: --help or -h prints the usage, --version the program's name and version;
// otherwise `command()` runs, and any exception
// becomes one line, "<program>: <what>", on stderr with exit status 2. A UsageError adds the
// usage's synopsis lines (those that start with "usage:") and where the rest is.
template <class Command>
int run_main(int argc, char** argv, const char* program, const char* usage, Command command) {
  if (argc >= 2 && (std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "-h")) {
    std::cout << usage;
    return 0;
  }
  if (argc >= 2 && std::string_view(argv[1]) == "--version") {
    std::cout << program << ' ' << COLLIDE2D_VERSION_STRING << '\n';
    return 0;
  }
  try {
    return command();
  } catch (const UsageError& e) {
    std::cerr << program << ": " << e.what() << '\n';
    std::istringstream lines(usage);
    for (std::string line; std::getline(lines, line);) {
      if (line.starts_with("usage:")) std::cerr << line << '\n';
    }
    std::cerr << "(" << program << " --help says more)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << '\n';
    return 2;
  }
}

}  // namespace collide2d::cli
