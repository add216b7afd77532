#include "options.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bounce/pair/pair_parameters.hpp"

namespace bounce::cli {

namespace {

// The --help line: the parameter's own, with the models (or laws) that take it when not all do.
std::string help_line(const ParameterSpec& s) {
  const std::vector<std::string> takers = api::models_taking(s.name);
  if (takers.empty()) return s.help;
  return fmt::format("{} [{}]", s.help, fmt::join(takers, ", "));
}

bool in_pair(const std::string& name) {
  for (const ParameterSpec& s : pair_parameters()) {
    if (s.name == name) return true;
  }
  return false;
}

// Option groups of --help: the two bodies, the model (or law), the command's own.
const char* group_of(const api::CommandSpec& command, const std::string& name) {
  for (const ParameterSpec& s : command.parameters) {  // the command's own first (atlas build's --radius)
    if (s.name == name) return "Options";
  }
  if (command.takes_pair && in_pair(name)) return "Bodies";
  return command.takes_model ? "Model" : "Law";
}

// How a value looks in --help: the spec's placeholder, or from its kind and unit
// ("S" for seconds, "PA", "R1,R2", "overlap|force", "X" for a dimensionless number).
std::string placeholder(const ParameterSpec& s) {
  if (!s.placeholder.empty()) return s.placeholder;
  switch (s.kind) {
    case ParameterKind::choice: return fmt::format("{}", fmt::join(s.choices, "|"));
    case ParameterKind::reals: return "R1,R2";
    case ParameterKind::text: return "TEXT";
    case ParameterKind::flag: return "";
    case ParameterKind::real: break;
  }
  if (s.unit.empty()) return "X";
  std::string u;
  for (char c : s.unit) u += c == ' ' || c == '/' ? '_' : c == '^' ? '\0' : static_cast<char>(std::toupper(c));
  u.erase(std::remove(u.begin(), u.end(), '\0'), u.end());
  return u;
}

}  // namespace

std::string option_name(const std::string& parameter) {
  std::string out = "--" + parameter;
  for (char& c : out) c = c == '_' ? '-' : c;
  return out;
}

Options::Options(CLI::App* app, const api::CommandSpec& command) : app_(app) {
  for (const ParameterSpec& s : api::offered_parameters(command.name)) {
    names_.insert(s.name);
    CLI::Option* option = nullptr;
    if (s.kind == ParameterKind::flag) {
      auto& value = flags_[s.name] = std::make_unique<bool>(false);
      option = app->add_flag(option_name(s.name), *value, help_line(s));
    } else {
      auto& value = text_[s.name] = std::make_unique<std::string>();
      option = app->add_option(option_name(s.name), *value, help_line(s))->type_name(placeholder(s));
    }
    option->group(group_of(command, s.name));
    options_[s.name] = option;
  }
}

bool* Options::add_flag(const std::string& name, const std::string& help) {
  auto& value = flags_[name] = std::make_unique<bool>(false);
  options_[name] = app_->add_flag(option_name(name), *value, help)->group("Output");
  own_.insert(name);
  return value.get();
}

std::string* Options::add_text(const std::string& name, const std::string& help, const std::string& placeholder,
                               const std::string& short_name) {
  auto& value = text_[name] = std::make_unique<std::string>();
  const std::string names = short_name.empty() ? option_name(name) : short_name + "," + option_name(name);
  options_[name] = app_->add_option(names, *value, help)->group("Output")->type_name(placeholder);
  own_.insert(name);
  return value.get();
}

std::string* Options::add_positional(const std::string& name, const std::string& help) {
  auto& value = text_[name] = std::make_unique<std::string>();
  options_[name] = app_->add_option(name, *value, help)->type_name("FILE");
  own_.insert(name);
  return value.get();
}

bool Options::given(const std::string& name) const {
  const auto it = options_.find(name);
  return it != options_.end() && it->second->count() > 0;
}

std::string Options::typed(const std::string& name) const {
  const auto text = text_.find(name);
  return text != text_.end() ? *text->second : "given";
}

std::set<std::string> Options::all_names() const {
  std::set<std::string> all = names_;
  all.insert(own_.begin(), own_.end());
  return all;
}

api::Inputs Options::inputs() const {
  api::Inputs in;
  for (const std::string& name : names_) {
    if (!given(name)) continue;
    if (const auto flag = flags_.find(name); flag != flags_.end()) {
      in.emplace(name, *flag->second);
    } else {
      in.emplace(name, *text_.at(name));
    }
  }
  return in;
}

}  // namespace bounce::cli
