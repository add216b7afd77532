#include "bounce/pair/pair.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/mixing.hpp"

namespace bounce {

namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();

void validate_body(const Body& body, const std::string& label, bool may_be_wall) {
  validate(body.material, [&](std::string_view field) { return label + "." + std::string(field); });
  if (body.is_wall()) {
    if (!may_be_wall) {
      throw InvalidArgument(label + ".radius", "inf", "a finite radius > 0 m (body 1 is a sphere)");
    }
  } else {
    require_positive(label + ".radius", body.radius, "radius [m]");
    if (body.rigid) {
      throw InvalidArgument(label + ".rigid", "true", "rigid only for a wall");
    }
    require_positive(label + ".inertia_factor", body.inertia_factor,
                     "moment of inertia factor J/(m R^2)");
    // (4/3) pi R^3 rho must be a normal double: R = 1e308 gave an infinite mass and a NaN
    // R_eff, R = 1e-300 a zero mass.
    if (!std::isnormal(body.mass())) {
      throw InvalidArgument(label + ".radius", format_value(body.radius),
                            fmt::format("a radius whose mass (4/3) pi R^3 rho (rho = {:g} kg/m^3) is finite and > 0 in "
                                        "double precision",
                                        body.material.density));
    }
  }
}

// A derived property of the pair must be a normal double (no overflow to inf, no underflow
// to 0): otherwise every result would be NaN or infinite.
void require_normal(double value, const char* parameter, double given, const char* what) {
  if (!std::isnormal(value)) {
    throw InvalidArgument(parameter, format_value(given),
                          fmt::format("values whose {} is finite and > 0 in double precision (it is {})", what,
                                      format_value(value)));
  }
}
}  // namespace

bool Body::is_wall() const { return std::isinf(radius) && radius > 0; }

double Body::mass() const {
  return is_wall() ? infinity : sphere_mass(radius, material.density);
}

Body sphere(Material material, double radius) {
  return Body{std::move(material), radius, false, 0.4};
}

Body wall(Material material) { return Body{std::move(material), infinity, false, 0.4}; }

Body rigid_wall(Material material) { return Body{std::move(material), infinity, true, 0.4}; }

Pair::Pair(Body body1, Body body2) : body1_(std::move(body1)), body2_(std::move(body2)) {
  validate_body(body1_, "body1", false);
  validate_body(body2_, "body2", true);
  effective_radius_ = bounce::effective_radius(body1_.radius, body2_.radius);
  effective_mass_ = bounce::effective_mass(body1_.mass(), body2_.mass());
  const double youngs2 = body2_.rigid ? infinity : body2_.material.youngs_modulus;
  effective_modulus_ = bounce::effective_modulus(body1_.material.youngs_modulus,
                                                 body1_.material.poisson_ratio, youngs2,
                                                 body2_.material.poisson_ratio);
  kappa_ = bounce::tangential_mass_factor(body1_.mass(), body1_.inertia_factor, body2_.mass(),
                                          body2_.inertia_factor);
  if (body1_.material.surface_energy && body2_.material.surface_energy) {
    surface_energy_ = combined_surface_energy(*body1_.material.surface_energy,
                                              *body2_.material.surface_energy);
  }
  require_normal(effective_radius_, "body1.radius", body1_.radius, "effective radius R1 R2/(R1 + R2)");
  require_normal(effective_modulus_, "body1.youngs_modulus", body1_.material.youngs_modulus, "effective modulus E*");
  require_normal(effective_mass_, "body1.radius", body1_.radius, "effective mass m1 m2/(m1 + m2)");
}

Pair Pair::identical(Material material, double radius) {
  Body b = sphere(std::move(material), radius);
  return Pair(b, b);
}

double Pair::hertz_compliance_d() const noexcept {
  return bounce::hertz_compliance_d(effective_modulus_);
}

double Pair::hertz_constant() const noexcept {
  return bounce::hertz_constant(effective_modulus_, effective_radius_);
}

double Pair::transversal_sound_speed() const {
  auto of = [](const Material& m) {
    return bounce::transversal_sound_speed(m.youngs_modulus, m.poisson_ratio, m.density);
  };
  const double c1 = of(body1_.material);
  return body2_.rigid ? c1 : std::min(c1, of(body2_.material));
}

double Pair::require_surface_energy(const std::string& law) const {
  if (surface_energy_) return *surface_energy_;
  const Material& lacking =
      body1_.material.surface_energy ? body2_.material : body1_.material;
  std::string detail;
  if (lacking.surface_energy_range) {
    detail = fmt::format("; material '{}' only has the range {}-{} J/m^2",
                         lacking.name, (*lacking.surface_energy_range)[0],
                         (*lacking.surface_energy_range)[1]);
  } else if (!lacking.name.empty()) {
    detail = fmt::format("; material '{}' has none", lacking.name);
  }
  throw InvalidArgument("gamma", "(not given)",
                        fmt::format("a surface energy >= 0 J/m^2 ({} needs one{})", law, detail));
}

}  // namespace bounce
