// BP04's series and Pade forms and the master curve, elementwise over arrays.
#include <cmath>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bounce/analytic/master_curve.hpp"
#include "bounce/analytic/viscoelastic.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

// The a_k of BP04 (8.89) by name: "bp04-simple", "bp04" (quoted), "bounce" (master curve fit).
analytic::IntegerSeries series_named(const std::string& name) {
  if (name == "bp04-simple") return analytic::bp04_simple_series();
  if (name == "bp04") return analytic::bp04_rigorous_series();
  if (name == "bounce") return analytic::master_series_overlap();
  throw InvalidArgument("series", name, "one of bp04-simple, bp04, bounce");
}

// The d_k of BP04 (8.92): "bp04-printed" (8.93 as printed) or (8.93) applied to a named series.
analytic::PadeCoefficients pade_named(const std::string& name) {
  if (name == "bp04-printed") return analytic::bp04_printed_pade();
  if (name == "bp04-simple" || name == "bp04" || name == "bounce") return analytic::pade_coefficients(series_named(name));
  throw InvalidArgument("coefficients", name, "one of bp04-printed, bp04-simple, bp04, bounce");
}

// BP04's forms of e(q) for q = (g/g*)^{1/5} >= 0 (the library leaves q unchecked: q < 0 gave
// e(-1) = 3.75, q = inf NaN), and never an inf or NaN (the series' q^4 overflows at 1e78).
template <class Form>
double cor_of_q(double q, Form form) {
  require_non_negative("q", q, "q = (g/g*)^{1/5}");
  const double e = form(q);
  if (!std::isfinite(e)) {
    throw InvalidArgument("q", format_value(q),
                          fmt::format("q = (g/g*)^{{1/5}} >= 0 at which the form is finite in double precision "
                                      "(e = {})",
                                      format_value(e)));
  }
  return e;
}

}  // namespace

void bind_analytic(py::module_& m) {
  m.def(
      "cor_series",
      [](const py::object& q, const std::string& series) {
        const auto s = series_named(series);
        return map_values<double>("q", q, [&](double x) {
          return cor_of_q(x, [&](double y) { return analytic::cor_series(y, s); });
        });
      },
      py::arg("q"), py::arg("series") = "bounce",
      "BP04 (8.89) truncated after a4, e(q) with q = (g/g*)^{1/5}; series = 'bounce' (master curve fit), "
      "'bp04' (BP04's quoted a_k) or 'bp04-simple'.");
  m.def(
      "cor_pade",
      [](const py::object& q, const std::string& coefficients) {
        const auto d = pade_named(coefficients);
        return map_values<double>("q", q, [&](double x) {
          return cor_of_q(x, [&](double y) { return analytic::cor_pade(y, d); });
        });
      },
      py::arg("q"), py::arg("coefficients") = "bp04-printed",
      "BP04 (8.92) Pade form e(q), q = (g/g*)^{1/5}; coefficients = 'bp04-printed' ((8.93) as printed, BP04 "
      "Fig 8.2) or (8.93) applied to the a_k of 'bp04', 'bp04-simple' or 'bounce'.");
  m.def(
      "master_cor",
      [](const py::object& kappa, const std::string& contact_end) {
        const auto rule = models::parse_end_rule(contact_end);
        return map_values<double>("kappa", kappa, [&](double k) { return analytic::master_cor(k, rule); });
      },
      py::arg("kappa"), py::arg("contact_end") = "overlap",
      "The viscoelastic master curve e(kappa) (BP04 (8.66) scaling), error <= 1e-10.");
}

}  // namespace bounce::python
