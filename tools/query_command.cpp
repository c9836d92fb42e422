#include "tools/query_command.h"

#include "shapes/kinds.h"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <ostream>
#include <utility>
#include <vector>

namespace collide2d::tool {
namespace {

std::vector<std::string_view> split_words(std::string_view text) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t' && text[j] != '\r') ++j;
    if (j > i) words.push_back(text.substr(i, j - i));
    i = j;
  }
  return words;
}

// The whole word as a number in std::from_chars' grammar (decimal or scientific, inf, nan), a leading
// '+' allowed; out of range where it overflows or underflows to zero (a subnormal is in range). Read
// with strtod, as some standard libraries lack from_chars for doubles (Emscripten's, which builds
// the testbed); strtod's hexadecimal numbers are not in the grammar.
std::errc read_number(std::string_view word, double& value) {
  if (word.starts_with('+')) word.remove_prefix(1);
  const std::string text(word);
  if (text.empty() || text.find_first_of("xX") != std::string::npos) return std::errc::invalid_argument;
  errno = 0;
  char* end = nullptr;
  const double read = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::errc::invalid_argument;
  if (errno == ERANGE && (std::isinf(read) || read == 0.0)) return std::errc::result_out_of_range;
  value = read;
  return {};
}

double parse_number(std::string_view word) {
  double value = 0.0;
  const std::errc ec = read_number(word, value);
  if (ec == std::errc::result_out_of_range) throw ParseError("'" + std::string(word) + "' is out of range");
  if (ec != std::errc()) throw ParseError("'" + std::string(word) + "' is not a number");
  return value;
}

bool is_number(std::string_view word) {
  double value = 0.0;
  return read_number(word, value) != std::errc::invalid_argument;
}

using detail::Kind;
using detail::Kinds;

// `<word> <numbers>` for a kind written as a row (shapes/kinds.h): exactly its row's numbers, the
// shape made from them and checked.
template <class T>
Shape parse_row(const std::vector<std::string_view>& words) {
  constexpr std::size_t count = Kind<T>::row.size();
  const std::string word(Kind<T>::word), fields(detail::grammar_of<T>());
  const std::string takes = word + " takes " + std::to_string(count) + " numbers (" + fields + ")";
  std::vector<double> values;
  for (std::size_t k = 1; k < words.size() && k <= count; ++k) values.push_back(parse_number(words[k]));
  if (words.size() - 1 > count) {
    const std::string_view extra = words[count + 1];
    throw ParseError(is_number(extra) ? takes + ", got " + std::to_string(words.size() - 1)
                                      : "unexpected '" + std::string(extra) + "' after " + word + "'s " +
                                            std::to_string(count) + " numbers (" + fields + ")");
  }
  if (values.size() != count) throw ParseError(takes + ", got " + std::to_string(values.size()));
  Shape shape = Kind<T>::from_row(values.data());
  validate(shape);
  return shape;
}

// `polygon cx cy theta r x0 y0 x1 y1 ...`: 3 to 8 vertices, counter-clockwise about the centre.
Shape parse_polygon(const std::vector<std::string_view>& words) {
  std::vector<double> v;
  for (std::size_t k = 1; k < words.size(); ++k) v.push_back(parse_number(words[k]));
  if (v.size() < 10 || v.size() > 20 || v.size() % 2 != 0) {
    throw ParseError("polygon takes 4 numbers (cx cy theta r) and 3 to 8 vertices (x y each), got " +
                     std::to_string(v.size()) + " numbers");
  }
  std::vector<Vec2> vertices;
  for (std::size_t k = 4; k < v.size(); k += 2) vertices.emplace_back(v[k], v[k + 1]);
  Shape shape = ConvexPolygon::of(vertices, v[3]).at(Vec2(v[0], v[1]), v[2]);
  validate(shape);
  return shape;
}

Shape parse_shape(std::string_view text, const char* side) {
  const std::vector<std::string_view> words = split_words(text);
  if (words.empty()) throw ParseError(std::string("shape ") + side + " is missing");
  if (words[0] == Kind<ConvexPolygon>::word) return parse_polygon(words);
  std::optional<Shape> shape;
  Kinds::each([&]<class T>() {
    if constexpr (detail::HasRow<T>) {
      if (words[0] == Kind<T>::word) shape = parse_row<T>(words);
    }
  });
  if (shape) return *shape;
  throw ParseError("unknown shape '" + std::string(words[0]) + "' (expected " + Kinds::words("chain") + ")");
}

