#include "bounce/core/parameters.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/core/suggest.hpp"

namespace bounce {

bool Range::contains(double x) const {
  if (std::isnan(x) || (std::isinf(x) && !infinite)) return false;
  const bool above = lo_included ? x >= lo : x > lo;
  const bool below = hi_included ? x <= hi : x < hi;
  return above && below && (!integer || x == std::floor(x));
}

std::string Range::describe(std::string_view what) const {
  const bool lo_finite = std::isfinite(lo), hi_finite = std::isfinite(hi);
  if (lo_finite && hi_finite) {
    return fmt::format("{}{} {} {} {} {}", integer ? "an integer " : "", format_value(lo), lo_included ? "<=" : "<",
                       what, hi_included ? "<=" : "<", format_value(hi));
  }
  std::string s(what);
  if (lo_finite) s += fmt::format(" {} {}", lo_included ? ">=" : ">", format_value(lo));
  if (hi_finite) s += fmt::format(" {} {}", hi_included ? "<=" : "<", format_value(hi));
  if (infinite) return s;
  return lo_finite || hi_finite ? s + " and finite" : s + ": a finite number";
}

Range positive() { return Range{0.0, std::numeric_limits<double>::infinity(), false, false, false}; }
Range non_negative() { return Range{0.0, std::numeric_limits<double>::infinity(), true, false, false}; }
Range open_interval(double lo, double hi) { return Range{lo, hi, false, false, false}; }

std::string ParameterSpec::what() const { return unit.empty() ? quantity : fmt::format("{} [{}]", quantity, unit); }

std::string ParameterSpec::default_text() const { return default_value ? value_text(*default_value) : std::string(); }

ParameterSpec real_parameter(std::string name, std::string quantity, std::string unit, Range range, std::string help) {
  ParameterSpec s;
  s.name = std::move(name);
  s.quantity = std::move(quantity);
  s.unit = std::move(unit);
  s.range = range;
  s.help = std::move(help);
  return s;
}

ParameterSpec choice_parameter(std::string name, std::vector<std::string> choices, std::string help) {
  ParameterSpec s;
  s.name = std::move(name);
  s.kind = ParameterKind::choice;
  s.quantity = s.name;
  s.default_value = choices.front();
  s.choices = std::move(choices);
  s.help = std::move(help);
  return s;
}

ParameterSpec text_parameter(std::string name, std::string help, std::string placeholder) {
  ParameterSpec s;
  s.name = std::move(name);
  s.kind = ParameterKind::text;
  s.quantity = help;
  s.help = std::move(help);
  s.placeholder = std::move(placeholder);
  return s;
}

ParameterSpec flag_parameter(std::string name, std::string help) {
  ParameterSpec s = text_parameter(std::move(name), std::move(help), "");
  s.kind = ParameterKind::flag;
  return s;
}

ParameterSpec with_default(ParameterSpec spec, ParameterValue value) {
  spec.default_value = std::move(value);
  return spec;
}

ParameterSpec fittable(ParameterSpec spec, FitGrid grid) {
  spec.fit = std::move(grid);
  return spec;
}

std::string value_text(const ParameterValue& value) {
  struct Text {
    std::string operator()(double x) const { return format_value(x); }
    std::string operator()(const std::string& s) const { return s.empty() ? "\"\"" : s; }
    std::string operator()(const std::vector<double>& v) const {
      std::string s;
      for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + format_value(v[i]);
      return s;
    }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
  };
  return std::visit(Text{}, value);
}

double parse_real(std::string_view name, std::string_view text, bool infinite) {
  if (infinite && text == "inf") return std::numeric_limits<double>::infinity();
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
    throw InvalidArgument(std::string(name), text.empty() ? "\"\"" : std::string(text), "a number");
  }
  return value;
}

