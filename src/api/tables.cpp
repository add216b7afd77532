// The front door's tables: eps^N(g) or eps^T(g^N, g^T) for other simulators, and the value
// of a saved table.
#include <fmt/format.h>

#include "binding.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::api {

namespace {

// The range errors of the builders (velocity_min, tangential_velocity_max, ...) name the
// interval the user gave.
template <class Build>
auto naming_ranges(const Parameters& own, Build build) {
  try {
    return build();
  } catch (const InvalidArgument& e) {
    for (const auto& [range, single] : {std::pair{"velocities", "velocity"}, {"tangential_velocities", "tangential_velocity"}}) {
      if (e.parameter() == std::string(single) + "_min" || e.parameter() == std::string(single) + "_max") {
        throw InvalidArgument(range, own.text(range), e.allowed());
      }
      if (e.parameter() == single) {  // one collision of the range refused (above c_t, say)
        throw InvalidArgument(range, own.text(range), fmt::format("a range whose speeds are valid: {} = {} fails, expected {}",
                                                                   single, e.value(), e.allowed()));
      }
    }
    throw;
  }
}

}  // namespace

std::variant<analysis::NormalTable, analysis::TangentialTable> table(const Inputs& inputs, const Progress& progress) {
  const detail::Bound bound = detail::bind_inputs(command("table"), inputs);
  const Parameters& own = bound.own;
  own.refuse_given(std::array{"velocity", "tangential_velocity"},
                   "a saved table to read (they are the speeds at which to read it)");
  if (!own.given("velocities")) throw InvalidArgument("velocities", "(not given)", "LO:HI in m/s (the table's range)");
  // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
  const auto range = detail::parse_interval("velocities", own.text("velocities"));
  const double lo = range[0], hi = range[1];
  const bool tangential = own.given("tangential_velocities");
  const auto gt = tangential ? detail::parse_interval("tangential_velocities", own.text("tangential_velocities"))
                             : std::array<double, 2>{};
  const Case c = detail::make_case(bound);
  analysis::TableOptions options;
  options.bound = *own.real("bound");
  options.progress = progress;
  if (tangential) {
    return naming_ranges(own, [&] {
      return analysis::build_tangential_table(c.pair, c.model, lo, hi, gt[0], gt[1], c.options, options);
    });
  }
  c.model_parameters.refuse_given(detail::tangential_names,
                                  "tangential_velocities too (the asperity law tabulates eps^T(g^N, g^T))");
  return naming_ranges(own, [&] { return analysis::build_normal_table(c.pair, c.model, lo, hi, c.options, options); });
}

namespace {

// A table read from JSON; a malformed one is reported against "load".
template <class Table>
Table parse_loaded(std::string_view json) {
  try {
    return Table::from_json(std::string(json));
  } catch (const InvalidArgument& e) {
    throw InvalidArgument("load", "(the file)", e.allowed());
  }
}

double required(const Inputs& inputs, const char* name, const char* why) {
  const auto it = inputs.find(name);
  if (it == inputs.end()) throw InvalidArgument(name, "(not given)", why);
  if (const auto* x = std::get_if<double>(&it->second)) return *x;
  if (const auto* s = std::get_if<std::string>(&it->second)) return parse_real(name, *s);
  throw InvalidArgument(name, value_text(it->second), "a number");
}

}  // namespace

Record table_value(std::string_view json, const Inputs& inputs) {
  const bool tangential = analysis::is_tangential_table(std::string(json));
  for (const auto& [name, value] : inputs) {
    if (name != "velocity" && !(tangential && name == "tangential_velocity")) {
      throw InvalidArgument(name, value_text(value), "only the speeds at which to read a saved table");
    }
  }
  const double g = required(inputs, "velocity", "the (normal) impact speed at which to read the table");
  if (tangential) {
    const auto t = parse_loaded<analysis::TangentialTable>(json);
    const double gt = required(inputs, "tangential_velocity", "the tangential impact speed at which to read the table");
    return Record()
        .set("velocity", g)
        .set("tangential_velocity", gt)
        .set("cor_tangential", t.cor(g, gt))
        .set("breaks", t.breaks(g, gt))
        .set("bound", t.bound)
        .set("description", t.description);
  }
  const auto t = parse_loaded<analysis::NormalTable>(json);
  return Record()
      .set("velocity", g)
      .set("cor", t.cor(g))
      .set("outcome", dynamics::to_string(t.outcome(g)))
      .set("bound", t.bound)
      .set("description", t.description);
}

}  // namespace bounce::api
