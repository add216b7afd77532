#pragma once
// The whole command line as one call, so that main() and the CLI fuzz target
// (fuzz/fuzz_cli.cpp) run exactly the same code.

namespace bounce::cli {

/// Parses argv (argv[0] is the program name), runs the command, prints to std::cout and
/// std::cerr; the exit code (docs/cli.md: 0 ok, 2 bad input, 3 refused or not computable).
int run(int argc, const char* const* argv);

/// Ctrl-C (SIGINT) ends the process with exit code 130 and one line on stderr; what was written
/// to stdout stays (the streamed rows of a curve or a table are flushed one by one, docs/cli.md),
/// and a JSON document being built is closed with the points it has (interrupt.hpp).
/// main() installs it; the in-process fuzz target does not.
void exit_on_interrupt();

}  // namespace bounce::cli
