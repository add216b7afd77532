#pragma once
// The version of the bounce library: the CMake project's, compiled in (cmake/version.cpp.in),
// so that the CLI's --version, Python's bounce.__version__ and the packages all say the same.

#include <string_view>

namespace bounce {

/// "MAJOR.MINOR.PATCH" of the library that is running (not of the headers compiled against).
std::string_view version();

}  // namespace bounce
