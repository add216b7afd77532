#include "bounce/core/error.hpp"

#include <utility>

namespace bounce {

namespace {
std::string compose(const std::string& parameter, const std::string& value,
                    const std::string& allowed) {
  // An empty value is shown as "" (`--material = "" is invalid`, not `--material =  is`).
  return parameter + " = " + (value.empty() ? std::string("\"\"") : value) + " is invalid: expected " + allowed;
}
}  // namespace

InvalidArgument::InvalidArgument(std::string parameter, std::string value,
                                 std::string allowed)
    : Error(compose(parameter, value, allowed)),
      parameter_(std::move(parameter)),
      value_(std::move(value)),
      allowed_(std::move(allowed)) {}

InvalidArgument InvalidArgument::renamed(std::string parameter) const {
  return InvalidArgument(std::move(parameter), value_, allowed_);
}

}  // namespace bounce
