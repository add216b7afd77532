#include "bounce/contact/dmt.hpp"

#include <cmath>
#include <numbers>

#include "bounce/contact/hertz.hpp"
#include "bounce/contact/law.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/pair/mixing.hpp"

namespace bounce::contact::dmt {

double pull_off_force(const Parameters& p) {  // BP04 after (8.52)
  return -2.0 * std::numbers::pi * p.surface_energy * p.effective_radius;
}

double force(const Parameters& p, double overlap) {
  return hertz::force(hertz_constant(p.effective_modulus, p.effective_radius), overlap) +
         pull_off_force(p);
}

double overlap_from_force(const Parameters& p, double f) {
  return hertz::overlap_from_force(hertz_constant(p.effective_modulus, p.effective_radius),
                                   f - pull_off_force(p));
}

double contact_radius(const Parameters& p, double overlap) {
  return hertz::contact_radius(p.effective_radius, overlap);
}

}  // namespace bounce::contact::dmt

// --- the "dmt" contact law -------------------------------------------------------

namespace bounce::contact {
namespace {

class DmtLaw final : public ContactLaw {
 public:
  explicit DmtLaw(const Pair& pair)
      : p_{pair.effective_radius(), pair.effective_modulus(), pair.require_surface_energy("law dmt")} {}

  std::string_view name() const override { return "dmt"; }

  ContactPoint at_force(double force) const override {
    const double f_c = dmt::pull_off_force(p_);
    require_at_least("force", force, f_c, "force >= the DMT pull-off force ", " N");
    const double overlap = dmt::overlap_from_force(p_, force);
    return {dmt::contact_radius(p_, overlap), overlap, force};
  }

  ContactPoint at_overlap(double overlap) const override {
    require_at_least("overlap", overlap, 0.0, "overlap >= ", " m (DMT keeps the Hertz geometry)");
    return {dmt::contact_radius(p_, overlap), overlap, dmt::force(p_, overlap)};
  }

  ContactPoint at_contact_radius(double a) const override {
    require_non_negative("contact_radius", a, "contact radius [m]");
    const double overlap = a * a / p_.effective_radius;
    return {a, overlap, dmt::force(p_, overlap)};
  }

  std::optional<AdhesionSummary> adhesion() const override {
    AdhesionSummary s;
    s.pull_off_force = dmt::pull_off_force(p_);
    s.pull_off_contact_radius = 0.0;
    s.zero_load_overlap = dmt::overlap_from_force(p_, 0.0);
    s.zero_load_contact_radius = dmt::contact_radius(p_, s.zero_load_overlap);
    s.separation_overlap = 0.0;
    s.separation_contact_radius = 0.0;
    return s;
  }

 private:
  dmt::Parameters p_;
};

}  // namespace

std::unique_ptr<ContactLaw> make_dmt_law(const Pair& pair) { return std::make_unique<DmtLaw>(pair); }

}  // namespace bounce::contact
