// "Did you mean …?" (core/suggest.hpp): the edit distance and when a name is offered.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/suggest.hpp"

using bounce::closest_name;
using bounce::did_you_mean;
using bounce::edit_distance;

TEST(Suggest, EditDistanceCountsEachEditOnce) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("velocty", "velocity"), 1u);  // a deletion
  EXPECT_EQ(edit_distance("velocityy", "velocity"), 1u);  // an insertion
  EXPECT_EQ(edit_distance("velocitx", "velocity"), 1u);  // a substitution
  EXPECT_EQ(edit_distance("kirjt", "krijt"), 1u);  // a transposition of neighbours
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("ca", "abc"), 3u);  // optimal string alignment: no edit of a transposed pair
  EXPECT_EQ(edit_distance("water-ice", "ice-bshp96"), edit_distance("ice-bshp96", "water-ice"));
}

TEST(Suggest, LikelyTyposAreNamed) {
  const std::vector<std::string> options = {"--velocity", "--velocities", "--radius", "--radius2", "--json"};
  EXPECT_EQ(closest_name("--velocty", options), "--velocity");
  EXPECT_EQ(closest_name("--radus", options), "--radius");
  EXPECT_EQ(closest_name("--JSON", options), "--json");  // case is ignored
  const std::vector<std::string> materials = {"steel", "water-ice", "ice-bshp96"};
  EXPECT_EQ(closest_name("Steel", materials), "steel");
  EXPECT_EQ(closest_name("watr-ice", materials), "water-ice");
  EXPECT_EQ(closest_name("water", materials), "water-ice");  // the only name it begins
  EXPECT_EQ(did_you_mean("stel", materials), "; did you mean steel?");
}

TEST(Suggest, NoGuessWhenNothingIsClose) {
  const std::vector<std::string> options = {"--velocity", "--velocities", "--radius"};
  EXPECT_EQ(closest_name("--xyzzy", options), "");
  EXPECT_EQ(closest_name("--velo", options), "");  // begins two names: no guess
  EXPECT_EQ(closest_name("", options), "");
  EXPECT_EQ(closest_name("--radius", options), "");  // a known name needs no suggestion
  EXPECT_EQ(closest_name("ab", {"abcdef"}), "");  // too short to be taken for a prefix
  EXPECT_EQ(closest_name("x", {}), "");
  EXPECT_EQ(did_you_mean("zzzz", {"steel"}), "");
}

TEST(Suggest, RegistryLookupsSuggestInTheirMessage) {
  struct Row {
    std::string name;
  };
  const std::vector<Row> rows = {{"hertz"}, {"viscoelastic"}, {"krijt"}};
  try {
    bounce::find_named(rows, "krjit", "model");
    FAIL() << "no error";
  } catch (const bounce::InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "model");
    EXPECT_EQ(e.value(), "krjit");
    EXPECT_EQ(e.allowed(), "one of hertz, viscoelastic, krijt; did you mean krijt?");
  }
  try {
    bounce::find_named(rows, "plastic", "model");
    FAIL() << "no error";
  } catch (const bounce::InvalidArgument& e) {
    EXPECT_EQ(e.allowed(), "one of hertz, viscoelastic, krijt");
  }
}
