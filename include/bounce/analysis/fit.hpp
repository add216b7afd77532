#pragma once
// Fitting a model to a measured restitution curve (K13 §4, docs/fitting.md).
//
// K13's method: chi^2 (31), the mean squared residual, on a grid of log-spaced parameter
// values, e from (30) with e_A integrated and e_P from (28)-(29) (the yield strength Y costs
// no collisions: every e_A is reused across the Y axis); the uncertainty of a parameter is the
// range over which its profile chi^2 stays within a factor 2 of the minimum, one-sided where
// that range reaches the grid's edge (K13 Fig 7's grey arrows). Beyond K13: the grid minimum
// refined by a local optimiser in log-parameters, and, where the data carry errors, the
// proper chi^2 with its Delta chi^2 = 1 profile intervals.
//
// This layer knows nothing of parameter names beyond "yield": a front end (api::fit) says
// how a trial's values become a pair and a model (FitProblem::case_at).

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bounce/analysis/collide.hpp"
#include "bounce/models/model.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::analysis {

// --- the data ---------------------------------------------------------------------------

/// One measured collision.
struct Measurement {
  double velocity = 0.0;            ///< impact speed [m/s]
  double cor = 0.0;                 ///< measured e (0: the grains stuck)
  std::optional<double> cor_error;  ///< 1 sigma of cor, where the file gives it
  bool stuck = false;               ///< an observed sticking collision (cor = 0 or outcome = stick)
  std::size_t line = 0;             ///< its line in the file (messages)
};

/// One experiment: a measured restitution curve.
struct Experiment {
  std::string source;  ///< the file name, for messages
  std::vector<Measurement> points;
  /// True when every point has a cor_error.
  bool has_errors() const;
};

/// The file's header name of each of our columns that it names otherwise (`--columns
/// velocity=Speed,cor=e`): ours (velocity, cor, cor_error, outcome) -> the file's.
using ColumnNames = std::map<std::string, std::string>;
/// `--columns` read: OURS=NAME pairs separated by commas (InvalidArgument "columns" otherwise).
ColumnNames parse_column_names(std::string_view text);

/// The CSV of docs/fitting.md: a header naming `velocity`, `cor` and optionally `cor_error`
/// and `outcome` (bounce | stick), or the names `names` maps them to; `#` starts a comment;
/// blank lines are skipped. Real files' forms are read (docs/fitting.md, "The data"): a UTF-8
/// byte-order mark, a tab or semicolon delimiter (sniffed from the header), quoted fields,
/// names in any case with a unit in brackets (velocity in m/s, cm/s or mm/s), a decimal comma
/// where the delimiter is not the comma. A malformed file is an InvalidArgument naming
/// `source:LINE`, the value and what is allowed.
Experiment parse_experiment(std::string_view text, std::string_view source, const ColumnNames& names = {});

/// K13 (31): the mean squared residual of model values `cor` against the data.
double mean_squared_residual(const Experiment& data, std::span<const double> cor);
/// The proper chi^2, sum ((e - e_m) / sigma)^2 (data with errors).
double weighted_chi2(const Experiment& data, std::span<const double> cor);

// --- the problem ------------------------------------------------------------------------

/// One parameter's grid: `values` [SI] increasing and geometric (log-spaced).
struct FitAxis {
  std::string name;
  std::vector<double> values;
};

/// A trial's pair, model and numerical options.
struct FitCase {
  Pair pair;
  models::Model model;
  CollideOptions options;
};
/// The case at given values of the collision axes (in their order). Must be callable from
/// several threads at once.
using CaseAt = std::function<FitCase(std::span<const double> values)>;

/// Called after each collision (from one thread at a time) with (done, total) collisions: the
/// grid's total on the grid, 0 after it (the refinement and the ranges, whose number is not
/// known in advance). It may throw to stop the fit (Python's Ctrl-C): the fit rethrows it.
using FitProgress = std::function<void(std::size_t, std::size_t)>;

struct FitProblem {
  Experiment data;
  /// The axes that change the collision (everything but the yield strength), outermost first.
  std::vector<FitAxis> collision_axes;
  /// The yield strength's axis: K13 (28)-(30) after the collision, at no cost in collisions.
  std::optional<FitAxis> yield_axis;
  CaseAt case_at;
  /// Worker threads (0: every core). The results do not depend on it, bit for bit.
  unsigned threads = 0;
  /// Refine the grid minimum with a local optimiser (Nelder-Mead in log-parameters).
  bool refine = true;
  /// Relative precision of the refined parameters.
  double precision = 1e-3;
  /// Keep the whole chi^2 grid in the result (else only the profiles).
  bool keep_grid = false;
  FitProgress progress;
};

