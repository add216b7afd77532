// The front door's contact resistance (resistance.hpp, docs/resistance.md).
#include "bounce/api/resistance.hpp"

#include "binding.hpp"
#include "bounce/contact/resistance.hpp"
#include "bounce/pair/pair_parameters.hpp"

namespace bounce::api {

const CommandSpec& resistance_command() {
  static const CommandSpec spec = [] {
    CommandSpec c{"contact resistance",
                  "Rolling, sliding and twisting resistance of a JKR contact, and the energy to break it (Dominik & "
                  "Tielens; Wada et al. 2007)",
                  true,
                  false,
                  {text_parameter("materials", "body 1's and body 2's materials A[,B] (as --material, --material2)",
                                  "A[,B]"),
                   with_default(real_parameter("xi_crit", "critical rolling displacement", "m", positive(),
                                               "critical rolling displacement xi_crit [m] (default 8e-10, Wada et "
                                               "al. 2007's; 0 < xi_crit < a0)"),
                                contact::resistance::standard_critical_rolling)}};
    return c;
  }();
  return spec;
}

namespace {

Record mode_record(const contact::resistance::Mode& m, const char* displacement, const char* limit) {
  return Record()
      .set("stiffness", m.stiffness)
      .set(displacement, m.critical_displacement)
      .set(limit, m.limit)
      .set("energy", m.energy);
}

}  // namespace

Record contact_resistance(const Inputs& inputs) {
  const detail::Bound b = detail::bind_inputs(resistance_command(), detail::with_materials(inputs));
  const Pair pair = bounce::make_pair(b.pair);
  const double xi_crit = *b.own.real("xi_crit");
  const contact::resistance::Resistance r = contact::resistance::contact_resistance(pair, xi_crit);
  Record rolling = mode_record(r.rolling, "critical_displacement", "moment");
  rolling.set("force", r.rolling_force);
  return Record()
      .set("law", "jkr")
      .set("pair", pair_record(pair))
      .set("surface_energy_per_surface", r.surface_energy)
      .set("contact_radius", r.contact_radius)
      .set("pull_off_force", r.pull_off_force)
      .set("critical_overlap", r.critical_overlap)
      .set("break_energy", r.break_energy)
      .set("rolling", rolling)
      .set("sliding", mode_record(r.sliding, "critical_displacement", "force"))
      .set("twisting", mode_record(r.twisting, "critical_angle", "moment"))
      .set("warnings", Value::List{});
}

}  // namespace bounce::api
