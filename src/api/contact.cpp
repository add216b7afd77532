// The front door's static contact: one state of a law, or its curve.
#include <fmt/format.h>

#include "binding.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/contact/surface_forces.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/pair_parameters.hpp"

namespace bounce::api {

namespace {

struct ContactCase {
  Pair pair;
  std::string law_name;
  std::unique_ptr<contact::ContactLaw> law;
  Parameters law_parameters, own;
};

ContactCase make_contact_case(const Inputs& inputs) {
  detail::Bound b = detail::bind_inputs(command("contact"), inputs);
  Pair pair = bounce::make_pair(b.pair);
  auto law = contact::make_contact_law(b.model, pair, b.model_parameters);
  return ContactCase{std::move(pair), b.model, std::move(law), std::move(b.model_parameters), std::move(b.own)};
}

Record point_record(const contact::ContactPoint& p) {
  return Record().set("contact_radius", p.contact_radius).set("overlap", p.overlap).set("force", p.force);
}

// The Tabor parameters of an adhesive law and the regime warnings.
void add_tabor(Record& out, Value::List& warnings, const ContactCase& c) {
  const double gamma = *c.pair.surface_energy();
  if (gamma <= 0.0) return;
  const auto t = contact::surface::tabor_summary(c.pair.effective_radius(), c.pair.effective_modulus(), gamma,
                                                 *c.law_parameters.real("z0"));
  out.set("z0", t.z0);
  out.set("tabor_parameter", t.tabor_parameter);
  out.set("tabor_parameter_bp04", t.tabor_parameter_bp04);
  out.set("maugis_lambda", t.maugis_lambda);
  out.set("regime_k13", t.regime_k13);
  out.set("regime_bp04", t.regime_bp04);
  const std::string warning = contact::surface::regime_warning(t, c.law_name);
  if (!warning.empty()) warnings.push_back(warning);
}

constexpr std::array<const char*, 3> ranges = {"forces", "overlaps", "contact_radii"};

}  // namespace

Record contact(const Inputs& inputs) {
  const ContactCase c = make_contact_case(inputs);
  c.own.refuse_given(ranges, "a CSV curve (contact_curve): one state takes force or overlap");
  c.own.refuse_given(std::array{"log"}, "a range (forces, overlaps or contact_radii) to space");
  if (c.own.given("force") && c.own.given("overlap")) {
    throw InvalidArgument("force", c.own.typed("force"), "force or overlap, not both");
  }
  const contact::ContactPoint p =
      c.own.given("overlap") ? c.law->at_overlap(*c.own.real("overlap")) : c.law->at_force(*c.own.real("force"));
  Record out;
  out.set("law", c.law->name());
  out.set("pair", pair_record(c.pair));
  Value::List warnings;
  const Record point = point_record(p);
  for (const auto& [key, value] : point.fields()) out.set(key, value);
  if (const auto shape = c.law->shape(p); !shape.empty()) out.set("ellipse", to_record(shape));
  if (const auto a = c.law->adhesion()) {
    for (const auto& [key, value] : contact::named_values(*a)) out.set(key, value);
    add_tabor(out, warnings, c);
  }
  out.set("warnings", std::move(warnings));
  return out;
}

void contact_curve(const Inputs& inputs, const std::function<void(const Table& row)>& sink) {
  const ContactCase c = make_contact_case(inputs);
  int given = 0;
  for (const char* name : ranges) given += c.own.given(name);
  if (given != 1) {
    throw InvalidArgument("forces", c.own.given("forces") ? c.own.text("forces") : "(not given)",
                          "one range: forces, overlaps or contact_radii LO:HI:N");
  }
  c.own.refuse_given(std::array{"force", "overlap"}, "no single state with a curve (one range only)");
  const char* range = c.own.given("forces") ? "forces" : c.own.given("overlaps") ? "overlaps" : "contact_radii";
  const detail::Points values = detail::parse_points(range, c.own.text(range), c.own.flag("log"));
  auto at = [&](double v) {
    const std::string_view r = range;
    try {
      return r == "forces" ? c.law->at_force(v) : r == "overlaps" ? c.law->at_overlap(v) : c.law->at_contact_radius(v);
    } catch (const InvalidArgument& e) {  // a point of the range, named as the option the user typed
      throw InvalidArgument(range, c.own.text(range),
                            fmt::format("values that are all valid: {} fails, expected {}", e.value(), e.allowed()));
    }
  };
  // Each point costs microseconds: all are computed once to check them (a stream cannot take
  // back its rows, so a bad one is refused before any), then again as they are written.
  for (std::size_t i = 0; i < values.size(); ++i) (void)at(values[i]);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const contact::ContactPoint p = at(values[i]);
    Table row;
    row.columns = {"contact_radius", "overlap", "force"};
    row.rows.push_back({p.contact_radius, p.overlap, p.force});
    sink(row);
  }
}

Table contact_curve(const Inputs& inputs) {
  Table t;
  t.columns = {"contact_radius", "overlap", "force"};
  contact_curve(inputs, [&t](const Table& row) { t.rows.push_back(row.rows.front()); });
  return t;
}

}  // namespace bounce::api
