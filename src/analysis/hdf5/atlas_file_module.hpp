#pragma once
// Private: the atlas's HDF5 code (docs/atlas.md, "Format"). In a shared libbounce it is the module
// lib/bounce/atlas_hdf5.so, opened by the first write_atlas or read_atlas: libhdf5 and the ~35
// libraries it brings (curl, GnuTLS, Kerberos, ...) cost every other program 4 ms at start-up
// (docs/benchmarks.md). In a static libbounce (the pip wheel) it is linked in.

#include <cstddef>
#include <string>

#include "bounce/analysis/atlas.hpp"

namespace bounce::analysis::detail {

struct AtlasFileModule {
  std::size_t atlas_size;  ///< sizeof(Atlas) where the module was built: another build's is refused
  void (*write)(const Atlas& atlas, const std::string& path);
  Atlas (*read)(const std::string& path, const std::string& expected_model);
};

void write_atlas_hdf5(const Atlas& atlas, const std::string& path);       // atlas_write.cpp
Atlas read_atlas_hdf5(const std::string& path, const std::string& model);  // atlas_read.cpp

}  // namespace bounce::analysis::detail

/// The module's entry point, looked up by name.
extern "C" const bounce::analysis::detail::AtlasFileModule* bounce_atlas_file_module();
