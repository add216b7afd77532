// The atlas file (docs/atlas.md, "Format"): HDF5 through its C API (Debian's libhdf5), every
// quantity with its unit, and a CRC-32 of the whole content (Boost.CRC) that the reader checks.
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <boost/crc.hpp>
#include <fmt/format.h>

#include "bounce/analysis/atlas.hpp"
#include "bounce/core/error.hpp"
#include "atlas_file_module.hpp"

namespace bounce::analysis {

namespace {

constexpr int format_version = 1;
constexpr const char* field_names = "cor_factor,ln_contact_time,bulk_fraction,crack_fraction";

// An HDF5 handle closed by its own close function.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// The canonical text and bytes of everything the file holds, for its checksum.
std::uint32_t digest(const Atlas& a) {
  std::string text = fmt::format("{}|{}|{}|{}|", format_version, a.model, a.bounce_version, a.can_stick ? 1 : 0);
  for (const auto& p : a.parameters) text += fmt::format("{}={}[{}]|", p.name, p.value, p.unit);
  for (const Material* m : {&a.material1, &a.material2}) {
    text += fmt::format("{}:{:a},{:a},{:a},{:a}|", m->name, m->youngs_modulus, m->poisson_ratio, m->density,
                        m->surface_energy.value_or(-1.0));
  }
  for (double v : {a.radius_min, a.radius_max, a.velocity_min, a.velocity_max, a.density_min, a.density_max,
                   a.errors.cor, a.errors.cor_measured, a.errors.v_stick, a.errors.v_stick_measured,
                   a.errors.contact_time, a.errors.energy, a.errors.tolerance}) {
    text += fmt::format("{:a},", v);
  }
  text += fmt::format("{},{}|", a.errors.check_points, a.errors.v_stick_points);
  for (const AtlasAxis* axis : {&a.x, &a.y, &a.z}) text += fmt::format("{:a},{:a},{}|", axis->start, axis->step, axis->count);
  for (const auto& w : a.warnings) text += w + "|";
  boost::crc_32_type crc;
  crc.process_bytes(text.data(), text.size());
  crc.process_bytes(a.x.nodes.data(), a.x.nodes.size() * sizeof(double));
  crc.process_bytes(&a.ln_v_reference, sizeof(double));
  crc.process_bytes(a.stick_ratio.data(), a.stick_ratio.size() * sizeof(double));
  crc.process_bytes(a.defined.data(), a.defined.size());
  crc.process_bytes(a.values.data(), a.values.size() * sizeof(double));
  return crc.checksum();
}

// --- writing ---------------------------------------------------------------------------

void fail_write(const std::string& path, const std::string& what) {
  throw InvalidArgument("output", path, fmt::format("a file bounce can write (HDF5: {} failed)", what));
}

void string_attribute(hid_t where, const char* name, const std::string& value, const std::string& path) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1));
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate2(where, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.ok() || H5Awrite(attr.get(), type.get(), value.empty() ? "\0" : value.data()) < 0) fail_write(path, name);
}

void number_attribute(hid_t where, const char* name, double value, const std::string& path) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate2(where, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.ok() || H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value) < 0) fail_write(path, name);
}

