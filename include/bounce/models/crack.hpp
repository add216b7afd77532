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
// 0.5% at 3.7; for K13's k = 0.02 we use (17) on [0.31, 3.6], (16) outside
// [0.29, 3.7], and a C1 (smoothstep) blend on the two short overlaps, so that a
// stiff solver never meets a jump. This is the *reference law* f_ref.
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
//
// Third decision (docs/adhesive.md, "the crack law at any k"): (17) exists for k = 0.02 only,
// and a law that switched from (16) and (17) to (16) alone at k != 0.02 jumped (a COR from
// 0.533 to 0.562). In the Barenblatt-Schapery theory of a Dugdale zone in a three-element
// solid (Greenwood 2004, the theory behind (16) and (17)), the opening crack's law is
// f(beta) / beta a function of y = (1 - 1/beta)/(1 - k) alone, whatever k; (16) has that form
// above 1, and below 1 the like form beta f(beta) of y = (1 - beta)/(1 - k) alone. So f at any
// k is the reference law carried to k at equal y:
//   beta < 1:  f(beta, k) = (beta_r / beta) f_ref(beta_r),  1 - beta_r = c (1 - beta),
//   beta > 1:  f(beta, k) = (beta / beta_r) f_ref(beta_r),  1 - 1/beta_r = c (1 - 1/beta),
// c = (1 - 0.02)/(1 - k). It is (16) exactly wherever the reference law is (16), K13's law
// exactly at k = 0.02, and continuous (smooth) in k.

#include <vector>

namespace bounce::models {

struct CrackSpeed {
  double value = 0.0;       ///< f(beta)
  double derivative = 0.0;  ///< df/dbeta
};

/// Half-width of the C2 join around beta = 1.
constexpr double crack_smoothing_width = 1e-4;

/// The k of K13 (17), at which the reference law is K13's own.
constexpr double crack_reference_k = 0.02;

/// f(beta) and its derivative for k in (0, 1) and beta in (k, 1/k): the reference law carried to k.
CrackSpeed crack_speed_function(double beta, double k);

/// beta carried to the reference k at equal y (above), and c = (1 - 0.02)/(1 - k).
struct CrackBeta {
  double beta = 0.0;
  double c = 1.0;
};
/// Inline (with crack_speed_at_k): they run at every evaluation of the crack law, and out of
/// line they cost K13's collision ~5 % (measured, docs/benchmarks.md).
inline CrackBeta reference_beta(double beta, double k) {
  // y = (1 - beta) / (1 - k) below 1, (1 - 1/beta) / (1 - k) above, is the same at k and at the
  // reference k: c = (1 - k_ref) / (1 - k) carries 1 - beta (or 1 - 1/beta) from one to the other.
  const double c = (1.0 - crack_reference_k) / (1.0 - k);
  if (c == 1.0) return {beta, c};  // K13's own k: the identity, exactly (1 - (1 - beta) is not)
  if (beta <= 1.0) return {1.0 - c * (1.0 - beta), c};
  const double u = 1.0 - c * (1.0 - 1.0 / beta), beta_ref = 1.0 / u;
  return {beta_ref, c};
}
/// f and df/dbeta at beta (at k) from f_ref and df_ref/dbeta_r at r = reference_beta(beta, k).
inline CrackSpeed crack_speed_at_k(const CrackSpeed& f, double beta, const CrackBeta& r) {
  // Below 1: f = (b_r / b) f_r(b_r), b_r = 1 - c (1 - b): df/db = ((c - 1)/b^2) f_r + (b_r/b) c f_r'.
  // Above 1: f = (b / b_r) f_r(b_r), 1/b_r = 1 - c (1 - 1/b): df/db = (1 - c) f_r + c (b_r/b) f_r'.
  if (r.c == 1.0) return f;
  const double c = r.c, ratio = r.beta / beta;
  if (beta <= 1.0) return {ratio * f.value, (c - 1.0) / (beta * beta) * f.value + ratio * c * f.derivative};
  return {f.value / ratio, (1.0 - c) * f.value + c * ratio * f.derivative};
}
/// K13 (16) alone.
CrackSpeed crack_speed_high(double beta, double k);
/// K13 (17) alone (k = 0.02), for 0 < beta (beta != 1 excluded from nothing: f(1) = 0).
CrackSpeed crack_speed_low(double beta);

/// Whether f is concave at beta (f'' <= 0, f' < 0), where that is known: where (17) holds alone
/// above beta = 1 in the reference law, 1 + crack_smoothing_width <= beta_r <= 3.6. At k = 0.02 in
/// closed form ((17) there is -(a x + b) x^p with a, b > 0, p = 1.1403 > 1 and x = beta - 1, whose
/// second derivative is -(a p (p + 1) x^(p-1) + b p (p - 1) x^(p-2)) < 0); carried to another k
/// (f = (1 + (1 - c) x) f_ref(c x / (1 + (1 - c) x)) with x = beta - 1) it stays concave there,
/// tested on a dense grid for k from 1e-9 to 0.99 (CrackLaw.ConcaveWhereDeclared). Elsewhere
/// false: the join and the blends are not concave everywhere, nor is (16) near beta = 1.
bool crack_speed_concave(double beta, double k);

/// crack_speed_function at one k, for a DEM code that evaluates it once per contact and step:
/// where (17) alone holds in the reference law (0.31 <= beta_r <= 3.6) and outside the join
/// around beta = 1, f_ref and f_ref' come from a cubic Hermite table of (17)'s own values and
/// slopes, on cells graded in (17)'s variable x (1/beta - 1 or beta - 1; 32 cells to a binade of
/// x), carried to k as crack_speed_function does; elsewhere crack_speed_function itself. The
/// cells do not depend on k: one set, built once.
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

  struct Cell {
    double c0, c1, c2, c3;  // f = c0 + t (c1 + t (c2 + t c3)), t in [0, 1) across the cell
  };

 private:
  CrackSpeed lookup(const std::vector<Cell>& cells, double x) const;
  CrackSpeed reference(double beta_ref) const;  // f_ref, tabulated where (17) holds alone
  double k_;
  const std::vector<Cell>* below_ = nullptr;  // x = 1/beta - 1
  const std::vector<Cell>* above_ = nullptr;  // x = beta - 1
};

}  // namespace bounce::models
