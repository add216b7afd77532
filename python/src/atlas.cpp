// The collision atlas in Python (docs/atlas.md): the library's Atlas with numpy lookups that
// broadcast (R1, R2, v) like ufuncs; python/bounce/atlas.py adds p_stick and the docs.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <optional>

#include "bounce/analysis/atlas.hpp"
#include "bounce/api/atlas.hpp"
#include "objects.hpp"

namespace bounce::python {

namespace {

using analysis::Atlas;
using analysis::AtlasValue;

// A vectorised lookup of one of the quantities a collision has only when it bounces (NaN when
// the grains stick).
template <class Get>
auto field(Get get) {
  return py::vectorize([get](const Atlas* a, double r1, double r2, double v) {
    return get(a->at({r1, r2, v})).value_or(std::numeric_limits<double>::quiet_NaN());
  });
}

analysis::Atlas open(const std::string& path, const std::optional<std::string>& model) {
  return analysis::read_atlas(path, model.value_or(""));
}

}  // namespace

void bind_atlas(py::module_& m) {
  py::class_<Atlas>(m, "Atlas", "A collision atlas read from a file of `bounce atlas build` (docs/atlas.md).")
      .def("cor", py::vectorize([](const Atlas* a, double r1, double r2, double v) { return a->cor(r1, r2, v); }),
           py::arg("radius1"), py::arg("radius2"), py::arg("velocity"))
      .def(
          "_cor_many",
          [](const Atlas& a, const py::array_t<double, py::array::c_style>& r1, const py::array_t<double, py::array::c_style>& r2,
             const py::array_t<double, py::array::c_style>& v) {
            const auto n = static_cast<std::size_t>(v.size());
            if (static_cast<std::size_t>(r1.size()) != n || static_cast<std::size_t>(r2.size()) != n) {
              throw std::invalid_argument("_cor_many: arrays of one size");  // bounce.atlas broadcasts first
            }
            py::array_t<double> out(static_cast<py::ssize_t>(n));
            {
              py::gil_scoped_release release;
              a.cor_many(n, r1.data(), r2.data(), v.data(), out.mutable_data());
            }
            return out;
          },
          "eps at flat arrays of equal size (NaN outside the atlas): bounce.atlas.Atlas.cor's loop")
      .def("sticks", py::vectorize([](const Atlas* a, double r1, double r2, double v) { return a->sticks(r1, r2, v); }),
           py::arg("radius1"), py::arg("radius2"), py::arg("velocity"))
      .def("v_stick", py::vectorize([](const Atlas* a, double r1, double r2) { return a->v_stick(r1, r2); }),
           py::arg("radius1"), py::arg("radius2"))
      .def("contact_time", field([](const AtlasValue& v) { return v.contact_time; }), py::arg("radius1"),
           py::arg("radius2"), py::arg("velocity"))
      .def("bulk_fraction", field([](const AtlasValue& v) { return v.bulk_fraction; }), py::arg("radius1"),
           py::arg("radius2"), py::arg("velocity"))
      .def("crack_fraction", field([](const AtlasValue& v) { return v.crack_fraction; }), py::arg("radius1"),
           py::arg("radius2"), py::arg("velocity"))
      .def("describe", [](const Atlas& a) { return to_python(api::atlas_record(a)); })
      .def_readonly("model", &Atlas::model)
      .def_readonly("radius_min", &Atlas::radius_min)
      .def_readonly("radius_max", &Atlas::radius_max)
      .def_readonly("velocity_min", &Atlas::velocity_min)
      .def_readonly("velocity_max", &Atlas::velocity_max)
      .def_property_readonly("cor_error", [](const Atlas& a) { return a.errors.cor; })
      .def_property_readonly("v_stick_error", [](const Atlas& a) { return a.errors.v_stick; });
  m.def("open_atlas", &open, py::arg("path"), py::arg("model") = std::nullopt,
        "Reads an atlas (ValueError for a file that is not one, was changed, or is of another model).");
}

}  // namespace bounce::python
