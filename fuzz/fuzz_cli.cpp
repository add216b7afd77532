// Fuzz target: the whole command line, bounce::cli::run in-process (the code main() runs).
//
// Input: the arguments after `bounce`, one per line, then optionally a line "%%" and a text
// that is both standard input (`rules`, `--load -`) and the file @FILE@. In arguments,
// @MATERIALS@, @TABLE@, @TTABLE@ and @RULES@ stand for valid files (data/materials.toml, an
// eps^N and an eps^T table, rules encounters) and @FILE@ for that text. The seeds are the
// recorded calls of tests/golden/calls.txt; the mutator below edits them with the real option
// set (api::commands(), api::offered_parameters(), the CLI's own flags): it changes the command,
// adds an option with a value drawn from its declaration (its range's ends and just beyond,
// zero, extremes, nan/inf, junk; a range LO:HI:N), retypes or removes one; and sometimes
// leaves the bytes to libFuzzer's own mutations. Crossovers cut at option boundaries.
// Properties: the CLI's contract (fuzz/oracle.hpp, docs/hardening.md). Work is capped, not
// judged: inputs with a range of more than 8 points (64 for `contact`) or more than 10000
// trajectory samples are skipped, and so are a `fit` without a small --grid (small_fit: at
// most 3 values an axis, 8 in all; @DATA@ is a 4-point data file, @FILE@ any text) and --help
// beside other options.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bounce/api/front_door.hpp"
#include "bounce/pair/materials_table.hpp"
#include "oracle.hpp"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace {

using Rng = std::minstd_rand;

// --- the input format ----------------------------------------------------------------------

struct Call {
  std::vector<std::string> args;
  std::optional<std::string> text;  // after "%%"
};

Call parse(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  Call call;
  std::size_t start = 0;
  while (start <= input.size()) {
    const std::size_t end = std::min(input.find('\n', start), input.size());
    std::string line = input.substr(start, end - start);
    if (line == "%%") {
      call.text = end < input.size() ? input.substr(end + 1) : std::string();
      break;
    }
    if (end == input.size() && line.empty()) break;  // the final newline
    call.args.push_back(std::move(line));
    start = end + 1;
  }
  return call;
}

std::string serialise(const Call& call) {
  std::string s;
  for (const std::string& a : call.args) s += a + "\n";
  if (call.text) s += "%%\n" + *call.text;
  return s;
}

// --- the option set --------------------------------------------------------------------------

struct Option {
  std::string name;                        // parameter name ("contact_end")
  std::optional<bounce::ParameterSpec> spec;  // none: one of the CLI's own
  std::string own;                         // the CLI's own: "flag", "file", "prefix"
};

// The CLI's own options (apps/bounce/commands.cpp), which the front door does not declare.
std::vector<Option> own_options(const std::string& command) {
  static const std::map<std::string, std::vector<std::pair<const char*, const char*>>> own = {
      {"materials", {{"json", "flag"}}},
      {"models", {{"json", "flag"}, {"markdown", "flag"}}},
      {"contact", {{"json", "flag"}, {"csv", "flag"}}},
      {"collide", {{"json", "flag"}, {"csv", "flag"}}},
      {"curve", {{"json", "flag"}, {"csv", "flag"}, {"progress", "flag"}}},
      {"analytic", {{"json", "flag"}}},
      {"sticking", {{"json", "flag"}, {"progress", "flag"}}},
      {"rules", {{"input", "file"}}},
      {"table", {{"json", "flag"}, {"csv", "flag"}, {"c_header", "prefix"}, {"load", "file"}, {"progress", "flag"}}},
      {"fit", {{"json", "flag"}, {"progress", "flag"}, {"data", "file"}, {"columns", "prefix"}}},
  };
  std::vector<Option> out;
  if (const auto it = own.find(command); it != own.end()) {
    for (const auto& [name, kind] : it->second) out.push_back({name, std::nullopt, kind});
  }
  return out;
}

const std::vector<Option>& options_of(const std::string& command) {
  static std::map<std::string, std::vector<Option>> cache;
  auto it = cache.find(command);
  if (it != cache.end()) return it->second;
  std::vector<Option> options = own_options(command);
  try {
    for (const bounce::ParameterSpec& s : bounce::api::offered_parameters(command)) options.push_back({s.name, s, ""});
  } catch (const bounce::Error&) {  // not a command: nothing to offer
  }
  return cache.emplace(command, std::move(options)).first->second;
}

std::string option_name(const std::string& parameter) {
  std::string out = "--" + parameter;
  for (char& c : out) c = c == '_' ? '-' : c;
  return out;
}

// --- values ------------------------------------------------------------------------------------

template <class T>
const T& pick(Rng& rng, const std::vector<T>& items) {
  return items[rng() % items.size()];
}