struct Side {
  Shape shape;
  Motion motion;
  bool moving = false;
};

std::string_view first_word(std::string_view text) {
  const std::vector<std::string_view> words = split_words(text);
  return words.empty() ? std::string_view{} : words[0];
}

// `chain gx1 gy1 x1 y1 x2 y2 gx2 gy2`: the chain segment from (x1, y1) to (x2, y2) between its
// ghosts, level geometry, so shape A and unmoving.
ChainSegment parse_chain(std::string_view text) {
  if (text.find('@') != std::string_view::npos) throw ParseError("a chain segment is level geometry: it does not move");
  const std::vector<std::string_view> words = split_words(text);
  std::vector<double> v;
  for (std::size_t k = 1; k < words.size(); ++k) v.push_back(parse_number(words[k]));
  if (v.size() != 8)
    throw ParseError("chain takes 8 numbers (gx1 gy1 x1 y1 x2 y2 gx2 gy2), got " + std::to_string(v.size()));
  const ChainSegment s = ChainSegment::of(Vec2(v[0], v[1]), Vec2(v[2], v[3]), Vec2(v[4], v[5]), Vec2(v[6], v[7]));
  validate(s);
  return s;
}

// `<shape>` or `<shape> @ vx vy w`.
Side parse_side(std::string_view text, const char* side) {
  const auto at = text.find('@');
  if (at == std::string_view::npos) return {parse_shape(text, side), {}, false};
  const std::vector<std::string_view> words = split_words(text.substr(at + 1));
  if (words.size() != 3) {
    throw ParseError(std::string("a motion takes 3 numbers (vx vy w) after '@', got ") + std::to_string(words.size()));
  }
  return {parse_shape(text.substr(0, at), side),
          {{parse_number(words[0]), parse_number(words[1])}, parse_number(words[2])},
          true};
}

std::string_view trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// A named method answers its own pairs only; any other line is refused, naming both.
void check_method_covers(const QueryLine& q, const QueryOptions& options) {
  const auto refuse = [&q](std::string_view word, const char* covers) {
    const std::string kinds = q.chain ? std::string("chain") : shape_name(q.a);
    throw ParseError("--method " + std::string(word) + " " + covers + "; this line is " + kinds + " ; " +
                     shape_name(q.b));
  };
  if (options.rect_ellipse && !baselines::rect_ellipse_covers(q.a, q.b)) {
    refuse(options.rect_ellipse->word, "tests a rect and an ellipse");
  }
  const bool boundary = options.answer == Answer::boundary;
  if (options.ellipse && !baselines::ellipse_solver_covers(q.a, q.b, boundary)) {
    refuse(options.ellipse->word,
           boundary ? "measures two ellipses, or a circle and an ellipse" : "measures two ellipses");
  }
}

}  // namespace

std::string shape_grammar(std::string_view indent) {
  std::array<std::string, Kinds::size> by_number;
  Kinds::each([&]<class T>() {
    by_number[Kind<T>::number] = std::string(Kind<T>::word) + ' ' + std::string(detail::grammar_of<T>());
  });
  std::string out;
  for (std::size_t k = 0; k < by_number.size(); ++k) {
    if (k % 3 != 0) {
      out += " | ";
    } else {
      if (k > 0) out += '\n';
      out += indent;
    }
    out += by_number[k];
  }
  return out + "\n";
}

std::optional<QueryLine> parse_query_line(std::string_view line) {
  const std::string_view body = trimmed(line);
  if (body.empty() || body.front() == '#') return std::nullopt;
  const auto sep = body.find(';');
  if (sep == std::string_view::npos) throw ParseError("expected '<shape> ; <shape>', found no ';'");
  if (body.find(';', sep + 1) != std::string_view::npos) throw ParseError("expected one ';', found more");
  const std::string_view a_text = body.substr(0, sep), b_text = body.substr(sep + 1);
  if (first_word(b_text) == "chain") throw ParseError("a chain segment is shape A only: write it first");
  if (first_word(a_text) == "chain") {
    const ChainSegment chain = parse_chain(a_text);
    const Side b = parse_side(b_text, "B");
    return QueryLine{chain.segment, b.shape, {}, b.motion, b.moving, chain};
  }
  const Side a = parse_side(a_text, "A"), b = parse_side(b_text, "B");
  return QueryLine{a.shape, b.shape, a.motion, b.motion, a.moving || b.moving};
}

