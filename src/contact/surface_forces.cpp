#include "bounce/contact/surface_forces.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <numbers>

namespace bounce::contact::surface {

namespace {
constexpr double pi = std::numbers::pi;
}

double lennard_jones_pressure(double hamaker, double z0, double h) {  // BP04 (8.53)
  const double ratio3 = (z0 / h) * (z0 / h) * (z0 / h);
  return hamaker / (6.0 * pi * h * h * h) * (ratio3 * ratio3 - 1.0);
}

double surface_energy_from_hamaker(double hamaker, double z0) {  // BP04 (8.54)
  return hamaker / (16.0 * pi * z0 * z0);
}

double hamaker_from_surface_energy(double gamma, double z0) {  // BP04 (8.54) inverted
  return 16.0 * pi * z0 * z0 * gamma;
}

double lennard_jones_max_tension(double gamma, double z0) {  // extremum of BP04 (8.53)
  return 16.0 * gamma / (9.0 * std::sqrt(3.0) * z0);
}

double tabor_parameter(double R, double e_star, double gamma, double z0) {  // K13 (11)
  return std::cbrt(R * gamma * gamma / (e_star * e_star * z0 * z0 * z0));
}

double tabor_parameter_bp04(double R, double e_star, double gamma, double z0) {  // BP04 (8.55)
  const double d = 3.0 / (4.0 * e_star);
  const double mu_three_halves = 2.0 / 3.0 * gamma * d * std::sqrt(R / (z0 * z0 * z0));
  return std::cbrt(mu_three_halves * mu_three_halves);
}

double maugis_parameter(double R, double e_star, double gamma, double z0) {
  const double sigma0 = lennard_jones_max_tension(gamma, z0);
  const double k = 4.0 * e_star / 3.0;
  return 2.0 * sigma0 * std::cbrt(R / (pi * gamma * k * k));
}

std::string regime_k13(double mu) {
  if (mu > 5.0) return "jkr";
  if (mu < 0.1) return "dmt";
  return "transition";
}

std::string regime_bp04(double mu) {
  if (mu < 1e-2) return "dmt";
  if (mu > 10.0) return "jump-into-contact";
  if (mu >= 1.0) return "jkr";
  return "transition";
}

ParameterSpec z0_parameter() {
  // Below a femtometre (a nucleus) or above a micrometre the surface-force picture (forces
  // of range z0, BP04 (8.53)) means nothing; the bounds also keep z0^3 (Tabor's parameter),
  // sigma0 = gamma/z0 and Maugis' lambda far from underflow and overflow (z0 = 1e-150 m gave
  // an infinite Tabor parameter).
  const Range physical{1e-15, 1e-6, true, true, false};
  // `bounce fit` can fit it (K13 does not state its z0): 0.05-1 nm around atomic spacings.
  return fittable(with_default(real_parameter("z0", "equilibrium separation z0", "m", physical,
                                              "equilibrium separation z0 [m] of the surfaces: Tabor parameter K13 "
                                              "(11), Maugis' lambda, krijt's sigma0 = gamma/z0 (default 2e-10)"),
                               0.2e-9),
                  {0.05e-9, 1e-9, 20, ""});
}

TaborSummary tabor_summary(double r, double e, double gamma, double z0) {
  TaborSummary t;
  t.z0 = z0;
  t.tabor_parameter = tabor_parameter(r, e, gamma, z0);
  t.tabor_parameter_bp04 = tabor_parameter_bp04(r, e, gamma, z0);
  t.maugis_lambda = maugis_parameter(r, e, gamma, z0);
  t.regime_k13 = regime_k13(t.tabor_parameter);
  t.regime_bp04 = regime_bp04(t.tabor_parameter_bp04);
  return t;
}

std::string regime_warning(const TaborSummary& t, std::string_view law) {
  if ((law != "jkr" && law != "dmt") || t.regime_k13 == law) return "";
  return fmt::format(
      "Tabor parameter mu = {:.3g} (K13 (11), z0 = {:g} m): K13 puts this pair in the {} "
      "regime (JKR for mu > 5, DMT for mu < 0.1); law {} may be inaccurate, maugis covers all",
      t.tabor_parameter, t.z0, t.regime_k13, law);
}

}  // namespace bounce::contact::surface
