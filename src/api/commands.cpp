// The commands of the front door, their own parameters, and how inputs are split and checked.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <regex>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "binding.hpp"
#include "bounce/api/aggregate.hpp"
#include "bounce/api/atlas.hpp"
#include "bounce/api/resistance.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/core/suggest.hpp"
#include "bounce/models/registry.hpp"
#include "bounce/pair/pair_parameters.hpp"

namespace bounce::api {

namespace {

bool declares(std::span<const ParameterSpec> specs, std::string_view name) {
  return std::any_of(specs.begin(), specs.end(), [&](const ParameterSpec& s) { return s.name == name; });
}

// The models (or laws) that declare `name`.
std::vector<std::string> takers(std::string_view name, bool laws) {
  std::vector<std::string> out;
  if (laws) {
    for (const auto& row : contact::contact_laws()) {
      if (declares(row.parameters, name)) out.push_back(row.name);
    }
  } else {
    for (const auto& row : models::model_registry().rows()) {
      if (declares(row.parameters, name)) out.push_back(row.name);
    }
  }
  return out;
}

// How messages name the command: "bounce collide", or LAMMPS's "pair_coeff".
std::string who(const CommandSpec& command) {
  return command.name == "pair_coeff" ? std::string("pair_coeff") : "bounce " + command.name;
}

[[noreturn]] void refuse_unknown(const std::string& name, const ParameterValue& value, const CommandSpec& command,
                                 const std::string& model, const std::vector<std::string>& names) {
  const std::string value_given = value_text(value);
  const char* what = command.takes_model ? "model" : "law";
  if (command.takes_model || command.name == "contact") {
    const auto others = takers(name, !command.takes_model);
    if (!others.empty()) {
      throw InvalidArgument(name, value_given,
                            fmt::format("no {} with {} {} ({}s that take it: {})", name, what, model, what,
                                        fmt::join(others, ", ")));
    }
  }
  std::vector<std::string> owners;
  for (const CommandSpec& c : commands()) {
    if (declares(c.parameters, name)) owners.push_back(c.name);
  }
  if (!owners.empty()) {
    throw InvalidArgument(name, value_given,
                          fmt::format("no {} with {}: it belongs to bounce {}", name, who(command), fmt::join(owners, ", ")));
  }
  throw InvalidArgument(name, value_given,
                        fmt::format("a parameter that {} takes: one of {}{}", who(command), fmt::join(names, ", "),
                                    did_you_mean(name, names)));
}

// Does `command` work with the model `name`?
bool takes_model(const CommandSpec& command, std::string_view name) {
  return command.models.empty() || std::find(command.models.begin(), command.models.end(), name) != command.models.end();
}

// The reason `command` gives for never using a model's parameter `name`, if it never does.
const Unused* unused_by(const CommandSpec& command, std::string_view name) {
  for (const Unused& u : command.unused) {
    if (std::find(u.names.begin(), u.names.end(), name) != u.names.end()) return &u;
  }
  return nullptr;
}

std::string chosen(const Inputs& inputs, const char* key, const char* fallback) {
  const auto it = inputs.find(key);
  if (it == inputs.end()) return fallback;
  if (const auto* s = std::get_if<std::string>(&it->second)) return *s;
  throw InvalidArgument(key, value_text(it->second), "a name");
}

}  // namespace

const std::vector<CommandSpec>& commands() {
  static const std::vector<CommandSpec> table = detail::make_commands();
  return table;
}

const CommandSpec& command(std::string_view name) {
  if (name.starts_with("atlas ")) return atlas_command(name);  // `bounce atlas WORD`
  if (name == "contact resistance") return resistance_command();
  if (name == "aggregate build") return aggregate_commands().front();  // `bounce aggregate build`
  return find_named(commands(), name, "command");
}

namespace {
// A keyword among `names` (the registry's), with its default.
ParameterSpec keyword_parameter(const char* name, std::vector<std::string> names, const char* fallback) {
  const std::string help = fmt::format("{} (default {})", fmt::join(names, " | "), fallback);
  ParameterSpec s = with_default(choice_parameter(name, std::move(names), help), std::string(fallback));
  s.placeholder = "NAME";
  return s;
}
// A keyword among `names` that has no default: one must be named.
ParameterSpec required_keyword(const char* name, std::vector<std::string> names) {
  const std::string help = fmt::format("{} (required: no default)", fmt::join(names, " | "));
  ParameterSpec s = choice_parameter(name, std::move(names), help);
  s.placeholder = "NAME";
  return s;
}
}  // namespace

ParameterSpec model_parameter() {
  return keyword_parameter("model", models::model_registry().names(), models::ModelRegistry::default_name());
}

// The model a command uses when none is named: its own default, else the registry's where the
// command takes it, else its first.
std::string default_model(const CommandSpec& c) {
  if (!c.default_model.empty()) return c.default_model;
  const std::string fallback = models::ModelRegistry::default_name();
  if (c.models.empty() || std::find(c.models.begin(), c.models.end(), fallback) != c.models.end()) return fallback;
  return c.models.front();
}

ParameterSpec law_parameter() {
  std::vector<std::string> names;
  for (const auto& row : contact::contact_laws()) names.push_back(row.name);
  return keyword_parameter("law", std::move(names), "hertz");
}

std::vector<ParameterSpec> offered_parameters(std::string_view name) {
  const CommandSpec& c = command(name);
  std::vector<ParameterSpec> extra;
  if (c.takes_model) {
    extra.push_back(c.model_required ? required_keyword("model", c.models)
                    : c.models.empty() ? model_parameter()
                                       : keyword_parameter("model", c.models, default_model(c).c_str()));
    for (const auto& row : models::model_registry().rows()) {
      if (!takes_model(c, row.name)) continue;
      for (const ParameterSpec& s : row.parameters) {
        if (!unused_by(c, s.name)) extra.push_back(s);
      }
    }
  }
  if (c.name == "contact") {
    extra.push_back(law_parameter());
    for (const auto& row : contact::contact_laws()) extra.insert(extra.end(), row.parameters.begin(), row.parameters.end());
  }
  std::vector<ParameterSpec> pair;  // the pair's, but those the command never uses
  if (c.takes_pair) {
    for (const ParameterSpec& s : pair_parameters()) {
      if (!unused_by(c, s.name)) pair.push_back(s);
    }
  }
  return merge_specs({c.parameters, pair, extra});
}

std::vector<std::string> models_taking(std::string_view parameter) {
  for (const bool laws : {false, true}) {
    const auto t = takers(parameter, laws);
    const std::size_t all = laws ? contact::contact_laws().size() : models::model_registry().rows().size();
    if (!t.empty()) return t.size() == all ? std::vector<std::string>{} : t;
  }
  return {};
}

namespace detail {

Bound bind_inputs(const CommandSpec& c, const Inputs& inputs) {
  Bound b;
  const bool law = c.name == "contact";
  std::vector<ParameterSpec> group;  // the model's or the law's parameters
  if (c.takes_model) {
    b.model = chosen(inputs, "model", default_model(c).c_str());
    group = models::model_registry().at(b.model).parameters;
    if (!takes_model(c, b.model)) throw InvalidArgument("model", b.model, c.models_why);
    for (const auto& [name, value] : inputs) {
      if (const Unused* u = unused_by(c, name)) throw InvalidArgument(name, value_text(value), u->why);
    }
  } else if (law) {
    b.model = chosen(inputs, "law", "hertz");
    group = contact::contact_law(b.model).parameters;
  }
  const std::span<const ParameterSpec> pair = c.takes_pair ? pair_parameters() : std::span<const ParameterSpec>{};
  Inputs own_in, pair_in, group_in;
  for (const auto& [name, value] : inputs) {
    if ((c.takes_model && name == "model") || (law && name == "law")) continue;
    if (declares(c.parameters, name)) {
      own_in.emplace(name, value);
    } else if (declares(pair, name)) {
      pair_in.emplace(name, value);
    } else if (declares(group, name)) {
      group_in.emplace(name, value);
    } else {
      std::vector<std::string> names;
      for (const auto& s : merge_specs({c.parameters, pair, group})) {
        if (!unused_by(c, s.name)) names.push_back(s.name);
      }
      refuse_unknown(name, value, c, b.model, names);
    }
  }
  b.own = bind_parameters(c.parameters, own_in, "bounce " + c.name);
  b.pair = bind_parameters(pair, pair_in, "the pair");
  b.model_parameters = bind_parameters(group, group_in, fmt::format("{} {}", law ? "law" : "model", b.model));
  return b;
}

Points parse_points(const std::string& name, const std::string& text, bool log) {
  static const std::regex pattern(R"(^([^:]+):([^:]+):([^:]+)$)");
  constexpr long max_points = 10'000'000;
  const std::string allowed = "LO:HI:N with numbers LO <= HI and an integer N >= 1";
  std::smatch match;
  if (!std::regex_match(text, match, pattern)) throw InvalidArgument(name, text, allowed);
  auto number = [&](const std::string& s) {
    double v = 0.0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v)) throw InvalidArgument(name, text, allowed);
    return v;
  };
  const double lo = number(match[1]), hi = number(match[2]);
  // N is a whole number however written (1000, 1e3, 1000.0); 1e3 is as much an integer as 1000.
  const std::string count = match[3];
  double n = 0.0;
  const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), n);
  const bool read = ec == std::errc() && end == count.data() + count.size();
  if (ec == std::errc::result_out_of_range || (read && n > static_cast<double>(max_points))) {
    throw InvalidArgument(name, text, fmt::format("LO:HI:N with at most N = {} points", max_points));
  }
  if (!read || n != std::floor(n) || n < 1 || lo > hi) throw InvalidArgument(name, text, allowed);
  if (n == 1 && lo != hi) throw InvalidArgument(name, text, "LO:HI:N with N >= 2 from LO to HI (one point: LO = HI)");
  if (log && lo <= 0.0) throw InvalidArgument(name, text, "LO > 0 with log");
  return Points{lo, hi, static_cast<std::size_t>(n), log};
}

