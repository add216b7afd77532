// bounce: collision physics of adhesive, viscoelastic grains (command line).
// Thin: the options come from the front door's declarations, the work from the library
// (docs/architecture.md); docs/cli.md is the contract.
#include "cli.hpp"


#include <algorithm>
#include <iostream>
#include <map>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bounce/core/suggest.hpp"
#include "bounce/core/version.hpp"
#include "aggregate.hpp"
#include "atlas.hpp"
#include "commands.hpp"
#include "completion.hpp"
#include "first_steps.hpp"
#include "interrupt.hpp"
#include "output.hpp"
#include "resistance.hpp"

namespace {

using bounce::cli::full_name;

// The options of a (sub)command as typed: "--velocity", "--help", ...
std::vector<std::string> long_options(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  }
  return names;
}

// What the user typed that the chosen command does not take, in the one-line rule
// (`--force = 3 is invalid: expected ...`), naming the commands that do take it, or the
// command's own option it looks like a typo of (`--velocty`: did you mean --velocity?).
std::string unexpected_argument(const CLI::App& app, const std::vector<const CLI::App*>& commands) {
  for (const CLI::App* command : commands) {
    if (!command->parsed() || !command->get_subcommands().empty()) continue;  // `contact` of `contact resistance`
    const auto extras = command->remaining();
    const std::string name = full_name(*command);
    const std::vector<std::string> own = long_options(*command);
    if (extras.empty() || !extras.front().starts_with("-")) {
      const std::string word = extras.empty() ? "(none)" : extras.front();
      const bool dashes_missing = std::find(own.begin(), own.end(), "--" + word) != own.end();  // velocity
      return fmt::format("argument = {} is invalid: expected only options (see `bounce {} --help`){}", word, name,
                         extras.empty()    ? ""
                         : dashes_missing ? fmt::format("; did you mean --{}?", word)
                                          : bounce::did_you_mean("--" + word, own));
    }
    const std::string& typed = extras.front();
    const auto equals = typed.find('=');
    const std::string flag = typed.substr(0, equals);  // --force=3 names --force
    const std::string value = equals != std::string::npos               ? typed.substr(equals + 1)
                              : extras.size() > 1 && !extras[1].starts_with("--") ? extras[1]
                                                                                   : "(given)";
    std::vector<std::string> takers;
    for (const CLI::App* other : commands) {
      if (other != command && other->get_option_no_throw(flag) != nullptr) takers.push_back(full_name(*other));
    }
    const std::string where = takers.empty() ? fmt::format("see `bounce {} --help`", name)
                                             : fmt::format("commands that take it: {}", fmt::join(takers, ", "));
    return fmt::format("{} = {} is invalid: expected no {} in `bounce {}` ({}){}", flag, value, flag, name, where,
                       takers.empty() ? bounce::did_you_mean(flag, own) : "");
  }
  return fmt::format("argument = {} is invalid: expected a command (see `bounce --help`)",
                     fmt::join(app.remaining(), " "));
}

// No command, or a word that is none: the commands, and the one it looks like a typo of; an
// option before any command (`bounce --verison`) is compared with bounce's own options.
std::string missing_command(const CLI::App& app, int argc, const char* const* argv, const std::vector<std::string>& names) {
  const std::string typed = argc > 1 ? argv[1] : "(not given)";
  const CLI::App* group = nullptr;
  for (const CLI::App* command : app.get_subcommands({})) group = command->get_name() == typed ? command : group;
  if (group != nullptr && !group->get_subcommands({}).empty()) {
    // `bounce atlas` alone, or with a word that is none of its commands
    std::vector<std::string> words;
    for (const CLI::App* sub : group->get_subcommands({})) words.push_back(sub->get_name());
    const std::string word = argc > 2 ? argv[2] : "(not given)";
    return fmt::format("bounce {} = {} is invalid: expected one of {} (`bounce {} build --help`){}", typed, word,
                       fmt::join(words, ", "), typed, bounce::did_you_mean(word, words));
  }
  if (typed.starts_with("-")) {
    return fmt::format("{} = (given) is invalid: expected a command first, one of {}{}", typed, fmt::join(names, ", "),
                       bounce::did_you_mean(typed, long_options(app)));
  }
  return fmt::format("command = {} is invalid: expected one of {}{}", typed, fmt::join(names, ", "),
                     bounce::did_you_mean(typed, names));
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

// `bounce help [COMMAND [SUBCOMMAND]]`: the help of bounce or of that command (exit 0), or the
// rule's message for a word that is none (exit 2).
int help_command(const CLI::App& app, int argc, const char* const* argv, const std::vector<std::string>& names) {
  if (argc == 2) {
    std::cout << app.help();
    return 0;
  }
  const CLI::App* command = nullptr;
  for (const CLI::App* c : app.get_subcommands({})) command = c->get_name() == argv[2] ? c : command;
  if (command != nullptr && argc > 3) {
    const CLI::App* sub = nullptr;
    for (const CLI::App* c : command->get_subcommands({})) sub = c->get_name() == argv[3] ? c : sub;
    command = sub;
  }
  if (command == nullptr || argc > (command->get_parent() == &app ? 3 : 4)) {
    const std::string typed = argc > 3 && command == nullptr ? fmt::format("{} {}", argv[2], argv[3]) : argv[2];
    std::cerr << "bounce: error: help = " << typed << " is invalid: expected a command, one of "
              << fmt::format("{}", fmt::join(names, ", ")) << bounce::did_you_mean(argv[2], names) << '\n';
    return 2;
  }
  std::cout << command->help(command->get_parent() == &app ? "bounce" : "bounce " + command->get_parent()->get_name());
  return 0;
}

// A first word that is no command (`bounce colide --help`): refused with a suggestion, before
// CLI11 would print bounce's own help for the --help that follows. Empty when it is one.
std::string unknown_command(int argc, const char* const* argv, const std::vector<std::string>& names) {
  if (argc < 2 || argv[1][0] == '-') return {};
  const std::string word = argv[1];
  if (word == "help" || std::find(names.begin(), names.end(), word) != names.end()) return {};
  return fmt::format("command = {} is invalid: expected one of {} (or help){}", word, fmt::join(names, ", "),
                     bounce::did_you_mean(word, names));
}

// A command run with nothing after its name that needs something: what it needs, and an example.
std::string needs(const CLI::App& command, int argc) {
  const std::string name = full_name(command);
  const bounce::cli::FirstSteps* s = bounce::cli::first_steps(name);
  const int words = name.find(' ') == std::string::npos ? 1 : 2;  // `collide`, `atlas query`
  if (argc > 1 + words || s == nullptr || s->needs.empty()) return {};
  return fmt::format("options = (none given) is invalid: expected what `bounce {}` needs: {}; e.g. `{}` (`bounce {} "
                     "--help` lists every option)",
                     name, s->needs, s->examples.front(), name);
}

}  // namespace

