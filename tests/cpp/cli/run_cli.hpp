#pragma once
// Runs the bounce CLI as a user would and captures what it printed.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

namespace bounce::testing {

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline CliResult run_cli(const std::vector<std::string>& args) {
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() /
                       ("bounce-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::create_directories(dir);
  std::string command = quote(BOUNCE_CLI);
  for (const auto& a : args) command += " " + quote(a);
  command += " >" + quote((dir / "out").string()) + " 2>" + quote((dir / "err").string());
  const int status = std::system(command.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  fs::remove_all(dir);
  return r;
}

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

/// The bad-input rule (exit 2, nothing on stdout, one line on stderr naming the
/// parameter, its value and the allowed range, no uncaught exception).
inline void expect_rejected(const std::vector<std::string>& args, const std::string& parameter,
                            const std::string& value) {
  const auto r = run_cli(args);
  SCOPED_TRACE(::testing::PrintToString(args));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(parameter + " = " + value), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("expected"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("terminate"), std::string::npos) << r.err;
}

/// Compiles `main_c` (next to headers already written into `dir`) as strict C99 with the C
/// compiler found at configure time (-std=c99 -pedantic -Wall -Wextra -Werror), runs it
/// and returns what it printed; a failure to compile or run fails the test.
inline std::string compile_and_run_c99(const std::filesystem::path& dir, const std::string& main_c) {
  std::ofstream(dir / "main.c") << main_c;
  const std::string compile = std::string(BOUNCE_C_COMPILER) + " -std=c99 -pedantic -Wall -Wextra -Werror -o " +
                              quote((dir / "main").string()) + " " + quote((dir / "main.c").string()) + " -lm";
  if (std::system(compile.c_str()) != 0) {
    ADD_FAILURE() << "does not compile: " << compile;
    return "";
  }
  const std::string run = quote((dir / "main").string()) + " > " + quote((dir / "out.txt").string());
  if (std::system(run.c_str()) != 0) ADD_FAILURE() << "does not run: " << run;
  return slurp(dir / "out.txt");
}

}  // namespace bounce::testing