namespace {

std::string choice_list(const std::vector<std::string>& choices) {
  if (choices.size() <= 1) return choices.empty() ? std::string() : choices.front();
  std::vector<std::string> head(choices.begin(), choices.end() - 1);
  return fmt::format("{} or {}", fmt::join(head, ", "), choices.back());
}

// `shown`: the value as the user typed it.
double checked_real(const ParameterSpec& spec, double x, const std::string& shown) {
  if (!spec.range.contains(x)) throw InvalidArgument(spec.name, shown, spec.range.describe(spec.what()));
  return x;
}

std::vector<double> reals_from_text(const ParameterSpec& spec, const std::string& text) {
  std::vector<double> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    try {
      out.push_back(parse_real(spec.name, item, spec.range.infinite));
    } catch (const InvalidArgument&) {
      throw InvalidArgument(spec.name, text, fmt::format("{} numbers separated by commas: {}", spec.count, spec.what()));
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

// The value converted to the spec's kind and checked against its range or choices.
ParameterValue checked(const ParameterSpec& spec, const ParameterValue& value) {
  const auto* text = std::get_if<std::string>(&value);
  switch (spec.kind) {
    case ParameterKind::real: {
      if (const auto* x = std::get_if<double>(&value)) return checked_real(spec, *x, format_value(*x));
      if (text) return checked_real(spec, parse_real(spec.name, *text, spec.range.infinite), *text);
      throw InvalidArgument(spec.name, value_text(value), "a number");
    }
    case ParameterKind::reals: {
      std::vector<double> v;
      if (const auto* list = std::get_if<std::vector<double>>(&value)) v = *list;
      if (text) v = reals_from_text(spec, *text);
      if (v.size() != spec.count) {
        throw InvalidArgument(spec.name, value_text(value),
                              fmt::format("{} numbers separated by commas: {}", spec.count, spec.what()));
      }
      for (double x : v) {
        if (!spec.range.contains(x)) {
          throw InvalidArgument(spec.name, value_text(value), spec.range.describe(spec.what()));
        }
      }
      return v;
    }
    case ParameterKind::choice:
      if (!text || std::find(spec.choices.begin(), spec.choices.end(), *text) == spec.choices.end()) {
        throw InvalidArgument(spec.name, value_text(value), choice_list(spec.choices));
      }
      return value;
    case ParameterKind::text:
      if (!text) throw InvalidArgument(spec.name, value_text(value), fmt::format("text: {}", spec.what()));
      return value;
    case ParameterKind::flag:
      if (!std::holds_alternative<bool>(value)) throw InvalidArgument(spec.name, value_text(value), "true or false");
      return value;
  }
  throw std::logic_error("unknown parameter kind");
}

}  // namespace

Parameters bind_parameters(std::span<const ParameterSpec> specs, const ParameterInputs& inputs, std::string_view owner) {
  Parameters p;
  p.specs_.assign(specs.begin(), specs.end());
  for (const auto& [name, value] : inputs) {
    const ParameterSpec* spec = p.spec(name);
    if (spec == nullptr) {
      std::vector<std::string> names;
      for (const ParameterSpec& s : specs) names.push_back(s.name);
      throw InvalidArgument(name, value_text(value),
                            fmt::format("a parameter of {}: one of {}{}", owner, fmt::join(names, ", "),
                                        did_you_mean(name, names)));
    }
    p.values_.emplace(name, checked(*spec, value));
    p.typed_.emplace(name, value);
  }
  return p;
}

const ParameterSpec* Parameters::spec(std::string_view name) const {
  for (const ParameterSpec& s : specs_) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

namespace {
// The value given, else the default; the name must be declared (a factory asking for an
// undeclared name is a bug, not bad input).
const ParameterValue* value_or_default(const Parameters& p, std::string_view name) {
  const ParameterSpec* spec = p.spec(name);
  if (spec == nullptr) throw std::logic_error(fmt::format("parameter {} is not declared", name));
  const auto it = p.values().find(name);
  if (it != p.values().end()) return &it->second;
  return spec->default_value ? &*spec->default_value : nullptr;
}
}  // namespace

bool Parameters::given(std::string_view name) const { return values_.find(name) != values_.end(); }

void Parameters::set(std::string_view name, double value) {
  const ParameterSpec* s = spec(name);
  if (s == nullptr || s->kind != ParameterKind::real || !s->range.contains(value)) {
    throw std::logic_error(fmt::format("Parameters::set({}, {}): not a real parameter of these, or out of its range",
                                       name, value));
  }
  values_.insert_or_assign(std::string(name), value);
  typed_.insert_or_assign(std::string(name), value);
}

std::string Parameters::typed(std::string_view name) const {
  const auto it = typed_.find(name);
  return it == typed_.end() ? std::string() : value_text(it->second);
}

void Parameters::refuse_given(std::span<const char* const> names, std::string_view why) const {
  for (const char* name : names) {
    if (given(name)) throw InvalidArgument(name, typed(name), std::string(why));
  }
}

std::optional<double> Parameters::real(std::string_view name) const {
  const ParameterValue* v = value_or_default(*this, name);
  if (v == nullptr) return std::nullopt;
  return std::get<double>(*v);
}

double Parameters::require_real(std::string_view name, std::string_view why) const {
  const auto x = real(name);
  if (!x) throw InvalidArgument(std::string(name), "(not given)", std::string(why));
  return *x;
}

std::optional<std::vector<double>> Parameters::reals(std::string_view name) const {
  const ParameterValue* v = value_or_default(*this, name);
  if (v == nullptr) return std::nullopt;
  return std::get<std::vector<double>>(*v);
}

std::string Parameters::text(std::string_view name) const {
  const ParameterValue* v = value_or_default(*this, name);
  return v == nullptr ? std::string() : std::get<std::string>(*v);
}

bool Parameters::flag(std::string_view name) const {
  const ParameterValue* v = value_or_default(*this, name);
  return v != nullptr && std::get<bool>(*v);
}

std::vector<ParameterSpec> merge_specs(std::initializer_list<std::span<const ParameterSpec>> lists) {
  std::vector<ParameterSpec> out;
  for (const auto& list : lists) {
    for (const ParameterSpec& s : list) {
      const bool seen = std::any_of(out.begin(), out.end(), [&](const ParameterSpec& o) { return o.name == s.name; });
      if (!seen) out.push_back(s);
    }
  }
  return out;
}

void ParameterRule::check(const Parameters& p, std::string_view owner) const {
  const std::vector<std::string>* first_given = nullptr;
  for (const auto& alternative : alternatives) {
    const auto given = std::find_if(alternative.begin(), alternative.end(), [&](const auto& n) { return p.given(n); });
    if (given == alternative.end()) continue;
    for (const std::string& name : alternative) {
      if (p.given(name)) continue;
      throw InvalidArgument(name, "(not given)", fmt::format("{} given with {} ({})", name, *given, owner));
    }
    if (exclusive && first_given) {
      const std::string typed = p.typed(*given);  // a fit's trial value was set, not typed
      throw InvalidArgument(*given, typed.empty() ? format_value(p.real(*given).value_or(0.0)) : typed,
                            fmt::format("{}, not two ({})", expected, owner));
    }
    if (!first_given) first_given = &alternative;
  }
  if (required && !first_given && !alternatives.empty() && !alternatives.front().empty()) {
    throw InvalidArgument(alternatives.front().front(), "(not given)", fmt::format("{} ({})", expected, owner));
  }
}

}  // namespace bounce
