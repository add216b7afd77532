#pragma once
// Restitution tables for other simulators (docs/tables.md): eps^N(g^N) with the outcome,
// on a grid refined until a stated interpolation error holds, exported as JSON, CSV and
// a self-contained C header, and loaded back here.
//
// A piecewise cubic Hermite interpolant in a logarithmic variable with explicit jumps
// (located by bisection to 1e-11) where the outcome changes. Tables of eps^T(g^N, g^T)
// are not provided yet: docs/tables.md says why.

#include <functional>
#include <string>
#include <vector>

#include "bounce/analysis/collide.hpp"

namespace bounce {

/// A function of one variable, smooth between jumps: cubic Hermite between the nodes of
/// a piece (nodes with one label), a jump between pieces (their facing nodes 1e-11 apart).
struct PiecewiseCubic {
  std::vector<double> x;      ///< nodes, ascending
  std::vector<double> f;      ///< values
  std::vector<double> slope;  ///< derivatives df/dx
  std::vector<long> label;    ///< piece label of each node (the outcome: 1 bounce, 0 stick)

  double operator()(double x) const;
  /// The value of the piece with this label at x, extrapolating it beyond its ends
  /// (the side of a jump a point inside its 1e-11 bracket belongs to).
  double in_piece(long label, double x) const;
  long label_at(double x) const;
};

struct TableOptions {
  double bound = 1e-6;  ///< interpolation error to reach at every check point
  /// Called with (work done, work estimate) as the table grows.
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

  double cor(double g) const;  ///< InvalidArgument outside [g_min, g_max]
  dynamics::Outcome outcome(double g) const;

  std::string to_json() const;
  std::string to_csv() const;  ///< the nodes: g, x, eps^N, slope, outcome
  /// A C99 header with the data and `double <prefix>_cor(double g)`, `int <prefix>_sticks(double g)`.
  std::string to_c_header(const std::string& prefix) const;
  static NormalTable from_json(const std::string& text);
};

NormalTable build_normal_table(const Pair& pair, const models::ModelSpec& model, double g_min, double g_max,
                               const CollideOptions& options = {}, const TableOptions& table = {});

}  // namespace bounce
