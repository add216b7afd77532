#include "bounce/contact/jkr.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <boost/math/tools/roots.hpp>

#include "bounce/contact/independent.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"

namespace bounce::contact::jkr {

namespace {
constexpr double pi = std::numbers::pi;
}

double overlap(const Parameters& p, double a) {  // K13 (8)
  return a * a / p.effective_radius -
         std::sqrt(2.0 * pi * p.surface_energy * a / p.effective_modulus);
}

double force(const Parameters& p, double a) {  // K13 (9)
  return 4.0 * p.effective_modulus * a * a * a / (3.0 * p.effective_radius) -
         std::sqrt(8.0 * pi * p.surface_energy * p.effective_modulus * a * a * a);
}

double equilibrium_contact_radius(const Parameters& p) {  // K13 (10)
  return std::cbrt(9.0 * pi * p.surface_energy * p.effective_radius * p.effective_radius /
                   (2.0 * p.effective_modulus));
}

double pull_off_force(const Parameters& p) {  // K13 after (10)
  return -1.5 * pi * p.surface_energy * p.effective_radius;
}

double pull_off_contact_radius(const Parameters& p) {  // dF/da = 0; BP04 (8.52)
  return equilibrium_contact_radius(p) / std::cbrt(4.0);
}

double separation_contact_radius(const Parameters& p) {  // d delta / da = 0 in K13 (8)
  return equilibrium_contact_radius(p) / std::cbrt(36.0);
}

double separation_overlap(const Parameters& p) {
  return overlap(p, separation_contact_radius(p));
}

double pull_off_overlap(const Parameters& p) { return overlap(p, pull_off_contact_radius(p)); }  // K13 (8)

double contact_radius_from_force(const Parameters& p, double f) {  // BP04 (8.47), K13 notation
  const double R = p.effective_radius;
  const double adhesion = 3.0 * pi * p.surface_energy * R;
  const double discriminant = 2.0 * adhesion * f + adhesion * adhesion;  // 6 pi gamma R F + (3 pi gamma R)^2
  return std::cbrt(3.0 * R / (4.0 * p.effective_modulus) *
                   (f + adhesion + std::sqrt(std::max(discriminant, 0.0))));
}

double contact_radius_from_overlap(const Parameters& p, double delta) {
  // K13 (8) is delta(a) = a^2/R - c sqrt(a): decreasing below a_sep, increasing above.
  // The displacement-stable branch is a >= a_sep, where the root is unique.
  const double a_sep = separation_contact_radius(p);
  if (p.surface_energy == 0.0) return delta > 0.0 ? std::sqrt(p.effective_radius * delta) : 0.0;
  auto residual = [&](double a) { return overlap(p, a) - delta; };
  double lo = a_sep;
  double hi = std::max(2.0 * a_sep, std::sqrt(p.effective_radius * std::abs(delta)));
  while (residual(hi) < 0.0) hi *= 2.0;
  if (residual(lo) >= 0.0) return lo;
  std::uintmax_t iterations = 200;
  auto [x0, x1] = boost::math::tools::toms748_solve(residual, lo, hi,
                                                    boost::math::tools::eps_tolerance<double>(50),
                                                    iterations);
  return 0.5 * (x0 + x1);
}

DisplacementBranch::DisplacementBranch(const Parameters& p)
    : r_(p.effective_radius), c_(std::sqrt(2.0 * pi * p.surface_energy / p.effective_modulus)),
      u_fold_(std::cbrt(c_ * r_ / 4.0)) {}

double DisplacementBranch::radius(double delta) const {  // K13 (8) in u = sqrt(a)
  const double cr = c_ * r_;
  auto h = [&](double u) { return u * u * u * u - cr * u - r_ * delta; };
  double u = std::max(2.0 * u_fold_, std::sqrt(std::sqrt(std::max(2.0 * r_ * delta, 0.0))));
  while (h(u) < 0.0) u *= 2.0;
  for (int i = 0; i < 60; ++i) {
    const double step = h(u) / (4.0 * u * u * u - cr);
    u -= step;
    if (u <= u_fold_) {
      u = u_fold_;
      break;
    }
    if (std::abs(step) <= 1e-16 * u) break;
  }
  return u * u;
}

double total_energy(const Parameters& p, double a) {  // K13 (3) + (6)
  const independent::Geometry g{p.effective_radius, p.effective_modulus};
  return independent::elastic_energy(g, a, overlap(p, a)) +
         independent::surface_energy(a, p.surface_energy);
}

double snap_on_contact_radius(const Parameters& p) {  // K13 (8) at delta = 0
  return std::cbrt(2.0 * pi * p.surface_energy * p.effective_radius * p.effective_radius /
                   p.effective_modulus);
}

namespace bp04 {

double boussinesq_force(double d, double gamma, double a) {  // BP04 (8.46)
  return -2.0 * pi * a * a * std::sqrt(3.0 * gamma / (2.0 * pi * d * a));
}

double contact_radius(double d, double gamma, double R, double f) {  // BP04 (8.47)
  const double adhesion = 1.5 * pi * gamma * R;
  return std::cbrt(0.5 * d * R *
                   (f + adhesion + std::sqrt(std::max(3.0 * pi * gamma * R * f + adhesion * adhesion,
                                                      0.0))));
}

double compression(double d, double gamma, double R, double a) {  // BP04 (8.48)
  return 2.0 * a * a / R - std::sqrt(8.0 * pi * gamma * d * a / 3.0);
}

double force(double d, double gamma, double R, double a) {  // BP04 (8.49)
  return 2.0 * a * a * a / (d * R) - std::sqrt(6.0 * pi * gamma / d) * std::pow(a, 1.5);
}

double zero_load_contact_radius(double d, double gamma, double R) {  // BP04 (8.50)
  return std::cbrt(1.5 * d * pi * gamma * R * R);
}

double separation_force(double gamma, double R) {  // BP04 (8.51)
  return -0.75 * pi * gamma * R;
}

double separation_contact_radius(double d, double gamma, double R) {  // BP04 (8.52)
  return std::cbrt(0.375 * d * pi * gamma * R * R);
}

}  // namespace bp04

}  // namespace bounce::contact::jkr

