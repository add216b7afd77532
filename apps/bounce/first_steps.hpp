#pragma once
// Each command's first steps: what it needs, and examples that run as written (each command's
// --help shows them under its usage; tests/python/test_first_steps.py runs every one).

#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace bounce::cli {

struct FirstSteps {
  std::string_view needs;                  ///< what a run needs, "" for a command that runs alone
  std::vector<std::string_view> examples;  ///< shell lines, run from an empty folder
};

/// A command's name as typed: "collide", or "atlas build" for a command of a group.
std::string full_name(const CLI::App& command);

/// The first steps of a command by its full name ("collide", "atlas build"), or nullptr.
const FirstSteps* first_steps(std::string_view command);

/// A help formatter that prints a command's examples right under its usage line.
class ExamplesFormatter : public CLI::Formatter {
 public:
  std::string make_usage(const CLI::App* app, std::string name) const override;
};

}  // namespace bounce::cli
