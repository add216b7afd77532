// `bounce table`: eps^N(g) with the outcome, or eps^T(g^N, g^T), as a table for other
// simulators (JSON, CSV or a self-contained C header; docs/tables.md), or the value of a
// saved JSON table.
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "bounce/analysis/tables.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "cli.hpp"
#include "commands.hpp"

namespace bounce::cli {

namespace {

struct TableCommand {
  explicit TableCommand(CLI::App* app) : bodies(app), numbers(app), model(app, numbers) {}
  BodyOptions bodies;
  NumberOptions numbers;
  ModelOptions model;
  std::string velocities;
  std::string tangential_velocities;
  bool json = false, csv = false;
  std::string c_header_prefix;
  std::string load;
  bool progress = false;
};

// "LO:HI" -> the two ends (velocities > 0, HI > LO).
std::array<double, 2> parse_interval(const std::string& option, const std::string& text) {
  const std::string allowed = "LO:HI in m/s with 0 < LO < HI";
  const auto colon = text.find(':');
  if (colon == std::string::npos || text.find(':', colon + 1) != std::string::npos) {
    throw InvalidArgument(option, text, allowed);
  }
  double lo = 0.0, hi = 0.0;
  try {
    std::size_t n1 = 0, n2 = 0;
    lo = std::stod(text.substr(0, colon), &n1);
    hi = std::stod(text.substr(colon + 1), &n2);
    if (n1 != colon || n2 != text.size() - colon - 1) throw InvalidArgument(option, text, allowed);
  } catch (const std::logic_error&) {
    throw InvalidArgument(option, text, allowed);
  }
  if (!(lo > 0.0) || !(hi > lo) || !std::isfinite(hi)) throw InvalidArgument(option, text, allowed);
  return {lo, hi};
}

// A table read from the --load file; a malformed one is reported against --load.
template <class Table>
Table parse_loaded(const TableCommand& c, const std::string& text) {
  try {
    return Table::from_json(text);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument("--load", c.load, e.allowed());
  }
}

int run_load_tangential(const TableCommand& c, const std::string& text) {
  const auto t = parse_loaded<TangentialTable>(c, text);
  const double gn = c.numbers.require("--velocity", "the normal impact speed g^N at which to read the table");
  const double gt = c.numbers.require("--tangential-velocity", "the tangential impact speed g^T at which to read the table");
  const double cor = t.cor(gn, gt);
  const long breaks = t.breaks(gn, gt);
  if (c.json) {
    print_json({{"velocity", gn}, {"tangential_velocity", gt}, {"cor_tangential", cor}, {"breaks", breaks},
                {"bound", t.bound}, {"description", t.description}});
  } else {
    std::cout << fmt::format("cor_tangential {:.10g} ({} asperity breaks), table error <= {:g}\n", cor, breaks, t.bound);
  }
  return 0;
}

int run_load(const TableCommand& c) {
  std::ifstream in(c.load);
  if (!in) throw InvalidArgument("--load", c.load, "a readable JSON file written by bounce table --json");
  std::stringstream text;
  text << in.rdbuf();
  if (is_tangential_table(text.str())) return run_load_tangential(c, text.str());
  const auto t = parse_loaded<NormalTable>(c, text.str());
  const double g = c.numbers.require("--velocity", "the impact speed at which to read the table");
  const double cor = t.cor(g);
  const auto outcome = t.outcome(g);
  if (c.json) {
    print_json({{"velocity", g}, {"cor", cor}, {"outcome", std::string(dynamics::to_string(outcome))},
                {"bound", t.bound}, {"description", t.description}});
  } else {
    std::cout << fmt::format("cor {:.10g} ({}), table error <= {:g}\n", cor, dynamics::to_string(outcome), t.bound);
  }
  return 0;
}

int run_table(const TableCommand& c) {
  if (!c.load.empty()) return run_load(c);
  if (c.velocities.empty()) throw InvalidArgument("--velocities", "(missing)", "LO:HI in m/s (the table's range)");
  const int formats = int(c.json) + int(c.csv) + int(!c.c_header_prefix.empty());
  if (formats != 1) {
    throw InvalidArgument("format", fmt::format("{} given", formats), "exactly one of --json, --csv, --c-header PREFIX");
  }
  const auto [lo, hi] = parse_interval("--velocities", c.velocities);
  TableOptions options;
  options.bound = c.numbers.get("--bound").value_or(1e-6);
  require_open_interval("bound", options.bound, 1e-10, 0.1, "interpolation error bound");
  Progress progress("bounce table", c.progress);
  options.progress = [&](std::size_t done, std::size_t total) { progress(done, total); };
  auto write = [&c](const auto& t) {
    if (c.json) std::cout << t.to_json() << '\n';
    if (c.csv) std::cout << t.to_csv();
    if (!c.c_header_prefix.empty()) std::cout << t.to_c_header(c.c_header_prefix);
  };
  if (!c.tangential_velocities.empty()) {
    const auto [gt_lo, gt_hi] = parse_interval("--tangential-velocities", c.tangential_velocities);
    write(build_tangential_table(c.bodies.pair(), c.model.spec(), lo, hi, gt_lo, gt_hi, c.model.collide_options(),
                                 options));
    return 0;
  }
  write(build_normal_table(c.bodies.pair(), c.model.spec(), lo, hi, c.model.collide_options(), options));
  return 0;
}

}  // namespace

Command add_table_command(CLI::App& root) {
  auto* app = root.add_subcommand(
      "table", "eps^N(g) and the outcome, or eps^T(g^N, g^T), as a table for other simulators (docs/tables.md)");
  auto c = std::make_shared<TableCommand>(app);
  app->add_option("--velocities", c->velocities, "the table's range LO:HI of (normal) impact speeds [m/s]");
  app->add_option("--tangential-velocities", c->tangential_velocities,
                  "a table of eps^T(g^N, g^T) (asperity law) with this range LO:HI of g^T [m/s]");
  app->add_flag("--json", c->json, "write the table as JSON (read back by --load and NormalTable::from_json)");
  app->add_flag("--csv", c->csv, "write the table's nodes as CSV");
  app->add_option("--c-header", c->c_header_prefix, "write a self-contained C99 header; PREFIX names its symbols");
  app->add_option("--load", c->load, "read a JSON table and print its value at --velocity");
  app->add_flag("--progress", c->progress, "report progress on stderr (automatic on a terminal)");
  c->numbers.add("--bound", "interpolation error to reach (default 1e-6)");
  c->numbers.add("--velocity", "with --load: the (normal) impact speed [m/s]");
  return {app, [c]() { return run_table(*c); }};
}

}  // namespace bounce::cli
