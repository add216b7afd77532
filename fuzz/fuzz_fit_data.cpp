// Fuzz target: the restitution-data reader of `bounce fit` (analysis::parse_experiment,
// docs/fitting.md).
//
// Input: the text of a data file. Properties (docs/hardening.md):
//  * parse_experiment returns or throws InvalidArgument (nothing else: the CLI would exit 4);
//  * what it accepts is what docs/fitting.md allows: at least one row, velocity > 0 and
//    finite, 0 <= cor <= 1, stuck exactly for cor = 0, 1e-6 <= cor_error <= 1.5, line
//    numbers increasing;
//  * the residual sums of a fit are finite for any model e in [0, 1].
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bounce/analysis/fit.hpp"
#include "oracle.hpp"

using bounce::fuzz::finding;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::optional<bounce::analysis::Experiment> e;
  if (!bounce::fuzz::only_bounce_errors("parse_experiment",
                                        [&] { e = bounce::analysis::parse_experiment(text, "fuzz.csv"); })) {
    return 0;
  }
  if (e->points.empty()) finding("an experiment without rows was accepted");
  std::size_t line = 0;
  for (const auto& m : e->points) {
    if (!(m.velocity > 0.0) || !std::isfinite(m.velocity)) finding("a velocity outside (0, inf) was accepted");
    if (!(m.cor >= 0.0 && m.cor <= 1.0)) finding("a cor outside [0, 1] was accepted");
    if (m.stuck != (m.cor == 0.0)) finding("stuck disagrees with cor = 0");
    if (m.cor_error && !(*m.cor_error >= 1e-6 && *m.cor_error <= 1.5)) finding("a cor_error outside [1e-6, 1.5]");
    if (m.line <= line) finding("line numbers do not increase");
    line = m.line;
  }
  for (double model : {0.0, 0.5, 1.0}) {
    const std::vector<double> cor(e->points.size(), model);
    if (!std::isfinite(bounce::analysis::mean_squared_residual(*e, cor))) finding("chi^2 (31) is not finite");
    if (e->has_errors() && !std::isfinite(bounce::analysis::weighted_chi2(*e, cor))) finding("the proper chi^2 is not finite");
  }
  return 0;
}
