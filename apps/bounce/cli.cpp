#include "cli.hpp"

#include <unistd.h>
#include <charconv>
#include <chrono>
#include <cmath>
#include <iostream>
#include <regex>

#include <fmt/format.h>

#include "bounce/analysis/closed_forms.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/mixing.hpp"

namespace bounce::cli {

void NumberOptions::add(const std::string& name, const std::string& help) {
  options_[name] = app_->add_option(name, text_[name], help);
}

bool NumberOptions::given(const std::string& name) const {
  auto it = options_.find(name);
  return it != options_.end() && it->second->count() > 0;
}

std::optional<double> NumberOptions::get(const std::string& name) const {
  if (!given(name)) return std::nullopt;
  const std::string& text = text_.at(name);
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || text.empty()) {
    throw InvalidArgument(name, text.empty() ? "\"\"" : text, "a number");
  }
  return value;
}

std::string NumberOptions::text(const std::string& name) const {
  auto it = text_.find(name);
  return it == text_.end() ? std::string() : it->second;
}

double NumberOptions::require(const std::string& name, const std::string& what) const {
  auto value = get(name);
  if (!value) throw InvalidArgument(name, "(not given)", what);
  return *value;
}

BodyOptions::BodyOptions(CLI::App* app) : app_(app), numbers_(app) {
  app->add_option("--material", material_, "body 1 material from the table (see `bounce materials`)");
  numbers_.add("--E", "body 1 Young's modulus [Pa] (overrides the material)");
  numbers_.add("--nu", "body 1 Poisson ratio (overrides the material)");
  numbers_.add("--density", "body 1 density [kg/m^3] (overrides the material)");
  numbers_.add("--gamma", "body 1 surface energy (work of adhesion) [J/m^2]");
  numbers_.add("--radius", "body 1 radius [m]");
  app->add_option("--material2", material2_, "body 2 material (default: body 1's)");
  numbers_.add("--E2", "body 2 Young's modulus [Pa]");
  numbers_.add("--nu2", "body 2 Poisson ratio");
  numbers_.add("--density2", "body 2 density [kg/m^3]");
  numbers_.add("--gamma2", "body 2 surface energy [J/m^2]");
  numbers_.add("--radius2", "body 2 radius [m] (default: body 1's)");
  numbers_.add("--inertia", "body 1 moment of inertia J/(m R^2) (default 2/5, a solid sphere; BSHP96 (4))");
  numbers_.add("--inertia2", "body 2 moment of inertia J/(m R^2) (default 2/5)");
  app->add_flag("--wall", wall_, "body 2 is a flat elastic wall (of body 2's material)");
  app->add_flag("--rigid-wall", rigid_wall_, "body 2 is a flat, ideally rigid wall");
  app->add_option("--materials-file", materials_file_,
                  "TOML materials table to use instead of the built-in one");
}

MaterialTable BodyOptions::table() const {
  if (materials_file_.empty()) return MaterialTable::builtin();
  return MaterialTable::from_file(materials_file_);
}

Material BodyOptions::resolve_material(const MaterialTable& table, bool second,
                                       const std::optional<Material>& fallback) const {
  const std::string suffix = second ? "2" : "";
  const std::string& name = second ? material2_ : material_;
  Material m;
  bool have_base = false;
  if (!name.empty()) {
    try {
      m = table.at(name);
    } catch (const InvalidArgument& e) {
      throw e.renamed("--material" + suffix);
    }
    have_base = true;
  } else if (fallback) {
    m = *fallback;
    have_base = true;
  }
  auto take = [&](const std::string& option, double& field) {
    if (auto v = numbers_.get(option + suffix)) {
      field = *v;
    } else if (!have_base) {
      throw InvalidArgument(option + suffix, "(not given)",
                            fmt::format("a value, or --material{} NAME", suffix));
    }
  };
  take("--E", m.youngs_modulus);
  take("--nu", m.poisson_ratio);
  take("--density", m.density);
  if (auto g = numbers_.get("--gamma" + suffix)) m.surface_energy = *g;
  const bool overridden = numbers_.given("--E" + suffix) || numbers_.given("--nu" + suffix) ||
                          numbers_.given("--density" + suffix) ||
                          numbers_.given("--gamma" + suffix);
  if (overridden && !m.name.empty()) m.name += " (modified)";
  return m;
}

