#pragma once
// `bounce atlas build|query|export` (docs/atlas.md).

#include <vector>

#include <CLI/CLI.hpp>

#include "commands.hpp"

namespace bounce::cli {

/// The `atlas` command and its three subcommands (their Commands, to run the parsed one).
std::vector<Command> add_atlas_commands(CLI::App& root);

}  // namespace bounce::cli
