#pragma once
// Reference solution of the scaled viscoelastic collision, BP04 (8.67) with
// alpha = 3/2, beta = 1, gamma = 1/2 (the corrected exponent order, see
// docs/viscoelastic.md):
//
//   x'' + (5/4) x^{3/2} + kappa sqrt(x) x' = 0,   x(0) = 0, x'(0) = 1.
//
// Used to build the master curves at build time and by tests. Deliberately
// different from the library's engine (src/dynamics): long double, Fehlberg
// 7(8), and regularised formulations instead of a generic integrator:
//  * near x = 0 (both ends of the contact) w = sqrt(x) is the independent
//    variable: dt/dw = 2w/v, dv/dw = -(5/2) w^4/v - 2 kappa w^2 are smooth;
//  * for kappa >= 1 the time phase uses w = v + (5/4) x / kappa, because the
//    scaled force is exactly kappa sqrt(x) w: its zero (the `force` end rule)
//    is then located with a purely relative tolerance, which keeps the force-
//    rule quantities accurate where v itself is a tiny difference.
// Events are located by bisection on the length of a finely sub-stepped step.

#include <array>
#include <cmath>
#include <stdexcept>

// GCC 12 reports odeint's steppers as copying uninitialised work buffers when
// they are built inline (make_controlled(..., stepper())); the buffers are
// written before they are read. Silence only these two diagnostics, here.
#if defined(__GNUC__) && !defined(__clang__)  // GCC's false positives; clang has no -Wmaybe-uninitialized
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint.hpp>

