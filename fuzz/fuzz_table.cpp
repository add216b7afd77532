// Fuzz target: the saved-table loaders (NormalTable::from_json, TangentialTable::from_json,
// `bounce table --load`).
//
// Input: the text of a table file. Properties (docs/hardening.md):
//  * from_json (both kinds) returns or throws InvalidArgument; lookups in a table it accepted
//    (cor, outcome, breaks at the corners and inside its range) return or throw a
//    bounce::Error, and never read outside the table (AddressSanitizer);
//  * for an accepted table, `bounce table --load F --velocity V [--tangential-velocity VT]
//    --json` keeps the CLI's contract (exit 0, 2 or 3, no nan/inf).
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bounce/analysis/tables.hpp"
#include "oracle.hpp"

using bounce::fuzz::only_bounce_errors;

namespace {

// Points of [lo, hi]: the ends and inside (a table's range may be anything once fuzzed).
std::vector<double> points_of(double lo, double hi) {
  std::vector<double> p = {lo, hi};
  for (int k = 1; k < 8; ++k) p.push_back(lo + (hi - lo) * k / 8.0);
  if (lo > 0.0 && hi > 0.0) p.push_back(std::sqrt(lo * hi));
  return p;
}

std::string number(double x, double fallback) {
  return fmt::format("{:.17g}", std::isfinite(x) && x > 0.0 ? x : fallback);
}

void look_up_normal(const bounce::analysis::NormalTable& t) {
  for (double g : points_of(t.g_min, t.g_max)) {
    only_bounce_errors("NormalTable::cor", [&] { (void)t.cor(g); });
    only_bounce_errors("NormalTable::outcome", [&] { (void)t.outcome(g); });
  }
  only_bounce_errors("NormalTable::cor", [&] { (void)t.cor(t.sticking_velocity); });
}

void look_up_tangential(const bounce::analysis::TangentialTable& t) {
  for (double gn : points_of(t.gn_min, t.gn_max)) {
    for (double gt : {t.gt_min, 0.5 * (t.gt_min + t.gt_max), t.gt_max}) {
      only_bounce_errors("TangentialTable::cor", [&] { (void)t.cor(gn, gt); });
      only_bounce_errors("TangentialTable::breaks", [&] { (void)t.breaks(gn, gt); });
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> args = {"table", "--load", bounce::fuzz::scratch_file("table.json", text), "--json"};

  bounce::analysis::NormalTable normal;
  if (only_bounce_errors("NormalTable::from_json", [&] { normal = bounce::analysis::NormalTable::from_json(text); })) {
    look_up_normal(normal);
    args.insert(args.end(), {"--velocity", number(0.5 * (normal.g_min + normal.g_max), 1.0)});
  }
  bounce::analysis::TangentialTable tangential;
  if (only_bounce_errors("TangentialTable::from_json",
                         [&] { tangential = bounce::analysis::TangentialTable::from_json(text); })) {
    look_up_tangential(tangential);
    args.insert(args.end(), {"--velocity", number(0.5 * (tangential.gn_min + tangential.gn_max), 1.0),
                             "--tangential-velocity", number(0.5 * (tangential.gt_min + tangential.gt_max), 0.1)});
  }
  // A table both loaders refuse is refused by the CLI the same way (exit 2, checked by the
  // loaders' InvalidArgument above): the CLI runs for the accepted ones, which is much faster.
  if (args.size() == 4) return 0;
  bounce::fuzz::check_cli(args, bounce::fuzz::run_cli(args), text);
  return 0;
}
