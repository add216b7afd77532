#pragma once
// The viscoelastic crack law of K13 §2.2.1 (after Greenwood 2004): the contact
// edge moves with a speed set by beta = G_eff / gamma,
//
//   (sigma0^2 T_vis / (E* gamma)) a' = f(beta),      sigma0 = gamma / z0,
//
// f from K13 (16) (all speeds, any k) and, for k = 0.02, the low-speed fit (17)
// (valid 0.29 < beta < 3.7). f > 0 for k < beta < 1 (closing crack, growing
// contact), f < 0 for 1 < beta < 1/k; f -> +inf at beta -> k and -inf at 1/k.
//
// Decision (docs/adhesive.md): (16) and (17) differ by 0.7% at beta = 0.29 and by
// 0.5% at 3.7; for k = 0.02 we use (17) on [0.31, 3.6], (16) outside
// [0.29, 3.7], and a C1 (smoothstep) blend on the two short overlaps, so that a
// stiff solver never meets a jump. For k != 0.02 only (16) exists.
//
// Second decision: at the JKR equilibrium beta = 1, (17) behaves like
// |beta - 1|^{1.116} and |beta - 1|^{1.140} (and (16) like 1/ln): continuous with its
// slope but with an unbounded second derivative, on which a stiff solver chatters
// when a fast crack keeps beta within 1e-6 of 1 (one K13 collision took 670 000
// steps there). Within |beta - 1| < smoothing_width we use the sextic that matches f,
// f' and f'' at both edges and vanishes at beta = 1 (the JKR equilibrium stays
// where it is), which changes crack speeds only where the crack is quasi-static
// (|f| < 1.2e-5 for k = 0.02) and the results by less than the integration error
// (docs/adhesive.md).

#include <vector>

namespace bounce::models {

struct CrackSpeed {
  double value = 0.0;       ///< f(beta)
  double derivative = 0.0;  ///< df/dbeta
};

/// Half-width of the C2 join around beta = 1.
constexpr double crack_smoothing_width = 1e-4;

/// f(beta) and its derivative for k in (0, 1) and beta in (k, 1/k).
CrackSpeed crack_speed_function(double beta, double k);
/// K13 (16) alone.
CrackSpeed crack_speed_high(double beta, double k);
/// K13 (17) alone (k = 0.02), for 0 < beta (beta != 1 excluded from nothing: f(1) = 0).
CrackSpeed crack_speed_low(double beta);

/// Whether f is concave at beta (f'' <= 0, f' < 0), where that holds in closed form: for
/// k = 0.02 where (17) holds alone above beta = 1, 1 + crack_smoothing_width <= beta <= 3.6
/// ((17) there is -(a x + b) x^p with a, b > 0, p = 1.1403 > 1 and x = beta - 1, whose second
/// derivative is -(a p (p + 1) x^(p-1) + b p (p - 1) x^(p-2)) < 0). Elsewhere false: the join
/// and the blends are not concave everywhere, nor is (16) near beta = 1 (its 1 / ln).
bool crack_speed_concave(double beta, double k);

/// crack_speed_function at one k, for a DEM code that evaluates it once per contact and step:
/// for k = 0.02, where (17) alone holds (0.31 <= beta <= 3.6) and outside the join around
/// beta = 1, f and f' come from a cubic Hermite table of (17)'s own values and slopes, on cells
/// graded in (17)'s variable x (1/beta - 1 or beta - 1; 32 cells to a binade of x); elsewhere,
/// and for any other k (whose (16) costs one log), crack_speed_function itself.
/// Why a table of our own: (17)'s powers x^1.116 and x^1.1403 cost a libm pow each (20 ns on
/// the reference machine, a quarter of krijt's DEM step, docs/benchmarks.md), a lookup a few ns;
/// Boost's cardinal interpolators take a uniform grid, on which the power at x -> 0 would need
/// ~1e6 nodes, or a log per evaluation. The error of a cubic Hermite cell of relative width
/// 1/32 on x^p is (1/32)^4 |p (p-1) (p-2) (p-3)| / 384 = 5.4e-10 of f for p = 1.116: measured,
/// f within 6e-10 and f' within 6e-8 (test_crack.cpp). A crack step's change of a moves by
/// 6e-10 of itself, ~1e-11 a, against Newton's stop at 1e-4 a.
class CrackSpeedTable {
 public:
  explicit CrackSpeedTable(double k);
  CrackSpeed operator()(double beta) const;

 private:
  struct Cell {
    double c0, c1, c2, c3;  // f = c0 + t (c1 + t (c2 + t c3)), t in [0, 1) across the cell
  };
  CrackSpeed lookup(const std::vector<Cell>& cells, double x) const;
  double k_;
  bool tabulated_ = false;
  std::vector<Cell> below_, above_;  // x = 1/beta - 1 and x = beta - 1
};

}  // namespace bounce::models
