#pragma once
// Private: what fit and posterior (fit.cpp, posterior.cpp) share: the data from a call's
// arguments and the fitted parameters' names as the front door's text.

#include <string>

#include <pybind11/pybind11.h>

#include "bounce/analysis/fit.hpp"

namespace bounce::python {

namespace py = pybind11;

/// The experiment of arrays velocity, cor (, cor_error) or of data, a CSV file (not both; with
/// `columns`, the CLI's --columns mapping, a dict or "velocity=...,cor=..."): the library's
/// reader, refusals naming the array and index or the file and line.
analysis::Experiment experiment_from(const py::object& velocity, const py::object& cor, const py::object& cor_error,
                                     const py::object& data, const py::object& columns = py::none());
/// fit=("gamma", "tvis") or "gamma,tvis" as the front door's text ("gamma,tvis").
std::string fit_text(const py::object& names);
/// grid={"gamma": (lo, hi, n)} as the front door's text ("gamma=lo:hi:n").
std::string grid_text(const py::dict& grid);

}  // namespace bounce::python