Pair BodyOptions::pair(std::optional<double> radius) const {
  const MaterialTable materials = table();
  if (wall_ && rigid_wall_) {
    throw InvalidArgument("--rigid-wall", "true", "either --wall or --rigid-wall, not both");
  }
  const Material m1 = resolve_material(materials, false, std::nullopt);
  const Material m2 = resolve_material(materials, true, m1);
  const double radius1 = radius ? *radius : numbers_.require("--radius", "a radius > 0 m for body 1");
  Body b1 = sphere(m1, radius1);
  if (auto j = numbers_.get("--inertia")) b1.inertia_factor = *j;
  Body b2;
  if (wall_ || rigid_wall_) {
    for (const char* option : {"--radius2", "--inertia2"}) {
      if (numbers_.given(option)) {
        throw InvalidArgument(option, numbers_.text(option), fmt::format("no {} with --wall/--rigid-wall", option));
      }
    }
    b2 = rigid_wall_ ? rigid_wall(m2) : wall(m2);
  } else {
    b2 = sphere(m2, numbers_.get("--radius2").value_or(radius1));
    b2.inertia_factor = numbers_.get("--inertia2").value_or(b1.inertia_factor);
  }
  try {
    return Pair(b1, b2);
  } catch (const InvalidArgument& e) {
    throw e.renamed(option_name(e.parameter()));
  }
}

std::vector<double> parse_range(const std::string& option, const std::string& text, bool log) {
  static const std::regex pattern(R"(^([^:]+):([^:]+):([0-9]+)$)");
  std::smatch match;
  const std::string allowed = "LO:HI:N with numbers LO <= HI and an integer N >= 1";
  if (!std::regex_match(text, match, pattern)) throw InvalidArgument(option, text, allowed);
  auto number = [&](const std::string& s) {
    double v = 0.0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v)) {
      throw InvalidArgument(option, text, allowed);
    }
    return v;
  };
  const double lo = number(match[1]);
  const double hi = number(match[2]);
  const long n = std::stol(match[3]);
  if (n < 1 || n > 10'000'000 || lo > hi) throw InvalidArgument(option, text, allowed);
  if (log && lo <= 0.0) throw InvalidArgument(option, text, "LO > 0 with --log");
  std::vector<double> values(static_cast<std::size_t>(n));
  for (long i = 0; i < n; ++i) {
    const double f = n == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(n - 1);
    values[static_cast<std::size_t>(i)] =
        log ? std::exp(std::log(lo) + f * (std::log(hi) - std::log(lo))) : lo + f * (hi - lo);
  }
  values.front() = lo;
  values.back() = hi;
  return values;
}

std::string option_name(const std::string& parameter) {
  static const std::regex body(R"(^body([12])\.(\w+)$)");
  static const std::regex plain(R"(^[A-Za-z][A-Za-z0-9_]*$)");
  std::smatch match;
  if (std::regex_match(parameter, match, body)) {
    const std::string field = match[2].str() == "inertia_factor" ? "inertia" : match[2].str();
    return "--" + field + (match[1] == "2" ? "2" : "");
  }
  if (std::regex_match(parameter, plain)) {
    std::string out = "--" + parameter;
    for (char& c : out) c = c == '_' ? '-' : c;
    return out;
  }
  return parameter;
}

nlohmann::json pair_json(const Pair& pair) {
  auto body = [](const Body& b) {
    nlohmann::json j;
    j["material"] = b.material.name;
    j["youngs_modulus"] = b.material.youngs_modulus;
    j["poisson_ratio"] = b.material.poisson_ratio;
    j["density"] = b.material.density;
    j["surface_energy"] = b.material.surface_energy ? nlohmann::json(*b.material.surface_energy)
                                                   : nlohmann::json(nullptr);
    if (b.is_wall()) {
      j["kind"] = b.rigid ? "rigid-wall" : "wall";
    } else {
      j["kind"] = "sphere";
      j["radius"] = b.radius;
      j["mass"] = b.mass();
    }
    return j;
  };
  nlohmann::json j;
  j["body1"] = body(pair.body1());
  j["body2"] = body(pair.body2());
  j["effective_radius"] = pair.effective_radius();
  j["effective_mass"] = pair.effective_mass();
  j["effective_modulus"] = pair.effective_modulus();
  j["hertz_compliance_d"] = pair.hertz_compliance_d();
  j["hertz_constant"] = pair.hertz_constant();
  j["tangential_mass_factor"] = pair.tangential_mass_factor();
  j["surface_energy"] = pair.surface_energy() ? nlohmann::json(*pair.surface_energy())
                                              : nlohmann::json(nullptr);
  return j;
}

