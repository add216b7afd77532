// The C headers `bounce table --c-header P` writes, dropped into a client that calls only one of
// their functions (issue 40, 12b): they must compile without a warning as C99 and as C++ under
// -Wall -Wextra -Wpedantic -Werror, as a project building with -Werror would compile them
// (REBOUND builds with -std=c99 -Wall -Wpedantic -Wextra). A helper that is `static` but not
// `inline` warns "defined but not used" when the client does not call it.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/run_cli.hpp"

using namespace bounce::testing;

namespace {

const std::vector<std::string> ice = {"table", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6"};

std::string header(std::vector<std::string> extra) {
  std::vector<std::string> args = ice;
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = run_cli(args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.out;
}

// Compiles `body` (the statements of main, after #include "table.h") with `compiler` and
// `standard` under -Wall -Wextra -Wpedantic -Werror, runs it and returns what it printed; a
// warning fails the compile, and the test with the compiler's message.
std::string compile_and_run(const std::string& compiler, const std::string& standard, const std::string& text,
                            const std::string& body) {
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() / ("bounce-c-header-" + std::to_string(::getpid()) + "-" +
                                                    std::to_string(counter++));
  fs::create_directories(dir);
  std::ofstream(dir / "table.h") << text;
  std::ofstream(dir / "main.c") << "#include <stdio.h>\n#include \"table.h\"\nint main(void) {\n" << body
                                << "\n  return 0;\n}\n";
  const std::string language = standard.find("c++") != std::string::npos ? " -x c++" : "";
  const std::string compile = compiler + " -std=" + standard + language + " -Wall -Wextra -Wpedantic -Werror -o " +
                              quote((dir / "main").string()) + " " + quote((dir / "main.c").string()) + " -lm 2>" +
                              quote((dir / "log").string());
  std::string out;
  if (std::system(compile.c_str()) != 0) {
    ADD_FAILURE() << "does not compile cleanly: " << compile << "\n" << slurp(dir / "log");
  } else if (std::system((quote((dir / "main").string()) + " > " + quote((dir / "out").string())).c_str()) != 0) {
    ADD_FAILURE() << "does not run";
  } else {
    out = slurp(dir / "out");
  }
  fs::remove_all(dir);
  return out;
}

struct Compiler {
  std::string path, standard;
};
const std::vector<Compiler> compilers = {{BOUNCE_C_COMPILER, "c99"}, {BOUNCE_CXX_COMPILER, "c++17"}};

}  // namespace

// eps^N: each of the two functions alone (today's CHeaderCompilesStandaloneAndAgrees calls both).
TEST(CHeader, NormalTableWithOneFunctionCompilesWithoutWarnings) {
  const std::string text = header({"--velocities", "0.1:10", "--c-header", "ice"});
  for (const Compiler& c : compilers) {
    SCOPED_TRACE(c.path + " -std=" + c.standard);
    const double cor = std::atof(compile_and_run(c.path, c.standard, text, "  printf(\"%.17g\\n\", ice_cor(1.0));").c_str());
    EXPECT_GT(cor, 0.0);
    EXPECT_LT(cor, 1.0);
    EXPECT_EQ(compile_and_run(c.path, c.standard, text, "  printf(\"%d\\n\", ice_sticks(1.0));"), "0\n");
  }
}

// eps^T: its one public function, and the header included without a call at all.
TEST(CHeader, TangentialTableCompilesWithoutWarnings) {
  const std::string text = header({"--friction", "0.014142", "--asperity", "1e-6", "--asperity-form", "published",
                                   "--velocities", "0.5:2",
                                   "--tangential-velocities", "0.01:0.1", "--bound", "1e-4", "--c-header", "fig2"});
  for (const Compiler& c : compilers) {
    SCOPED_TRACE(c.path + " -std=" + c.standard);
    const std::string out = compile_and_run(c.path, c.standard, text, "  printf(\"%.17g\\n\", fig2_cor_tangential(1.0, 0.05));");
    EXPECT_FALSE(out.empty());
    EXPECT_EQ(compile_and_run(c.path, c.standard, text, "  (void)0;"), "");
  }
}
