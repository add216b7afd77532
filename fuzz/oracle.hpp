#pragma once
// What the fuzz targets check (docs/hardening.md), shared by all of them: the CLI run
// in-process with its streams captured, the CLI's contract (docs/cli.md) as the oracle, and
// the library's error policy (only bounce::Error escapes). A violated property is reported
// on stderr as "FINDING: ..." and aborts, which libFuzzer records as a crash with its input.

#include <string>
#include <string_view>
#include <vector>

#include "bounce/core/error.hpp"

namespace bounce::fuzz {

/// Prints "FINDING: <what>" on stderr and aborts (libFuzzer saves the input).
[[noreturn]] void finding(const std::string& what);

/// Runs `body`: true when it returns, false when it throws a bounce::Error (bad input or a
/// numerical failure, both reported to the user); any other exception is a finding (the
/// CLI would exit 4, "internal error").
template <class Body>
bool only_bounce_errors(std::string_view what, Body&& body) {
  try {
    body();
    return true;
  } catch (const Error&) {
    return false;
  } catch (const std::exception& e) {
    finding(std::string(what) + " threw a non-bounce exception: " + e.what());
  }
}

struct CliResult {
  int code = -1;
  std::string out, err;
};

/// bounce::cli::run with argv = {"bounce", args...}, `input` as standard input, and
/// std::cout/std::cerr captured.
CliResult run_cli(const std::vector<std::string>& args, const std::string& input = "");

/// The CLI's contract: exit code 0, 2 or 3 (4, an internal error, is a finding); exit 2 with
/// nothing on stdout and one line "bounce: error: ..." on stderr (warnings and progress aside);
/// exit 3 with one "bounce: numerical error: ..." (or a failed write) line; no number printed
/// as nan or inf on stdout, nor in the allowed range of an error message. `echoed`: text the user gave
/// (file contents, names) that the output may repeat, where nan/inf are words, not numbers.
void check_cli(const std::vector<std::string>& args, const CliResult& result, const std::string& echoed = "");

/// A file in this process's scratch directory (removed at exit) holding `text`; its path.
std::string scratch_file(const std::string& name, std::string_view text);

/// `args` as one shell-quoted line, for reports.
std::string command_line(const std::vector<std::string>& args);

}  // namespace bounce::fuzz
