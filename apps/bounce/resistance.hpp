#pragma once
// `bounce contact resistance` (docs/resistance.md).

#include <CLI/CLI.hpp>

#include "commands.hpp"

namespace bounce::cli {

/// The `resistance` subcommand of `contact`, and its Command (to run it when parsed).
Command add_resistance_command(CLI::App& contact);

}  // namespace bounce::cli
