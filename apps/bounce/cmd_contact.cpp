// `bounce contact`: static contact of two bodies under one law (SPEC §7).
#include <cmath>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "bounce/contact/convex.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/contact/surface_forces.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "cli.hpp"
#include "commands.hpp"

namespace bounce::cli {

namespace {

struct ContactOptions {
  explicit ContactOptions(CLI::App* app) : bodies(app), numbers(app) {}
  BodyOptions bodies;
  NumberOptions numbers;
  std::string law = "hertz";
  bool json = false;
  bool csv = false;
  bool log = false;
  std::string forces, overlaps, radii;
  std::string curvature1, curvature2;
};

nlohmann::json point_json(const contact::ContactPoint& p) {
  return {{"contact_radius", p.contact_radius}, {"overlap", p.overlap}, {"force", p.force}};
}

// Tabor parameters and the regime warnings for an adhesive law.
void add_tabor(nlohmann::json& out, const Pair& pair, const std::string& law, double z0) {
  const double gamma = *pair.surface_energy();
  if (gamma <= 0.0) return;
  const double R = pair.effective_radius();
  const double E = pair.effective_modulus();
  const double mu = surface::tabor_parameter(R, E, gamma, z0);
  const double mu_bp04 = surface::tabor_parameter_bp04(R, E, gamma, z0);
  out["z0"] = z0;
  out["tabor_parameter"] = mu;
  out["tabor_parameter_bp04"] = mu_bp04;
  out["maugis_lambda"] = surface::maugis_parameter(R, E, gamma, z0);
  out["regime_k13"] = surface::regime_k13(mu);
  out["regime_bp04"] = surface::regime_bp04(mu_bp04);
  const std::string regime = surface::regime_k13(mu);
  if ((law == "jkr" || law == "dmt") && regime != law) {
    out["warnings"].push_back(fmt::format(
        "Tabor parameter mu = {:.3g} (K13 (11), z0 = {:g} m): K13 puts this pair in the {} "
        "regime (JKR for mu > 5, DMT for mu < 0.1); law {} may be inaccurate, maugis covers all",
        mu, z0, regime, law));
  }
}

void print_text(const nlohmann::json& out) {
  std::cout << fmt::format("law: {}\n", out["law"].get<std::string>());
  const auto& pair = out["pair"];
  std::cout << fmt::format("pair: R_eff = {:.6g} m, m_eff = {:.6g} kg, E* = {:.6g} Pa",
                           pair["effective_radius"].get<double>(),
                           pair["effective_mass"].get<double>(),
                           pair["effective_modulus"].get<double>());
  if (!pair["surface_energy"].is_null()) {
    std::cout << fmt::format(", gamma = {:.6g} J/m^2", pair["surface_energy"].get<double>());
  }
  std::cout << "\n";
  std::cout << fmt::format("contact radius a     = {:.6g} m\n", out["contact_radius"].get<double>());
  std::cout << fmt::format("overlap        delta = {:.6g} m\n", out["overlap"].get<double>());
  std::cout << fmt::format("force          F     = {:.6g} N\n", out["force"].get<double>());
  if (out.contains("ellipse")) {
    const auto& e = out["ellipse"];
    std::cout << fmt::format("contact ellipse: a = {:.6g} m, b = {:.6g} m (x0 = a^2/b^2 = {:.6g}), "
                             "C0 = {:.6g} N/m^1.5\n",
                             e["semi_axis_a"].get<double>(), e["semi_axis_b"].get<double>(),
                             e["x0"].get<double>(), e["force_constant"].get<double>());
  }
  if (out.contains("pull_off_force")) {
    std::cout << fmt::format("pull-off force (force control)  = {:.6g} N at a = {:.6g} m\n",
                             out["pull_off_force"].get<double>(),
                             out["pull_off_contact_radius"].get<double>());
    std::cout << fmt::format("zero load                       : a = {:.6g} m, delta = {:.6g} m\n",
                             out["zero_load_contact_radius"].get<double>(),
                             out["zero_load_overlap"].get<double>());
    std::cout << fmt::format("separation (overlap control)    : delta = {:.6g} m at a = {:.6g} m\n",
                             out["separation_overlap"].get<double>(),
                             out["separation_contact_radius"].get<double>());
  }
  if (out.contains("tabor_parameter")) {
    std::cout << fmt::format(
        "Tabor parameter mu = {:.4g} (K13 (11): {}), BP04 (8.55) mu = {:.4g} ({}), Maugis lambda = "
        "{:.4g}, z0 = {:g} m\n",
        out["tabor_parameter"].get<double>(), out["regime_k13"].get<std::string>(),
        out["tabor_parameter_bp04"].get<double>(), out["regime_bp04"].get<std::string>(),
        out["maugis_lambda"].get<double>(), out["z0"].get<double>());
  }
  for (const auto& w : out["warnings"]) std::cout << "warning: " << w.get<std::string>() << "\n";
}

int run_contact(const ContactOptions& o) {
  const Pair pair = o.bodies.pair();
  const double z0 = o.numbers.get("--z0").value_or(0.2e-9);
  const bool convex = !o.curvature1.empty() || !o.curvature2.empty() || o.numbers.given("--angle");
  if (convex && o.law != "hertz") {
    throw InvalidArgument("--law", o.law, "hertz when --curvature-radii/--angle describe convex bodies");
  }
  const auto law = contact::make_contact_law(o.law, pair, contact::LawOptions{z0});

  const int ranges = !o.forces.empty() + !o.overlaps.empty() + !o.radii.empty();
  const bool single_force = o.numbers.given("--force");
  const bool single_overlap = o.numbers.given("--overlap");
  if (single_force + single_overlap + ranges > 1) {
    throw InvalidArgument("--force", o.numbers.text("--force"),
                          "only one of --force, --overlap, --forces, --overlaps, --contact-radii");
  }
  if (o.csv != (ranges == 1)) {
    throw InvalidArgument("--csv", o.csv ? "given" : "(not given)",
                          "--csv together with one range --forces/--overlaps/--contact-radii LO:HI:N");
  }

  std::optional<convex::ConvexContact> body_shape;
  if (convex) {
    if (o.curvature1.empty()) {
      throw InvalidArgument("--curvature-radii", "(not given)", "R1,R2 of body 1 in m");
    }
    const auto r1 = parse_radii("--curvature-radii", o.curvature1);
    const double inf = std::numeric_limits<double>::infinity();
    const auto r2 = o.curvature2.empty()
                        ? (pair.body2().is_wall() ? std::array<double, 2>{inf, inf} : r1)
                        : parse_radii("--curvature-radii2", o.curvature2);
    body_shape = convex::solve({r1[0], r1[1], r2[0], r2[1], o.numbers.get("--angle").value_or(0.0)},
                               pair.hertz_compliance_d());
  }

  if (o.csv) {
    std::vector<double> values;
    std::string kind;
    if (!o.forces.empty()) values = parse_range("--forces", o.forces, o.log), kind = "force";
    if (!o.overlaps.empty()) values = parse_range("--overlaps", o.overlaps, o.log), kind = "overlap";
    if (!o.radii.empty()) values = parse_range("--contact-radii", o.radii, o.log), kind = "radius";
    if (body_shape) {
      throw InvalidArgument("--csv", "given", "a single --force or --overlap for convex bodies");
    }
    std::ostringstream text;
    text << "contact_radius,overlap,force\n";
    for (double v : values) {
      contact::ContactPoint p;
      if (kind == "force") {
        p = law->at_force(v);
      } else if (kind == "overlap") {
        p = law->at_overlap(v);
      } else {
        p = law->at_contact_radius(v);
      }
      text << csv_row({p.contact_radius, p.overlap, p.force}) << '\n';
    }
    std::cout << text.str();
    return 0;
  }

  nlohmann::json out;
  out["law"] = std::string(law->name());
  out["pair"] = pair_json(pair);
  out["warnings"] = nlohmann::json::array();
  if (body_shape) {
    const double d = pair.hertz_compliance_d();
    double overlap = 0.0;
    if (single_overlap) {
      overlap = require_non_negative("overlap", *o.numbers.get("--overlap"), "overlap [m]");
    } else {
      const double f = require_non_negative("force", o.numbers.get("--force").value_or(0.0),
                                            "force [N] (hertz has no adhesion)");
      overlap = std::cbrt((f / body_shape->force_constant) * (f / body_shape->force_constant));
    }
    const auto ellipse = convex::ellipse(*body_shape, d, overlap);
    out["overlap"] = overlap;
    out["force"] = convex::force(*body_shape, overlap);
    out["contact_radius"] = std::sqrt(ellipse.semi_axis_a * ellipse.semi_axis_b);
    out["ellipse"] = {{"semi_axis_a", ellipse.semi_axis_a},
                      {"semi_axis_b", ellipse.semi_axis_b},
                      {"x0", body_shape->x0},
                      {"b1", body_shape->form.b1},
                      {"b2", body_shape->form.b2},
                      {"n_x0", body_shape->n_x0},
                      {"m_x0", body_shape->m_x0},
                      {"force_constant", body_shape->force_constant}};
  } else {
    contact::ContactPoint p = single_overlap ? law->at_overlap(*o.numbers.get("--overlap"))
                                             : law->at_force(o.numbers.get("--force").value_or(0.0));
    out.update(point_json(p));
  }
  if (auto a = law->adhesion()) {
    for (const auto& [key, value] : contact::named_values(*a)) out[key] = value;
    add_tabor(out, pair, o.law, z0);
  }
  if (o.json) {
    print_json(out);
  } else {
    print_text(out);
  }
  return 0;
}

}  // namespace

Command add_contact_command(CLI::App& root) {
  auto* app = root.add_subcommand(
      "contact", "Static contact of two bodies: Hertz, JKR, DMT or Maugis-Dugdale (SPEC §2)");
  auto o = std::make_shared<ContactOptions>(app);
  app->add_option("--law", o->law, "hertz | jkr | dmt | maugis (default hertz)");
  o->numbers.add("--force", "total normal force [N] (default 0: zero external load)");
  o->numbers.add("--overlap", "overlap (mutual approach) [m]");
  o->numbers.add("--z0", "equilibrium separation of the surfaces [m] (default 2e-10)");
  o->numbers.add("--angle", "angle phi between the planes of R1 and R1' [rad] (convex bodies)");
  app->add_option("--curvature-radii", o->curvature1,
                  "principal radii R1,R2 of body 1 [m] (convex bodies; hertz only)");
  app->add_option("--curvature-radii2", o->curvature2,
                  "principal radii R1',R2' of body 2 [m] (default: as body 1, or flat for a wall)");
  app->add_flag("--json", o->json, "print JSON");
  app->add_flag("--csv", o->csv, "print a CSV curve (needs one of the ranges below)");
  app->add_option("--forces", o->forces, "CSV curve over forces LO:HI:N [N]");
  app->add_option("--overlaps", o->overlaps, "CSV curve over overlaps LO:HI:N [m]");
  app->add_option("--contact-radii", o->radii,
                  "CSV curve over contact radii LO:HI:N [m] (whole curve, both branches)");
  app->add_flag("--log", o->log, "geometric spacing of the range");
  return {app, [o]() { return run_contact(*o); }};
}

}  // namespace bounce::cli
