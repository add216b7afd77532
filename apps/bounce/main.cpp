// bounce: collision physics of adhesive, viscoelastic grains (command line).
// Thin: parse, call the library, print. See docs/cli.md for the contract.
#include <iostream>
#include <vector>

#include "cli.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  using namespace bounce::cli;
  CLI::App app{"bounce: will two adhesive, viscoelastic spheres bounce or stick?", "bounce"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "bounce 0.1.0");
  std::vector<Command> commands = {add_materials_command(app), add_contact_command(app),
                                  add_collide_command(app),   add_curve_command(app),
                                  add_analytic_command(app),  add_sticking_command(app),
                                  add_rules_command(app),     add_table_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    std::cerr << "bounce: error: " << e.what()
              << " (expected an option listed by `bounce <command> --help`)\n";
    return 2;
  } catch (const CLI::ParseError& e) {
    std::cerr << "bounce: error: " << e.what() << '\n';
    return 2;
  }
  for (const Command& command : commands) {
    if (command.app->parsed()) return run_guarded(command.run);
  }
  return 2;
}
