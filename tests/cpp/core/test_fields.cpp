// Parameter structs and their field tables (core/fields.hpp): the specs they generate, the struct
// read from bound values (defaults, absent optionals, required numbers), and Parameters::set.
#include <optional>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "bounce/core/error.hpp"
#include "bounce/core/fields.hpp"

using namespace bounce;

namespace {
struct Example {
  double required = 0.0;
  double with_default = 0.0;
  std::optional<double> maybe;
  std::string choice;
};
const FieldTable<Example>& example_fields() {
  using S = Example;
  static const FieldTable<S> table{
      {real_parameter("required", "a required number", "m", positive(), "help"), &S::required},
      {with_default(real_parameter("with_default", "a number", "s", positive(), "help"), 2.5), &S::with_default},
      {real_parameter("maybe", "an optional number", "", non_negative(), "help"), &S::maybe},
      {choice_parameter("choice", {"one", "two"}, "help"), &S::choice}};
  return table;
}
Parameters bound(const ParameterInputs& inputs) {
  const auto specs = example_fields().specs();
  return bind_parameters(specs, inputs, "the example");
}
}  // namespace

TEST(Fields, SpecsInTheTablesOrder) {
  const auto specs = example_fields().specs();
  ASSERT_EQ(specs.size(), 4u);
  EXPECT_EQ(specs[0].name, "required");
  EXPECT_EQ(specs[3].name, "choice");
  EXPECT_EQ(specs[1].unit, "s");
}

TEST(Fields, ReadGivenDefaultsAndAbsentOptionals) {
  const Example e = example_fields().read(bound({{"required", std::string("3e-3")}}));
  EXPECT_EQ(e.required, 3e-3);
  EXPECT_EQ(e.with_default, 2.5);
  EXPECT_FALSE(e.maybe.has_value());
  EXPECT_EQ(e.choice, "one");  // a choice's default is its first
  const Example f = example_fields().read(bound({{"required", 1.0}, {"maybe", 0.0}, {"choice", std::string("two")}}));
  EXPECT_EQ(f.maybe, 0.0);
  EXPECT_EQ(f.choice, "two");
}

// A number without a default that was not given is refused by the one-line rule, naming it.
TEST(Fields, RequiredNumberNotGivenIsRefused) {
  try {
    (void)example_fields().read(bound({}));
    FAIL() << "accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "required");
    EXPECT_EQ(e.value(), "(not given)");
    EXPECT_NE(e.allowed().find("a required number [m] > 0"), std::string::npos) << e.allowed();
  }
}

// Parameters::set puts a checked number in as given (a fit's trial); anything else is a bug.
TEST(Fields, SetTakesCheckedNumbersOnly) {
  Parameters p = bound({{"required", 1.0}});
  p.set("maybe", 4.0);
  EXPECT_TRUE(p.given("maybe"));
  EXPECT_EQ(example_fields().read(p).maybe, 4.0);
  EXPECT_THROW(p.set("maybe", -1.0), std::logic_error);    // out of its range
  EXPECT_THROW(p.set("choice", 1.0), std::logic_error);    // not a real
  EXPECT_THROW(p.set("unknown", 1.0), std::logic_error);   // not declared
}
