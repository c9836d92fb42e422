// The table of pairs as docs/algorithms/README.md shows it, made from the registry of kinds and the
// pair table (shapes/kinds.h, narrowphase/pairs.h): for each pair of kinds in rank order, the file
// of its kernel for each query (its own, or the convex cores' method), whether it has a boundary
// distance and a batch. ctest pair_table checks the page; --write puts the table in it.
//
//   collide2d_pair_table (--check | --write) docs/algorithms/README.md
#include "narrowphase/pairs.h"

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>

namespace {

using namespace collide2d;
using detail::Kind;
using detail::Pair;

constexpr const char* kBegin =
    "<!-- pair table: made by collide2d_pair_table from the registry; ctest pair_table -->\n";
constexpr const char* kEnd = "<!-- pair table end -->\n";

// A row's kernel of its own is a function (its address taken as is); the cores' methods are
// templates of the row's base, OnCores.
template <class A, class B>
std::string link(const std::string& query, bool own) {
  const std::string file = own ? query + "_" + std::string(Kind<A>::word) + "_" + std::string(Kind<B>::word)
                           : std::is_same_v<B, Ellipse> ? query + "_core_ellipse"
                                                        : query + "_cores";
  return "[" + file + "](../../narrowphase/" + query + "/" + file + ".cpp)";
}

template <class A, class B>
std::string row() {
  using Row = Pair<A, B>;
  std::string out = "| " + std::string(Kind<A>::word) + "–" + std::string(Kind<B>::word) + " | ";
  out += link<A, B>(
             "overlap", requires { &Row::overlap; }) +
         " | ";
  out += link<A, B>(
             "distance", requires { &Row::distance; }) +
         " | ";
  out += link<A, B>(
             "contact", requires { &Row::contact; }) +
         " | ";
  out += std::string(requires { &Row::boundary; } ? "yes" : "—") + " | ";
  out += std::string(Row::batched ? "yes" : "—") + " |\n";
  return out;
}

std::string table() {
  std::string out = kBegin;
  out += "| pair | overlap | distance | contact | boundary distance | batch |\n";
  out += "| --- | --- | --- | --- | --- | --- |\n";
  [&out]<class... P>(std::tuple<P...>*) {
    ((out += row<typename P::First, typename P::Second>()), ...);
  }(static_cast<detail::AllPairs<detail::Kinds>::type*>(nullptr));
  return out + kEnd;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc == 3 ? argv[1] : "";
  if (mode != "--check" && mode != "--write") {
    std::cerr << "usage: collide2d_pair_table (--check | --write) docs/algorithms/README.md\n";
    return 2;
  }
  std::ifstream in(argv[2]);
  std::stringstream page;
  page << in.rdbuf();
  const std::string text = page.str();
  const std::size_t begin = text.find(kBegin), end = text.find(kEnd);
  if (!in || begin == std::string::npos || end == std::string::npos) {
    std::cerr << argv[2] << ": no pair table (between '" << kBegin << "' and '" << kEnd << "')\n";
    return 2;
  }
  const std::string now = table();
  const std::string shown = text.substr(begin, end + std::string(kEnd).size() - begin);
  if (mode == "--check") {
    if (shown == now) return 0;
    std::cerr << argv[2] << ": the pair table differs from the registry's; it is\n"
              << now << "(collide2d_pair_table --write " << argv[2] << " puts it there)\n";
    return 1;
  }
  std::ofstream(argv[2]) << text.substr(0, begin) << now << text.substr(end + std::string(kEnd).size());
  return 0;
}
