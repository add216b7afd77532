#pragma once
// The front door: "a pair + a model + what to compute", for every front end (the CLI, the
// Python package, and next the fitter and the LAMMPS plugin).
//
// A front end hands over what the user typed, by parameter name (core/parameters.hpp): the
// pair's (pair/pair_parameters.hpp), the model's (models/registry.hpp, with "model" naming
// it), and the command's own (velocity, velocities, ...). The front door checks every input
// once against its declaration, refuses one that the command or the model does not use
// (InvalidArgument naming it), builds the pair and the model, runs the library and returns a
// Record whose keys are those of the CLI's JSON and of Python's dicts.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "bounce/analysis/collide.hpp"
#include "bounce/analysis/fit.hpp"
#include "bounce/analysis/tables.hpp"
#include "bounce/core/parameters.hpp"
#include "bounce/core/record.hpp"
#include "bounce/models/dem_law.hpp"
#include "bounce/models/model.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::api {

using Inputs = ParameterInputs;
/// Called with (done, total) as a long run goes; total = 0 while it is not known (an
/// adaptive table: done counts its collisions).
using Progress = std::function<void(std::size_t, std::size_t)>;

/// Models' parameters that a command never uses, and why (the message when one is given).
struct Unused {
  std::vector<std::string> names;
  std::string why;
};

/// A command: its name, what it does, and the parameters it takes beside the pair's and the
/// model's.
struct CommandSpec {
  std::string name;
  std::string summary;
  bool takes_pair = false;
  bool takes_model = false;
  std::vector<ParameterSpec> parameters;  ///< its own
  std::vector<std::string> models = {};   ///< the models it works with (empty: every model), from their traits
  std::string models_why = {};            ///< ... and why only those
  std::string default_model = {};         ///< empty: the registry's default (models::ModelRegistry::default_name)
  bool model_required = false;            ///< no default model: one of `models` must be named (sticking)
  std::vector<Unused> unused = {};        ///< models' parameters it never uses (not offered, refused)
};
const std::vector<CommandSpec>& commands();
/// InvalidArgument("command", name, "one of …") for an unknown command.
const CommandSpec& command(std::string_view name);

/// The model a command uses when the inputs name none.
std::string default_model(const CommandSpec& command);

/// The spec of "model" (the keyword), "law" (the contact law).
ParameterSpec model_parameter();
ParameterSpec law_parameter();

/// Every parameter a command can take with any model or law (its own, the pair's, the
/// models' or laws'): what a front end offers (CLI options, --help lines).
std::vector<ParameterSpec> offered_parameters(std::string_view command);
/// The models (or contact laws) that take a parameter, for help lines: empty when all do.
std::vector<std::string> models_taking(std::string_view parameter);

/// A pair, a model and how to integrate it, every input checked once.
struct Case {
  Pair pair;
  models::Model model;
  analysis::CollideOptions options;
  Parameters pair_parameters, model_parameters, own;  ///< the inputs, by group, bound
};
/// The case of `command` (collide, curve, sticking, analytic, rules, table). With `radius`,
/// body 1 has that radius (sweeps over radii).
Case make_case(std::string_view command, const Inputs& inputs, std::optional<double> radius = std::nullopt);
/// The pair alone (the pair's parameters; anything else is refused).
Pair make_pair(const Inputs& inputs);
/// The model's inputs checked against its row (Python's Model(...) before it meets a pair).
Parameters check_model(std::string_view name, const Inputs& inputs);
/// `e` with its value as the user typed it: a check below the front door formats the number it
/// checked ("1e+05"); where `e` names an input given as text that reads as that number ("1e5"),
/// the text. Otherwise `e` itself.
InvalidArgument as_typed(const InvalidArgument& e, const Inputs& inputs);

// --- the commands: each returns the Record the CLI prints as JSON ----------------------
Record collide(const Inputs& inputs);
/// Takes the points (rows) of a long output one at a time, as they are computed: the CLI writes
/// each at once, so that memory stays flat in the number of points (docs/cli.md, "Memory").
using PointSink = std::function<void(const Record& point)>;
/// {points, boundaries} of a sweep over velocities (or radii at one velocity).
Record curve(const Inputs& inputs, const Progress& progress = {});
/// The same with each point handed to `sink` as it is computed, none kept: {boundaries} (none
/// located without `boundaries`). Every point's speed and pair are checked before the first
/// collision, so a bad input is refused before `sink` is called.
Record curve(const Inputs& inputs, const PointSink& sink, const Progress& progress, bool boundaries = true);
/// The columns of a curve (the CLI's CSV, Python's arrays), from curve()'s Record.
Table curve_table(const Record& curve);
/// collide() over speeds as columns (velocity, cor, outcome, contact_time, max_overlap,
/// bulk_dissipated, crack_dissipated, and cor_tangential when oblique): Python's arrays.
/// `warnings`: where given, each kind of validity warning the collisions gave, once, as the CLI's
/// curve prints them ("at velocity 10: ..." of the last speed that gave it), merged into what it
/// holds already (a curve computed in pieces).
Table collide_columns(const Inputs& inputs, const std::vector<double>& velocities,
                      std::vector<std::string>* warnings = nullptr);