void array(hid_t where, const char* name, const void* data, hid_t file_type, hid_t memory_type,
           std::vector<hsize_t> dims, const std::string& unit, const std::string& path) {
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  Handle set(H5Dcreate2(where, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  if (!set.ok() || H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) fail_write(path, name);
  string_attribute(set.get(), "unit", unit, path);
}

void scalar(hid_t where, const char* name, double value, const std::string& unit, const std::string& path) {
  array(where, name, &value, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {1}, unit, path);
}

hid_t group(hid_t where, const char* name, const std::string& path) {
  const hid_t g = H5Gcreate2(where, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) fail_write(path, name);
  return g;
}

void write_material(hid_t root, const char* name, const Material& m, const std::string& path) {
  Handle g(group(root, name, path), H5Gclose);
  string_attribute(g.get(), "name", m.name, path);
  scalar(g.get(), "youngs_modulus", m.youngs_modulus, "Pa", path);
  scalar(g.get(), "poisson_ratio", m.poisson_ratio, "1", path);
  scalar(g.get(), "density", m.density, "kg/m^3", path);
  if (m.surface_energy) scalar(g.get(), "surface_energy", *m.surface_energy, "J/m^2 (work of adhesion)", path);
}

void write_axis(hid_t grid, const char* name, const AtlasAxis& axis, const std::string& unit, const std::string& path) {
  std::vector<double> nodes(axis.count);
  for (std::size_t i = 0; i < axis.count; ++i) nodes[i] = axis.value(i);
  array(grid, name, nodes.data(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {axis.count}, unit, path);
  Handle set(H5Dopen2(grid, name, H5P_DEFAULT), H5Dclose);
  number_attribute(set.get(), "start", axis.start, path);
  number_attribute(set.get(), "step", axis.step, path);
}

void write_contents(hid_t file, const Atlas& a, const std::string& path) {
  string_attribute(file, "format", "bounce-atlas", path);
  number_attribute(file, "format_version", format_version, path);
  string_attribute(file, "bounce_version", a.bounce_version, path);
  string_attribute(file, "model", a.model, path);
  number_attribute(file, "can_stick", a.can_stick ? 1.0 : 0.0, path);
  std::string warnings;
  for (const auto& w : a.warnings) warnings += (warnings.empty() ? "" : "\n") + w;
  string_attribute(file, "warnings", warnings, path);
  {
    Handle g(group(file, "parameters", path), H5Gclose);
    for (const auto& p : a.parameters) {
      Handle one(group(g.get(), p.name.c_str(), path), H5Gclose);
      string_attribute(one.get(), "value", p.value, path);
      string_attribute(one.get(), "unit", p.unit.empty() ? "1" : p.unit, path);
    }
  }
  {
    Handle g(group(file, "materials", path), H5Gclose);
    write_material(g.get(), "body1", a.material1, path);
    write_material(g.get(), "body2", a.material2, path);
  }
  {
    Handle g(group(file, "ranges", path), H5Gclose);
    scalar(g.get(), "reduced_radius_min", a.radius_min, "m", path);
    scalar(g.get(), "reduced_radius_max", a.radius_max, "m", path);
    scalar(g.get(), "velocity_min", a.velocity_min, "m/s", path);
    scalar(g.get(), "velocity_max", a.velocity_max, "m/s", path);
    scalar(g.get(), "effective_density_min", a.density_min, "kg/m^3", path);
    scalar(g.get(), "effective_density_max", a.density_max, "kg/m^3", path);
  }
  {
    Handle g(group(file, "grid", path), H5Gclose);
    write_axis(g.get(), "x_ln_reduced_radius", a.x, "ln(m) (non-uniform: refined where needed; step: the narrowest cell)", path);
    write_axis(g.get(), "y_ln_effective_density", a.y, "ln(kg/m^3)", path);
    write_axis(g.get(), "z_ln_velocity_above_v_stick", a.z, "ln(m/s)", path);
    array(g.get(), "stick_ratio", a.stick_ratio.data(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {a.x.count, a.y.count},
          "1 (w = v_ref / v_stick, v_ref = exp(a - 5/6 x - y/2))", path);
    scalar(g.get(), "ln_v_reference", a.ln_v_reference, "ln(m/s) (a)", path);
    array(g.get(), "v_stick_defined", a.defined.data(), H5T_STD_U8LE, H5T_NATIVE_UINT8, {a.x.count, a.y.count},
          "1: v_stick below the sound speed, 0: the grains stick throughout", path);
    array(g.get(), "values", a.values.data(), H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
          {atlas_field_count, a.x.count, a.y.count, a.z.count}, "1, ln(s), 1, 1", path);
    Handle set(H5Dopen2(g.get(), "values", H5P_DEFAULT), H5Dclose);
    string_attribute(set.get(), "fields", field_names, path);
  }
  {
    Handle g(group(file, "errors", path), H5Gclose);
    const AtlasErrors& e = a.errors;
    scalar(g.get(), "cor", e.cor, "1 (stated bound: twice the largest measured)", path);
    scalar(g.get(), "cor_measured", e.cor_measured, "1", path);
    scalar(g.get(), "v_stick", e.v_stick, "1 (relative; stated bound)", path);
    scalar(g.get(), "v_stick_measured", e.v_stick_measured, "1 (relative)", path);
    scalar(g.get(), "contact_time_measured", e.contact_time, "1 (relative)", path);
    scalar(g.get(), "energy_fraction_measured", e.energy, "1", path);
    scalar(g.get(), "check_points", static_cast<double>(e.check_points), "collisions", path);
    scalar(g.get(), "v_stick_points", static_cast<double>(e.v_stick_points), "bisections", path);
    scalar(g.get(), "tolerance", e.tolerance, "1 (--tol)", path);
  }
  string_attribute(file, "checksum", fmt::format("crc32:{:08x}", digest(a)), path);
}

}  // namespace

void detail::write_atlas_hdf5(const Atlas& atlas, const std::string& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const std::string temporary = path + ".writing";
  {
    Handle file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (!file.ok()) fail_write(path, "creating " + temporary);
    try {
      write_contents(file.get(), atlas, path);
    } catch (...) {
      std::remove(temporary.c_str());
      throw;
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::remove(temporary.c_str());
    fail_write(path, "renaming " + temporary + ": " + error.message());
  }
}

std::uint32_t atlas_digest(const Atlas& atlas) { return digest(atlas); }

}  // namespace bounce::analysis

const bounce::analysis::detail::AtlasFileModule* bounce_atlas_file_module() {
  static const bounce::analysis::detail::AtlasFileModule module{sizeof(bounce::analysis::Atlas),
                                                                 bounce::analysis::detail::write_atlas_hdf5,
                                                                 bounce::analysis::detail::read_atlas_hdf5};
  return &module;
}
