#pragma once
// Master curves of the viscoelastic collision (BP04 §8.3.2): in the scaled
// units of (8.66) the collision depends only on kappa (8.70), so the COR, the
// scaled contact time t_c g / xi0 and the scaled maximum overlap xi_max / xi0
// are functions of kappa alone, one per end rule.
//
// The curves are built at build time from a long-double reference integration
// (tools/generate_master_curves.cpp) and evaluated in tens of nanoseconds:
//   kappa in [0, 1]        Chebyshev series in sqrt(kappa) (the force rule has
//                          half-integer powers of kappa)
//   kappa in [1, 2^27)     one Chebyshev series per octave
//   kappa >= 8 (overlap)   e = C kappa^-5 exactly up to corrections below 1e-15, and
//                          t_c = kappa ((8/3) ln kappa + Phi(kappa^{-5/3}))
//   kappa >= 2^27 (force)  the leading asymptotes (docs/viscoelastic.md)
// Stated error: 1e-10 (absolute on the COR, relative on times and overlaps) for
// every kappa >= 0; tests check the tables against independent integrations.

#include "bounce/models/end_rule.hpp"

namespace bounce::analytic {

struct MasterValues {
  double cor = 1.0;           ///< e
  double contact_time = 0.0;  ///< t_c g / xi0
  double max_overlap = 1.0;   ///< xi_max / xi0 (the same for both end rules)
};

/// All three values at kappa >= 0 (InvalidArgument for negative or non-finite kappa).
MasterValues viscoelastic_master(double kappa, models::EndRule rule);
/// Only the COR (the fast path).
double master_cor(double kappa, models::EndRule rule);

/// The error the master curves are guaranteed to stay within.
constexpr double master_curve_stated_error = 1e-10;
/// The constant C of e_overlap = C kappa^-5 at large kappa (10.0749642661…).
double overlap_tail_constant();
/// The generator's convergence estimate of its Chebyshev fits (largest trailing coefficient).
double master_curve_fit_error();

}  // namespace bounce::analytic
