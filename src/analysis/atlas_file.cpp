// The atlas file's front: write_atlas and read_atlas call the HDF5 code of hdf5/, a module opened
// on first use in a shared libbounce (hdf5/atlas_file_module.hpp says why); the CSV export.
#include <cmath>

#include <fmt/format.h>

#include "bounce/analysis/atlas.hpp"
#include "bounce/core/error.hpp"
#include "bounce/core/module.hpp"
#include "hdf5/atlas_file_module.hpp"

namespace bounce::analysis {

namespace {

const detail::AtlasFileModule& file_module() {
#ifdef BOUNCE_ATLAS_MODULE
  static const detail::AtlasFileModule* module = [] {
    const auto* m = module_table<detail::AtlasFileModule>("atlas_hdf5.so", "bounce_atlas_file_module");
    if (m->atlas_size != sizeof(Atlas)) {
      throw InstallationError("bounce's module " + module_folder() + "/atlas_hdf5.so is from another build of bounce "
                              "(its atlas differs from this library's); reinstall bounce, or rebuild it");
    }
    return m;
  }();
#else
  static const detail::AtlasFileModule* module = bounce_atlas_file_module();
#endif
  return *module;
}

}  // namespace

void write_atlas(const Atlas& atlas, const std::string& path) { file_module().write(atlas, path); }

Atlas read_atlas(const std::string& path, const std::string& expected_model) {
  return file_module().read(path, expected_model);
}

std::string atlas_csv(const Atlas& a) {
  std::string out = "reduced_radius,effective_density,v_stick,velocity,cor,contact_time,bulk_fraction,crack_fraction\n";
  for (std::size_t ix = 0; ix < a.x.count; ++ix) {
    for (std::size_t iy = 0; iy < a.y.count; ++iy) {
      const std::size_t node = ix * a.y.count + iy;
      if (a.defined[node] == 0) continue;
      const double vs = a.node_v_stick(ix, iy);
      for (std::size_t iz = 0; iz < a.z.count; ++iz) {
        const double gap = std::exp(a.z.value(iz)), v = vs + gap;
        if (v < a.velocity_min || v > a.velocity_max) continue;
        const double eps = a.value(AtlasField::cor_factor, ix, iy, iz) * std::sqrt(gap / v);
        out += fmt::format("{},{},{},{},{},{},{},{}\n", std::exp(a.x.value(ix)), std::exp(a.y.value(iy)), vs, v, eps,
                           std::exp(a.value(AtlasField::ln_contact_time, ix, iy, iz)),
                           a.value(AtlasField::bulk_fraction, ix, iy, iz), a.value(AtlasField::crack_fraction, ix, iy, iz));
      }
    }
  }
  return out;
}

}  // namespace bounce::analysis
