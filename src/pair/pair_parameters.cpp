#include "bounce/pair/pair_parameters.hpp"

#include <array>
#include <regex>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/materials_table.hpp"

namespace bounce {

namespace {

// The specs of one body ("" for body 1, "2" for body 2).
void add_body(std::vector<ParameterSpec>& out, const std::string& n) {
  const std::string which = n.empty() ? "body 1" : "body 2";
  const std::string note = n.empty() ? " (overrides the material)" : " (default: body 1's)";
  out.push_back(text_parameter("material" + n,
                               n.empty() ? "body 1 material from the table (see `bounce materials`)"
                                         : "body 2 material (default: body 1's)",
                               "NAME"));
  out.push_back(real_parameter("E" + n, "Young's modulus E", "Pa", positive(), which + " Young's modulus [Pa]" + note));
  out.push_back(real_parameter("nu" + n, "Poisson ratio nu", "", open_interval(-1.0, 0.5), which + " Poisson ratio" + note));
  out.push_back(real_parameter("density" + n, "density", "kg/m^3", positive(), which + " density [kg/m^3]" + note));
  // At most 1e3 J/m^2: solids lie below ~10 (K13 table 2: 0.014-1.6); 1e300 overflowed the
  // adhesion work W0 of BP04 (8.95) in a warning (found by the CLI fuzzer).
  const Range surface_energy{0.0, 1e3, true, true, false};
  ParameterSpec gamma = real_parameter("gamma" + n, "surface energy gamma", "J/m^2", surface_energy,
                                       which + " work of adhesion gamma = 2 gamma_s of like surfaces [J/m^2] (K13's; "
                                       "for a per-surface energy, as Dominik & Tielens 1997 and Wada et al. 2007 give "
                                       "it, use --surface-energy" + n + ")" + note);
  // `bounce fit` fits the pair's gamma (both bodies get the trial value): K13 Fig 7 (a)
  // finds gamma / gamma_L from about 0.3 to 30.
  if (n.empty()) gamma = fittable(std::move(gamma), {0.1, 100.0, 60, "gamma_L"});
  out.push_back(std::move(gamma));
  out.push_back(real_parameter("surface_energy" + n, "surface energy per surface gamma_s", "J/m^2",
                               Range{0.0, 500.0, true, true, false},
                               which + " surface energy of one surface gamma_s [J/m^2] (the aggregate literature's "
                               "gamma): bounce's gamma is 2 gamma_s, and unlike surfaces combine as 2 sqrt(gamma_s1 "
                               "gamma_s2)" + note));
  out.push_back(real_parameter("radius" + n, "radius", "m", positive(),
                               n.empty() ? "body 1 radius [m]" : "body 2 radius [m] (default: body 1's)"));
  // Mass inside a ball of radius R has J <= m R^2 about any axis through its centre.
  out.push_back(real_parameter("inertia" + n, "moment of inertia factor J/(m R^2)", "", Range{0.0, 1.0, false, true},
                               which + " moment of inertia J/(m R^2) (default 2/5, a solid sphere; BSHP96 (4))"));
}

std::vector<ParameterSpec> make_specs() {
  std::vector<ParameterSpec> out;
  add_body(out, "");
  add_body(out, "2");
  out.push_back(flag_parameter("wall", "body 2 is a flat elastic wall (of body 2's material)"));
  out.push_back(flag_parameter("rigid_wall", "body 2 is a flat, ideally rigid wall"));
  out.push_back(text_parameter("materials_file",
                                "TOML materials added to the built-in table (an entry replaces the built-in one of its name)",
                                "FILE"));
  return out;
}

// A body's material: from the table (or body 1's for body 2), with the values given on top.
Material resolve_material(const Parameters& p, const MaterialTable& table, const std::string& n,
                          const Material* fallback) {
  Material m;
  const std::string name = p.text("material" + n);
  bool have_base = fallback != nullptr;
  if (p.given("material" + n)) {
    try {
      m = table.at(name);
    } catch (const InvalidArgument& e) {
      throw e.renamed("material" + n);
    }
    have_base = true;
  } else if (fallback) {
    m = *fallback;
  }
  auto take = [&](const std::string& field, double& value) {
    if (p.given(field + n)) {
      value = *p.real(field + n);
    } else if (!have_base) {
      throw InvalidArgument(field + n, "(not given)", fmt::format("a value, or material{} from the table", n));
    }
  };
  take("E", m.youngs_modulus);
  take("nu", m.poisson_ratio);
  take("density", m.density);
  if (p.given("gamma" + n)) m.surface_energy = *p.real("gamma" + n);
  if (p.given("surface_energy" + n)) {  // D2: the work of adhesion of like surfaces is twice the surface energy
    if (p.given("gamma" + n))
      throw InvalidArgument("gamma" + n, format_value(*p.real("gamma" + n)),
                            fmt::format("gamma{0} or surface_energy{0}, not both (gamma{0} = 2 surface_energy{0})", n));
    m.surface_energy = 2.0 * *p.real("surface_energy" + n);
  }
  const bool overridden = p.given("E" + n) || p.given("nu" + n) || p.given("density" + n) || p.given("gamma" + n) ||
                          p.given("surface_energy" + n);
  if (overridden && !m.name.empty()) m.name += " (modified)";
  return m;
}

Body second_body(const Parameters& p, const Material& m2, const Body& b1) {
  const bool wall = p.flag("wall"), rigid = p.flag("rigid_wall");
  if (wall && rigid) throw InvalidArgument("rigid_wall", "true", "a wall or a rigid wall, not both");
  if (wall || rigid) {
    p.refuse_given(std::array{"radius2", "inertia2"}, "none with a wall (a wall is flat)");
    p.refuse_given(std::array{"density2"}, "none with a wall (a wall does not move: its mass is infinite)");
    if (rigid) {
      p.refuse_given(std::array{"E2", "nu2"}, "none with a rigid wall (it does not deform; wall is the elastic one)");
    }
    return rigid ? rigid_wall(m2) : bounce::wall(m2);
  }
  Body b2 = sphere(m2, p.real("radius2").value_or(b1.radius));
  b2.inertia_factor = p.real("inertia2").value_or(b1.inertia_factor);
  return b2;
}

}  // namespace

std::span<const ParameterSpec> pair_parameters() {
  static const std::vector<ParameterSpec> specs = make_specs();
  return specs;
}

Pair make_pair(const Parameters& p, std::optional<double> radius) {
  const MaterialTable table =
      p.given("materials_file") ? MaterialTable::builtin().with(MaterialTable::from_file(p.text("materials_file")))
                                : MaterialTable::builtin();
  const Material m1 = resolve_material(p, table, "", nullptr);
  const Material m2 = resolve_material(p, table, "2", &m1);
  if (radius) p.refuse_given(std::array{"radius"}, "none with a sweep over radii (the sweep sets body 1's radius)");
  Body b1 = sphere(m1, radius ? *radius : p.require_real("radius", "a radius > 0 m for body 1"));
  if (auto j = p.real("inertia")) b1.inertia_factor = *j;
  const Body b2 = second_body(p, m2, b1);
  try {
    return Pair(b1, b2);
  } catch (const InvalidArgument& e) {
    throw e.renamed(pair_parameter_name(e.parameter()));
  }
}

std::string pair_parameter_name(std::string_view field) {
  static const std::regex body(R"(^body([12])\.(\w+)$)");
  const std::string text(field);
  std::smatch match;
  if (!std::regex_match(text, match, body)) return text;
  std::string name = match[2].str();
  if (name == "inertia_factor") name = "inertia";
  if (name == "rigid") name = "rigid_wall";
  return name + (match[1] == "2" ? "2" : "");
}

}  // namespace bounce
