#pragma once
// The whole command line as one call, so that main() and the CLI fuzz target
// (fuzz/fuzz_cli.cpp) run exactly the same code.

namespace bounce::cli {

/// Parses argv (argv[0] is the program name), runs the command, prints to std::cout and
/// std::cerr; the exit code (docs/cli.md: 0 ok, 2 bad input, 3 refused or not computable).
int run(int argc, const char* const* argv);

}  // namespace bounce::cli
