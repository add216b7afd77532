// The CLI's listing of the registries: `bounce models` in words and as the Markdown tables
// of docs/models.md (`bounce models --markdown`).
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "text.hpp"

namespace bounce::cli {

namespace {

const std::string& str(const Record& r, std::string_view key) { return r.at(key).text(); }

// A model's traits in words: "force law, ends overlap | force, master curve, convex".
std::string traits_text(const Record& t) {
  std::string s = str(t, "engine");
  std::string rules;
  for (const Value& r : t.at("end_rules").list()) rules += (rules.empty() ? "" : " | ") + r.text();
  s += ", ends " + rules;
  if (str(t, "adhesion") != "negligible" && str(t, "adhesion") != "unchecked") s += ", adhesion " + str(t, "adhesion");
  for (const char* flag : {"master_curve", "convex"}) {
    if (std::get<bool>(t.at(flag).data())) s += std::string(", ") + (flag == std::string("convex") ? "convex" : "master curve");
  }
  if (str(t, "dem_law") != "none") s += ", DEM law";
  return s;
}

// A Markdown table cell: pipes escaped.
std::string cell(std::string text) {
  for (std::size_t p = text.find('|'); p != std::string::npos; p = text.find('|', p + 2)) text.replace(p, 1, "\\|");
  return text;
}

// One parameter as a Markdown table row: name, unit, allowed, default, what it is.
std::string parameter_row(const Record& p) {
  const std::string unit = str(p, "unit").empty() ? "-" : str(p, "unit");
  std::string allowed = "-";
  if (p.contains("allowed")) allowed = str(p, "allowed");
  if (p.contains("choices")) {
    allowed.clear();
    for (const Value& c : p.at("choices").list()) allowed += (allowed.empty() ? "" : " | ") + c.text();
  }
  const std::string fallback = p.at("default").is_null() ? "-" : str(p, "default");
  return fmt::format("| `{}` | {} | {} | {} | {} |\n", str(p, "name"), cell(unit), cell(allowed), cell(fallback),
                     cell(str(p, "help")));
}

// The parameters of a list whose name is not in `skip`, as a Markdown table.
std::string parameters_markdown(const Value& parameters, const std::set<std::string>& skip = {}) {
  std::string rows;
  for (const Value& p : parameters.list()) {
    if (!skip.count(p.record().at("name").text())) rows += parameter_row(p.record());
  }
  if (rows.empty()) return "No parameters of its own.\n";
  return "| parameter | unit | allowed | default | meaning |\n|---|---|---|---|---|\n" + rows;
}

// The parameters every model takes (in the first model's order).
std::set<std::string> common_parameters(const Value::List& models, Value::List& common) {
  std::set<std::string> names;
  for (const Value& p : models.front().record().at("parameters").list()) {
    const std::string& name = p.record().at("name").text();
    const bool everywhere = std::all_of(models.begin(), models.end(), [&](const Value& m) {
      const auto& ps = m.record().at("parameters").list();
      return std::any_of(ps.begin(), ps.end(), [&](const Value& q) { return q.record().at("name").text() == name; });
    });
    if (everywhere) {
      names.insert(name);
      common.push_back(p);
    }
  }
  return names;
}

}  // namespace

std::string models_markdown(const Value& registry) {
  const Record& r = registry.record();
  const Value::List& models = r.at("models").list();
  std::string s = "| model | what | references | traits |\n|---|---|---|---|\n";
  for (const Value& m : models) {
    const Record& row = m.record();
    s += fmt::format("| `{}` | {} | {} | {} |\n", str(row, "name"), cell(str(row, "summary")), cell(str(row, "references")),
                     traits_text(row.at("traits").record()));
  }
  Value::List common;
  const std::set<std::string> shared = common_parameters(models, common);
  s += "\n### Parameters of every model\n\n" + parameters_markdown(Value(common));
  for (const Value& m : models) {
    const Record& row = m.record();
    s += fmt::format("\n### `{}`\n\n{} ({}).\n\n", str(row, "name"), str(row, "summary"), str(row, "references"));
    s += parameters_markdown(row.at("parameters"), shared);
  }
  s += "\n### Contact laws (`bounce contact --law`)\n\n| law | what | references | needs gamma |\n|---|---|---|---|\n";
  for (const Value& l : r.at("laws").list()) {
    const Record& row = l.record();
    s += fmt::format("| `{}` | {} | {} | {} |\n", str(row, "name"), cell(str(row, "summary")), cell(str(row, "references")),
                     std::get<bool>(row.at("needs_surface_energy").data()) ? "yes" : "no");
  }
  for (const Value& l : r.at("laws").list()) {
    const Record& row = l.record();
    if (row.at("parameters").list().empty()) continue;
    s += fmt::format("\n#### law `{}`\n\n", str(row, "name")) + parameters_markdown(row.at("parameters"));
  }
  return s;
}

std::string models_text(const Value& registry) {
  std::string s;
  for (const Value& m : registry.record().at("models").list()) {
    const Record& row = m.record();
    s += fmt::format("{:<22} {}\n{:<22} {}; {}\n", str(row, "name"), str(row, "summary"), "", str(row, "references"),
                     traits_text(row.at("traits").record()));
    std::vector<std::string> names;
    for (const Value& p : row.at("parameters").list()) names.push_back(p.record().at("name").text());
    std::string line;
    for (const auto& n : names) line += (line.empty() ? "" : " ") + std::string("--") + n;
    for (char& c : line) c = c == '_' ? '-' : c;
    s += fmt::format("{:<22} {}\n", "", line);
  }
  s += "contact laws:";
  for (const Value& l : registry.record().at("laws").list()) s += " " + l.record().at("name").text();
  return s + "\n";
}

}  // namespace bounce::cli