void apply_method(std::string_view name, QueryOptions& options) {
  using baselines::EllipseSolver;
  using baselines::RectEllipseTest;
  constexpr NamedMethod<RectEllipseTest> overlap_methods[] = {{"minkowski", std::nullopt},
                                                              {"closest-features", RectEllipseTest::closest_features},
                                                              {"all-features", RectEllipseTest::all_features}};
  constexpr NamedMethod<EllipseSolver> distance_methods[] = {
      {"robust", std::nullopt}, {"gradient", EllipseSolver::gradient}, {"polynomial", EllipseSolver::polynomial}};
  for (const auto& named : overlap_methods) {
    if (name == named.word) return void(options.rect_ellipse = named);
  }
  for (const auto& named : distance_methods) {
    if (name == named.word) return void(options.ellipse = named);
  }
  throw ParseError("unknown method '" + std::string(name) +
                   "' (expected minkowski, closest-features, all-features, robust, gradient or polynomial)");
}

void check_options(const QueryOptions& options) {
  if ((options.rect_ellipse || options.ellipse) &&
      (options.answer == Answer::contact || options.answer == Answer::toi || options.answer == Answer::area)) {
    throw ParseError(
        "--method picks an overlap test or a distance solver: it does not go with --contact, --toi or --area");
  }
}

std::string answer(const QueryLine& q, const QueryOptions& options) {
  char buf[200];
  int n = 0;
  if (q.moving && options.answer != Answer::toi) throw ParseError("a motion ('@ vx vy w') needs --toi");
  check_method_covers(q, options);
  if (options.answer == Answer::toi) {
    // A chain segment stops only what starts in front of it.
    const TimeOfImpact r =
        q.chain && !in_front(*q.chain, q.b) ? TimeOfImpact{} : time_of_impact(q.a, q.a_motion, q.b, q.b_motion);
    n = std::snprintf(buf, sizeof buf, "%d %.17g %.17g %.17g %.17g %.17g", r.status == ToiStatus::miss ? 0 : 1,
                      r.t + 0.0, r.normal.x() + 0.0, r.normal.y() + 0.0, r.point.x() + 0.0, r.point.y() + 0.0);
  } else if (options.answer == Answer::area) {
    if (q.chain) throw ParseError("a chain segment has no area: --area takes two solid shapes");
    const OverlapArea o = overlap_area(q.a, q.b);
    n = std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %.17g", o.area, o.centroid.x() + 0.0, o.centroid.y() + 0.0,
                      iou(q.a, q.b));
  } else if (options.answer == Answer::contact) {
    const Contact c = q.chain ? contact(*q.chain, q.b) : contact(q.a, q.b);
    if (c.empty()) return "none";
    // + 0.0 prints a zero as 0, never -0 (a normal's sign of zero carries nothing).
    n = std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g", c.separation + 0.0,
                      c.normal.x() + 0.0, c.normal.y() + 0.0, c.point_a.x() + 0.0, c.point_a.y() + 0.0,
                      c.point_b.x() + 0.0, c.point_b.y() + 0.0);
  } else {
    const auto overlap_test = options.rect_ellipse ? options.rect_ellipse->method : std::nullopt;
    const auto solver = options.ellipse ? options.ellipse->method : std::nullopt;
    const bool hit = overlap_test ? baselines::overlaps(q.a, q.b, *overlap_test) : overlaps(q.a, q.b);
    const bool boundary = options.answer == Answer::boundary;
    const DistanceResult d =
        solver     ? boundary ? baselines::boundary_distance(q.a, q.b, *solver) : baselines::distance(q.a, q.b, *solver)
            : boundary ? boundary_distance(q.a, q.b)
                   : distance(q.a, q.b);
    n = std::snprintf(buf, sizeof buf, "%d %.17g %.17g %.17g %.17g %.17g", hit ? 1 : 0, d.distance, d.point_a.x(),
                      d.point_a.y(), d.point_b.x(), d.point_b.y());
  }
  return std::string(buf, static_cast<std::size_t>(n));
}

int run_query(std::istream& in, std::ostream& out, std::ostream& err, const QueryOptions& options) {
  int status = 0;
  std::string line;
  for (long number = 1; std::getline(in, line); ++number) {
    try {
      const std::optional<QueryLine> q = parse_query_line(line);
      if (q) out << answer(*q, options) << '\n';
    } catch (const std::exception& e) {  // ParseError, InvalidShape, UnsupportedPair
      out << "error: " << e.what() << '\n';
      err << "line " << number << ": " << e.what() << '\n';
      status = 2;
    }
  }
  return status;
}

}  // namespace collide2d::tool
