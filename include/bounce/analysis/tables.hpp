#pragma once
// Restitution tables for other simulators (docs/tables.md): eps^N(g^N) with the outcome
// and eps^T(g^N, g^T), on grids refined until a stated interpolation error holds,
// exported as JSON, CSV and a self-contained C header, and loaded back here.
//
// eps^N: a piecewise cubic Hermite interpolant in a logarithmic variable with explicit
// jumps (located by bisection to 1e-11) where the outcome changes.
// eps^T: the contact's fundamental solutions on a (ln g^N, s) grid, on which a lookup
// replays the asperity breaks (eps^T itself jumps along curves in the g^N-g^T plane,
// so no grid of its values holds 1e-6; docs/tables.md).

#include <functional>
#include <string>
#include <vector>

#include "bounce/analysis/collide.hpp"

namespace bounce::analysis {

/// A function of one variable, smooth between jumps: cubic Hermite between the nodes of
/// a piece (nodes with one label), a jump between pieces (their facing nodes 1e-11 apart).
/// Evaluated by the C99 core that the C headers carry too (src/analysis/normal_table_core.h).
struct PiecewiseCubic {
  std::vector<double> x;      ///< nodes, ascending
  std::vector<double> f;      ///< values
  std::vector<double> slope;  ///< derivatives df/dx
  std::vector<double> label;  ///< piece label of each node (the outcome: 1 bounce, 0 stick)

  double operator()(double x) const;
  /// The value of the piece with this label at x, extrapolating it beyond its ends
  /// (the side of a jump a point inside its 1e-11 bracket belongs to).
  double in_piece(double label, double x) const;
  double label_at(double x) const;
};

struct TableOptions {
  double bound = 1e-6;  ///< interpolation error to reach at every check point
  /// Called with (work done, work estimate) as the table grows.
  /// (collisions done, 0) as the table grows (its size is not known in advance), then
  /// (done, done) when it is built.
  std::function<void(std::size_t, std::size_t)> progress;
};

/// eps^N(g^N) for one pair and model on [g_min, g_max]. Below the sticking velocity v_s
/// (adhesive models) the outcome is "stick" and eps^N = 0; above it the curve is
/// tabulated in x = ln(g - v_s), where eps^N ~ sqrt(g - v_s) becomes smooth (x = ln g
/// without sticking).
struct NormalTable {
  std::string description;
  double g_min = 0.0, g_max = 0.0;  ///< [m/s]
  double sticking_velocity = 0.0;   ///< v_s [m/s]; 0: the grains never stick in range
  double bound = 0.0;               ///< stated interpolation error of eps^N
  PiecewiseCubic curve;             ///< eps^N of x; label 1: bounce, 0: stick
  /// Validity warnings of the collisions it was built from (one per kind; not saved).
  std::vector<std::string> warnings;

  double cor(double g) const;  ///< InvalidArgument outside [g_min, g_max]
  dynamics::Outcome outcome(double g) const;

  std::string to_json() const;
  std::string to_csv() const;  ///< the nodes: g, x, eps^N, slope, outcome
  /// A C99 header with the data and `double <prefix>_cor(double g)`, `int <prefix>_sticks(double g)`.
  std::string to_c_header(const std::string& prefix) const;
  static NormalTable from_json(const std::string& text);
};

/// eps^T(g^N, g^T) of the asperity law (published form, BSHP96 (35) in the history form
/// of docs/decisions.md D11) for a non-adhesive force-law normal model. Between breaks the tangential
/// motion is linear, p'' = -K(tau) p (docs/tables.md), so the table holds its
/// fundamental solutions y1, y2 (and y1', y2', K, dK/ds) on nodes in s = sqrt(tau/tau_end)
/// for rows equally spaced in ln g^N; a lookup interpolates the rows (Lagrange, `order`
/// points), builds quintic Hermite pieces in s and replays the breaks on them. The same
/// C99 code runs in the library and in the header it writes.
struct TangentialTable {
  std::string description;
  double gn_min = 0.0, gn_max = 0.0;  ///< range of g^N [m/s]
  double gt_min = 0.0, gt_max = 0.0;  ///< range of g^T [m/s]
  double bound = 0.0;                 ///< stated error of eps^T (checked, see below)
  double checked_error = 0.0;         ///< largest error at the build's check points
  long check_points = 0;              ///< random (g^N, g^T) compared with direct integration
  double asperity_size = 0.0;         ///< zeta0 [m]
  int order = 8;                      ///< rows in a Lagrange stencil
  double x0 = 0.0, dx = 0.0;          ///< ln g^N of row 0, spacing of the rows
  std::vector<double> s;              ///< nodes in [0, 1]
  std::vector<double> rows;           ///< per row: tau_end, ln t_u
  std::vector<double> nodes;          ///< per row and node: y1, y1', y2, y2', K, dK/ds
  /// Validity warnings of the collisions it was built from (one per kind; not saved).
  std::vector<std::string> warnings;

  std::size_t row_count() const { return rows.size() / 2; }
  /// eps^T; InvalidArgument outside [gn_min, gn_max] x [gt_min, gt_max].
  double cor(double gn, double gt) const;
  /// The number of asperities that break in that collision.
  long breaks(double gn, double gt) const;

  std::string to_json() const;
  std::string to_csv() const;  ///< the grid: row, g^N, s, tau, y1, y1', y2, y2', K, dK/ds
  /// A C99 header with the data and `double <prefix>_cor_tangential(double gn, double gt)`.
  std::string to_c_header(const std::string& prefix) const;
  static TangentialTable from_json(const std::string& text);
};

/// True when `json` is a table written by TangentialTable::to_json (false for an eps^N table).
bool is_tangential_table(const std::string& json);

/// Refines the nodes (checked at the rows) and then the rows (checked at random points)
/// until eps^T agrees with direct integration within bound/8 and bound/4. InvalidArgument
/// for models it cannot tabulate: adhesive or dynamic-contact normal models, the step law
/// or the passive form, and g^T so large that the direct integration averages dense
/// asperity breaks (docs/tangential.md).
TangentialTable build_tangential_table(const Pair& pair, const models::Model& model, double gn_min,
                                       double gn_max, double gt_min, double gt_max,
                                       const CollideOptions& options = {}, const TableOptions& table = {});

NormalTable build_normal_table(const Pair& pair, const models::Model& model, double g_min, double g_max,
                               const CollideOptions& options = {}, const TableOptions& table = {});

}  // namespace bounce::analysis