namespace bounce::reference {

using Real = long double;
using Pair2 = std::array<Real, 2>;

struct MasterQuantities {
  Real cor_overlap = 0;          ///< e under the overlap end rule
  Real contact_time_overlap = 0; ///< scaled t_c, overlap rule
  Real cor_force = 0;            ///< e under the force end rule
  Real contact_time_force = 0;   ///< scaled t_c, force rule
  Real max_overlap = 0;          ///< scaled maximum overlap (the same for both rules)
};

namespace detail {

struct WPhase {  // independent w = sqrt(x); state (t, v)
  Real kappa;
  void operator()(const Pair2& s, Pair2& d, Real w) const {
    d[0] = 2 * w / s[1];
    d[1] = -Real(2.5) * w * w * w * w / s[1] - 2 * kappa * w * w;
  }
};
struct TimeXV {  // state (x, v)
  Real kappa;
  void operator()(const Pair2& s, Pair2& d, Real) const {
    const Real root = std::sqrt(s[0] > 0 ? s[0] : Real(0));
    d[0] = s[1];
    d[1] = -Real(1.25) * s[0] * root - kappa * root * s[1];
  }
};
struct TimeXW {  // state (x, w), w = v + (5/4) x / kappa
  Real kappa;
  void operator()(const Pair2& s, Pair2& d, Real) const {
    const Real root = std::sqrt(s[0] > 0 ? s[0] : Real(0));
    const Real v = s[1] - Real(1.25) * s[0] / kappa;
    d[0] = v;
    d[1] = -kappa * root * s[1] + Real(1.25) * v / kappa;
  }
};

template <class System>
Pair2 advance(const System& system, Pair2 y, Real t, Real h) {
  boost::numeric::odeint::runge_kutta_fehlberg78<Pair2, Real> rk;
  constexpr int substeps = 8;
  for (int i = 0; i < substeps; ++i) {
    rk.do_step(system, y, t, h / substeps);
    t += h / substeps;
  }
  return y;
}

// Smallest h in (0, h_max] with g(advance(h)) <= 0, given g(y0) > 0 >= g(advance(h_max)).
template <class System, class G>
Real bisect_step(const System& system, const Pair2& y0, Real t0, Real h_max, G g) {
  Real lo = 0, hi = h_max;
  for (int i = 0; i < 120 && hi - lo > Real(1e-30) * h_max; ++i) {
    const Real mid = (lo + hi) / 2;
    (g(advance(system, y0, t0, mid)) > 0 ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace detail

/// All master-curve quantities at kappa > 0. With need_overlap = false the
/// integration stops at the force-rule end (much cheaper at large kappa), and
/// the overlap-rule fields are left at zero.
inline MasterQuantities master_quantities(Real kappa, bool need_overlap = true, Real tol = 1e-18L) {
  using namespace boost::numeric::odeint;
  using detail::WPhase;
  MasterQuantities q;
  const bool w_form = kappa >= 1;
  // Leave the regularised start well before the maximum (x_max ~ kappa^{-2/3}).
  const Real x_start = Real(1e-2) / std::max(Real(1), std::cbrt(kappa * kappa));
  // Hand over to the end phase inside the inertial region x ~ kappa^{-4} (overlap rule).
  const Real x_end = kappa > 1 ? x_start / (kappa * kappa * kappa * kappa) : x_start;

  auto wstep = make_controlled(tol, tol, runge_kutta_fehlberg78<Pair2, Real>());
  Pair2 tv{0, 1};  // (t, v) as functions of w
  integrate_adaptive(wstep, WPhase{kappa}, tv, Real(0), std::sqrt(x_start), std::sqrt(x_start) / 100);
  Real t = tv[0];

  // Time phase. y = (x, v) or (x, w).
  auto to_v = [&](const Pair2& y) { return w_form ? y[1] - Real(1.25) * y[0] / kappa : y[1]; };
  auto force_g = [&](const Pair2& y) {  // sign of the scaled force kappa sqrt(x) (x (5/4)/kappa + v)
    return w_form ? y[1] : Real(1.25) * y[0] + kappa * y[1];
  };
  Pair2 y = w_form ? Pair2{x_start, tv[1] + Real(1.25) * x_start / kappa} : Pair2{x_start, tv[1]};
  const Real abs_tol = w_form ? Real(1e-300) : tol;  // relative control in the (x, w) form
  auto xv = make_controlled(abs_tol, tol, runge_kutta_fehlberg78<Pair2, Real>());
  bool past_max = false, have_force = false;
  Real dt = Real(1e-4) / (1 + kappa);
  auto run = [&](const auto& system) {
    for (long step = 0;; ++step) {
      if (step > 200'000'000L) throw std::runtime_error("master reference: step budget exhausted");
      const Pair2 prev = y;
      const Real t_prev = t;
      while (xv.try_step(system, y, t, dt) != success) {
      }
      const Real h = t - t_prev;
      if (!past_max && to_v(y) <= 0) {
        const Real hm = detail::bisect_step(system, prev, t_prev, h, [&](const Pair2& z) { return to_v(z); });
        q.max_overlap = detail::advance(system, prev, t_prev, hm)[0];
        past_max = true;
      }
      if (past_max && !have_force && force_g(y) <= 0) {
        const Real hf = detail::bisect_step(system, prev, t_prev, h, force_g);
        const Pair2 z = detail::advance(system, prev, t_prev, hf);
        // At F = 0 the velocity is exactly -(5/4) x / kappa: no cancellation.
        q.cor_force = w_form ? Real(1.25) * z[0] / kappa : -z[1];
        q.contact_time_force = t_prev + hf;
        have_force = true;
        if (!need_overlap) return;
      }
      if (past_max && y[0] <= x_end) {
        const Real he = detail::bisect_step(system, prev, t_prev, h, [&](const Pair2& z) { return z[0] - x_end; });
        y = detail::advance(system, prev, t_prev, he);
        t = t_prev + he;
        return;
      }
    }
  };
  if (w_form) {
    run(detail::TimeXW{kappa});
  } else {
    run(detail::TimeXV{kappa});
  }
  if (have_force && !need_overlap) return q;

  // End phase in w, from sqrt(x_end) down to 0; the force may vanish here (small kappa).
  Pair2 end{t, to_v(y)};
  Real w = std::sqrt(x_end);
  boost::numeric::odeint::runge_kutta_fehlberg78<Pair2, Real> rk;
  const int pieces = 4000;
  const Real dw = w / pieces;
  for (int i = 0; i < pieces; ++i) {
    const Pair2 before = end;
    const Real w_before = w;
    rk.do_step(WPhase{kappa}, end, w, -dw);
    w -= dw;
    if (!have_force && Real(1.25) * w * w + kappa * end[1] <= 0) {
      Real lo = 0, hi = dw;
      for (int j = 0; j < 120; ++j) {
        const Real mid = (lo + hi) / 2;
        Pair2 z = before;
        Real ww = w_before;
        rk.do_step(WPhase{kappa}, z, ww, -mid);
        (Real(1.25) * (w_before - mid) * (w_before - mid) + kappa * z[1] > 0 ? lo : hi) = mid;
      }
      Pair2 z = before;
      Real ww = w_before;
      rk.do_step(WPhase{kappa}, z, ww, -hi);
      q.cor_force = -z[1];
      q.contact_time_force = z[0];
      have_force = true;
    }
  }
  q.cor_overlap = -end[1];
  q.contact_time_overlap = end[0];
  return q;
}

}  // namespace bounce::reference

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