// --- the "jkr" contact law -------------------------------------------------------

namespace bounce::contact {
namespace {

class JkrLaw final : public ContactLaw {
 public:
  explicit JkrLaw(const Pair& pair)
      : p_{pair.effective_radius(), pair.effective_modulus(), pair.require_surface_energy("law jkr")} {}

  std::string_view name() const override { return "jkr"; }

  ContactPoint at_force(double force) const override {
    const double f_c = jkr::pull_off_force(p_);
    require_at_least("force", force, f_c, "force >= the JKR pull-off force ", " N");
    const double a = jkr::contact_radius_from_force(p_, force);
    return {a, jkr::overlap(p_, a), force};
  }

  ContactPoint at_overlap(double overlap) const override {
    const double delta_c = jkr::separation_overlap(p_);
    require_at_least("overlap", overlap, delta_c,
                     "overlap >= ", " m (JKR contact breaks at more negative overlap)");
    const double a = jkr::contact_radius_from_overlap(p_, overlap);
    return {a, overlap, jkr::force(p_, a)};
  }

  ContactPoint at_contact_radius(double a) const override {
    require_non_negative("contact_radius", a, "contact radius [m]");
    return {a, jkr::overlap(p_, a), jkr::force(p_, a)};
  }

  std::optional<AdhesionSummary> adhesion() const override {
    AdhesionSummary s;
    s.pull_off_force = jkr::pull_off_force(p_);
    s.pull_off_contact_radius = jkr::pull_off_contact_radius(p_);
    s.zero_load_contact_radius = jkr::equilibrium_contact_radius(p_);
    s.zero_load_overlap = jkr::overlap(p_, s.zero_load_contact_radius);
    s.separation_contact_radius = jkr::separation_contact_radius(p_);
    s.separation_overlap = jkr::overlap(p_, s.separation_contact_radius);
    return s;
  }

 private:
  jkr::Parameters p_;
};

}  // namespace

std::unique_ptr<ContactLaw> make_jkr_law(const Pair& pair) { return std::make_unique<JkrLaw>(pair); }

}  // namespace bounce::contact
