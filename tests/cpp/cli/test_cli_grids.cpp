// Grids as typed (issue 40, 12): a log grid's decades and ends are the decimal values they
// stand for (0.1, not 0.10000000000000006), a table's ends are its range as given (20, not
// 19.999999999999979), and every number is printed in its shortest round-trip form.
#include <charconv>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "api/binding.hpp"  // the private range parser (src/)
#include "cli/run_cli.hpp"

using namespace bounce::testing;

namespace {

// The first column of a CSV (its header dropped).
std::vector<std::string> first_column(const std::string& csv) {
  std::vector<std::string> cells;
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line)) cells.push_back(line.substr(0, line.find(',')));
  return cells;
}

// `cell` is the shortest text that reads back as its number (fmt's "{}", nlohmann's form).
void expect_shortest(const std::string& cell) {
  double x = 0.0;
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), x);
  ASSERT_TRUE(ec == std::errc() && end == cell.data() + cell.size()) << cell;
  EXPECT_EQ(cell, fmt::format("{}", x));
}

}  // namespace

// The call: main printed 0.10000000000000006, 1.0000000000000009, 10.00000000000001.
TEST(Grids, LogCurveDecadesAreExact) {
  const auto r = run_cli({"curve", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--velocities",
                          "0.01:100:9", "--log", "--csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> v = first_column(r.out);
  ASSERT_EQ(v.size(), 9u);
  EXPECT_EQ(v[0], "0.01");
  EXPECT_EQ(v[2], "0.1");
  EXPECT_EQ(v[4], "1");
  EXPECT_EQ(v[6], "10");
  EXPECT_EQ(v[8], "100");
  for (const std::string& cell : v) expect_shortest(cell);
}

// The parser itself: a whole number of decades from LO is LO's decimal shifted (0.03 -> 0.3, 3,
// 30 exactly; 0.5 -> 5, 50, ...); other points stay exp-log and the grid increasing.
TEST(Grids, LogRangeHitsDecadesExactly) {
  using bounce::api::detail::parse_range;
  EXPECT_EQ(parse_range("velocities", "0.03:300:5", true), (std::vector<double>{0.03, 0.3, 3, 30, 300}));
  const auto half = parse_range("velocities", "0.5:5e6:15", true);
  for (std::size_t i = 0; i < half.size(); i += 2) EXPECT_EQ(half[i], 0.5 * std::pow(10.0, static_cast<double>(i / 2))) << i;
  const auto dense = parse_range("velocities", "1e-3:1e3:601", true);  // 100 points a decade
  for (std::size_t i = 0; i < dense.size(); i += 100) EXPECT_EQ(dense[i], std::stod(fmt::format("1e{}", static_cast<long>(i / 100) - 3)));
  for (std::size_t i = 1; i < dense.size(); ++i) EXPECT_LT(dense[i - 1], dense[i]) << i;
  const auto wide = parse_range("velocities", "1e-300:1e300:7", true);  // HI / LO overflows: exp-log, no decades
  EXPECT_EQ(wide.front(), 1e-300);
  EXPECT_EQ(wide.back(), 1e300);
  for (std::size_t i = 1; i < wide.size(); ++i) EXPECT_LT(wide[i - 1], wide[i]) << i;
}

// A table's CSV: its ends are the range as typed (main printed 19.999999999999996 for 20 here).
TEST(Grids, TableCsvEndsAreTheRange) {
  const auto r = run_cli({"table", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--velocities",
                          "0.1:20", "--csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> v = first_column(r.out);
  ASSERT_GT(v.size(), 2u);
  EXPECT_EQ(v.front(), "0.1");
  EXPECT_EQ(v.back(), "20");
  std::istringstream lines(r.out);
  std::string line;
  std::getline(lines, line);
  while (std::getline(lines, line)) {
    std::istringstream cells(line);
    std::string cell;
    for (int column = 0; column < 4 && std::getline(cells, cell, ','); ++column) expect_shortest(cell);
  }
  // With sticking the nodes are v_s + exp(x): the table ended at 19.999999999999979.
  const auto k13 = run_cli({"table", "--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis",
                            "1e-11", "--velocities", "0.1:20", "--csv"});
  ASSERT_EQ(k13.exit_code, 0) << k13.err;
  EXPECT_EQ(first_column(k13.out).back(), "20");
}
