// bounce: collision physics of adhesive, viscoelastic grains (command line).
// Thin: the options come from the front door's declarations, the work from the library
// (docs/architecture.md); docs/cli.md is the contract.
#include "cli.hpp"

#include <unistd.h>

#include <csignal>
#include <iostream>
#include <map>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands.hpp"
#include "output.hpp"

namespace {

// Async-signal-safe: write(2) and _exit(2) only. The rows already flushed stay where they went.
extern "C" void on_interrupt(int /*signal*/) {
  static const char message[] = "bounce: interrupted (SIGINT): the output written so far is kept\n";
  [[maybe_unused]] const auto written = ::write(STDERR_FILENO, message, sizeof message - 1);
  ::_exit(130);
}

// What the user typed that the chosen command does not take, in the one-line rule
// (`--force = 3 is invalid: expected ...`), naming the commands that do take it.
std::string unexpected_argument(const CLI::App& app, const std::vector<bounce::cli::Command>& commands) {
  for (const auto& command : commands) {
    if (!command.app->parsed()) continue;
    const auto extras = command.app->remaining();
    const std::string name = command.app->get_name();
    if (extras.empty() || !extras.front().starts_with("-")) {
      return fmt::format("argument = {} is invalid: expected only options (see `bounce {} --help`)",
                         extras.empty() ? "(none)" : extras.front(), name);
    }
    const std::string& typed = extras.front();
    const auto equals = typed.find('=');
    const std::string flag = typed.substr(0, equals);  // --force=3 names --force
    const std::string value = equals != std::string::npos               ? typed.substr(equals + 1)
                              : extras.size() > 1 && !extras[1].starts_with("--") ? extras[1]
                                                                                   : "(given)";
    std::vector<std::string> takers;
    for (const auto& other : commands) {
      if (other.app != command.app && other.app->get_option_no_throw(flag) != nullptr) {
        takers.push_back(other.app->get_name());
      }
    }
    const std::string where = takers.empty() ? fmt::format("see `bounce {} --help`", name)
                                             : fmt::format("commands that take it: {}", fmt::join(takers, ", "));
    return fmt::format("{} = {} is invalid: expected no {} in `bounce {}` ({})", flag, value, flag, name, where);
  }
  return fmt::format("argument = {} is invalid: expected a command (see `bounce --help`)",
                     fmt::join(app.remaining(), " "));
}

// An option given twice (`--velocity 1 --velocity 2`, `--json --json`): which value would be
// meant is a guess, so it is refused like any bad input. Empty when none is.
std::string repeated_option(int argc, const char* const* argv) {
  std::map<std::string, std::vector<std::string>> seen;
  for (int i = 1; i < argc; ++i) {
    const std::string_view token = argv[i];
    if (token == "--") break;  // the rest are values
    if (!token.starts_with("--")) continue;
    const auto equals = token.find('=');
    const std::string name(token.substr(0, equals));
    const bool inline_value = equals != std::string_view::npos;
    const bool next_is_value = i + 1 < argc && !std::string_view(argv[i + 1]).starts_with("--");
    seen[name].push_back(inline_value ? std::string(token.substr(equals + 1)) : next_is_value ? argv[i + 1] : "(given)");
  }
  for (const auto& [name, values] : seen) {
    if (values.size() > 1) {
      return fmt::format("{} = {} is invalid: expected {} once (given {} times)", name, fmt::join(values, ", "), name,
                         values.size());
    }
  }
  return {};
}

// CLI11's "--force: 1 required N missing" in the one-line rule.
std::string missing_value(const CLI::ArgumentMismatch& e) {
  const std::string what = e.what();
  const std::string name = what.substr(0, what.find(':'));
  return fmt::format("{} = (no value) is invalid: expected a value after {} (see --help)", name, name);
}

}  // namespace

namespace bounce::cli {

void exit_on_interrupt() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGINT, &action, nullptr);
}

int run(int argc, const char* const* argv) {
  CLI::App app{"bounce: will two adhesive, viscoelastic spheres bounce or stick?", "bounce"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "bounce 0.1.0");
  std::vector<Command> commands;
  std::vector<std::string> names;
  for (const auto& spec : bounce::api::commands()) {
    commands.push_back(add_command(app, spec));
    names.push_back(spec.name);
  }
  if (const std::string repeated = repeated_option(argc, argv); !repeated.empty()) {
    std::cerr << "bounce: error: " << repeated << '\n';
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError&) {
    std::cerr << "bounce: error: " << unexpected_argument(app, commands) << '\n';
    return 2;
  } catch (const CLI::RequiredError& e) {
    const bool typed = argc > 1 && argv[1][0] != '-';  // a word that is no command
    std::cerr << fmt::format("bounce: error: command = {} is invalid: expected one of {}\n",
                             typed ? argv[1] : "(not given)", fmt::join(names, ", "));
    return 2;
  } catch (const CLI::ArgumentMismatch& e) {
    std::cerr << "bounce: error: " << missing_value(e) << '\n';
    return 2;
  } catch (const CLI::ParseError& e) {
    std::cerr << "bounce: error: " << e.what() << '\n';
    return 2;
  }
  for (const Command& command : commands) {
    if (command.app->parsed()) return run_guarded(command.run, command.options->all_names(), command.options->inputs());
  }
  return 2;
}

}  // namespace bounce::cli
