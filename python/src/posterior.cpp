// The likelihood of a fit for bounce.posterior (python/bounce/posterior.py): the fit's inputs
// bound once by the front door, ln L of a whole ensemble at once in C++ (GIL released, the
// trials on threads), Ctrl-C checked between pieces of trials.
#include <algorithm>
#include <chrono>
#include <thread>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bounce/api/posterior.hpp"
#include "bounce/core/error.hpp"
#include "fit.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

// ln L of each row of a 2-D array (trials x parameters), in pieces of about 0.1 s between
// which Ctrl-C is checked (KeyboardInterrupt within about one piece).
Array evaluate(const api::Likelihood& l, const py::object& values, unsigned threads) {
  const Array a = to_array("values", values);
  const std::size_t width = l.names().size();
  if (a.ndim() != 2 || static_cast<std::size_t>(a.shape(1)) != width) {
    throw InvalidArgument("values", fmt::format("an array of shape ({})", fmt::join(a.shape(), a.shape() + a.ndim(), ", ")),
                          fmt::format("a 2-D array of trials x {} parameters", width));
  }
  const std::size_t rows = static_cast<std::size_t>(a.shape(0));
  Array out(std::vector<py::ssize_t>{static_cast<py::ssize_t>(rows)});
  double* result = out.mutable_data();
  const double* in = a.data();
  using Clock = std::chrono::steady_clock;
  // A first piece of one trial a thread keeps every thread busy; pieces double while they take
  // under 0.05 s.
  const unsigned cores = threads != 0 ? threads : std::max(std::thread::hardware_concurrency(), 1U);
  std::size_t done = 0, piece = cores;
  while (done < rows) {
    const std::size_t n = std::min(piece, rows - done);
    const auto start = Clock::now();
    std::vector<double> part;
    {
      py::gil_scoped_release release;
      part = l.evaluate(std::span(in + done * width, n * width), n, threads);
    }
    check_signals();
    std::copy(part.begin(), part.end(), result + done);
    done += n;
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (seconds < 0.05) piece = std::min<std::size_t>(2 * piece, 4096);
  }
  return out;
}

api::Likelihood likelihood(const PyPair& pair, const PyModel& model, const py::object& velocity, const py::object& cor,
                           const py::object& cor_error, const py::object& data, const py::object& fit_names,
                           const py::object& grid, const py::kwargs& options) {
  const analysis::Experiment experiment = experiment_from(velocity, cor, cor_error, data);
  api::Inputs in = case_inputs(pair, model, options);
  if (!fit_names.is_none()) in["fit"] = fit_text(fit_names);
  if (!grid.is_none()) in["grid"] = grid_text(grid.cast<py::dict>());
  py::gil_scoped_release release;  // the plan builds the pair (a materials file may be read)
  return api::Likelihood(in, experiment);
}

}  // namespace

void bind_posterior(py::module_& m) {
  py::class_<api::Likelihood>(m, "Likelihood",
                              "ln L of a fit's parameters (docs/fitting.md, Posteriors): made by _likelihood(), used "
                              "by bounce.posterior")
      .def_property_readonly("names", &api::Likelihood::names, "the fitted parameters (collision axes, then yield)")
      .def_property_readonly("ranges", &api::Likelihood::ranges, "each one's default grid [lo, hi] in SI units (yield: at most 0.2 E_soft)")
      .def_property_readonly("weighted", &api::Likelihood::weighted,
                             "True where every point has a cor_error (else sigma is marginalised)")
      .def("evaluate", &evaluate, py::arg("values"), py::arg("threads") = 0,
           "ln L of each row of values (trials x names), computed in C++ without the GIL (Ctrl-C interrupts it)");
  m.def("_likelihood", &likelihood, py::arg("pair"), py::arg("model"), py::arg("velocity") = py::none(),
        py::arg("cor") = py::none(), py::kw_only(), py::arg("cor_error") = py::none(), py::arg("data") = py::none(),
        py::arg("fit") = py::none(), py::arg("grid") = py::none(),
        "The Likelihood of a fit with fit()'s arguments (bounce.posterior's engine; use bounce.posterior).");
}

}  // namespace bounce::python
