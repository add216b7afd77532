// `bounce contact resistance` (docs/resistance.md): the front door's record, in words with units.
#include "resistance.hpp"

#include <iostream>

#include <fmt/format.h>

#include "bounce/api/resistance.hpp"
#include "output.hpp"

namespace bounce::cli {

namespace {

double num(const Record& r, std::string_view key) { return r.at(key).number(); }

std::string resistance_text(const Record& out) {
  const Record& pair = out.at("pair").record();
  const Record& roll = out.at("rolling").record();
  const Record& slide = out.at("sliding").record();
  const Record& twist = out.at("twisting").record();
  std::string s = fmt::format(
      "JKR contact: R_eff = {:.6g} m, E* = {:.6g} Pa, gamma = {:.6g} J/m^2 (work of adhesion; per surface gamma_s = "
      "{:.6g} J/m^2)\n",
      num(pair, "effective_radius"), num(pair, "effective_modulus"), num(pair, "surface_energy"),
      num(out, "surface_energy_per_surface"));
  s += fmt::format("  a0 = {:.6g} m, F_c = {:.6g} N, delta_c = {:.6g} m, E_break = {:.6g} J\n",
                   num(out, "contact_radius"), num(out, "pull_off_force"), num(out, "critical_overlap"),
                   num(out, "break_energy"));
  s += fmt::format("rolling:  k_r = {:.6g} N/m, xi_crit = {:.6g} m, M_roll = {:.6g} N m, F_roll = {:.6g} N, "
                   "E_roll = {:.6g} J\n",
                   num(roll, "stiffness"), num(roll, "critical_displacement"), num(roll, "moment"), num(roll, "force"),
                   num(roll, "energy"));
  s += fmt::format("sliding:  k_s = {:.6g} N/m, xi_s = {:.6g} m, F_slide = {:.6g} N, E_slide = {:.6g} J\n",
                   num(slide, "stiffness"), num(slide, "critical_displacement"), num(slide, "force"),
                   num(slide, "energy"));
  s += fmt::format("twisting: k_t = {:.6g} N m/rad, phi_crit = {:.6g} rad, M_twist = {:.6g} N m, E_twist = {:.6g} J\n",
                   num(twist, "stiffness"), num(twist, "critical_angle"), num(twist, "moment"), num(twist, "energy"));
  return s;
}

}  // namespace

Command add_resistance_command(CLI::App& contact) {
  const api::CommandSpec& spec = api::resistance_command();
  Command c;
  c.app = contact.add_subcommand("resistance", spec.summary);
  c.options = std::make_unique<Options>(c.app, spec);
  const bool* json = c.options->add_flag("json", "print JSON");
  Options& o = *c.options;
  c.run = [&o, json] {
    const Record out = api::contact_resistance(o.inputs());
    *json ? print_json(out) : print_text(out, resistance_text(out));
    return 0;
  };
  return c;
}

}  // namespace bounce::cli
