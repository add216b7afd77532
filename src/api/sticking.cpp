// The front door's sticking velocity, alone or against the radius (K13 fig. 5, right),
// beside its closed forms.
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "binding.hpp"
#include "bounce/analysis/sticking.hpp"
#include "bounce/analytic/adhesive.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/registry.hpp"

namespace bounce::api {

namespace {

// The closed forms beside a sticking velocity: K13 (25) and the exact elastic JKR value;
// BP04 (8.100), (8.101) and W0 (8.95) for BP04's weak-adhesion model.
Record sticking_closed_forms(const Pair& pair, const models::Model& model) {
  const double gamma = pair.require_surface_energy("model " + model.name);
  const double r = pair.effective_radius(), e = pair.effective_modulus(), m = pair.effective_mass();
  Record j;
  if (model.traits.closed_forms.jkr) {
    j.set("sticking_velocity_jkr", analytic::sticking_velocity_jkr(m, r, e, gamma));
    j.set("sticking_velocity_k13_25", analytic::sticking_velocity_k13(m, r, e, gamma));
  }
  if (model.traits.closed_forms.bp04_weak) {
    const double w0 = analytic::tensile_work(r, e, gamma);
    j.set("sticking_velocity_bp04_8_100", analysis::sticking_velocity_bp04(pair, model));
    j.set("sticking_velocity_bp04_8_101",
          analytic::sticking_velocity_bp04_leading(w0, m, model.hertz->dissipative_constant, model.hertz->force_constant));
    j.set("tensile_work_bp04_8_95", w0);
  }
  j.set("effective_radius", r);
  return j;
}

Record sticking_record(const Case& c) {
  const double tolerance = *c.own.real("relative_tolerance");
  const analysis::StickingVelocity s = analysis::sticking_velocity(c.pair, c.model, c.options, tolerance);
  Record j = sticking_closed_forms(c.pair, c.model);
  if (s.sticks_up_to_sound_speed) {
    j.set("sticking_velocity", nullptr);
    j.set("bracket", nullptr);
    j.set("note", fmt::format("the grains stick at every speed up to the transversal sound speed c_t = {:.4g} m/s, "
                              "where the quasi-static models end (BSHP96 (B11)): no sticking velocity below it",
                              s.lower));
  } else {
    j.set("sticking_velocity", s.velocity);
    j.set("bracket", std::vector<double>{s.lower, s.upper});
  }
  j.set("collisions", s.collisions);
  j.set("relative_tolerance", tolerance);
  return j;
}

// The default model cannot stick: with none named, that is said first (before the default's
// own parameters, which the user never meant to give, are asked for).
void require_model(const Inputs& inputs) {
  if (inputs.count("model")) return;
  const auto adhesive = models::model_registry().names_where([](const models::ModelRow& r) { return r.traits.adhesive; });
  throw InvalidArgument("model", "(not given)",
                        fmt::format("an adhesive model ({}): the default, {}, has no adhesion and never sticks",
                                    fmt::join(adhesive, ", "), models::ModelRegistry::default_name()));
}

}  // namespace

Record sticking(const Inputs& inputs, const Progress&) {
  require_model(inputs);
  const detail::Bound bound = detail::bind_inputs(command("sticking"), inputs);
  bound.own.refuse_given(std::array{"log"}, "radii with it (log spaces the radii)");
  bound.own.refuse_given(std::array{"radii"}, "none for one sticking velocity (radii give one for each radius)");
  return sticking_record(detail::make_case(bound));
}

namespace {

// The sticking velocity at each radius of body 1, one Record each (with its radius); a threshold
// that cannot be found is reported in its row, not fatal.
template <class Radii>  // detail::Points or std::vector<double>
void over_radii(const detail::Bound& bound, const Radii& radii, const PointSink& sink, const Progress& progress) {
  // Every radius's case first: a stream cannot take back its rows, so a bad one is refused before.
  for (std::size_t i = 0; i < radii.size(); ++i) (void)detail::make_case(bound, radii[i]);
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const Case c = detail::make_case(bound, radii[i]);
    Record j;
    try {
      j = sticking_record(c);
    } catch (const NumericalError& e) {  // a threshold that cannot be found: reported, not fatal
      j = sticking_closed_forms(c.pair, c.model);
      j.set("sticking_velocity", nullptr);
      j.set("note", e.what());
    }
    j.set("radius", radii[i]);
    sink(j);
    if (progress) progress(i + 1, radii.size());
  }
}

}  // namespace

void sticking_over_radii(const Inputs& inputs, const PointSink& sink, const Progress& progress) {
  require_model(inputs);
  const detail::Bound bound = detail::bind_inputs(command("sticking"), inputs);
  const auto radii = detail::parse_points("radii", bound.own.text("radii"), bound.own.flag("log"));
  if (radii.front() <= 0.0) throw InvalidArgument("radii", bound.own.text("radii"), "radii > 0 m (LO > 0)");
  over_radii(bound, radii, sink, progress);
}

void sticking_over_radii(const Inputs& inputs, const std::vector<double>& radii, const PointSink& sink,
                         const Progress& progress) {
  require_model(inputs);
  const detail::Bound bound = detail::bind_inputs(command("sticking"), inputs);
  bound.own.refuse_given(std::array{"radii"}, "none with the radii given as numbers");
  for (const double r : radii)
    if (!(r > 0.0) || !std::isfinite(r)) throw InvalidArgument("radii", format_value(r), "radii > 0 m and finite");
  over_radii(bound, radii, sink, progress);
}

Value sticking_over_radii(const Inputs& inputs, const Progress& progress) {
  Value::List rows;
  sticking_over_radii(inputs, [&rows](const Record& row) { rows.push_back(row); }, progress);
  return rows;
}

Table sticking_table(const Value& rows) {
  Table t;
  t.columns = {"radius", "effective_radius", "sticking_velocity", "sticking_velocity_jkr", "sticking_velocity_k13_25",
               "note"};
  for (const Value& row : rows.list()) {
    const Record& j = row.record();
    t.rows.push_back({j.at("radius"), j.at("effective_radius"), j.at("sticking_velocity"),
                      j.at("sticking_velocity_jkr"), j.at("sticking_velocity_k13_25"),
                      j.contains("note") ? j.at("note") : Value(std::string())});
  }
  return t;
}

}  // namespace bounce::api
