#pragma once
// Private: how the front door splits and checks what a user typed (commands.cpp).

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bounce/api/front_door.hpp"

namespace bounce::api::detail {

/// The inputs of one command, split into their groups and bound to their specs.
struct Bound {
  std::string model;  ///< the model's keyword (commands that take a model) or the law's (contact)
  Parameters pair, model_parameters, own;
};

/// Splits `inputs` among the command's own parameters, the pair's and the model's (or the
/// contact law's), and binds each group. A name none of them takes is refused with a message
/// that says which models, laws or commands do take it.
Bound bind_inputs(const CommandSpec& command, const Inputs& inputs);

/// The case from bound inputs (make_case after bind_inputs; the command's own inputs can be
/// checked in between, before the pair and the model are built).
Case make_case(const Bound& bound, std::optional<double> radius = std::nullopt);

/// The N values of "LO:HI:N" (geometric with `log`), each computed when asked for: a sweep of
/// 1e7 points holds three numbers (docs/cli.md, "Memory").
struct Points {
  double lo = 0.0, hi = 0.0;
  std::size_t n = 0;
  bool log = false;
  std::size_t size() const { return n; }
  double front() const { return lo; }
  double back() const { return hi; }
  double operator[](std::size_t i) const;
};
/// "LO:HI:N" read (N written as a whole number, 1000 or 1e3); errors name `name`.
Points parse_points(const std::string& name, const std::string& text, bool log);
/// "LO:HI:N" as N values (geometric with `log`); errors name `name`.
std::vector<double> parse_range(const std::string& name, const std::string& text, bool log);
/// "LO:HI" with 0 < LO < HI; errors name `name`.
std::array<double, 2> parse_interval(const std::string& name, const std::string& text);

/// "materials" = "A" or "A,B" into material and material2 (given beside it, they are refused).
Inputs with_materials(Inputs inputs);

/// The commands of the front door, in the order `bounce --help` lists them (command_table.cpp).
std::vector<CommandSpec> make_commands();

/// The tangential law's parameters (they need a tangential velocity).
inline constexpr std::array<const char*, 5> tangential_names = {"friction", "asperity", "shear_damping",
                                                                "tangential_law", "asperity_form"};

}  // namespace bounce::api::detail
