// The data files real instruments and spreadsheets write (docs/fitting.md, "The data"): a
// UTF-8 byte-order mark, tab or semicolon delimiters, a decimal comma, units in brackets, names
// in any case, quoted fields, other names mapped by --columns; and what is still refused.
#include <string>

#include <gtest/gtest.h>

#include "bounce/analysis/fit.hpp"
#include "bounce/core/error.hpp"

using namespace bounce;
using namespace bounce::analysis;

namespace {

// The plain file every variant below must read as.
void expect_plain(const Experiment& e) {
  ASSERT_EQ(e.points.size(), 2U);
  EXPECT_DOUBLE_EQ(e.points[0].velocity, 1.5);
  EXPECT_DOUBLE_EQ(e.points[0].cor, 0.5);
  EXPECT_DOUBLE_EQ(e.points[1].velocity, 2.0);
  EXPECT_DOUBLE_EQ(e.points[1].cor, 0.25);
}

std::string refusal(const std::string& text, const ColumnNames& names = {}) {
  try {
    parse_experiment(text, "f.csv", names);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return {};
}

}  // namespace

TEST(FitDataFormats, ReadsTheFormsOfRealFiles) {
  expect_plain(parse_experiment("velocity,cor\n1.5,0.5\n2,0.25\n", "f.csv"));
  // Excel's "CSV UTF-8" starts with a byte-order mark (it was read as part of the name).
  expect_plain(parse_experiment("\xEF\xBB\xBFvelocity,cor\n1.5,0.5\n2,0.25\n", "f.csv"));
  expect_plain(parse_experiment("velocity\tcor\n1.5\t0.5\n2\t0.25\n", "f.csv"));
  expect_plain(parse_experiment("velocity;cor\n1.5;0.5\n2;0.25\n", "f.csv"));
  expect_plain(parse_experiment("velocity;cor\n1,5;0,5\n2;0,25\n", "f.csv"));  // a decimal comma
  expect_plain(parse_experiment("Velocity,COR\n1.5,0.5\n2,0.25\n", "f.csv"));
  expect_plain(parse_experiment("velocity [m/s],cor [-]\n1.5,0.5\n2,0.25\n", "f.csv"));
  expect_plain(parse_experiment("Velocity (m s^-1),cor\n1.5,0.5\n2,0.25\n", "f.csv"));
  expect_plain(parse_experiment("\"velocity\",\"cor\"\n\"1.5\",\"0.5\"\n\"2\", \"0.25\"\r\n", "f.csv"));
  expect_plain(parse_experiment("\"velocity [m/s]\";\"cor\"\n\"1,5\";\"0,5\"\n2;0,25\n", "f.csv"));
  expect_plain(parse_experiment("velocity [cm/s],cor\n150,0.5\n200,0.25\n", "f.csv"));  // converted to m/s
}

TEST(FitDataFormats, MapsOtherColumnNames) {
  const ColumnNames names = parse_column_names("velocity=Speed,cor=e,cor_error=sigma");
  const Experiment e = parse_experiment("Speed [m/s],E,sigma\n1.5,0.5,0.01\n2,0.25,0.02\n", "f.csv", names);
  expect_plain(e);
  EXPECT_DOUBLE_EQ(*e.points[1].cor_error, 0.02);
  // With a mapping the message names the mapped columns.
  EXPECT_NE(refusal("v,cor\n1,0.5\n", parse_column_names("velocity=Speed")).find("columns named speed, cor"),
            std::string::npos);
}

TEST(FitDataFormats, RefusesWhatItCannotRead) {
  // The header's cell as typed, the allowed forms, and --columns named.
  const std::string unknown = refusal("speed,cor\n1,0.5\n");
  EXPECT_NE(unknown.find("f.csv:1: header = speed is invalid"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("--columns"), std::string::npos) << unknown;
  EXPECT_NE(refusal("velocity [km/h],cor\n1,0.5\n").find("header = velocity [km/h] is invalid"), std::string::npos);
  EXPECT_NE(refusal("velocity,cor [%]\n1,0.5\n").find("header = cor [%] is invalid"), std::string::npos);
  EXPECT_NE(refusal("velocity,cor\n\"1,0.5\n").find("closing double quote"), std::string::npos);
  EXPECT_NE(refusal("velocity;cor\n1;0.5;3\n").find("2 semicolon-separated fields"), std::string::npos);
  EXPECT_NE(refusal(std::string("\xFF\xFE", 2) + "v").find("UTF-8"), std::string::npos);
  // A decimal comma in a comma-separated file is two fields, not a number.
  EXPECT_NE(refusal("velocity,cor\n1,5,0.5\n").find("2 comma-separated fields"), std::string::npos);
}

TEST(FitDataFormats, RefusesMalformedColumnMaps) {
  for (const char* text : {"", "velocity", "speed=v", "velocity=", "velocity=a,velocity=b"}) {
    try {
      parse_column_names(text);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "columns") << text;
    }
  }
}
