#pragma once
// One function per subcommand; main() registers them all.
#include "cli.hpp"

namespace bounce::cli {
Command add_materials_command(CLI::App& root);
Command add_contact_command(CLI::App& root);
Command add_collide_command(CLI::App& root);
Command add_curve_command(CLI::App& root);
Command add_analytic_command(CLI::App& root);
Command add_sticking_command(CLI::App& root);
Command add_rules_command(CLI::App& root);
Command add_table_command(CLI::App& root);
}  // namespace bounce::cli