std::string junk(Rng& rng) {
  static const std::vector<std::string> words = {"",     " ",    "-",      "--",   "1e",  "0x10", "1,2", "1:2",
                                                 "1 2",  "+1",   "1e-3x",  "true", "NaN", "INF",  "-0",  "0e0",
                                                 "1e+", ".5",    "5.",     "@FILE@", "=", "1e-3,", ",", "\t1"};
  return pick(rng, words);
}

std::string number(Rng& rng, const bounce::Range* range) {
  const double lo = range ? range->lo : -INFINITY, hi = range ? range->hi : INFINITY;
  switch (rng() % 10) {
    case 0: return pick(rng, std::vector<std::string>{"0", "-0", "1", "-1", "2", "0.5", "1e-6", "1e3"});
    case 1: return pick(rng, std::vector<std::string>{"inf", "-inf", "nan", "1e308", "-1e308", "1.7976931348623157e308"});
    case 2: return pick(rng, std::vector<std::string>{"5e-324", "1e-310", "2.2250738585072014e-308", "1e-300", "1e-30"});
    case 3: return std::isfinite(lo) ? fmt::format("{}", lo) : "-1e300";
    case 4: return std::isfinite(hi) ? fmt::format("{}", hi) : "1e300";
    case 5: return fmt::format("{}", std::isfinite(lo) ? std::nextafter(lo, -INFINITY) : -1e-300);
    case 6: return fmt::format("{}", std::isfinite(hi) ? std::nextafter(hi, INFINITY) : 1e-300);
    case 7: return junk(rng);
    default: {  // log-uniform, either sign, inside the range when it has finite ends
      std::uniform_real_distribution<double> exponent(-20.0, 20.0), unit(0.0, 1.0);
      double x = std::pow(10.0, exponent(rng)) * (rng() % 4 == 0 ? -1.0 : 1.0);
      if (std::isfinite(lo) && std::isfinite(hi) && rng() % 2 == 0) x = lo + unit(rng) * (hi - lo);
      if (range && range->integer) x = std::round(x);
      return fmt::format("{:.6g}", x);
    }
  }
}

std::string range_text(Rng& rng, bool with_count) {
  std::string s = number(rng, nullptr) + ":" + number(rng, nullptr);
  if (rng() % 3 != 0) {  // mostly a sensible range
    std::uniform_real_distribution<double> exponent(-9.0, 3.0);
    const double lo = std::pow(10.0, exponent(rng)), hi = lo * std::pow(10.0, exponent(rng) / 3.0 + 1.0);
    s = fmt::format("{:.4g}:{:.4g}", lo, hi);
  }
  if (with_count) s += fmt::format(":{}", rng() % 10 == 0 ? pick(rng, std::vector<int>{0, 1, 100000000}) : 1 + int(rng() % 8));
  return s;
}

std::string file(Rng& rng) {
  return pick(rng, std::vector<std::string>{"@MATERIALS@", "@TABLE@", "@TTABLE@", "@RULES@", "@FILE@", "@DATA@", "-",
                                            "/nonexistent/file", "/"});
}

// A value for `option`, or none for a flag.
std::optional<std::string> value_for(Rng& rng, const Option& option) {
  if (!option.spec) {
    if (option.own == "flag") return std::nullopt;
    if (option.own == "file") return file(rng);
    return pick(rng, std::vector<std::string>{"k13", "t", "_x1", "1abc", "", "a-b", "int", "nan"});
  }
  const bounce::ParameterSpec& s = *option.spec;
  if (rng() % 16 == 0) return junk(rng);
  switch (s.kind) {
    case bounce::ParameterKind::flag: return std::nullopt;
    case bounce::ParameterKind::real: return number(rng, &s.range);
    case bounce::ParameterKind::reals: {
      std::string v = number(rng, &s.range);
      const std::size_t count = rng() % 8 == 0 ? s.count + 1 : s.count;
      for (std::size_t i = 1; i < count; ++i) v += "," + number(rng, &s.range);
      return v;
    }
    case bounce::ParameterKind::choice: return pick(rng, s.choices);
    case bounce::ParameterKind::text:
      if (s.name == "material" || s.name == "material2") return pick(rng, bounce::MaterialTable::builtin().names());
      if (s.name == "materials_file") return file(rng);
      if (s.placeholder == "LO:HI:N") return range_text(rng, true);
      if (s.placeholder == "LO:HI") return range_text(rng, false);
      return junk(rng);
  }
  return junk(rng);
}

// --- the mutator --------------------------------------------------------------------------------

bool is_option(const std::string& arg) { return arg.starts_with("--"); }

