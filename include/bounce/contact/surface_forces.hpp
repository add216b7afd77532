#pragma once
// Surface forces between two half-spaces and the Tabor parameters that decide
// which adhesive contact theory applies (BP04 (8.53)-(8.55), K13 (11)).

#include <string>
#include <string_view>

#include "bounce/core/parameters.hpp"

namespace bounce::contact::surface {

/// BP04 (8.53): Lennard-Jones pressure P_s(h) = H/(6 pi h^3) [z0^6/h^6 - 1] [Pa]
/// (positive = repulsive) at separation h, Hamaker constant H [J], equilibrium z0 [m].
double lennard_jones_pressure(double hamaker, double z0, double separation);
/// BP04 (8.54): gamma = H / (16 pi z0^2) [J/m^2].
double surface_energy_from_hamaker(double hamaker, double z0);
/// Inverse of (8.54): H = 16 pi z0^2 gamma [J].
double hamaker_from_surface_energy(double gamma, double z0);
/// Largest tensile stress of (8.53), at h = 3^{1/6} z0: sigma_th = 16 gamma / (9 sqrt(3) z0).
double lennard_jones_max_tension(double gamma, double z0);

/// K13 (11): mu = (R gamma^2 / (E*^2 z0^3))^{1/3}, the usual Tabor parameter.
double tabor_parameter(double effective_radius, double effective_modulus, double gamma,
                       double z0);
/// BP04 (8.55): mu^{3/2} = (2/3) gamma D sqrt(R_eff / z0^3); equals K13's / 4^{1/3}.
double tabor_parameter_bp04(double effective_radius, double effective_modulus, double gamma,
                            double z0);
/// Maugis' transition parameter lambda = 2 sigma0 (R / (pi gamma K^2))^{1/3}, K = 4E*/3,
/// with the Dugdale stress sigma0 matched to the Lennard-Jones peak tension.
/// lambda = 1.157 mu (K13 (11)).
double maugis_parameter(double effective_radius, double effective_modulus, double gamma,
                        double z0);

/// Regime by K13 §2.1.2: "jkr" for mu > 5, "dmt" for mu < 0.1, else "transition".
std::string regime_k13(double tabor_k13);
/// Regime by BP04 §8.2.3: "dmt" for mu < 1e-2, "jkr" for 1 <= mu <= 10,
/// "jump-into-contact" above 10 (both fail), else "transition".
std::string regime_bp04(double tabor_bp04);

/// The parameter z0 [m] (default 2e-10 m: K13 does not state the one it used).
ParameterSpec z0_parameter();

/// The Tabor parameters of a pair and the regimes they put it in.
struct TaborSummary {
  double z0 = 0.0;                    ///< [m]
  double tabor_parameter = 0.0;       ///< K13 (11)
  double tabor_parameter_bp04 = 0.0;  ///< BP04 (8.55)
  double maugis_lambda = 0.0;         ///< 1.157 mu
  std::string regime_k13;
  std::string regime_bp04;
};
TaborSummary tabor_summary(double effective_radius, double effective_modulus, double gamma, double z0);
/// The warning for a law ("jkr", "dmt") used outside its regime by K13 §2.1.2, or "".
std::string regime_warning(const TaborSummary& summary, std::string_view law);

}  // namespace bounce::contact::surface
