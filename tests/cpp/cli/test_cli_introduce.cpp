// The CLI introduces itself (docs/cli.md): --version, `bounce` alone, and "did you mean" for a
// misspelt option, command, model or material, within the one-line rule for bad input.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bounce/api/front_door.hpp"
#include "cli/run_cli.hpp"

using bounce::testing::count_lines;
using bounce::testing::expect_rejected;
using bounce::testing::run_cli;

namespace {

const std::vector<std::string> ice = {"--material", "water-ice", "--radius", "1e-6"};

std::vector<std::string> cmd(const std::string& command, std::vector<std::string> more) {
  std::vector<std::string> args = {command};
  args.insert(args.end(), ice.begin(), ice.end());
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// Rejected under the one-line rule, and the line ends with the suggestion (or has none).
void expect_suggestion(const std::vector<std::string>& args, const std::string& parameter, const std::string& value,
                       const std::string& suggestion) {
  expect_rejected(args, parameter, value);
  const auto r = run_cli(args);
  const std::string tail = suggestion.empty() ? "" : "; did you mean " + suggestion + "?\n";
  if (suggestion.empty()) {
    EXPECT_EQ(r.err.find("did you mean"), std::string::npos) << r.err;
  } else {
    ASSERT_GE(r.err.size(), tail.size()) << r.err;
    EXPECT_EQ(r.err.substr(r.err.size() - tail.size()), tail) << r.err;
  }
}

}  // namespace

TEST(CliIntroduce, VersionIsTheProjects) {
  const auto r = run_cli({"--version"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, std::string("bounce ") + BOUNCE_PROJECT_VERSION + "\n");
  EXPECT_EQ(r.err, "");
}

TEST(CliIntroduce, AloneListsTheCommands) {
  const auto r = run_cli({});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  std::vector<std::string> names = {"completion"};
  for (const auto& spec : bounce::api::commands()) names.push_back(spec.name);
  for (const auto& name : names) {
    EXPECT_NE(r.out.find("\n  " + name + " "), std::string::npos) << name << " in\n" << r.out;
  }
  EXPECT_EQ(r.out, run_cli({"--help"}).out);  // the same as --help
}

TEST(CliIntroduce, HelpAllShowsEveryCommandsOptions) {
  const auto r = run_cli({"--help-all"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("--velocity"), std::string::npos);
  EXPECT_NE(r.out.find("--law"), std::string::npos);
}

TEST(CliIntroduce, MisspeltNamesGetASuggestion) {
  expect_suggestion(cmd("collide", {"--velocty", "1"}), "--velocty", "1", "--velocity");
  expect_suggestion(cmd("collide", {"velocity", "1"}), "argument", "velocity", "--velocity");
  expect_suggestion({"colide", "--velocity", "1"}, "command", "colide", "collide");
  expect_suggestion({"--verison"}, "--verison", "(given)", "--version");
  expect_suggestion(cmd("collide", {"--model", "krjit", "--velocity", "1"}), "--model", "krjit", "krijt");
  expect_suggestion({"collide", "--material", "watr-ice", "--radius", "1e-6", "--velocity", "1"}, "--material",
                    "watr-ice", "water-ice");
  expect_suggestion({"collide", "--material", "water-ice", "--material2", "Steel", "--radius", "1e-6", "--velocity",
                     "1"},
                    "--material2", "Steel", "steel");
  expect_suggestion(cmd("contact", {"--law", "jrk"}), "--law", "jrk", "jkr");
}

TEST(CliIntroduce, NoSuggestionWhenNothingIsClose) {
  expect_suggestion(cmd("collide", {"--xyzzy", "1"}), "--xyzzy", "1", "");
  expect_suggestion({"plot"}, "command", "plot", "");
  expect_suggestion(cmd("collide", {"--model", "plastic", "--velocity", "1"}), "--model", "plastic", "");
  expect_suggestion({"collide", "--material", "granite", "--radius", "1e-6", "--velocity", "1"}, "--material",
                    "granite", "");
  // An option another command takes names those commands, not a look-alike.
  const auto r = run_cli(cmd("collide", {"--force", "3", "--velocity", "1"}));
  EXPECT_EQ(count_lines(r.err), 1);
  EXPECT_NE(r.err.find("commands that take it: contact"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("did you mean"), std::string::npos) << r.err;
}