Record sticking(const Inputs& inputs, const Progress& progress = {});
/// With radii: a list of sticking records, one per radius (a radius without a threshold has
/// sticking_velocity null and the reason in "note").
Value sticking_over_radii(const Inputs& inputs, const Progress& progress = {});
/// The same with each record handed to `sink` as it is computed, none kept.
void sticking_over_radii(const Inputs& inputs, const PointSink& sink, const Progress& progress);
/// The same at each of `radii` [m] (body 1's radius; body 2's follows it unless given): Python's
/// sticking(..., radii=array).
void sticking_over_radii(const Inputs& inputs, const std::vector<double>& radii, const PointSink& sink,
                         const Progress& progress);
Table sticking_table(const Value& rows);
Record contact(const Inputs& inputs);
/// The contact law's curve over forces, overlaps or contact radii (one of them given).
Table contact_curve(const Inputs& inputs);
/// The same with each row handed to `sink` (a Table of that one row) as it is computed, after
/// every point was checked (a bad one is refused before `sink` is called).
void contact_curve(const Inputs& inputs, const std::function<void(const Table& row)>& sink);
Record analytic(const Inputs& inputs);
/// `encounters`: JSON text, one encounter object or a list of them (docs/cli.md).
Value rules(const Inputs& inputs, std::string_view encounters);
/// eps^N table, or eps^T with tangential_velocities.
std::variant<analysis::NormalTable, analysis::TangentialTable> table(const Inputs& inputs, const Progress& progress = {});
/// The value of a saved JSON table at velocity (and tangential_velocity for eps^T).
Record table_value(std::string_view json, const Inputs& inputs);
/// The model fitted to one measured restitution curve (K13 §4, docs/fitting.md): best values,
/// factor-2 ranges, chi^2 (31), profiles, the data with the model's e; Delta chi^2 = 1
/// intervals when every point has an error; with `compare`, the comparison models too.
Record fit(const Inputs& inputs, const analysis::Experiment& data, const Progress& progress = {});

/// A fit in two steps, for a batch over MPI ranks (docs/fitting.md): the grid's points,
/// integrated anywhere in pieces, then the Record from all of them (the same as fit()'s
/// without `compare`, which a batch refuses, as it does `chi2_grid` and `timing`).
class FitJob {
 public:
  FitJob(const Inputs& inputs, const analysis::Experiment& data);
  std::size_t grid_points() const;
  /// Grid points [first, first + count), on the fit's threads.
  std::vector<analysis::GridPoint> integrate(std::size_t first, std::size_t count) const;
  /// The fit from every grid point, in order.
  Record finish(std::vector<analysis::GridPoint> points) const;
  const analysis::FitProblem& problem() const;

  struct State;

 private:
  std::shared_ptr<const State> state_;
};

/// One experiment of a batch manifest (TOML, docs/fitting.md): its name, its data and the
/// fit's inputs (the manifest's [defaults] with the entry's own on top).
struct BatchEntry {
  std::string name;
  analysis::Experiment data;
  Inputs inputs;
};
/// The entries of a manifest; `directory` resolves their data files. InvalidArgument naming
/// "FILE: experiment N: KEY" for a malformed manifest or data file.
std::vector<BatchEntry> read_fit_manifest(std::string_view text, const std::string& source, const std::string& directory);

/// LAMMPS's `pair_coeff I J MODEL key value …` (pair_style bounce, docs/lammps.md): not a CLI
/// command, but bound by the same rules. It takes the pair's materials and the model's
/// parameters; radii, masses and walls are LAMMPS's, and what the DEM step does not use
/// (yield, the integrators' settings, convex shapes) is refused with the reason.
const CommandSpec& pair_coeff_command();
/// The contact law of one pair of atom types from its pair_coeff inputs, checked like the
/// CLI's (InvalidArgument naming the input).
models::DemModel dem_model(const Inputs& inputs);
/// LAMMPS's `fix wall/bounce`: the same for atoms against a flat wall, which is body 2 (an
/// elastic wall of material2, E2, nu2, gamma2, or rigid_wall).
const CommandSpec& fix_wall_command();
models::DemModel wall_dem_model(const Inputs& inputs);

/// `bounce lammps`: the stock `pair_style granular` lines that best represent a model for a
/// pair (eta_n0 = 2 A E*/m_eff, gamma_LAMMPS = w/2, limit_damping for the force rule), with
/// notes saying what stock LAMMPS cannot represent (docs/lammps.md).
Record lammps_export(const Inputs& inputs);

/// The materials table (built-in, or materials_file).
Value materials(const Inputs& inputs);
/// The model registry and the contact laws, with every parameter.
Value models();

/// The pair as a Record (bodies and pair quantities, SI).
Record pair_record(const Pair& pair);
/// A collision outcome as a Record (with the trajectory as a Table when recorded).
Record outcome_record(const dynamics::CollisionOutcome& outcome);

}  // namespace bounce::api
