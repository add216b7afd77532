#pragma once
// `bounce fit --plot FILE`: the fit's figure (K13 Fig 6), drawn by Debian's /usr/bin/python3
// with matplotlib on the bounce package beside this executable (docs/fitting.md, "The figure").
#include <string>

namespace bounce::cli {

/// Refuse (InvalidArgument naming `--plot`, exit 2) a FILE whose extension is not png, svg or
/// pdf, or a machine where /usr/bin/python3 cannot import matplotlib and the bounce package:
/// asked before the fit, so that a fit of minutes is not lost.
void check_plot(const std::string& file);

/// Write the figure of `fit_json` (the JSON of `bounce fit --json`) to `file`.
void write_plot(const std::string& file, const std::string& fit_json);

}  // namespace bounce::cli