namespace {

// `x` times 10^decades, computed on x's shortest decimal form (0.01 -> "0.01e1"), so that the
// result is the decimal value correctly rounded: 0.1, not 0.01 * 10 = 0.10000000000000001.
double shifted_by_decades(double x, long decades) {
  std::string text = fmt::format("{}", x);
  long exponent = decades;
  if (const auto e = text.find('e'); e != std::string::npos) {
    exponent += std::stol(text.substr(e + 1));
    text.resize(e);
  }
  text += fmt::format("e{}", exponent);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() ? value : x * std::pow(10.0, static_cast<double>(decades));
}

// Point i of n on a log grid from lo to hi (0 < i < n - 1). Where HI/LO is a whole number m of
// decades (to 1e-12 of a decade: the round-off of log10(hi/lo) is ~1e-15) and point i lies a
// whole number of decades i m / (n - 1) above LO, it is LO shifted by those decades, exactly as
// typed (0.01:100:9 gives 0.1, 1 and 10), and between them LO 10^(i m / (n - 1)); elsewhere
// LO (HI/LO)^f by exp and log.
double log_point(double lo, double hi, std::size_t i, std::size_t n) {
  const double decades = std::log10(hi / lo), m = std::round(decades);  // hi / lo may overflow: inf
  if (m >= 1.0 && m <= 1000.0 && std::abs(decades - m) <= 1e-12) {
    const auto steps = static_cast<long>(i) * static_cast<long>(m), intervals = static_cast<long>(n - 1);
    if (steps % intervals == 0) return shifted_by_decades(lo, steps / intervals);
    return lo * std::pow(10.0, static_cast<double>(steps) / static_cast<double>(intervals));  // 1 ulp, not exp-log's ~5
  }
  const double f = static_cast<double>(i) / static_cast<double>(n - 1);
  return std::exp(std::log(lo) + f * (std::log(hi) - std::log(lo)));
}

}  // namespace

