#include "catalogue.hpp"

#include "bounce/contact/surface_forces.hpp"

#include <utility>

namespace bounce::models::catalogue {

namespace {
ParameterSpec real(std::string name, std::string quantity, std::string unit, Range range, std::string help,
                   std::optional<double> default_value = std::nullopt) {
  ParameterSpec s = real_parameter(std::move(name), std::move(quantity), std::move(unit), range, std::move(help));
  if (default_value) s.default_value = *default_value;
  return s;
}
}  // namespace

ParameterSpec dissipative_constant() {
  // From nanosecond relaxation in micrometre grains to BSHP96's centimetre ice (~1e-5 s).
  return fittable(real("A", "dissipative constant A", "s", non_negative(),
                       "dissipative constant A [s] (BP04 (8.38), BSHP96 (23))"),
                  {1e-12, 1e-2, 60, ""});
}
ParameterSpec shear_viscosity() {
  return real("eta1", "shear viscosity eta1", "Pa s", non_negative(), "shear viscosity eta1 [Pa s] (A from BP04 (8.38))");
}
ParameterSpec bulk_viscosity() {
  return real("eta2", "bulk viscosity eta2", "Pa s", non_negative(), "bulk viscosity eta2 [Pa s] (A from BP04 (8.38))");
}
ParameterSpec relaxation_time() {
  // K13 Fig 8 (b): 1e-14 s to 1e-9 s, with a decade to spare on either side.
  return fittable(real("tvis", "viscous relaxation time T_vis", "s", positive(),
                       "viscous relaxation time T_vis [s] (A = T_vis/nu^2 unless A is given, K13 after (18))"),
                  {1e-15, 1e-8, 60, ""});
}
ParameterSpec dissipative_constant_b() {
  return real("B", "dissipative constant B", "s", non_negative(),
              "dissipative constant B [s] of BP04 (8.57) (default: from eta1, eta2, else A)");
}
ParameterSpec z0() { return contact::surface::z0_parameter(); }
ParameterSpec krijt_z0() {
  // krijt's sigma0 = gamma/z0 sets its crack speed scale c = E* z0^2 / (gamma T_vis): at z0 =
  // 3e-13 m a 1 um ice collision at 30 m/s ran out of its time budget (the surface-force
  // picture's 1e-15 m, K13 (16) at 1e-30 of its speed, exceeded it at 8 m/s). 1e-12 m
  // (a hundredth of an atomic spacing) to 1 um works over the grid of docs/adhesive.md.
  ParameterSpec s = z0();
  s.range.lo = 1e-12;
  s.help += "; krijt: >= 1e-12 m";
  return s;
}
ParameterSpec k() {
  // K13 App. B starts the crack at beta0 = 1.01 k, inside the crack law's domain k < beta < 1/k
  // only while k < 0.995. Both ends tested over the grid of docs/adhesive.md (ice, R from
  // 0.1 um to 1 cm, g from 0.01 to 100 m/s, T_vis from 1e-16 to 1e-7 s): below 1e-10 the
  // formation at beta0 = 1.01 k underflows the first step (k = 1e-11: both engines failed at
  // 8 m/s), and above 0.5 slow cracks of millimetre grains do (k = 0.9, T_vis = 1e-7 s, 30 m/s).
  const Range tested{1e-10, 0.5, true, true, false};
  return fittable(real("k", "k (relaxed / instantaneous modulus)", "", tested,
                       "relaxed / instantaneous modulus k of the crack law K13 (16)-(17) (default 0.02)", 0.02),
                  {1e-3, 0.5, 30, ""});
}
ParameterSpec power_d1() {
  return real("power_d1", "power-law constant D1", "m^(1-alpha)/s^2", positive(), "power-law D1 [m^{1-alpha}/s^2]");
}
ParameterSpec power_alpha() {
  return real("power_alpha", "power-law elastic exponent alpha", "", positive(),
              "power-law elastic exponent alpha (default 1.5)", 1.5);
}
ParameterSpec power_d2() {
  return real("power_d2", "power-law constant D2", "m^(1-gamma-beta) s^(beta-2)", non_negative(),
              "power-law D2 [m^{1-gamma-beta} s^{beta-2}]");
}
ParameterSpec power_beta() {
  return real("power_beta", "power-law rate exponent beta", "", positive(), "power-law rate exponent beta (default 1)",
              1.0);
}
ParameterSpec power_gamma() {
  return real("power_gamma", "power-law overlap exponent gamma", "", non_negative(),
              "power-law overlap exponent gamma of the dissipative term (default 0.5)", 0.5);
}

const FieldTable<NoParameters>& no_fields() {
  static const FieldTable<NoParameters> table{};
  return table;
}

namespace {
// A from A, from the viscosities (BP04 (8.38)) or from T_vis (K13 after (18)): one way.
ParameterRule one_dissipative_constant() {
  return {{{"A"}, {"eta1", "eta2"}, {"tvis"}}, true, true, "one of A, the viscosities eta1 and eta2, or T_vis"};
}
}  // namespace

const FieldTable<ViscousParameters>& viscous_fields() {
  using S = ViscousParameters;
  static const FieldTable<S> table = FieldTable<S>{{dissipative_constant(), &S::dissipative_constant},
                                                   {shear_viscosity(), &S::shear_viscosity},
                                                   {bulk_viscosity(), &S::bulk_viscosity},
                                                   {relaxation_time(), &S::relaxation_time}}
                                         .with(one_dissipative_constant());
  return table;
}

const FieldTable<PowerLawParameters>& power_law_fields() {
  using S = PowerLawParameters;
  static const FieldTable<S> table{{power_d1(), &S::d1},
                                   {power_alpha(), &S::alpha},
                                   {power_d2(), &S::d2},
                                   {power_beta(), &S::beta},
                                   {power_gamma(), &S::gamma}};
  return table;
}

const FieldTable<AdhesiveViscousParameters>& adhesive_viscous_fields() {
  using S = AdhesiveViscousParameters;
  static const FieldTable<S> table = FieldTable<S>{{dissipative_constant(), &S::dissipative_constant},
                                                   {shear_viscosity(), &S::shear_viscosity},
                                                   {bulk_viscosity(), &S::bulk_viscosity},
                                                   {relaxation_time(), &S::relaxation_time},
                                                   {dissipative_constant_b(), &S::dissipative_constant_b},
                                                   {z0(), &S::z0}}
                                         .with(one_dissipative_constant());
  return table;
}

const FieldTable<ContactModelParameters>& contact_fields() {
  using S = ContactModelParameters;
  // The bulk damping A of K13 (19): given, or T_vis / nu^2 (K13 after (18)); both may be given.
  static const FieldTable<S> table =
      FieldTable<S>{
          {relaxation_time(), &S::relaxation_time}, {dissipative_constant(), &S::dissipative_constant}, {z0(), &S::z0}}
          .with({{{"tvis"}, {"A"}}, false, true, "a viscous relaxation time T_vis > 0 s, or A"});
  return table;
}

const FieldTable<CrackModelParameters>& crack_fields() {
  using S = CrackModelParameters;
  static const FieldTable<S> table = FieldTable<S>{{relaxation_time(), &S::relaxation_time},
                                                   {dissipative_constant(), &S::dissipative_constant},
                                                   {krijt_z0(), &S::z0},
                                                   {k(), &S::k}}
                                         .with({{{"tvis"}}, true, true,
                                                "a viscous relaxation time T_vis > 0 s for the crack law K13 (16)"});
  return table;
}

}  // namespace bounce::models::catalogue
