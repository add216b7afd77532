#pragma once
// Private: what the eps^N and eps^T tables share (descriptions, ranges, C text).

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/models/model.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::analysis::detail {

inline std::string describe(const Pair& pair, const models::Model& model) {
  return fmt::format("model {}, R1 = {:g} m, R2 = {:g} m, m_eff = {:.6g} kg, E* = {:.6g} Pa{}", model.name,
                     pair.body1().radius, pair.body2().radius, pair.effective_mass(), pair.effective_modulus(),
                     pair.surface_energy() ? fmt::format(", gamma = {:g} J/m^2", *pair.surface_energy()) : "");
}

// The validity warnings of the collisions a table is built from: one per kind (the text
// without its numbers), from the fastest collision that gave it (where they are worst).
class WarningLog {
 public:
  void add(double g, const std::vector<std::string>& warnings) {
    for (const std::string& w : warnings) {
      auto [it, fresh] = seen_.try_emplace(message_kind(w), g, w);
      if (!fresh && g > it->second.first) it->second = {g, w};
    }
  }
  std::vector<std::string> list() const {
    std::vector<std::string> out;
    for (const auto& [kind, entry] : seen_) out.push_back(entry.second);
    return out;
  }

 private:
  std::map<std::string, std::pair<double, std::string>> seen_;
};

// A whole-number field of a saved table, checked before it is converted (a float beyond
// long's range cast to long is undefined: the fuzzer found label 1e20, order 1e10).
inline long integer_field(const nlohmann::json& v, const char* key, long lo, long hi) {
  const bool number = v.is_number();
  const double x = number ? v.get<double>() : 0.0;
  if (!number || !(x >= static_cast<double>(lo) && x <= static_cast<double>(hi)) || x != std::floor(x)) {
    throw InvalidArgument("table", fmt::format("{} = {}", key, v.dump()),
                          fmt::format("a whole number from {} to {} (a table written by bounce table)", lo, hi));
  }
  return static_cast<long>(x);
}

// A finite number field of a saved table.
inline double finite_field(const nlohmann::json& v, const char* key) {
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw InvalidArgument("table", fmt::format("{} = {}", key, v.dump()), "a finite number");
  return x;
}

inline void check_range(const char* name, double lo, double hi) {
  require_positive(std::string(name) + "_min", lo, "velocity [m/s]");
  if (!(hi > lo) || !std::isfinite(hi)) {
    throw InvalidArgument(std::string(name) + "_max", fmt::format("{:g}", hi), fmt::format("a velocity > {:g} m/s", lo));
  }
}

// C text of a double array.
inline std::string c_array(const std::string& type, const std::string& name, const std::vector<double>& v) {
  std::string s = fmt::format("static const {} {}[{}] = {{", type, name, std::max<std::size_t>(v.size(), 1));
  for (std::size_t i = 0; i < v.size(); ++i) s += fmt::format("{}{:.17g}", i % 4 ? ", " : (i ? ",\n  " : "\n  "), v[i]);
  return s + "};\n";
}

// Replaces every PREFIX in a C text by the user's prefix.
inline std::string with_prefix(std::string text, const std::string& prefix) {
  for (std::size_t p = text.find("PREFIX"); p != std::string::npos; p = text.find("PREFIX", p)) {
    text.replace(p, 6, prefix);
  }
  return text;
}

// The C99 core of a table kind with every name `tag` (e.g. "nt_") prefixed by the user's
// prefix: "nt_cor" -> "<prefix>_nt_cor".
inline std::string renamed_core(std::string core, const std::string& tag, const std::string& prefix) {
  const std::string renamed = prefix + "_" + tag;
  for (std::size_t p = core.find(tag); p != std::string::npos; p = core.find(tag, p + 1)) {
    const bool word_start = p == 0 || !(std::isalnum(static_cast<unsigned char>(core[p - 1])) || core[p - 1] == '_');
    if (!word_start) continue;
    core.replace(p, tag.size(), renamed);
    p += renamed.size() - 1;
  }
  return core;
}

inline void check_prefix(const std::string& prefix) {
  const bool ok = !prefix.empty() && (std::isalpha(static_cast<unsigned char>(prefix[0])) || prefix[0] == '_') &&
                  std::all_of(prefix.begin(), prefix.end(),
                              [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
  if (!ok) throw InvalidArgument("prefix", prefix, "a C identifier");
}

}  // namespace bounce::analysis::detail
