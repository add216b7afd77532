// Errors that blame the right thing (issue 40, section B): a refusal names the inputs that
// caused it, not the one that happened to be checked.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/run_cli.hpp"

using namespace bounce::testing;

namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

// Point 4: 70 typed for 70 GPa makes c_t = 0.167 m/s. Main said only "--velocity = 1 is
// invalid: expected an impact velocity <= the transversal sound speed c_t = 0.1673 m/s, where
// the quasi-static models end (BSHP96 (B11))": the inputs that made c_t small, and the unit, named.
TEST(Blame, SmallSoundSpeedNamesTheModulusAndAsksForItsUnit) {
  const std::vector<std::string> args{"collide", "--material", "water-ice", "--radius", "1e-6", "--E",     "70",
                                      "--model", "krijt",     "--tvis",    "1e-11",  "--velocity", "1"};
  expect_rejected(args, "--velocity", "1");
  const std::string err = run_cli(args).err;
  EXPECT_TRUE(has(err, "c_t = 0.1673 m/s")) << err;
  EXPECT_TRUE(has(err, "E = 70 Pa")) << err;
  EXPECT_TRUE(has(err, "density = 1000 kg/m^3")) << err;
  EXPECT_TRUE(has(err, "is it in the unit [Pa] (70 GPa would be 7e+10 Pa)?")) << err;
}

// Body 2 sets c_t when it is the slower: its names (E2, density2) are the ones given; a
// plausible E is not questioned (the speed is simply too high).
TEST(Blame, SoundSpeedOfTheSlowerBodyWithoutAQuestionWhenEIsPlausible) {
  const auto r = run_cli({"collide", "--material", "quartz", "--radius", "1e-6", "--material2", "water-ice", "--model", "hertz",
                          "--density2", "1e5", "--velocity", "500"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(has(r.err, "of body 2 (water-ice (modified)): E2 = 7e+09 Pa")) << r.err;
  EXPECT_TRUE(has(r.err, "density2 = 100000 kg/m^3")) << r.err;
  EXPECT_FALSE(has(r.err, "is it in the unit")) << r.err;
}

