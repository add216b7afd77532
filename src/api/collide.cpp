// The front door's collisions: collide, curve (sweeps over speeds or radii), and the columns
// of a sweep.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "binding.hpp"
#include "bounce/analysis/closed_forms.hpp"
#include "bounce/analysis/curve.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/registry.hpp"
#include "records.hpp"

namespace bounce::api {

namespace {

// The tangential law's parameters need a tangential velocity (checked before the model is
// built, which would ask for the rest of the law first).
void check_oblique(const detail::Bound& b) {
  if (b.own.real("tangential_velocity").value_or(0.0) > 0.0) return;
  b.model_parameters.refuse_given(detail::tangential_names,
                                  "a tangential velocity g^T > 0 too (tangential_velocity; without it, or with 0, the "
                                  "collision is head-on): it is the tangential law of an oblique collision");
}

// How to collide: the model's numerical settings and the command's own (tangential
// velocity, trajectory, follow time).
analysis::CollideOptions collide_options(const Case& c) {
  analysis::CollideOptions o = c.options;
  o.tangential_velocity = c.own.real("tangential_velocity").value_or(0.0);
  if (c.own.spec("trajectory") != nullptr) {
    o.record_trajectory = c.own.flag("trajectory");
    o.trajectory_points = static_cast<int>(*c.own.real("trajectory_points"));
    if (c.own.given("trajectory_points") && !o.record_trajectory) {
      c.own.refuse_given(std::array{"trajectory_points"}, "trajectory too (the samples of a trajectory)");
    }
  }
  if (c.own.spec("follow") != nullptr && c.own.given("follow")) {
    if (c.model.traits.engine == models::Engine::force_law) {
      std::vector<std::string> with;
      for (const auto& row : models::model_registry().rows()) {
        if (row.traits.engine != models::Engine::force_law) with.push_back(row.name);
      }
      c.own.refuse_given(std::array{"follow"}, fmt::format("a model with contact dynamics ({}): the others stop at "
                                                           "separation", fmt::join(with, ", ")));
    }
    o.follow_time = *c.own.real("follow");
  }
  return o;
}

}  // namespace

Record collide(const Inputs& inputs) {
  const detail::Bound bound = detail::bind_inputs(command("collide"), inputs);
  check_oblique(bound);
  const Case c = detail::make_case(bound);
  const double velocity = c.own.require_real("velocity", "an impact velocity > 0 m/s");
  const auto outcome = analysis::collide(c.pair, c.model, velocity, collide_options(c));
  Record out = outcome_record(outcome);
  out.set("model", c.model.name);
  out.set("contact_end", models::to_string(c.model.end_rule));
  out.set("velocity", velocity);
  detail::add_scales(out, c.pair, c.model, velocity);
  if (c.model.traits.adhesive || c.model.yield_strength) {
    out.set("closed_forms", detail::closed_forms_record(c.pair, c.model, velocity));
  }
  if (outcome.outcome == dynamics::Outcome::stick) out.set("merged", detail::merged_record(c.pair, velocity));
  out.set("pair", pair_record(c.pair));
  return out;
}

namespace {

struct Sweep {
  bool by_radius = false;
  detail::Points values;   // speeds, or radii at one speed
  double velocity = 0.0;  // the speed of a sweep over radii
};

Sweep sweep_of(const Parameters& own) {
  Sweep s;
  s.by_radius = own.given("radii");
  if (s.by_radius == own.given("velocities")) {
    throw InvalidArgument("velocities", own.given("velocities") ? own.text("velocities") : "(not given)",
                          "either velocities LO:HI:N, or radii LO:HI:N with velocity V");
  }
  const bool log = own.flag("log");
  if (s.by_radius) {
    s.values = detail::parse_points("radii", own.text("radii"), log);
    if (s.values.front() <= 0.0) throw InvalidArgument("radii", own.text("radii"), "radii > 0 m (LO > 0)");
    s.velocity = own.require_real("velocity", "an impact velocity > 0 m/s with radii");
  } else {
    own.refuse_given(std::array{"velocity"}, "radii with it (a sweep over velocities has no fixed velocity)");
    s.values = detail::parse_points("velocities", own.text("velocities"), log);
    if (s.values.front() <= 0.0) {
      throw InvalidArgument("velocities", own.text("velocities"), "velocities > 0 m/s (LO > 0)");
    }
  }
  return s;
}

// Every point's pair and speed checked before the first collision: a stream cannot take back
// the rows it wrote, so a bad point is refused (exit 2) before any (a speed of the sweep named
// as the option the user typed; a force law that cannot be integrated at it, its own parameter).
void check_sweep(const detail::Bound& bound, const Sweep& s, const Case& first) {
  for (std::size_t i = 0; i < s.values.size(); ++i) {
    if (s.by_radius) {
      const Case c = detail::make_case(bound, s.values[i]);
      analysis::require_impact_velocity(c.pair, s.velocity);
      if (const auto* law = c.model.force_law()) law->check_speed(s.velocity);
      continue;
    }
    try {
      analysis::require_impact_velocity(first.pair, s.values[i]);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument("velocities", bound.own.text("velocities"),
                            fmt::format("speeds that are all valid: {} fails, expected {}", e.value(), e.allowed()));
    }
    if (const auto* law = first.model.force_law()) law->check_speed(s.values[i]);
  }
}

Record curve_point(const dynamics::CollisionOutcome& o, const Sweep& s, std::size_t i, const Case& c,
                   bool closed_forms) {
  Record j = outcome_record(o);
  const double velocity = s.by_radius ? s.velocity : s.values[i];
  if (s.by_radius) {
    j.set("radius", s.values[i]);
    j.set("effective_radius", c.pair.effective_radius());
  }
  j.set("velocity", velocity);
  if (closed_forms) j.set("closed_forms", detail::closed_forms_record(c.pair, c.model, velocity));
  return j;
}

// A change of outcome between neighbouring speeds of a sweep, before it is located.
struct Change {
  double lo, hi;
  dynamics::Outcome below, above;
};

}  // namespace

Record curve(const Inputs& inputs, const PointSink& sink, const Progress& progress, bool boundaries) {
  const detail::Bound bound = detail::bind_inputs(command("curve"), inputs);
  check_oblique(bound);
  const Sweep s = sweep_of(bound.own);
  const Case first = detail::make_case(bound, s.by_radius ? std::optional(s.values.front()) : std::nullopt);
  const bool closed = first.own.flag("closed_forms");
  if (closed && !first.model.traits.adhesive) {
    throw InvalidArgument("closed_forms", "true", "an adhesive model (the columns are K13 (24), (26), (27))");
  }
  const analysis::CollideOptions options = collide_options(first);
  check_sweep(bound, s, first);
  std::vector<Change> changes;  // as many as the outcome changes, not as the points
  std::optional<dynamics::Outcome> last;
  for (std::size_t i = 0; i < s.values.size(); ++i) {
    const Case c = s.by_radius ? detail::make_case(bound, s.values[i]) : first;
    const auto outcome = analysis::collide(c.pair, c.model, s.by_radius ? s.velocity : s.values[i], options);
    if (!s.by_radius && last && *last != outcome.outcome) {
      changes.push_back({s.values[i - 1], s.values[i], *last, outcome.outcome});
    }
    last = outcome.outcome;
    sink(curve_point(outcome, s, i, c, closed));
    if (progress) progress(i + 1, s.values.size());
  }
  Value::List found;
  for (const Change& k : boundaries ? changes : std::vector<Change>{}) {
    const auto b = analysis::outcome_boundary(first.pair, first.model, k.lo, k.hi, k.below, k.above, options);
    found.push_back(Record()
                        .set("velocity", b.velocity)
                        .set("below", dynamics::to_string(b.below))
                        .set("above", dynamics::to_string(b.above)));
  }
  return Record().set("boundaries", std::move(found));
}

Record curve(const Inputs& inputs, const Progress& progress) {
  Value::List points;
  Record out = curve(inputs, [&points](const Record& point) { points.push_back(point); }, progress);
  return out.set("points", std::move(points));
}

Table curve_table(const Record& curve) {
  Table t;
  const Value::List& points = curve.at("points").list();
  const bool by_radius = !points.empty() && points.front().record().contains("radius");
  const bool closed = !points.empty() && points.front().record().contains("closed_forms");
  const bool oblique = !points.empty() && points.front().record().contains("cor_tangential");
  t.columns = by_radius ? std::vector<std::string>{"radius", "effective_radius"} : std::vector<std::string>{"velocity"};
  for (const char* c : {"cor", "outcome", "contact_time", "max_overlap", "bulk_dissipated", "crack_dissipated"}) {
    t.columns.push_back(c);
  }
  if (oblique) t.columns.push_back("cor_tangential");
  if (closed) t.columns.insert(t.columns.end(), {"e_jkr", "e_d", "e_i"});
  for (const Value& point : points) {
    const Record& p = point.record();
    const Record& e = p.at("energy").record();
    std::vector<Value> row;
    if (by_radius) {
      row = {p.at("radius"), p.at("effective_radius")};
    } else {
      row = {p.at("velocity")};
    }
    row.insert(row.end(), {p.at("cor"), p.at("outcome"), p.at("contact_time"), p.at("max_overlap"),
                           e.at("bulk_dissipated"), e.at("crack_dissipated")});
    if (oblique) row.push_back(p.contains("cor_tangential") ? p.at("cor_tangential") : Value());
    if (closed) {
      const Record& f = p.at("closed_forms").record();
      row.insert(row.end(), {f.at("e_jkr"), f.contains("e_d") ? f.at("e_d") : Value(1.0),
                             f.contains("e_i") ? f.at("e_i") : Value(0.0)});
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table collide_columns(const Inputs& inputs, const std::vector<double>& velocities, std::vector<std::string>* warnings) {
  const detail::Bound bound = detail::bind_inputs(command("collide"), inputs);
  check_oblique(bound);
  const Case c = detail::make_case(bound);
  c.own.refuse_given(std::array{"velocity", "trajectory", "follow"},
                     "a single velocity (an array of speeds gives the columns of a curve)");
  const analysis::CollideOptions options = collide_options(c);
  const bool oblique = options.tangential_velocity > 0.0;
  Table t;
  t.columns = {"velocity", "cor", "outcome", "contact_time", "max_overlap", "bulk_dissipated", "crack_dissipated"};
  if (oblique) t.columns.push_back("cor_tangential");
  const auto kind_of = [](const std::string& said) { return message_kind(said.substr(said.find(": ") + 2)); };
  for (const double v : velocities) {
    const auto o = analysis::collide(c.pair, c.model, v, options);
    for (const std::string& w : warnings ? o.warnings : std::vector<std::string>{}) {
      const std::string kind = message_kind(w), text = fmt::format("at velocity {:g}: {}", v, w);
      const auto same = std::find_if(warnings->begin(), warnings->end(), [&](const auto& a) { return kind_of(a) == kind; });
      if (same == warnings->end()) warnings->push_back(text);
      else *same = text;
    }
    std::vector<Value> row = {v, o.cor, dynamics::to_string(o.outcome), detail::contact_time_value(o),
                              detail::max_overlap_value(o), o.energy.bulk_dissipated, o.energy.crack_dissipated};
    if (oblique) row.push_back(o.tangential ? Value(o.tangential->cor) : Value());
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace bounce::api