double Points::operator[](std::size_t i) const {
  if (lo == hi) return lo;  // N copies (exp(log 3) need not be 3: the fuzzer's 3:3:127)
  if (i == 0) return lo;
  if (i + 1 >= n) return hi;
  if (log) return log_point(lo, hi, i, n);
  const double f = static_cast<double>(i) / static_cast<double>(n - 1), span = hi - lo;
  return std::isfinite(span) ? lo + f * span
                             : (1.0 - f) * lo + f * hi;  // HI - LO overflows (-1e308:1e308); both forms are monotone in f
}

std::vector<double> parse_range(const std::string& name, const std::string& text, bool log) {
  const Points points = parse_points(name, text, log);
  std::vector<double> values(points.size());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = points[i];
  return values;
}

std::array<double, 2> parse_interval(const std::string& name, const std::string& text) {
  const std::string allowed = "LO:HI in m/s with 0 < LO < HI";
  const auto colon = text.find(':');
  if (colon == std::string::npos || text.find(':', colon + 1) != std::string::npos) {
    throw InvalidArgument(name, text, allowed);
  }
  double lo = 0.0, hi = 0.0;
  try {
    lo = parse_real(name, text.substr(0, colon));
    hi = parse_real(name, text.substr(colon + 1));
  } catch (const InvalidArgument&) {
    throw InvalidArgument(name, text, allowed);
  }
  if (!(lo > 0.0) || !(hi > lo) || !std::isfinite(hi)) throw InvalidArgument(name, text, allowed);
  return {lo, hi};
}

