#pragma once
// Modules: parts of bounce that bring heavy libraries (HDF5 for atlas files, Open MPI for the
// CLI's sweeps) are shared objects opened on first use, so that a program that needs neither
// does not load them at start-up (docs/architecture.md, "Modules").

#include <string>

namespace bounce {

/// The folder bounce's modules live in: "bounce" beside the libbounce shared object that
/// holds this function (the build tree's lib/bounce, or the install's <libdir>/bounce).
std::string module_folder();

/// The address of `symbol` in the module `file` of module_folder(), opened on first use and
/// kept open. An InstallationError naming the file and the loader's reason when either is missing.
void* module_symbol(const std::string& file, const char* symbol);

/// A module's table of entry points: `symbol` names a function `const Table* symbol()` of it.
template <class Table>
const Table* module_table(const std::string& file, const char* symbol) {
  using Entry = const Table* (*)();
  return reinterpret_cast<Entry>(module_symbol(file, symbol))();
}

}  // namespace bounce
