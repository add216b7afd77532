#pragma once
// `bounce completion`: the bash completion script, generated from the CLI's own commands and
// options and from the library's registries (model, contact-law and material names, choices),
// so that it never lists a name by hand and follows every new model or option.

#include <string>

#include <CLI/CLI.hpp>

namespace bounce::cli {

/// The completion script for `app` (the whole CLI, its subcommands registered).
std::string bash_completion(const CLI::App& app);

/// Registers `bounce completion` on `app` (the caller prints bash_completion(app) when it is parsed).
CLI::App* add_completion_command(CLI::App& app);

}  // namespace bounce::cli
