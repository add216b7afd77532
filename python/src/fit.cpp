// fit: a model fitted to a restitution curve (docs/fitting.md) through the front door, the
// data read by the library's own reader (from a file, or from arrays written as its CSV).
#include <regex>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "fit.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

std::vector<double> column(const char* name, const py::object& values) {
  const Array a = to_array(name, values);
  if (a.ndim() != 1) throw InvalidArgument(name, fmt::format("an array of {} dimensions", a.ndim()), "a 1-D array");
  return {a.data(), a.data() + a.size()};
}

// Arrays as the reader's CSV (shortest round-trip numbers), so that they meet the same rules
// as a file; a refusal names the array and the index ("cor[3] = 2 is invalid: ...").
analysis::Experiment from_arrays(const py::object& velocity, const py::object& cor, const py::object& cor_error) {
  const std::vector<double> v = column("velocity", velocity), e = column("cor", cor);
  std::optional<std::vector<double>> s;
  if (!cor_error.is_none()) s = column("cor_error", cor_error);
  if (e.size() != v.size() || (s && s->size() != v.size())) {
    throw InvalidArgument("cor", fmt::format("{} values for {} velocities", s && e.size() == v.size() ? s->size() : e.size(),
                                             v.size()),
                          "velocity, cor (and cor_error) of the same length");
  }
  std::string text = s ? "velocity,cor,cor_error\n" : "velocity,cor\n";
  for (std::size_t i = 0; i < v.size(); ++i) {
    text += s ? fmt::format("{},{},{}\n", v[i], e[i], (*s)[i]) : fmt::format("{},{}\n", v[i], e[i]);
  }
  try {
    return analysis::parse_experiment(text, "arrays");
  } catch (const InvalidArgument& error) {
    static const std::regex row(R"(^arrays:([0-9]+): (\w+)$)");
    std::smatch m;
    if (std::regex_match(error.parameter(), m, row)) {
      throw error.renamed(fmt::format("{}[{}]", m[2].str(), std::stoul(m[1].str()) - 2));
    }
    if (error.parameter() == "data") throw InvalidArgument("velocity", "[]", "at least one measurement");
    throw;
  }
}

// columns={"velocity": "Speed", "cor": "e"} or "velocity=Speed,cor=e": the CLI's --columns.
analysis::ColumnNames column_names(const py::object& columns) {
  if (columns.is_none()) return {};
  if (py::isinstance<py::str>(columns)) return analysis::parse_column_names(columns.cast<std::string>());
  if (!py::isinstance<py::dict>(columns)) throw py::type_error("columns: expected a dict {ours: the file's name} or a str");
  std::vector<std::string> pairs;
  for (const auto& [key, value] : columns.cast<py::dict>()) {
    if (!py::isinstance<py::str>(key) || !py::isinstance<py::str>(value)) {
      throw py::type_error("columns: expected names (str) as keys and values");
    }
    pairs.push_back(fmt::format("{}={}", key.cast<std::string>(), value.cast<std::string>()));
  }
  return analysis::parse_column_names(fmt::format("{}", fmt::join(pairs, ",")));
}

analysis::Experiment from_file(const std::string& path, const analysis::ColumnNames& names) {
  return analysis::parse_experiment(read_text_file("data", path, "a readable CSV file (docs/fitting.md)"), path, names);
}

}  // namespace

analysis::Experiment experiment_from(const py::object& velocity, const py::object& cor, const py::object& cor_error,
                                     const py::object& data, const py::object& columns) {
  if (!columns.is_none() && data.is_none()) {
    throw InvalidArgument("columns", py::str(columns), "data (a CSV file) with it: arrays have no column names");
  }
  if (!data.is_none() && !(velocity.is_none() && cor.is_none() && cor_error.is_none())) {
    throw InvalidArgument("data", py::str(data), "either data (a file) or velocity and cor (arrays), not both");
  }
  if (data.is_none() && (velocity.is_none() || cor.is_none())) {
    throw InvalidArgument("velocity", "None", "arrays velocity and cor (or data, a CSV file)");
  }
  if (!data.is_none() && !py::isinstance<py::str>(data)) throw py::type_error("data: expected a file name (str)");
  return data.is_none() ? from_arrays(velocity, cor, cor_error)
                        : from_file(data.cast<std::string>(), column_names(columns));
}

