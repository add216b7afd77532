// Reading the atlas file (docs/atlas.md, "Format"): every group and array checked, the
// checksum compared, the lookups prepared. Any flaw is an InvalidArgument naming the file.
#include <hdf5.h>

#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "bounce/analysis/atlas.hpp"
#include "../atlas_grid.hpp"
#include "atlas_file_module.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/material.hpp"

namespace bounce::analysis {

std::uint32_t atlas_digest(const Atlas& atlas);  // atlas_write.cpp

namespace {

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidArgument("atlas", path_, "an atlas written by bounce atlas build: " + what);
  }

  hid_t check(hid_t id, const std::string& what) const {
    if (id < 0) fail(what + " is missing");
    return id;
  }

  // An attribute holds one value (a larger one would overrun what reads it).
  void require_single(hid_t attr, const char* name) const {
    const hid_t space = H5Aget_space(attr);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    H5Sclose(space);
    if (n != 1) {
      H5Aclose(attr);
      fail(fmt::format("the attribute {} holds one value (it has {})", name, n));
    }
  }

  std::string text(hid_t where, const char* name) const {
    const hid_t attr = check(H5Aopen(where, name, H5P_DEFAULT), fmt::format("the attribute {}", name));
    require_single(attr, name);
    const hid_t type = H5Aget_type(attr);
    std::string out;
    if (H5Tget_class(type) == H5T_STRING && !H5Tis_variable_str(type) && H5Tget_size(type) <= (1U << 20)) {
      out.resize(H5Tget_size(type));
      if (H5Aread(attr, type, out.data()) < 0) out.clear();
    } else {
      H5Tclose(type);
      H5Aclose(attr);
      fail(fmt::format("the attribute {} is a fixed-length string of at most 1 MiB", name));
    }
    H5Tclose(type);
    H5Aclose(attr);
    while (!out.empty() && out.back() == '\0') out.pop_back();
    return out;
  }

  double number(hid_t where, const char* name) const {
    const hid_t attr = check(H5Aopen(where, name, H5P_DEFAULT), fmt::format("the attribute {}", name));
    require_single(attr, name);
    double x = NAN;
    const herr_t r = H5Aread(attr, H5T_NATIVE_DOUBLE, &x);
    H5Aclose(attr);
    if (r < 0) fail(fmt::format("the attribute {} is not a number", name));
    return x;
  }

