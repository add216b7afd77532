#pragma once
// One subcommand per front-door command (api::commands()); main() registers them all.

#include <functional>
#include <memory>

#include <CLI/CLI.hpp>

#include "bounce/api/front_door.hpp"
#include "options.hpp"

namespace bounce::cli {

struct Command {
  CLI::App* app = nullptr;
  std::unique_ptr<Options> options;
  std::function<int()> run;  ///< prints the result; the exit code
};

Command add_command(CLI::App& root, const api::CommandSpec& spec);

}  // namespace bounce::cli
