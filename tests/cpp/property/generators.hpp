#pragma once
// Generators of physically valid inputs for the property tests (rapidcheck), SI units.
//
// Continuous quantities are drawn log-uniformly over wide ranges (a radius from 0.1 um to
// 1 m is as likely to be a micron grain as a pebble); rapidcheck shrinks a failing case
// towards the lower end of each range. Speeds stay inside the quasi-static validity of the
// models (BSHP96 (B11), small strain) and dissipative constants inside A << t_c (BSHP96
// (B12), BP04 (8.26)), so that every case is one the library is meant to answer.
//
// A failing case prints its inputs with all 17 digits (RC_LOG) beside rapidcheck's own
// short listing, so it can be replayed outside the test.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>

#include <rapidcheck.h>

#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/contact/hertz.hpp"
#include "bounce/core/parameters.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce {

// rapidcheck prints a generated value through showValue (found by ADL): full precision, so
// that a counterexample can be typed back in.
inline void showValue(const Material& m, std::ostream& os) {
  const auto precision = os.precision(17);
  os << "{E = " << m.youngs_modulus << " Pa, nu = " << m.poisson_ratio << ", density = " << m.density << " kg/m^3";
  if (m.surface_energy) os << ", gamma = " << *m.surface_energy << " J/m^2";
  os << "}";
  os.precision(precision);
}

inline void showValue(const Pair& p, std::ostream& os) {
  const auto precision = os.precision(17);
  os << "Pair{body1: R = " << p.body1().radius << " m, ";
  showValue(p.body1().material, os);
  os << "; body2: " << (p.body2().rigid ? "rigid " : "") << "R = " << p.body2().radius << " m, ";
  showValue(p.body2().material, os);
  os << "}";
  os.precision(precision);
}

}  // namespace bounce

