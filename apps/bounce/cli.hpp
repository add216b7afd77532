#pragma once
// Shared plumbing of the bounce CLI: options parsed as text by us (so that every
// bad value produces the one-line "name = value is invalid: expected …" message),
// the body options that build a Pair, and output that never prints NaN.

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bounce/analysis/collide.hpp"
#include "bounce/dynamics/outcome.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/materials_table.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::cli {

/// A subcommand: its CLI11 app and what to run when it was chosen.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

/// Numeric options of one subcommand, kept as text until read.
class NumberOptions {
 public:
  explicit NumberOptions(CLI::App* app) : app_(app) {}
  /// Register "--name" (a real number) with a help text that states the unit.
  void add(const std::string& name, const std::string& help);
  bool given(const std::string& name) const;
  /// The value if given; InvalidArgument(name, text, "a number …") if not a number.
  std::optional<double> get(const std::string& name) const;
  /// The value; InvalidArgument(name, "(not given)", what) if missing.
  double require(const std::string& name, const std::string& what) const;
  /// The text as given ("" if not given).
  std::string text(const std::string& name) const;

 private:
  CLI::App* app_;
  std::map<std::string, std::string> text_;
  std::map<std::string, CLI::Option*> options_;
};

/// --material, --E, --nu, --density, --gamma, --radius and their "2" twins,
/// --wall, --rigid-wall, --materials-file.
class BodyOptions {
 public:
  explicit BodyOptions(CLI::App* app);
  /// Build and validate the pair; errors name the CLI options. With `radius`,
  /// body 1 has that radius (and body 2 too unless --radius2 or a wall).
  Pair pair(std::optional<double> radius = std::nullopt) const;
  /// The table in use (built-in, or --materials-file).
  MaterialTable table() const;

 private:
  Material resolve_material(const MaterialTable& table, bool second,
                            const std::optional<Material>& fallback) const;
  CLI::App* app_;
  NumberOptions numbers_;
  std::string material_;
  std::string material2_;
  std::string materials_file_;
  bool wall_ = false;
  bool rigid_wall_ = false;
};

/// --model, --A, --eta1, --eta2, --contact-end, --method, convex-body and
/// power-law options: everything that selects a collision model.
class ModelOptions {
 public:
  ModelOptions(CLI::App* app, NumberOptions& numbers);
  models::ModelSpec spec() const;
  CollideOptions collide_options() const;
  const std::string& method_text() const { return method_; }

 private:
  NumberOptions& numbers_;
  std::string model_ = "viscoelastic";
  std::string contact_end_ = "overlap";
  std::string method_ = "auto";
  std::string curvature1_, curvature2_;
  double tolerance_ = 1e-12;
  double adhesive_tolerance_ = 1e-8;
  std::string stiff_engine_ = "rodas";
  std::string tangential_law_ = "asperity";
  std::string asperity_form_ = "published";
};

/// K13's and BP04's closed forms for an adhesive collision at `velocity` (JSON):
/// v_c (25) and exact, e_JKR (24), e_D (26), e_I (27), t_H (22), the Tabor
/// parameter; with a yield strength v_y (28), e_P (29), l (33); for
/// adhesive-viscoelastic BP04's W0 (8.95) and e_ad (8.98).
nlohmann::json adhesive_closed_forms(const Pair& pair, const models::ModelSpec& spec, double velocity);

/// The JSON object of a collision outcome (SPEC §7 fields plus the energy budget).
nlohmann::json outcome_json(const dynamics::CollisionOutcome& outcome, bool with_trajectory);

/// Progress on stderr for long runs: shown when stderr is a terminal or `forced`.
class Progress {
 public:
  Progress(std::string what, bool forced);
  void operator()(std::size_t done, std::size_t total);

 private:
  std::string what_;
  bool enabled_;
  double start_;
  double last_ = -1.0;
};

/// "R1,R2" -> two principal radii of curvature [m] ("inf" for a flat direction).
std::array<double, 2> parse_radii(const std::string& option, const std::string& text);

/// Parse "LO:HI:N" into N values (geometric spacing if log). Errors name `option`.
std::vector<double> parse_range(const std::string& option, const std::string& text, bool log);

/// Map a library parameter name to the CLI option: "body2.E" -> "--E2",
/// "contact_radius" -> "--contact-radius"; other names are kept.
std::string option_name(const std::string& parameter);

/// Pair quantities as JSON (SI units).
nlohmann::json pair_json(const Pair& pair);

/// Print JSON; NumericalError if any number in it is not finite.
void print_json(const nlohmann::json& value);
/// Format one CSV row; NumericalError on a non-finite value.
std::string csv_row(const std::vector<double>& values);

/// Run the parsed command with the error policy: InvalidArgument -> one line on
/// stderr and exit code 2; NumericalError -> one line, exit 3.
int run_guarded(const std::function<int()>& body);

}  // namespace bounce::cli