/// An uncertainty range; an end that reaches the grid's edge is none (a one-sided limit).
struct ParameterRange {
  std::optional<double> lo, hi;
};

/// chi^2 against one parameter, minimised over all the others, on the grid.
struct Profile {
  std::vector<double> values;
  std::vector<double> chi2;  ///< +inf where every trial of that value failed
};

/// A minimum: the parameters (collision axes, then yield) and the objective there.
struct FitMinimum {
  std::vector<double> values;
  double chi2 = 0.0;
};

struct FitResult {
  std::vector<std::string> names;  ///< the fitted parameters: collision axes, then yield
  FitMinimum grid_best;            ///< the grid's minimum of K13 (31)
  FitMinimum best;                 ///< refined (equal to grid_best without refinement)
  std::vector<ParameterRange> ranges;  ///< K13 §4.1: chi^2 <= 2 chi^2_min
  std::vector<Profile> profiles;       ///< of K13 (31), per parameter
  std::vector<double> cor;             ///< the model's e at each data point, at `best`
  // With errors on every point: the proper chi^2, its own minimum and Delta chi^2 = 1 intervals.
  std::optional<FitMinimum> weighted_best;
  std::vector<ParameterRange> intervals;
  std::vector<Profile> weighted_profiles;
  /// K13 (31) on the whole grid (keep_grid), row-major over the axes (yield innermost);
  /// +inf where the collision failed.
  std::vector<double> chi2_grid;
  std::vector<std::size_t> grid_shape;
  std::size_t collisions = 0;       ///< collisions integrated (grid and refinement)
  std::size_t grid_collisions = 0;  ///< ... of which on the grid
  std::size_t failed_trials = 0;  ///< grid points whose collisions failed (NumericalError)
  std::vector<std::string> warnings;
  /// Per parameter: the best value on its grid's lower edge (-1), upper edge (+1), or inside
  /// (0); an edge's best is a limit, not a value (a warning says so too).
  std::vector<int> grid_edges;
  /// Set when the data do not determine the yield strength: at the best fit every measured
  /// speed lies below the yield velocity K13 (28), so chi^2 is the same for every Y at or above
  /// this one (the Y whose yield velocity is the fastest speed). A lower limit, not a value:
  /// best's (and weighted_best's) Y is set to it, and a warning says so.
  std::optional<double> yield_lower_limit;
  /// Where the time went [s of wall-clock time]: the grid's collisions, its e_P table, its
  /// chi^2, the refinement; and the collisions' CPU time summed over threads.
  double collision_seconds = 0.0, plastic_seconds = 0.0, chi2_seconds = 0.0, refine_seconds = 0.0;
  double collision_cpu_seconds = 0.0;
};

/// K13 §4.1 and the refinements above. InvalidArgument for an empty grid or a data speed the
/// pair refuses (naming the line); NumericalError when no trial could be evaluated.
FitResult fit(const FitProblem& problem);

// --- the grid in pieces (a batch over MPI ranks, checkpoints) ---------------------------

/// The collisions of one point of the grid of collision axes.
struct GridPoint {
  std::vector<double> cor;  ///< e_A at each distinct speed of the data (ascending); empty if failed
  double radius = 0.0, mass = 0.0, modulus = 0.0;  ///< the trial pair's R_eff, m_eff, E* (K13 (28))
  std::string failure;      ///< why the collisions failed
};
/// The points of the grid of collision axes (row-major, the last axis fastest; 1 without).
std::size_t grid_point_count(const FitProblem& problem);
/// The collisions of grid points [first, first + count) (on `problem.threads` threads). The
/// same numbers wherever and whenever they run.
std::vector<GridPoint> integrate_grid_points(const FitProblem& problem, std::size_t first, std::size_t count);
/// The fit from every grid point, computed elsewhere (in index order): fit() without its
/// own integration of the grid.
FitResult fit(const FitProblem& problem, std::vector<GridPoint> points);

/// K13 (30) from e_A and e_P: e_A where e_P = 1 (below the yield velocity) or e_A = 0.
double combine_plastic(double cor_adhesive, double cor_plastic);

/// e of K13 (30) from e_A and the yield strength (none: e_A): (28)-(29) for the pair, 0 where
/// the radicand is negative (the grains stick) or e_A = 0.
double cor_with_yield(const Pair& pair, double velocity, double cor_adhesive, std::optional<double> yield);

/// The range of a profile where chi^2 <= threshold around `best` (a refined minimum inserted
/// as a sample), ends interpolated linearly in log(value); an end is none where the region
/// reaches the first or last grid value.
ParameterRange profile_range(const Profile& profile, double best_value, double best_chi2, double threshold);

}  // namespace bounce::analysis