namespace {
void check_finite(const nlohmann::json& value, const std::string& path) {
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {
    throw NumericalError("result " + path + " is not finite; refusing to print it");
  }
  if (value.is_object()) {
    for (const auto& [key, item] : value.items()) check_finite(item, path + "." + key);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      check_finite(value[i], path + "[" + std::to_string(i) + "]");
    }
  }
}
}  // namespace

void print_json(const nlohmann::json& value) {
  check_finite(value, "$");
  std::cout << value.dump(2) << '\n';
}

std::string csv_row(const std::vector<double>& values) {
  std::string row;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw NumericalError(fmt::format("CSV column {} is not finite; refusing to print it", i + 1));
    }
    if (i) row += ',';
    row += fmt::format("{}", values[i]);
  }
  return row;
}

int run_guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const InvalidArgument& e) {
    InvalidArgument named = e.renamed(option_name(e.parameter()));
    std::cerr << "bounce: error: " << named.what() << '\n';
    return 2;
  } catch (const NumericalError& e) {
    std::cerr << "bounce: numerical error: " << e.what() << '\n';
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "bounce: internal error: " << e.what() << '\n';
    return 4;
  }
}

}  // namespace bounce::cli

// --- model options, outcomes, progress -------------------------------------------

namespace bounce::cli {

std::array<double, 2> parse_radii(const std::string& option, const std::string& text) {
  const auto comma = text.find(',');
  const std::string allowed = "two principal radii R1,R2 in m (inf for a flat direction)";
  if (comma == std::string::npos) throw InvalidArgument(option, text, allowed);
  auto number = [&](const std::string& s) {
    double v = 0.0;
    const bool inf = s == "inf";
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (!inf && (ec != std::errc() || ptr != s.data() + s.size())) throw InvalidArgument(option, text, allowed);
    return inf ? std::numeric_limits<double>::infinity() : v;
  };
  return {number(text.substr(0, comma)), number(text.substr(comma + 1))};
}

namespace {
double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

ModelOptions::ModelOptions(CLI::App* app, NumberOptions& numbers) : numbers_(numbers) {
  app->add_option("--model", model_,
                  "hertz | viscoelastic | viscoelastic-shifted | power-law | adhesive-viscoelastic | krijt | "
                  "jkr-viscoelastic (default viscoelastic)");
  numbers_.add("--A", "dissipative constant A [s] (BP04 (8.38), BSHP96 (23))");
  numbers_.add("--eta1", "shear viscosity eta1 [Pa s] (A from BP04 (8.38))");
  numbers_.add("--eta2", "bulk viscosity eta2 [Pa s] (A from BP04 (8.38))");
  app->add_option("--contact-end", contact_end_, "overlap | force: when the contact ends (default overlap)");
  app->add_option("--method", method_, "integrate | master | auto (default: master where valid)");
  app->add_option("--tolerance", tolerance_, "relative and absolute tolerance of direct integration (default 1e-12)");
  app->add_option("--curvature-radii", curvature1_, "principal radii R1,R2 of body 1 [m] (convex bodies)");
  app->add_option("--curvature-radii2", curvature2_, "principal radii R1',R2' of body 2 [m]");
  numbers_.add("--angle", "angle phi between the planes of R1 and R1' [rad] (convex bodies)");
  numbers_.add("--tvis", "viscous relaxation time T_vis [s] (krijt; A = T_vis/nu^2 unless --A)");
  numbers_.add("--z0", "equilibrium separation z0 [m] (krijt crack law, sigma0 = gamma/z0; default 2e-10)");
  numbers_.add("--k", "relaxed / instantaneous modulus k of the crack law (default 0.02)");
  numbers_.add("--B", "dissipative constant B [s] of BP04 (8.57) (adhesive-viscoelastic; default A)");
  numbers_.add("--yield", "yield strength Y [Pa]: adds Thornton-Ning plastic losses, K13 (28)-(30)");
  app->add_option("--adhesive-tolerance", adhesive_tolerance_,
                  "relative tolerance of krijt / jkr-viscoelastic integration (default 1e-8)");
  app->add_option("--stiff-engine", stiff_engine_, "krijt: rodas | cvode (default rodas; cvode cross-checks)");
  numbers_.add("--power-d1", "power-law D1 [m^{1-alpha}/s^2]");
  numbers_.add("--power-alpha", "power-law elastic exponent alpha (default 1.5)");
  numbers_.add("--power-d2", "power-law D2 [m^{1-gamma-beta} s^{beta-2}]");
  numbers_.add("--tangential-velocity", "tangential impact velocity g^T [m/s]: an oblique collision (BSHP96 §II B)");
  app->add_option("--tangential-law", tangential_law_, "asperity (BSHP96 (35), default) | step (BSHP96 (39))");
  app->add_option("--asperity-form", asperity_form_,
                  "published (BSHP96 (35), default) | passive (no energy from the changing stiffness)");
  numbers_.add("--friction", "friction coefficient mu (BSHP96 (36))");
  numbers_.add("--asperity", "asperity size zeta0 [m] (BSHP96 (32); asperity law)");
  numbers_.add("--shear-damping", "gamma_s [1/s] (BSHP96 (39); step law)");
  numbers_.add("--power-beta", "power-law rate exponent beta (default 1)");
  numbers_.add("--power-gamma", "power-law overlap exponent gamma of the dissipative term (default 0.5)");
}

models::ModelSpec ModelOptions::spec() const {
  models::ModelSpec s;
  s.name = model_;
  (void)models::model_info(s.name);  // unknown model -> InvalidArgument("model", …)
  s.dissipative_constant = numbers_.get("--A");
  s.shear_viscosity = numbers_.get("--eta1");
  s.bulk_viscosity = numbers_.get("--eta2");
  s.end_rule = models::parse_end_rule(contact_end_);
  if (!curvature1_.empty() || !curvature2_.empty() || numbers_.given("--angle")) {
    if (curvature1_.empty()) throw InvalidArgument("--curvature-radii", "(not given)", "R1,R2 of body 1 in m");
    const auto r1 = parse_radii("--curvature-radii", curvature1_);
    const auto r2 = curvature2_.empty() ? r1 : parse_radii("--curvature-radii2", curvature2_);
    s.curvatures = convex::Curvatures{r1[0], r1[1], r2[0], r2[1], numbers_.get("--angle").value_or(0.0)};
  }
  s.relaxation_time = numbers_.get("--tvis");
  s.z0 = numbers_.get("--z0").value_or(0.2e-9);
  s.k = numbers_.get("--k").value_or(0.02);
  s.dissipative_constant_b = numbers_.get("--B");
  s.yield_strength = numbers_.get("--yield");
  try {
    s.tangential_law = models::parse_tangential_law(tangential_law_);
    s.asperity_form = models::parse_asperity_form(asperity_form_);
  } catch (const InvalidArgument& e) {
    throw e.renamed(option_name(e.parameter()));
  }
  s.friction = numbers_.get("--friction");
  s.asperity_size = numbers_.get("--asperity");
  s.shear_damping = numbers_.get("--shear-damping");
  if (s.name == "power-law") {
    models::PowerLawParameters p;
    p.d1 = numbers_.require("--power-d1", "D1 > 0 for the power-law model");
    p.d2 = numbers_.require("--power-d2", "D2 >= 0 for the power-law model");
    p.alpha = numbers_.get("--power-alpha").value_or(1.5);
    p.beta = numbers_.get("--power-beta").value_or(1.0);
    p.gamma = numbers_.get("--power-gamma").value_or(0.5);
    s.power_law = p;
  }
  return s;
}

CollideOptions ModelOptions::collide_options() const {
  CollideOptions o;
  o.method = parse_method(method_);
  require_open_interval("tolerance", tolerance_, 1e-15, 1e-3, "tolerance");
  o.integration.relative_tolerance = tolerance_;
  o.integration.absolute_tolerance = tolerance_;
  o.adhesive_tolerance = require_open_interval("adhesive_tolerance", adhesive_tolerance_, 1e-14, 1e-3, "tolerance");
  if (stiff_engine_ == "cvode") {
    o.stiff_engine = dynamics::StiffEngine::cvode;
  } else if (stiff_engine_ != "rodas") {
    throw InvalidArgument("--stiff-engine", stiff_engine_, "rodas or cvode");
  }
  if (auto g = numbers_.get("--tangential-velocity")) {
    o.tangential_velocity = require_positive("tangential_velocity", *g, "a tangential velocity > 0 m/s");
  }
  return o;
}

nlohmann::json adhesive_closed_forms(const Pair& pair, const models::ModelSpec& spec, double v) {
  nlohmann::json j;
  for (const auto& [key, value] : named_values(bounce::adhesive_closed_forms(pair, spec, v))) j[key] = value;
  return j;
}

nlohmann::json outcome_json(const dynamics::CollisionOutcome& o, bool with_trajectory) {
  nlohmann::json j;
  j["cor"] = o.cor;
  j["outcome"] = std::string(dynamics::to_string(o.outcome));
  j["contact_time"] = o.contact_time;
  j["max_overlap"] = o.max_overlap;
  j["time_of_max_overlap"] = o.time_of_max_overlap;
  j["method"] = o.method;
  j["steps"] = o.steps;
  const auto& e = o.energy;
  j["energy"] = {{"initial_kinetic", e.initial_kinetic},     {"final_kinetic", e.final_kinetic},
                 {"bulk_dissipated", e.bulk_dissipated},     {"crack_dissipated", e.crack_dissipated},
                 {"plastic_dissipated", e.plastic_dissipated}, {"elastic_remaining", e.elastic_remaining},
                 {"surface_remaining", e.surface_remaining}, {"closure_error", e.closure_error}};
  if (o.tangential) {
    const auto& t = *o.tangential;
    j["cor_tangential"] = t.cor;
    j["tangential"] = {{"cor", t.cor},
                       {"initial_kinetic", t.initial_kinetic},
                       {"final_kinetic", t.final_kinetic},
                       {"asperity_dissipated", t.asperity_dissipated},
                       {"stored_at_end", t.stored_at_end},
                       {"stiffness_work", t.stiffness_work},
                       {"breaks", t.breaks},
                       {"averaged_time", t.averaged_time},
                       {"steps", t.steps}};
  }
  j["warnings"] = o.warnings;
  j["notes"] = o.notes;
  if (with_trajectory) {
    nlohmann::json t = nlohmann::json::array();
    for (const auto& s : o.trajectory) {
      t.push_back({{"time", s.time}, {"overlap", s.overlap}, {"rate", s.rate},
                   {"contact_radius", s.contact_radius}, {"elastic_force", s.elastic_force},
                   {"dissipative_force", s.dissipative_force}, {"beta", s.effective_surface_energy_ratio},
                   {"kinetic", s.kinetic}, {"elastic", s.elastic}, {"surface", s.surface},
                   {"bulk_dissipated", s.bulk_dissipated}, {"crack_dissipated", s.crack_dissipated}});
    }
    j["trajectory"] = t;
  }
  return j;
}

Progress::Progress(std::string what, bool forced)
    : what_(std::move(what)), enabled_(forced || ::isatty(STDERR_FILENO)), start_(now_seconds()) {}

void Progress::operator()(std::size_t done, std::size_t total) {
  if (!enabled_) return;
  const double t = now_seconds() - start_;
  if (done < total && t - last_ < 1.0) return;  // at most once a second
  last_ = t;
  std::cerr << fmt::format("{}: {}/{} ({:.0f}%) {:.1f} s\n", what_, done, total,
                           100.0 * static_cast<double>(done) / static_cast<double>(total), t);
}

}  // namespace bounce::cli
