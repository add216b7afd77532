#include "bounce/contact/hertz.hpp"

#include <cmath>
#include <numbers>

#include "bounce/contact/law.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::contact::hertz {

double force(double hertz_constant, double overlap) {  // BP04 (8.24)
  return overlap > 0.0 ? hertz_constant * overlap * std::sqrt(overlap) : 0.0;
}

double overlap_from_force(double hertz_constant, double force) {  // BP04 (8.24) inverted
  return std::cbrt((force / hertz_constant) * (force / hertz_constant));
}

double contact_radius(double effective_radius, double overlap) {  // BP04 (8.23), K13 (4)
  return overlap > 0.0 ? std::sqrt(effective_radius * overlap) : 0.0;
}

double force_from_contact_radius(double effective_modulus, double effective_radius,
                                 double contact_radius) {  // K13 (5)
  return 4.0 * effective_modulus * contact_radius * contact_radius * contact_radius /
         (3.0 * effective_radius);
}

double elastic_energy(double hertz_constant, double overlap) {  // integral of BP04 (8.24)
  return overlap > 0.0 ? 0.4 * hertz_constant * overlap * overlap * std::sqrt(overlap) : 0.0;
}

double max_pressure(double force, double contact_radius) {  // BP04 (8.10) at the centre
  return 3.0 * force / (2.0 * std::numbers::pi * contact_radius * contact_radius);
}

double reference_overlap(double hertz_constant, double effective_mass, double speed) {  // BP04 (8.65)
  return std::pow(1.25 * effective_mass * speed * speed / hertz_constant, 0.4);
}

double scaled_collision_time() {  // 2 int_0^1 (1 - x^{5/2})^{-1/2} dx, a Beta function
  static const double t = 0.8 * std::sqrt(std::numbers::pi) * std::tgamma(0.4) / std::tgamma(0.9);
  return t;
}

double collision_time(double hertz_constant, double effective_mass, double speed) {  // BSHP96 (A13), exact
  return scaled_collision_time() * std::pow(1.25 * effective_mass / hertz_constant, 0.4) * std::pow(speed, -0.2);
}

}  // namespace bounce::contact::hertz

// --- the "hertz" contact law -----------------------------------------------------

namespace bounce::contact {
namespace {

class HertzLaw final : public ContactLaw {
 public:
  explicit HertzLaw(const Pair& pair)
      : radius_(pair.effective_radius()),
        modulus_(pair.effective_modulus()),
        rho_(pair.hertz_constant()) {}

  std::string_view name() const override { return "hertz"; }

  ContactPoint at_force(double force) const override {
    require_at_least("force", force, 0.0, "force >= ", " N (hertz has no adhesion)");
    const double overlap = hertz::overlap_from_force(rho_, force);
    return {hertz::contact_radius(radius_, overlap), overlap, force};
  }

  ContactPoint at_overlap(double overlap) const override {
    require_at_least("overlap", overlap, 0.0, "overlap >= ", " m (hertz spheres touch only for overlap >= 0)");
    return {hertz::contact_radius(radius_, overlap), overlap, hertz::force(rho_, overlap)};
  }

  ContactPoint at_contact_radius(double a) const override {
    require_non_negative("contact_radius", a, "contact radius [m]");
    return {a, a * a / radius_, hertz::force_from_contact_radius(modulus_, radius_, a)};
  }

  std::optional<AdhesionSummary> adhesion() const override { return std::nullopt; }

 private:
  double radius_;
  double modulus_;
  double rho_;
};

}  // namespace

std::unique_ptr<ContactLaw> make_hertz_law(const Pair& pair) {
  return std::make_unique<HertzLaw>(pair);
}

}  // namespace bounce::contact