// Where the option at args[i] ends (past its value, if that is a separate argument).
std::size_t option_end(const std::vector<std::string>& args, std::size_t i) {
  return args[i].find('=') == std::string::npos && i + 1 < args.size() && !is_option(args[i + 1]) ? i + 2 : i + 1;
}

void change_command(Rng& rng, Call& call) {
  std::vector<std::string> names;
  for (const auto& c : bounce::api::commands()) names.push_back(c.name);
  names.insert(names.end(), {"--version", "--help", "colide", ""});
  call.args.front() = names[rng() % (names.size() - (rng() % 16 == 0 ? 0 : 4))];
}

void add_option(Rng& rng, Call& call) {
  const auto& options = options_of(call.args.front());
  if (options.empty()) return change_command(rng, call);
  const Option& option = pick(rng, options);
  const auto value = value_for(rng, option);
  std::vector<std::string> added = {option_name(option.name)};
  if (value && rng() % 4 == 0) {
    added.front() += "=" + *value;
  } else if (value) {
    added.push_back(*value);
  }
  const std::size_t at = 1 + rng() % call.args.size();
  call.args.insert(call.args.begin() + static_cast<std::ptrdiff_t>(at), added.begin(), added.end());
}

std::vector<std::size_t> option_positions(const Call& call) {
  std::vector<std::size_t> at;
  for (std::size_t i = 1; i < call.args.size(); ++i) {
    if (is_option(call.args[i])) at.push_back(i);
  }
  return at;
}

void retype_option(Rng& rng, Call& call) {
  const auto at = option_positions(call);
  if (at.empty()) return add_option(rng, call);
  const std::size_t i = pick(rng, at);
  const std::string name = call.args[i].substr(2, call.args[i].find('=') - 2);
  std::string parameter = name;
  for (char& c : parameter) c = c == '-' ? '_' : c;
  for (const Option& option : options_of(call.args.front())) {
    if (option.name != parameter) continue;
    const auto value = value_for(rng, option);
    const std::size_t end = option_end(call.args, i);
    call.args.erase(call.args.begin() + static_cast<std::ptrdiff_t>(i), call.args.begin() + static_cast<std::ptrdiff_t>(end));
    std::vector<std::string> added = {option_name(parameter)};
    if (value) added.push_back(*value);
    call.args.insert(call.args.begin() + static_cast<std::ptrdiff_t>(i), added.begin(), added.end());
    return;
  }
}

void remove_option(Rng& rng, Call& call) {
  const auto at = option_positions(call);
  if (at.empty()) return;
  const std::size_t i = pick(rng, at);
  call.args.erase(call.args.begin() + static_cast<std::ptrdiff_t>(i),
                  call.args.begin() + static_cast<std::ptrdiff_t>(option_end(call.args, i)));
}


void mutate_text(Call& call, std::size_t max_size) {
  std::string text = call.text.value_or("");
  const std::size_t size = text.size();
  text.resize(std::max<std::size_t>(size * 2, 64));
  text.resize(LLVMFuzzerMutate(reinterpret_cast<std::uint8_t*>(text.data()), size, std::min(text.size(), max_size)));
  call.text = text;
}

// --- running a call ---------------------------------------------------------------------------

std::string substituted(std::string arg, const std::string& text_file) {
  static const std::vector<std::pair<std::string, std::string>> files = {
      {"@MATERIALS@", BOUNCE_SOURCE_DIR "/data/materials.toml"},
      {"@TABLE@", BOUNCE_FUZZ_DIR "/corpus/table/normal-krijt.json"},
      {"@TTABLE@", BOUNCE_FUZZ_DIR "/corpus/table/tangential-viscoelastic.json"},
      {"@RULES@", BOUNCE_SOURCE_DIR "/tests/golden/rules-oblique.json"},
      {"@DATA@", BOUNCE_FUZZ_DIR "/corpus/cli-data/small.csv"},
  };
  for (const auto& [key, path] : files) {
    for (auto at = arg.find(key); at != std::string::npos; at = arg.find(key)) arg.replace(at, key.size(), path);
  }
  if (const auto at = arg.find("@FILE@"); at != std::string::npos) arg.replace(at, 6, text_file);
  return arg;
}