namespace bounce::property {

/// The ranges every generator draws from: micron grains to metre-sized bodies, soft
/// polymers to diamond, foams to tungsten, weak to strong adhesion.
struct Ranges {
  static constexpr double radius_min = 1e-7, radius_max = 1.0;             ///< [m]
  static constexpr double modulus_min = 1e6, modulus_max = 1e12;           ///< E [Pa]
  static constexpr double poisson_min = 0.0, poisson_max = 0.49;           ///< nu
  static constexpr double density_min = 100.0, density_max = 2e4;          ///< [kg/m^3]
  static constexpr double surface_energy_min = 1e-3, surface_energy_max = 1.0;  ///< gamma [J/m^2]
};

/// A double uniform on [lo, hi] (53 random bits; lo itself is where rapidcheck shrinks to).
inline rc::Gen<double> uniform(double lo, double hi) {
  constexpr std::int64_t steps = std::int64_t{1} << 53;
  return rc::gen::map(rc::gen::inRange<std::int64_t>(0, steps + 1), [lo, hi](std::int64_t k) {
    const double u = static_cast<double>(k) / static_cast<double>(steps);
    return std::clamp(lo + (hi - lo) * u, lo, hi);
  });
}

/// A double whose logarithm is uniform on [ln lo, ln hi], lo > 0.
inline rc::Gen<double> log_uniform(double lo, double hi) {
  return rc::gen::map(uniform(std::log(lo), std::log(hi)),
                      [lo, hi](double x) { return std::clamp(std::exp(x), lo, hi); });
}

/// A material with a surface energy (the adhesive models need one; the others ignore it).
inline rc::Gen<Material> material() {
  return rc::gen::apply(
      [](double e, double nu, double density, double gamma) {
        Material m;
        m.name = "random";
        m.youngs_modulus = e;
        m.poisson_ratio = nu;
        m.density = density;
        m.surface_energy = gamma;
        return m;
      },
      log_uniform(Ranges::modulus_min, Ranges::modulus_max), uniform(Ranges::poisson_min, Ranges::poisson_max),
      log_uniform(Ranges::density_min, Ranges::density_max),
      log_uniform(Ranges::surface_energy_min, Ranges::surface_energy_max));
}

/// Two spheres of independent materials and radii (unlike in general).
inline rc::Gen<Pair> sphere_pair() {
  return rc::gen::apply([](Material m1, double r1, Material m2,
                           double r2) { return Pair(sphere(std::move(m1), r1), sphere(std::move(m2), r2)); },
                        material(), log_uniform(Ranges::radius_min, Ranges::radius_max), material(),
                        log_uniform(Ranges::radius_min, Ranges::radius_max));
}

/// A sphere on a sphere (as sphere_pair), on an elastic wall of another material, or on an
/// ideally rigid wall (docs/decisions.md D1), one third each.
inline rc::Gen<Pair> sphere_or_wall_pair() {
  return rc::gen::apply(
      [](Pair spheres, int kind) {
        if (kind == 0) return spheres;
        const Material& other = spheres.body2().material;
        return Pair(spheres.body1(), kind == 1 ? wall(other) : rigid_wall(other));
      },
      sphere_pair(), rc::gen::inRange(0, 3));
}

/// The same pair with body 1 and body 2 exchanged.
inline Pair swapped(const Pair& p) { return Pair(p.body2(), p.body1()); }

/// BP04 (8.65) for the Hertz force (alpha = 3/2): the elastic maximum overlap
/// xi0 = (5 m_eff g^2 / (4 rho))^{2/5} [m].
inline double hertz_reference_overlap(const Pair& p, double speed) {
  return std::pow(1.25 * p.effective_mass() * speed * speed / p.hertz_constant(), 0.4);
}

/// The largest impact speed [m/s] inside the quasi-static validity of the Hertz-type
/// models, with a safety factor 1/2 below the limits bounce warns at: g < 0.1 c_t
/// (BSHP96 (B11), c_t of (B3)) and contact radius a = sqrt(R_eff xi0) < 0.1 R_eff (small
/// strain, Hertz), i.e. xi0 < 0.01 R_eff, inverted with BP04 (8.65).
inline double max_valid_speed(const Pair& p) {
  const double sound = 0.1 * p.transversal_sound_speed();
  const double xi_max = 0.01 * p.effective_radius();
  const double strain = std::sqrt(0.8 * p.hertz_constant() * std::pow(xi_max, 2.5) / p.effective_mass());
  return 0.5 * std::min(sound, strain);
}

/// An impact speed within validity: log-uniform over six decades below max_valid_speed.
inline rc::Gen<double> valid_speed(const Pair& p) {
  const double hi = max_valid_speed(p);
  return log_uniform(1e-6 * hi, hi);
}

/// The elastic Hertz contact time at speed g [s] (exact constant, BSHP96 (A13)).
inline double hertz_time(const Pair& p, double speed) {
  return bounce::contact::hertz::collision_time(p.hertz_constant(), p.effective_mass(), speed);
}

/// The dissipative constant A [s] that gives the pair BP04's kappa (8.70) at speed g
/// (kappa is proportional to A).
inline double dissipative_constant_for_kappa(const Pair& p, double kappa, double speed) {
  return kappa / analytic::kappa(1.0, p.hertz_constant(), p.effective_mass(), speed);
}

/// A [s] with A / t_c log-uniform in [1e-6, 0.1] at speed g: the viscous time well below
/// the contact time (BSHP96 (B12), BP04 (8.26); bounce warns above 0.1). kappa (8.70) is
/// then ~5.5 A/t_c <= 0.55.
inline rc::Gen<double> valid_dissipative_constant(const Pair& p, double speed) {
  const double t_c = hertz_time(p, speed);
  return rc::gen::map(log_uniform(1e-6, 0.1), [t_c](double ratio) { return ratio * t_c; });
}

/// What a case of a registry model is made of: its name and its parameters as a front end
/// hands them over (models/registry.hpp).
struct ModelCase {
  std::string name;
  ParameterInputs inputs;
};

/// The parameters as NAME=VALUE, numbers with all 17 digits.
inline std::string describe(const ParameterInputs& inputs) {
  std::ostringstream os;
  os.precision(17);
  for (const auto& [name, value] : inputs) {
    os << " " << name << "=";
    if (const double* x = std::get_if<double>(&value)) {
      os << *x;
    } else {
      os << value_text(value);
    }
  }
  return os.str();
}

inline void showValue(const ModelCase& c, std::ostream& os) { os << c.name << describe(c.inputs); }

/// Parameters of registry model `name` for collisions of `pair` at speeds in [lo, hi],
/// drawn inside each model's validity at every speed of that range; std::nullopt for a
/// model this file does not know yet (a new registry row: the properties that iterate the
/// registry then fail and name it).
///
/// hertz: none. viscoelastic, viscoelastic-shifted, adhesive-viscoelastic, jkr-viscoelastic:
/// A with A/t_c(hi) in [1e-6, 0.1] (t_c is shortest at the top speed). krijt: the same A and
/// T_vis = f A, f in [1e-4, 0.24] (K13 after (18): A = T_vis/nu^2 with nu in [0.01, 0.49]).
/// maugis-viscoelastic: the same A and z0 log-uniform from 1e-12 m to 1e-7 m or R_eff/10.5,
/// whichever is smaller (the model takes the attraction's range h0 = 0.974 z0 up to R_eff/10),
/// which puts Maugis' lambda of these pairs from the JKR end (~1e4) through the transition
/// toward the DMT end (~1e-2).
/// power-law, BP04 (8.63): exponents alpha in [1, 2], beta in [0.5, 1.5], gamma in [0, 1];
/// D1 such that the elastic maximum overlap (8.65) at hi is the Hertz one (so the strain
/// stays small), and D2 such that the damping of the scaled equation (8.66)-(8.67),
/// k = D2 xi0^{gamma+1} g^{beta-2}, is in [1e-4, 0.5] at the speed of the range where it
/// is largest (k ~ g^{2(gamma+1)/(1+alpha) + beta - 2}). An overdamped power law can creep
/// towards xi = 0 without ever reaching it (for alpha = 2, gamma = 0, beta = 1 at k = 50,
/// x ~ 1/t): no collision ends, which is not a case the tests are about.
/// contact_end: overlap or force for the models without adhesion (an adhesive contact ends
/// where it breaks: they take overlap only).
inline std::optional<rc::Gen<ModelCase>> model_parameters(const std::string& name, const Pair& pair, double lo,
                                                          double hi) {
  const bool adhesive = models::model_registry().at(name).traits.adhesive;
  const auto end_rule = adhesive ? rc::gen::just(std::string("overlap"))
                                 : rc::gen::element(std::string("overlap"), std::string("force"));
  const auto with_end = [end_rule, name](rc::Gen<ParameterInputs> g) {
    return rc::gen::apply(
        [name](ParameterInputs in, std::string end) {
          in["contact_end"] = end;
          return ModelCase{name, std::move(in)};
        },
        g, end_rule);
  };
  const auto a = valid_dissipative_constant(pair, hi);
  if (name == "hertz") return with_end(rc::gen::just(ParameterInputs{}));
  if (name == "viscoelastic" || name == "viscoelastic-shifted" || name == "adhesive-viscoelastic" ||
      name == "jkr-viscoelastic") {
    return with_end(rc::gen::map(a, [](double x) { return ParameterInputs{{"A", x}}; }));
  }
  if (name == "maugis-viscoelastic") {
    const double z0_max = std::min(1e-7, pair.effective_radius() / 10.5);
    return with_end(rc::gen::apply([](double x, double z0) { return ParameterInputs{{"A", x}, {"z0", z0}}; }, a,
                                   log_uniform(1e-12, z0_max)));
  }
  if (name == "krijt") {
    return with_end(rc::gen::apply([](double x, double f) { return ParameterInputs{{"A", x}, {"tvis", f * x}}; },
                                   a, log_uniform(1e-4, 0.24)));
  }
  if (name == "power-law") {
    const double xi_hi = hertz_reference_overlap(pair, hi);
    return with_end(rc::gen::apply(
        [xi_hi, lo, hi](double alpha, double beta, double gamma, double damping) {
          const double d1 = 0.5 * (1.0 + alpha) * hi * hi / std::pow(xi_hi, 1.0 + alpha);  // (8.65) inverted
          const double exponent = 2.0 * (gamma + 1.0) / (1.0 + alpha) + beta - 2.0;
          const double g = exponent >= 0.0 ? hi : lo;  // where the scaled damping is largest
          const double xi0 = xi_hi * std::pow(g / hi, 2.0 / (1.0 + alpha));  // (8.65): xi0 ~ g^{2/(1+alpha)}
          const double d2 = damping / (std::pow(xi0, gamma + 1.0) * std::pow(g, beta - 2.0));
          return ParameterInputs{{"power_d1", d1}, {"power_alpha", alpha}, {"power_d2", d2},
                                 {"power_beta", beta}, {"power_gamma", gamma}};
        },
        uniform(1.0, 2.0), uniform(0.5, 1.5), uniform(0.0, 1.0), log_uniform(1e-4, 0.5)));
  }
  return std::nullopt;
}

/// The same for collisions at one speed.
inline std::optional<rc::Gen<ModelCase>> model_parameters(const std::string& name, const Pair& pair, double speed) {
  return model_parameters(name, pair, speed, speed);
}

}  // namespace bounce::property