// fit=("gamma", "tvis") or "gamma,tvis"; grid={"gamma": (lo, hi, n)}: the front door's text.
std::string fit_text(const py::object& names) {
  std::vector<std::string> parts;
  const py::object items = py::isinstance<py::str>(names) ? py::str(names).attr("split")(",") : names;
  for (const auto& item : items) {
    if (!py::isinstance<py::str>(item)) throw py::type_error("fit: expected parameter names (str)");
    parts.push_back(library_name(py::str(item).cast<std::string>()));
  }
  return fmt::format("{}", fmt::join(parts, ","));
}

std::string grid_text(const py::dict& grid) {
  std::vector<std::string> items;
  for (const auto& [key, value] : grid) {
    if (!py::isinstance<py::str>(key)) throw py::type_error("grid: expected parameter names (str) as keys");
    const auto t = value.cast<py::sequence>();
    if (t.size() != 3) throw InvalidArgument("grid", py::str(value), "(lo, hi, n) per parameter");
    const std::string name = library_name(py::str(key).cast<std::string>());
    const double lo = to_number(("grid[" + name + "]").c_str(), t[0]), hi = to_number(("grid[" + name + "]").c_str(), t[1]);
    const double n = to_number(("grid[" + name + "]").c_str(), t[2]);
    items.push_back(fmt::format("{}={}:{}:{}", name, lo, hi, n));
  }
  return fmt::format("{}", fmt::join(items, ","));
}

namespace {

// chi2_grid as an array of its shape (NaN where the collisions failed), with the axes.
void grid_to_numpy(py::dict& d) {
  if (!d.contains("chi2_grid")) return;
  const py::dict g = d["chi2_grid"];
  std::vector<py::ssize_t> shape;
  for (const auto& n : g["shape"]) shape.push_back(static_cast<py::ssize_t>(n.cast<double>()));
  const py::list values = g["values"];
  Array a(shape);
  double* out = a.mutable_data();
  for (py::ssize_t i = 0; i < static_cast<py::ssize_t>(values.size()); ++i) {
    out[i] = values[static_cast<std::size_t>(i)].is_none() ? std::nan("") : values[static_cast<std::size_t>(i)].cast<double>();
  }
  d["chi2_grid"] = a;
  py::dict axes;
  const py::dict profiles = d["profiles"];
  for (const auto& name : d["fitted"]) axes[name] = profiles[name]["value"];
  d["grid_values"] = axes;
}

py::dict fit(const PyPair& pair, const PyModel& model, const py::object& velocity, const py::object& cor,
             const py::object& cor_error, const py::object& data, const py::object& columns, const py::object& fit_names,
             const py::object& grid, const py::kwargs& options) {
  const analysis::Experiment experiment = experiment_from(velocity, cor, cor_error, data, columns);
  api::Inputs in = case_inputs(pair, model, options);
  in["chi2_grid"] = true;
  if (!fit_names.is_none()) in["fit"] = fit_text(fit_names);
  if (!grid.is_none()) {
    if (!py::isinstance<py::dict>(grid)) throw py::type_error("grid: expected a dict {name: (lo, hi, n)}");
    in["grid"] = grid_text(grid);
  }
  Record out;
  {
    py::gil_scoped_release release;
    // Ctrl-C stops the fit within a collision (~ms), as it stops curve().
    out = api::fit(in, experiment, [](std::size_t, std::size_t) { check_signals_without_gil(); });
  }
  check_signals();
  py::dict d = to_python(out);
  grid_to_numpy(d);
  return d;
}

}  // namespace

void bind_fit(py::module_& m) {
  m.def("fit", &fit, py::arg("pair"), py::arg("model"), py::arg("velocity") = py::none(), py::arg("cor") = py::none(),
        py::kw_only(), py::arg("cor_error") = py::none(), py::arg("data") = py::none(), py::arg("columns") = py::none(),
        py::arg("fit") = py::none(),
        py::arg("grid") = py::none(),
        "The model fitted to a measured restitution curve (K13 §4, docs/fitting.md): arrays velocity [m/s] and cor "
        "(cor = 0: the grains stuck), optionally cor_error, or data='file.csv' (columns={'velocity': 'Speed', ...}: the "
        "file's names of the columns, as --columns). fit: the parameters to fit (default "
        "the model's; krijt: gamma, tvis, yield), grid: {name: (lo, hi, n)} in SI units (log-spaced). Keywords of "
        "`bounce fit`: compare, threads, precision, grid_only, timing. A dict with the CLI's JSON keys (best, chi2, "
        "ranges, profiles, points, curve, comparison, ...) plus chi2_grid, a numpy array over the axes grid_values "
        "(NaN where the collisions failed). The yield strength is 'yield' (or 'yield_strength') in fit and grid.");
}

}  // namespace bounce::python
