// Aggregates in Python (docs/aggregates.md): bounce.build_aggregate, the CLI's `aggregate build`
// with the centres as a numpy array and the growth history beside the CLI's JSON keys.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <fstream>
#include <optional>

#include "bounce/aggregate/aggregate.hpp"
#include "bounce/api/aggregate.hpp"
#include "bounce/core/error.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

py::array_t<double> centres_array(const aggregate::Aggregate& a) {
  py::array_t<double> out({static_cast<py::ssize_t>(a.centres.size()), py::ssize_t{3}});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < a.centres.size(); ++i) {
    for (py::ssize_t d = 0; d < 3; ++d) view(static_cast<py::ssize_t>(i), d) = a.centres[i][static_cast<std::size_t>(d)];
  }
  return out;
}

py::dict history_dict(const aggregate::Aggregate& a) {
  py::array_t<double> n(static_cast<py::ssize_t>(a.history.size())), rg(static_cast<py::ssize_t>(a.history.size()));
  for (std::size_t i = 0; i < a.history.size(); ++i) {
    n.mutable_at(static_cast<py::ssize_t>(i)) = static_cast<double>(a.history[i].n);
    rg.mutable_at(static_cast<py::ssize_t>(i)) = a.history[i].radius_of_gyration;
  }
  py::dict out;
  out["n"] = n;
  out["radius_of_gyration"] = rg;
  return out;
}

py::dict build(const py::kwargs& kwargs, const std::optional<std::string>& output) {
  const api::AggregateJob job = api::aggregate_job(to_inputs(kwargs));
  aggregate::Aggregate built;
  std::optional<aggregate::FractalFit> ensemble;
  Record record;
  {
    py::gil_scoped_release release;
    const auto interruptible = [](std::size_t, std::size_t) { check_signals_without_gil(); };  // Ctrl-C
    built = aggregate::build(job.request, interruptible);
    if (job.ensemble > 0) ensemble = aggregate::ensemble_fit(job.request, job.ensemble, interruptible);
    record = api::aggregate_record(job, built, ensemble);
  }
  if (output) {
    std::ofstream file(*output, std::ios::binary);
    file << aggregate::lammps_data(built, job.density, 4.0 * job.request.radius, api::aggregate_title(job));
    if (!file.flush()) throw InvalidArgument("output", *output, "a file that can be written");
  }
  py::dict out = to_python(record);
  out["positions"] = centres_array(built);
  out["history"] = history_dict(built);
  return out;
}

}  // namespace

void bind_aggregate(py::module_& m) {
  m.def(
      "build_aggregate",
      [](const py::object& kind, const py::object& n, const py::object& radius, const py::object& material,
         const py::object& density, const py::object& seed, const py::object& ensemble, const py::object& output) {
        py::kwargs kw;
        kw["kind"] = kind, kw["n"] = n, kw["radius"] = radius, kw["material"] = material, kw["density"] = density;
        kw["seed"] = seed, kw["ensemble"] = ensemble;
        if (!output.is_none() && !py::isinstance<py::str>(output) &&
            !py::isinstance(output, py::module_::import("os").attr("PathLike"))) {
          refuse_type("output", output, "a str or a path");
        }
        std::optional<std::string> path;
        if (!output.is_none()) path = py::module_::import("os").attr("fspath")(output).cast<std::string>();
        return build(kw, path);
      },
      py::arg("kind"), py::arg("n"), py::arg("radius"), py::kw_only(), py::arg("material") = py::none(),
      py::arg("density") = py::none(), py::arg("seed") = 0, py::arg("ensemble") = 0, py::arg("output") = py::none(),
      "Grows a BPCA or BCCA aggregate of n monomers of radius [m] (docs/aggregates.md): a dict with the CLI's JSON\n"
      "keys, 'positions' (n, 3) [m] and 'history' (n, radius_of_gyration); output= writes the LAMMPS data file.");
}

}  // namespace bounce::python