namespace bounce::cli {

void exit_on_interrupt() { install_interrupt_handler(); }

namespace {

// CLI11's parse, its help and version exits, and its errors in the one-line rule (exit 2);
// nothing where the command is to run.
std::optional<int> parse(CLI::App& app, int argc, const char* const* argv, const std::vector<Command>& commands,
                         const std::vector<std::string>& names) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError&) {
    std::vector<const CLI::App*> apps;  // every command's, `atlas build` and its kin included
    for (const Command& c : commands) apps.push_back(c.app);
    std::cerr << "bounce: error: " << unexpected_argument(app, apps) << '\n';
    return 2;
  } catch (const CLI::RequiredError&) {
    std::cerr << "bounce: error: " << missing_command(app, argc, argv, names) << '\n';
    return 2;
  } catch (const CLI::ArgumentMismatch& e) {
    std::cerr << "bounce: error: " << missing_value(e) << '\n';
    return 2;
  } catch (const CLI::ParseError& e) {
    std::cerr << "bounce: error: " << e.what() << '\n';
    return 2;
  }
  return std::nullopt;
}

}  // namespace

int run(int argc, const char* const* argv) {
  CLI::App app{"bounce: will two adhesive, viscoelastic spheres bounce or stick?", "bounce"};
  app.formatter(std::make_shared<ExamplesFormatter>());  // before the commands, which inherit it
  app.require_subcommand(1);
  app.set_version_flag("--version", fmt::format("bounce {}", bounce::version()));
  app.set_help_all_flag("--help-all", "Print this help with every command's options");
  app.footer("`bounce COMMAND --help` (or `bounce help COMMAND`) lists the options of a command, with examples.");
  std::vector<Command> commands;
  std::vector<std::string> names;
  for (const auto& spec : bounce::api::commands()) {
    commands.push_back(add_command(app, spec));
    names.push_back(spec.name);
  }
  for (Command& c : add_atlas_commands(app)) commands.push_back(std::move(c));
  commands.push_back(add_resistance_command(*app.get_subcommand("contact")));
  names.push_back("atlas");
  for (Command& c : add_aggregate_commands(app)) commands.push_back(std::move(c));
  names.push_back("aggregate");
  const CLI::App* completion = add_completion_command(app);
  names.push_back(completion->get_name());
  if (argc <= 1) {  // `bounce` alone introduces itself: what it is and its commands
    return run_guarded([&app] {
      std::cout << app.help();
      return 0;
    }, {});
  }
  if (argc > 1 && std::string_view(argv[1]) == "help") return help_command(app, argc, argv, names);
  for (const std::string& refused : {unknown_command(argc, argv, names), repeated_option(argc, argv)}) {
    if (refused.empty()) continue;
    std::cerr << "bounce: error: " << refused << '\n';
    return 2;
  }
  if (const std::optional<int> code = parse(app, argc, argv, commands, names)) return *code;
  for (const Command& command : commands) {
    // `contact resistance` parses `contact` too: the word after it runs
    if (!command.app->parsed() || !command.app->get_subcommands().empty()) continue;
    if (const std::string missing = needs(*command.app, argc); !missing.empty()) {
      std::cerr << "bounce: error: " << missing << '\n';
      return 2;
    }
    return run_guarded(command.run, command.options->all_names(), command.options->inputs());
  }
  if (completion->parsed()) {
    return run_guarded([&app] {
      std::cout << bash_completion(app);
      return 0;
    }, {});
  }
  return 2;
}

}  // namespace bounce::cli