Inputs with_materials(Inputs inputs) {
  const auto it = inputs.find("materials");
  if (it == inputs.end()) return inputs;
  const std::string text = value_text(it->second);
  for (const char* name : {"material", "material2"}) {
    if (inputs.count(name)) {
      throw InvalidArgument(name, value_text(inputs.at(name)), "not given beside --materials (which names both bodies)");
    }
  }
  const auto comma = text.find(',');
  if (text.empty() || comma == 0 || comma + 1 == text.size() || text.find(',', comma + 1) != std::string::npos) {
    throw InvalidArgument("materials", text, "A or A,B: one or two material names");
  }
  inputs.erase("materials");
  inputs.emplace("material", text.substr(0, comma));
  if (comma != std::string::npos) inputs.emplace("material2", text.substr(comma + 1));
  return inputs;
}

}  // namespace detail

Case make_case(std::string_view name, const Inputs& inputs, std::optional<double> radius) {
  return detail::make_case(detail::bind_inputs(command(name), inputs), radius);
}

Case detail::make_case(const Bound& b, std::optional<double> radius) {
  Pair pair = bounce::make_pair(b.pair, radius);
  models::Model model = models::make_model(pair, b.model, b.model_parameters);
  analysis::CollideOptions options = analysis::collide_options(b.model_parameters);
  return Case{std::move(pair), std::move(model), options, b.pair, b.model_parameters, b.own};
}

Pair make_pair(const Inputs& inputs) {
  return bounce::make_pair(bind_parameters(pair_parameters(), inputs, "the pair"));
}

Parameters check_model(std::string_view name, const Inputs& inputs) {
  return models::bind_model_parameters(name, inputs);
}

InvalidArgument as_typed(const InvalidArgument& e, const Inputs& inputs) {
  const auto it = inputs.find(e.parameter());
  const std::string* text = it == inputs.end() ? nullptr : std::get_if<std::string>(&it->second);
  if (text == nullptr || *text == e.value()) return e;
  double typed = 0.0, checked = 0.0;
  const std::string& value = e.value();
  const auto a = std::from_chars(text->data(), text->data() + text->size(), typed);
  const auto b = std::from_chars(value.data(), value.data() + value.size(), checked);
  const bool same = a.ec == std::errc() && a.ptr == text->data() + text->size() && b.ec == std::errc() &&
                    b.ptr == value.data() + value.size() && typed == checked;
  return same ? InvalidArgument(e.parameter(), *text, e.allowed()) : e;
}

}  // namespace bounce::api
