#pragma once
// `bounce aggregate build` (docs/aggregates.md).

#include <vector>

#include <CLI/CLI.hpp>

#include "commands.hpp"

namespace bounce::cli {

/// The `aggregate` command and its subcommand `build` (their Commands, to run the parsed one).
std::vector<Command> add_aggregate_commands(CLI::App& root);

}  // namespace bounce::cli