  template <class T>
  std::vector<T> values(hid_t where, const char* name, hid_t memory_type, std::size_t expected) const {
    const hid_t set = check(H5Dopen2(where, name, H5P_DEFAULT), fmt::format("the dataset {}", name));
    const hid_t space = H5Dget_space(set);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    H5Sclose(space);
    std::vector<T> out;
    if (n < 0 || static_cast<std::size_t>(n) != expected) {
      H5Dclose(set);
      fail(fmt::format("{} has {} values, expected {}", name, n, expected));
    }
    // What the file really stores (bounce writes it whole, uncompressed): a small file that
    // declares a huge dataset it never wrote would otherwise cost that memory to refuse.
    const hsize_t stored = H5Dget_storage_size(set);
    if (expected > (std::size_t{1} << 28) || stored < expected * sizeof(T)) {
      H5Dclose(set);
      fail(fmt::format("{} stores its {} values ({} bytes stored)", name, expected, stored));
    }
    out.resize(expected);
    const herr_t r = H5Dread(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
    H5Dclose(set);
    if (r < 0) fail(fmt::format("{} could not be read", name));
    return out;
  }

  double scalar(hid_t where, const char* name) const { return values<double>(where, name, H5T_NATIVE_DOUBLE, 1)[0]; }

  hid_t group(hid_t where, const char* name) const {
    return check(H5Gopen2(where, name, H5P_DEFAULT), fmt::format("the group {}", name));
  }

  Material material(hid_t root, const char* name) const {
    const hid_t g = group(root, name);
    Material m;
    m.name = text(g, "name");
    m.youngs_modulus = scalar(g, "youngs_modulus");
    m.poisson_ratio = scalar(g, "poisson_ratio");
    m.density = scalar(g, "density");
    if (H5Lexists(g, "surface_energy", H5P_DEFAULT) > 0) m.surface_energy = scalar(g, "surface_energy");
    H5Gclose(g);
    try {
      validate(m);
    } catch (const InvalidArgument& e) {
      fail(fmt::format("{} has a valid material ({})", name, e.what()));
    }
    return m;
  }

  AtlasAxis axis(hid_t grid, const char* name, bool uniform) const {
    const hid_t set = check(H5Dopen2(grid, name, H5P_DEFAULT), fmt::format("the dataset {}", name));
    AtlasAxis a;
    a.start = number(set, "start");
    a.step = number(set, "step");
    const hid_t space = H5Dget_space(set);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    H5Sclose(space);
    H5Dclose(set);
    if (n < 4 || n > 1 << 24) fail(fmt::format("{} has 4 to 2^24 nodes", name));
    a.count = static_cast<std::size_t>(n);
    const auto nodes = values<double>(grid, name, H5T_NATIVE_DOUBLE, a.count);
    if (!uniform) {  // Atlas::prepare checks them (ascending, cells not too narrow)
      a.nodes = nodes;
      return a;
    }
    for (std::size_t i = 0; i < a.count; ++i) {
      if (!(std::abs(nodes[i] - a.value(i)) <= 1e-12 * (1.0 + std::abs(nodes[i])))) {
        fail(fmt::format("{} is uniform (start + i step)", name));
      }
    }
    return a;
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

void read_contents(const Reader& r, hid_t file, Atlas& a) {
  if (r.text(file, "format") != "bounce-atlas") r.fail("format = bounce-atlas");
  const double version = r.number(file, "format_version");
  if (version != 1.0) r.fail(fmt::format("format_version 1 (this file has {}; written by bounce {})", version, r.text(file, "bounce_version")));
  a.bounce_version = r.text(file, "bounce_version");
  a.model = r.text(file, "model");
  a.can_stick = r.number(file, "can_stick") != 0.0;
  for (std::string w = r.text(file, "warnings"); !w.empty();) {
    const auto nl = w.find('\n');
    a.warnings.push_back(w.substr(0, nl));
    w = nl == std::string::npos ? "" : w.substr(nl + 1);
  }
  const hid_t parameters = r.group(file, "parameters");
  H5G_info_t info{};
  H5Gget_info(parameters, &info);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256] = {};
    H5Lget_name_by_idx(parameters, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name - 1, H5P_DEFAULT);
    const hid_t g = r.group(parameters, name);
    a.parameters.push_back({name, r.text(g, "value"), r.text(g, "unit")});
    if (a.parameters.back().unit == "1") a.parameters.back().unit.clear();
    H5Gclose(g);
  }
  H5Gclose(parameters);
  const hid_t materials = r.group(file, "materials");
  a.material1 = r.material(materials, "body1");
  a.material2 = r.material(materials, "body2");
  H5Gclose(materials);
  const hid_t ranges = r.group(file, "ranges");
  a.radius_min = r.scalar(ranges, "reduced_radius_min");
  a.radius_max = r.scalar(ranges, "reduced_radius_max");
  a.velocity_min = r.scalar(ranges, "velocity_min");
  a.velocity_max = r.scalar(ranges, "velocity_max");
  a.density_min = r.scalar(ranges, "effective_density_min");
  a.density_max = r.scalar(ranges, "effective_density_max");
  H5Gclose(ranges);
  const auto densities = detail::density_range(a.material1.density, a.material2.density);
  if (!(std::abs(a.density_min / densities[0] - 1.0) <= 1e-9 && std::abs(a.density_max / densities[1] - 1.0) <= 1e-9)) {
    r.fail("the effective densities of its materials");
  }
}

void read_grid(const Reader& r, hid_t file, Atlas& a) {
  const hid_t grid = r.group(file, "grid");
  a.x = r.axis(grid, "x_ln_reduced_radius", false);
  a.y = r.axis(grid, "y_ln_effective_density", true);
  a.z = r.axis(grid, "z_ln_velocity_above_v_stick", true);
  const std::size_t nxy = a.x.count * a.y.count;
  a.stick_ratio = r.values<double>(grid, "stick_ratio", H5T_NATIVE_DOUBLE, nxy);
  a.ln_v_reference = r.scalar(grid, "ln_v_reference");
  a.defined = r.values<std::uint8_t>(grid, "v_stick_defined", H5T_NATIVE_UINT8, nxy);
  a.values = r.values<double>(grid, "values", H5T_NATIVE_DOUBLE, atlas_field_count * a.points());
  H5Gclose(grid);
  const hid_t errors = r.group(file, "errors");
  AtlasErrors& e = a.errors;
  e.cor = r.scalar(errors, "cor");
  e.cor_measured = r.scalar(errors, "cor_measured");
  e.v_stick = r.scalar(errors, "v_stick");
  e.v_stick_measured = r.scalar(errors, "v_stick_measured");
  e.contact_time = r.scalar(errors, "contact_time_measured");
  e.energy = r.scalar(errors, "energy_fraction_measured");
  const double points = r.scalar(errors, "check_points"), thresholds = r.scalar(errors, "v_stick_points");
  e.tolerance = r.scalar(errors, "tolerance");
  for (double x : {e.cor, e.cor_measured, e.v_stick, e.v_stick_measured, e.contact_time, e.energy, e.tolerance, points,
                   thresholds}) {
    if (!(x >= 0.0 && x <= 1e12)) r.fail("errors that are numbers >= 0");
  }
  e.check_points = static_cast<long>(points);
  e.v_stick_points = static_cast<long>(thresholds);
  H5Gclose(errors);
}

}  // namespace

Atlas detail::read_atlas_hdf5(const std::string& path, const std::string& expected_model) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  Reader r(path);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InvalidArgument("atlas", path, "an atlas file (HDF5) written by bounce atlas build: no such file");
  }
  if (H5Fis_hdf5(path.c_str()) <= 0) r.fail("an HDF5 file (this one is not)");
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) r.fail("a readable HDF5 file");
  Atlas a;
  std::string checksum;
  try {
    read_contents(r, file, a);
    read_grid(r, file, a);
    checksum = r.text(file, "checksum");
  } catch (...) {
    H5Fclose(file);
    throw;
  }
  H5Fclose(file);
  if (checksum != fmt::format("crc32:{:08x}", atlas_digest(a))) {
    r.fail(fmt::format("its checksum {} does not match its content (the file was changed after bounce wrote it)",
                       checksum));
  }
  if (!expected_model.empty() && a.model != expected_model) {
    throw InvalidArgument("model", expected_model,
                          fmt::format("the model of the atlas {} ({}; its lookups are that model's)", path, a.model));
  }
  a.prepare(path);
  return a;
}

}  // namespace bounce::analysis
