// Modules opened on first use (include/bounce/core/module.hpp): located from libbounce's own
// path, which dladdr gives for any address inside it.
#include "bounce/core/module.hpp"

#include <dlfcn.h>

#include <filesystem>

#include "bounce/core/error.hpp"

namespace bounce {

namespace {

const int anchor = 0;  // an address inside libbounce

// libbounce's folder as the loader found it, made absolute when the library is loaded: a relative
// LD_LIBRARY_PATH entry names it from the working directory of that moment, which may change.
std::string loaded_from() {
  Dl_info info{};
  if (dladdr(&anchor, &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code error;
  const std::filesystem::path path = std::filesystem::absolute(info.dli_fname, error);
  return error ? std::string() : path.parent_path().string();
}

const std::string library_folder = loaded_from();

}  // namespace

std::string module_folder() {
  if (library_folder.empty()) {
    throw InstallationError("bounce could not find where its library is loaded from (dladdr), so not its modules either");
  }
  return library_folder + "/bounce";
}

void* module_symbol(const std::string& file, const char* symbol) {
  const std::string path = module_folder() + "/" + file;
  // RTLD_NODELETE: the module's code may still run from static destructors at exit.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw InstallationError("bounce could not load its module " + path + " (" + (why != nullptr ? why : "no reason given") +
                "); reinstall bounce, or rebuild it");
  }
  void* address = dlsym(handle, symbol);
  if (address == nullptr) throw InstallationError("bounce's module " + path + " lacks " + symbol + ": it is from another build");
  return address;
}

}  // namespace bounce
