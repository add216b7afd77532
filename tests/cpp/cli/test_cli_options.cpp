// The CLI's options come from the registry (docs/architecture.md): every model's options are there,
// and every option a chosen model or command does not use is refused with exit 2 naming
// it (the one-line rule), for each model.
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/run_cli.hpp"

using bounce::testing::expect_rejected;
using bounce::testing::run_cli;

namespace {

std::string option(const std::string& name) {
  std::string o = "--" + name;
  for (char& c : o) c = c == '_' ? '-' : c;
  return o;
}

// A value of the right kind for a parameter (its default, else a number).
std::string some_value(const nlohmann::json& p) {
  if (!p["default"].is_null()) return p["default"].get<std::string>();
  if (p["kind"] == "reals") return "1e-3,1e-3";
  return "1e-3";
}

// The models as the CLI lists them (`bounce models --json`): the registry it was built with.
nlohmann::json models() {
  const auto r = run_cli({"models", "--json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out)["models"];
}

}  // namespace

TEST(CliOptions, EveryModelParameterIsAnOption) {
  const auto help = run_cli({"collide", "--help"});
  ASSERT_EQ(help.exit_code, 0);
  for (const auto& row : models()) {
    EXPECT_NE(help.out.find(row["name"].get<std::string>()), std::string::npos) << row["name"];
    for (const auto& p : row["parameters"]) {
      EXPECT_NE(help.out.find(option(p["name"]) + " "), std::string::npos) << p["name"];
    }
  }
}

TEST(CliOptions, EachModelRefusesOptionsOfOthers) {
  const nlohmann::json rows = models();
  for (const auto& row : rows) {
    std::set<std::string> own;
    for (const auto& p : row["parameters"]) own.insert(p["name"]);
    std::set<std::string> tried;
    for (const auto& other : rows) {
      for (const auto& p : other["parameters"]) {
        const std::string name = p["name"];
        if (own.count(name) || !tried.insert(name).second) continue;
        const std::string value = some_value(p);
        expect_rejected({"collide", "--material", "water-ice", "--radius", "1e-6", "--model", row["name"],
                         option(name), value, "--velocity", "1"},
                        option(name), value);
      }
    }
    EXPECT_FALSE(tried.empty()) << row["name"];
  }
}

// Options of other commands, of the tangential law without a tangential velocity, and of
// models in commands that do not use them.
TEST(CliOptions, CommandsRefuseUnusedOptions) {
  const std::vector<std::string> ice = {"--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6"};
  auto with = [&](std::vector<std::string> args) {
    args.insert(args.begin() + 1, ice.begin(), ice.end());
    return args;
  };
  expect_rejected(with({"collide", "--velocity", "1", "--friction", "0.3"}), "--friction", "0.3");
  expect_rejected(with({"collide", "--velocity", "1", "--follow", "1e-3"}), "--follow", "1e-3");
  expect_rejected(with({"collide", "--velocity", "1", "--trajectory-points", "100"}), "--trajectory-points", "100");
  expect_rejected(with({"curve", "--velocities", "1:2:3", "--velocity", "1"}), "--velocity", "1");
  expect_rejected(with({"analytic", "--velocity", "1", "--yield", "1e7"}), "--yield", "1e7");
  expect_rejected(with({"analytic", "--velocity", "1", "--contact-end", "force"}), "--contact-end", "force");
  expect_rejected(with({"sticking", "--model", "jkr-viscoelastic", "--gamma", "0.1", "--friction", "0.3"}),
                  "--friction", "0.3");
  expect_rejected(with({"table", "--velocities", "1:2", "--csv", "--velocity", "1"}), "--velocity", "1");
  expect_rejected(with({"table", "--velocities", "1:2", "--csv", "--friction", "0.3", "--asperity", "1e-6"}),
                  "--friction", "0.3");
  expect_rejected({"contact", "--material", "steel", "--radius", "1e-3", "--z0", "3e-10"}, "--z0", "3e-10");
  expect_rejected({"contact", "--material", "water-ice", "--radius", "1e-6", "--law", "jkr", "--angle", "0.3"},
                  "--angle", "0.3");
  expect_rejected({"contact", "--material", "steel", "--radius", "1e-3", "--log"}, "--log", "true");
  expect_rejected(with({"collide", "--velocity", "1", "--json", "--csv"}), "--csv", "given");
  // The other tangential law's parameters; a wall's contradictions; tolerance with the master curve.
  const std::vector<std::string> oblique = {"--velocity", "1", "--tangential-velocity", "0.01", "--friction", "0.01"};
  auto tangential = [&](std::vector<std::string> more) {
    auto args = with({"collide"});
    args.insert(args.end(), oblique.begin(), oblique.end());
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  expect_rejected(tangential({"--asperity", "1e-6", "--shear-damping", "5"}), "--shear-damping", "5");
  expect_rejected(tangential({"--tangential-law", "step", "--shear-damping", "5", "--asperity", "1e-6"}), "--asperity",
                  "1e-6");
  expect_rejected(tangential({"--tangential-law", "step", "--shear-damping", "5", "--asperity-form", "passive"}),
                  "--asperity-form", "passive");
  expect_rejected(with({"collide", "--velocity", "1", "--rigid-wall", "--E2", "1e9"}), "--E2", "1e9");
  expect_rejected(with({"collide", "--velocity", "1", "--wall", "--density2", "5"}), "--density2", "5");
  expect_rejected(with({"collide", "--velocity", "1", "--method", "master", "--tolerance", "1e-9"}), "--tolerance",
                  "1e-9");
}

// Options no parameter of the command stands for: CLI11 leaves them over; the message
// follows the same rule and names the commands that take the option.
TEST(CliOptions, OptionsOfOtherCommandsNameTheirCommands) {
  const std::vector<std::string> ice = {"--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6"};
  auto with = [&](const std::string& command, std::vector<std::string> args) {
    args.insert(args.begin(), ice.begin(), ice.end());
    args.insert(args.begin(), command);
    return args;
  };
  expect_rejected(with("collide", {"--velocity", "1", "--force", "3"}), "--force", "3");
  expect_rejected(with("collide", {"--velocity", "1", "--force=3"}), "--force", "3");
  expect_rejected({"contact", "--material", "steel", "--radius", "1e-3", "--velocity", "1"}, "--velocity", "1");
  expect_rejected(with("collide", {"--velocity", "1", "--no-such-option"}), "--no-such-option", "(given)");
  expect_rejected(with("collide", {"--velocity", "1", "stray"}), "argument", "stray");
  const auto r = run_cli(with("collide", {"--velocity", "1", "--force", "3"}));
  EXPECT_NE(r.err.find("commands that take it: contact"), std::string::npos) << r.err;
}

// A count takes whole numbers only; a moment of inertia J/(m R^2) is at most 1 (mass inside
// a ball of radius R).
TEST(CliOptions, CountsAndInertiaInTheirRanges) {
  const std::vector<std::string> ice = {"collide", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6",
                                        "--velocity", "1"};
  auto with = [&](std::vector<std::string> more) {
    more.insert(more.begin(), ice.begin(), ice.end());
    return more;
  };
  expect_rejected(with({"--trajectory", "--trajectory-points", "2.5"}), "--trajectory-points", "2.5");
  expect_rejected(with({"--tangential-velocity", "0.01", "--friction", "0.1", "--asperity", "1e-6", "--inertia", "5"}),
                  "--inertia", "5");
  EXPECT_EQ(run_cli(with({"--tangential-velocity", "0.01", "--friction", "0.1", "--asperity", "1e-6", "--inertia", "1"}))
                .exit_code,
            0);
}