// Work the harness does not wait for: long sweeps and trajectories; and --help among other
// options (one static text: mutations and crossovers would spread it over the corpus).
// A fit of a small grid: every axis of --grid (P=LO:HI:N,...) with N <= 3, at most 8 points in
// all, a quick model or --grid-only, and no batch (its manifest's fits have their own grids). A default grid integrates
// thousands of collisions (minutes under the sanitizers).
// The refinement after the grid takes hundreds of trials: with the adhesive engines (the
// default krijt) only with --grid-only.
bool small_fit(const std::vector<std::string>& args) {
  bool grid = false, quick = false;
  for (std::size_t i = 1; i < args.size(); ++i) {
    quick = quick || args[i] == "--grid-only" ||
            (i + 1 < args.size() && args[i] == "--model" && args[i + 1].starts_with("viscoelastic"));
  }
  if (!quick) return false;
  for (std::size_t i = 1; i + 1 < args.size(); ++i) {
    if (args[i] == "--batch") return false;
    if (args[i] != "--grid") continue;
    grid = true;
    long points = 1;
    for (std::size_t at = args[i + 1].find(':'); at != std::string::npos; at = args[i + 1].find(':', at + 1)) {
      const std::string& g = args[i + 1];
      const std::size_t end = std::min(g.find(',', at), g.size());
      if (g.find(':', at + 1) < end) continue;  // LO:HI: the count follows the second colon
      long n = 0;
      const auto [stop, ec] = std::from_chars(g.data() + at + 1, g.data() + end, n);
      if (ec != std::errc() || stop != g.data() + end || n > 3) return false;
      points *= n;
    }
    if (points > 8) return false;
  }
  return grid;
}

bool too_much_work(const std::vector<std::string>& args) {
  if (!args.empty() && args.front() == "fit" && !small_fit(args)) return true;
  // An atlas build refines until its checks pass (seconds to minutes) and writes files: its
  // inputs are refused by the front door's checks that the other commands exercise.
  if (args.size() > 1 && args[0] == "atlas" && args[1] == "build") return true;
  const long max_points = !args.empty() && args.front() == "contact" ? 64 : 8;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (args.size() > 2 && (a == "--help" || a == "-h")) return true;
    if (const auto colon = a.rfind(':'); colon != std::string::npos && colon + 1 < a.size()) {
      long n = 0;
      const auto [end, ec] = std::from_chars(a.data() + colon + 1, a.data() + a.size(), n);
      if ((ec == std::errc() && end == a.data() + a.size() && n > max_points) || ec == std::errc::result_out_of_range) {
        return true;
      }
    }
    if (a.starts_with("--trajectory-points") && a.find('=') == std::string::npos && i + 1 < args.size()) {
      double n = 0.0;
      std::from_chars(args[i + 1].data(), args[i + 1].data() + args[i + 1].size(), n);
      if (n > 10000.0) return true;
    } else if (a.starts_with("--trajectory-points=")) {
      double n = 0.0;
      std::from_chars(a.data() + 20, a.data() + a.size(), n);
      if (n > 10000.0) return true;
    }
  }
  return false;
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  Rng rng(seed);
  Call call = parse(data, size);
  const unsigned op = rng() % 20;
  if (op < 2 || call.args.empty()) return LLVMFuzzerMutate(data, size, max_size);
  if (op < 4) {
    change_command(rng, call);
  } else if (op < 10) {
    add_option(rng, call);
  } else if (op < 13) {
    remove_option(rng, call);
  } else if (op < 18) {
    retype_option(rng, call);
  } else {
    mutate_text(call, max_size / 2);
  }
  const std::string out = serialise(call);
  if (out.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
  std::memcpy(data, out.data(), out.size());
  return out.size();
}

// Crossover at option boundaries: the first call up to one of its options, the second from
// one of its options on (libFuzzer's byte crossover would glue arguments together).
extern "C" std::size_t LLVMFuzzerCustomCrossOver(const std::uint8_t* data1, std::size_t size1,
                                                 const std::uint8_t* data2, std::size_t size2, std::uint8_t* out,
                                                 std::size_t max_out_size, unsigned int seed) {
  Rng rng(seed);
  const Call first = parse(data1, size1), second = parse(data2, size2);
  if (first.args.empty() || second.args.empty()) return 0;
  auto cuts = [](const Call& call) {
    std::vector<std::size_t> at = option_positions(call);
    at.push_back(call.args.size());
    return at;
  };
  const std::size_t i = pick(rng, cuts(first)), j = pick(rng, cuts(second));
  Call child;
  child.args.assign(first.args.begin(), first.args.begin() + static_cast<std::ptrdiff_t>(i));
  child.args.insert(child.args.end(), second.args.begin() + static_cast<std::ptrdiff_t>(j), second.args.end());
  child.text = rng() % 2 == 0 ? first.text : second.text;
  const std::string bytes = serialise(child);
  if (bytes.size() > max_out_size) return 0;
  std::memcpy(out, bytes.data(), bytes.size());
  return bytes.size();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Call call = parse(data, size);
  const std::string text = call.text.value_or("");
  const std::string text_file = bounce::fuzz::scratch_file("file", text);
  std::vector<std::string> args;
  for (const std::string& a : call.args) args.push_back(substituted(a, text_file));
  if (too_much_work(args)) return -1;
  bounce::fuzz::check_cli(args, bounce::fuzz::run_cli(args, text), text);
  return 0;
}
