// bounce: collision physics of adhesive, viscoelastic grains (command line).
// Thin: the options come from the front door's declarations, the work from the library
// (docs/architecture.md); docs/cli.md is the contract.
#include <iostream>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands.hpp"
#include "output.hpp"

int main(int argc, char** argv) {
  using namespace bounce::cli;
  CLI::App app{"bounce: will two adhesive, viscoelastic spheres bounce or stick?", "bounce"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "bounce 0.1.0");
  std::vector<Command> commands;
  std::vector<std::string> names;
  for (const auto& spec : bounce::api::commands()) {
    commands.push_back(add_command(app, spec));
    names.push_back(spec.name);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    std::cerr << "bounce: error: " << e.what() << " (expected an option listed by `bounce <command> --help`)\n";
    return 2;
  } catch (const CLI::RequiredError& e) {
    const bool typed = argc > 1 && argv[1][0] != '-';  // a word that is no command
    std::cerr << fmt::format("bounce: error: command = {} is invalid: expected one of {}\n",
                             typed ? argv[1] : "(not given)", fmt::join(names, ", "));
    return 2;
  } catch (const CLI::ParseError& e) {
    std::cerr << "bounce: error: " << e.what() << '\n';
    return 2;
  }
  for (const Command& command : commands) {
    if (command.app->parsed()) return run_guarded(command.run, command.options->all_names());
  }
  return 2;
}
