#pragma once
// The CLI's options, generated from the front door's declarations (api::commands(), the
// pair's, the models' and the laws' parameters): every parameter is an option named
// --NAME (with '-' for '_'), read as text and handed to the front door, which checks it.

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bounce/api/front_door.hpp"

namespace bounce::cli {

/// "contact_end" -> "--contact-end".
std::string option_name(const std::string& parameter);

/// The options of one subcommand: the front door's parameters and the CLI's own flags.
class Options {
 public:
  Options(CLI::App* app, const api::CommandSpec& command);
  /// A flag that only the CLI has (output format, progress).
  bool* add_flag(const std::string& name, const std::string& help);
  /// A text option that only the CLI has (an input file, a C prefix); `placeholder` in --help.
  std::string* add_text(const std::string& name, const std::string& help, const std::string& placeholder,
                        const std::string& short_name = {});
  /// A positional argument that only the CLI has (an input file).
  std::string* add_positional(const std::string& name, const std::string& help);
  /// Was the CLI's own option given?
  bool given(const std::string& name) const;
  /// The value as typed ("given" for a flag), for messages.
  std::string typed(const std::string& name) const;

  /// What the user typed, by parameter name, for the front door.
  api::Inputs inputs() const;
  /// Every name these options stand for, the front door's and the CLI's own (to name
  /// them as --options in messages).
  std::set<std::string> all_names() const;

 private:
  CLI::App* app_;
  std::map<std::string, std::unique_ptr<std::string>> text_;
  std::map<std::string, std::unique_ptr<bool>> flags_;
  std::map<std::string, CLI::Option*> options_;
  std::set<std::string> names_;   // the front door's parameters
  std::set<std::string> own_;     // the CLI's own options
};

}  // namespace bounce::cli
