#pragma once
// The two bodies as parameters: what every front end takes to build a Pair (materials
// from the table with overrides, radii, walls), declared once.
//
// Body 1: material, E, nu, density, gamma, radius, inertia; body 2 the same names with a
// trailing 2 (each defaults to body 1's); wall or rigid_wall make body 2 a flat wall;
// materials_file replaces the built-in table.

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "bounce/core/parameters.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce {

/// The specs of the pair's parameters.
std::span<const ParameterSpec> pair_parameters();

/// The pair they describe. With `radius`, body 1 has that radius (and body 2 too unless
/// radius2 or a wall says otherwise): the sweeps over radii. Errors name the parameters
/// ("E2", "radius", "material2").
Pair make_pair(const Parameters& parameters, std::optional<double> radius = std::nullopt);

/// A library field name of the pair ("body2.E", "body1.inertia_factor") as the parameter
/// the user gave ("E2", "inertia"); other names unchanged.
std::string pair_parameter_name(std::string_view field);

}  // namespace bounce
