// The manifest of a batch of fits (docs/fitting.md): a TOML file with optional [defaults] and
// one [[experiment]] table per experiment, keys named as the command line's options.
#include <charconv>
#include <filesystem>
#include <set>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "bounce/api/front_door.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::api {

namespace {

// A key's value as the front door takes it: text, a number, or a flag.
// One rule for numbers in TOML, as in a materials file: a number is a TOML number, never a
// string that reads as one (radius = "0.635e-6" is refused, radius = 0.635e-6 taken).
ParameterValue value_of(const toml::node& node, const std::string& where) {
  if (const auto* s = node.as_string()) {
    const std::string& text = s->get();
    double x = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    if (!text.empty() && ec == std::errc() && end == text.data() + text.size()) {
      throw InvalidArgument(where, fmt::format("\"{}\"", text), fmt::format("a TOML number without quotes ({})", text));
    }
    return text;
  }
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  if (const auto* b = node.as_boolean()) return b->get();
  throw InvalidArgument(where, "(a table or an array)", "a string, a number or true/false");
}

// The keys of the batch itself (not the fit's options): an experiment's name, its data file
// and the file's column names (as --columns).
struct OwnKeys {
  std::string* name = nullptr;
  std::string* data = nullptr;
  std::string* columns = nullptr;
};

Inputs inputs_of(const toml::table& table, const std::string& where, const OwnKeys& own) {
  Inputs in;
  for (const auto& [key, node] : table) {
    const std::string k(key.str()), at = fmt::format("{}: {}", where, k);
    if (k == "name" || k == "data" || k == "columns") {
      std::string* slot = k == "name" ? own.name : k == "data" ? own.data : own.columns;
      const auto* s = node.as_string();
      if (s == nullptr || s->get().empty() || slot == nullptr) {
        throw InvalidArgument(at, "(not a name)", k == "name"   ? "a name for the experiment (in [[experiment]])"
                                                  : k == "data" ? "the data file's path (in [[experiment]])"
                                                                : "the file's column names, as --columns (in [[experiment]])");
      }
      *slot = s->get();
      continue;
    }
    in[k] = value_of(node, at);
  }
  return in;
}

analysis::Experiment read_data(const std::string& path, const std::string& where, const std::string& columns) {
  analysis::ColumnNames names;
  try {
    if (!columns.empty()) names = analysis::parse_column_names(columns);
  } catch (const InvalidArgument& e) {
    throw e.renamed(where + ": columns");
  }
  return analysis::parse_experiment(read_text_file(where + ": data", path, "a readable CSV file (docs/fitting.md)"), path,
                                    names);
}

}  // namespace

std::vector<BatchEntry> read_fit_manifest(std::string_view text, const std::string& source, const std::string& directory) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto& begin = e.source().begin;
    throw InvalidArgument(fmt::format("{}:{}:{}", source, begin.line, begin.column), "(malformed TOML)",
                          std::string(e.description()));
  }
  Inputs defaults;
  for (const auto& [key, node] : root) {
    if (key.str() == "experiment") continue;
    if (key.str() != "defaults" || !node.is_table()) {
      throw InvalidArgument(fmt::format("{}: {}", source, key.str()), "(unknown top-level key)",
                            "a [defaults] table and [[experiment]] tables");
    }
    defaults = inputs_of(*node.as_table(), fmt::format("{}: defaults", source), {});
  }
  const toml::array* experiments = root["experiment"].as_array();
  if (experiments == nullptr || experiments->empty()) {
    throw InvalidArgument(source, "(no [[experiment]] tables)", "at least one [[experiment]] with its data file");
  }
  std::vector<BatchEntry> out;
  std::set<std::string> names;
  for (std::size_t i = 0; i < experiments->size(); ++i) {
    const std::string where = fmt::format("{}: experiment {}", source, i + 1);
    const toml::table* table = (*experiments)[i].as_table();
    if (table == nullptr) throw InvalidArgument(where, "(not a table)", "an [[experiment]] table");
    BatchEntry e;
    std::string data, columns;
    e.inputs = defaults;
    for (auto& [key, value] : inputs_of(*table, where, {&e.name, &data, &columns})) e.inputs[key] = std::move(value);
    if (e.name.empty()) e.name = fmt::format("experiment {}", i + 1);
    if (!names.insert(e.name).second) throw InvalidArgument(where + ": name", e.name, "a name no other experiment has");
    if (data.empty()) throw InvalidArgument(where + ": data", "(not given)", "the data file's path");
    const std::filesystem::path given(data);
    const std::filesystem::path path = given.is_absolute() ? given : std::filesystem::path(directory) / given;
    e.data = read_data(path.string(), where, columns);
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace bounce::api
