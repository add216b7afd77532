// Fuzz target: the parsers of what a user types as numbers: ranges LO:HI:N (curves, sweeps),
// intervals LO:HI (tables), lists R1,R2 (curvature radii) and single numbers.
//
// Input: one letter choosing the parser, then the text it reads:
//   r  api::detail::parse_range (linear)      l  the same with --log (geometric)
//   i  api::detail::parse_interval             n  parse_real          m  parse_real with "inf"
//   c  a list of two numbers (bind_parameters, ParameterKind::reals, inf allowed)
//   f, o, a  a range the parser accepts, through the CLI: `bounce contact --csv` with --forces,
//            --overlaps or --contact-radii (jkr), with --log when the text has an odd length
// Properties (docs/hardening.md): each parser returns or throws InvalidArgument; a range is N
// finite, non-decreasing values from LO to HI (all > 0 with --log); an interval has
// 0 < LO < HI, finite; a list has its count of numbers, each in its range; the CLI keeps its
// contract. Ranges of more than 100000 points (the library allows 1e7) are skipped: their cost,
// not their parsing, would dominate.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "api/binding.hpp"  // the private parsers, as the unit tests reach them (src/)
#include "bounce/core/parameters.hpp"
#include "oracle.hpp"

using bounce::fuzz::finding;
using bounce::fuzz::only_bounce_errors;

namespace {

// The N of "LO:HI:N" when the text ends in ":N" with N a whole number in any form ("1000",
// "1e3", ".013031e8": parse_range takes each, docs/cli.md), else 0.
long points_of(const std::string& text) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos) return 0;
  double n = 0.0;
  const char* begin = text.data() + colon + 1;
  const auto [end, ec] = std::from_chars(begin, text.data() + text.size(), n);
  if (ec == std::errc::result_out_of_range) return -1;
  if (ec != std::errc() || end != text.data() + text.size() || !(n >= 0.0) || n != std::floor(n)) return 0;
  return n < 9e18 ? static_cast<long>(n) : -1;
}

void check_range(const std::string& text, bool log) {
  std::vector<double> v;
  if (!only_bounce_errors("parse_range", [&] { v = bounce::api::detail::parse_range("velocities", text, log); })) return;
  const long n = points_of(text);
  if (static_cast<long>(v.size()) != n) finding("parse_range(\"" + text + "\") gave " + std::to_string(v.size()) + " values");
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) finding("parse_range(\"" + text + "\") value " + std::to_string(i) + " is not finite");
    if (log && !(v[i] > 0.0)) finding("parse_range(\"" + text + "\", log) value " + std::to_string(i) + " is not > 0");
    if (i > 0 && v[i] < v[i - 1]) finding("parse_range(\"" + text + "\") decreases at value " + std::to_string(i));
  }
}

void check_interval(const std::string& text) {
  std::array<double, 2> v{};
  if (!only_bounce_errors("parse_interval", [&] { v = bounce::api::detail::parse_interval("velocities", text); })) return;
  if (!(v[0] > 0.0 && v[1] > v[0] && std::isfinite(v[1]))) finding("parse_interval(\"" + text + "\") is not 0 < LO < HI");
}

void check_list(const std::string& text) {
  bounce::ParameterSpec spec = bounce::real_parameter("curvature_radii", "curvature radii", "m", bounce::positive(), "");
  spec.kind = bounce::ParameterKind::reals;
  spec.count = 2;
  spec.range.infinite = true;
  const bounce::ParameterSpec specs[] = {spec};
  bounce::Parameters p;
  if (!only_bounce_errors("bind_parameters", [&] {
        p = bounce::bind_parameters(specs, {{"curvature_radii", text}}, "fuzz");
      })) {
    return;
  }
  const auto v = p.reals("curvature_radii");
  if (!v || v->size() != 2) finding("the list \"" + text + "\" was accepted without two numbers");
  for (double x : *v) {
    if (!spec.range.contains(x)) finding("the list \"" + text + "\" was accepted with a value out of range");
  }
}

void check_cli(char which, const std::string& text) {
  // A range the parser refuses, the CLI refuses the same way (exit 2): run it for the others,
  // which is much faster.
  if (!only_bounce_errors("parse_range", [&] { (void)bounce::api::detail::parse_range("forces", text, false); })) return;
  const char* option = which == 'f' ? "--forces" : which == 'o' ? "--overlaps" : "--contact-radii";
  std::vector<std::string> args = {"contact", "--material", "steel", "--radius", "1e-3", "--law",
                                   which == 'a' ? "jkr" : "hertz", "--csv", std::string(option) + "=" + text};
  if (text.size() % 2 == 1) args.emplace_back("--log");
  bounce::fuzz::check_cli(args, bounce::fuzz::run_cli(args));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const char which = static_cast<char>(data[0]);
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  const long n = points_of(text);
  if (n < 0 || n > 100000 || ((which == 'f' || which == 'o' || which == 'a') && n > 200)) return -1;
  switch (which) {
    case 'r': check_range(text, false); break;
    case 'l': check_range(text, true); break;
    case 'i': check_interval(text); break;
    case 'n': only_bounce_errors("parse_real", [&] { (void)bounce::parse_real("x", text); }); break;
    case 'm': only_bounce_errors("parse_real", [&] { (void)bounce::parse_real("x", text, true); }); break;
    case 'c': check_list(text); break;
    case 'f':
    case 'o':
    case 'a': check_cli(which, text); break;
    default: return -1;
  }
  return 0;
}
