// lammps/type_laws: pair_style bounce's coefficients as a restart file keeps them, without
// LAMMPS. Since issue 40 the asperity law's default form is passive; a restart written before
// it names no form and its contacts' springs hold the published form's extension, so such a
// file keeps the published form (docs/lammps.md, Restarts).
#include <gtest/gtest.h>

#include "type_laws.h"

namespace bounce::lammps {
namespace {

const Coeffs rough{{"model", "viscoelastic"}, {"material", "ice-bshp96"}, {"A", "1e-6"},
                   {"friction", "0.3"},       {"asperity", "1e-6"}};

models::AsperityForm form_of(const TypeLaw& t) { return t.law.tangential.value().form; }

// A pair_coeff naming no form takes the default, passive, and its text for a restart names it.
TEST(TypeLaws, RestartTextNamesTheAsperityForm) {
  const auto law = make_type_law(rough);
  EXPECT_EQ(form_of(*law), models::AsperityForm::passive);
  EXPECT_EQ(law->coeffs.at("asperity_form"), "passive");
  EXPECT_EQ(from_text(to_text(law->coeffs)), law->coeffs);
  Coeffs published = rough;
  published["asperity_form"] = "published";
  EXPECT_EQ(make_type_law(published)->coeffs, published);  // as typed
  Coeffs smooth = rough;
  smooth.erase("friction");
  smooth.erase("asperity");
  EXPECT_EQ(make_type_law(smooth)->coeffs, smooth);  // no tangential law: no form
  Coeffs step = smooth;
  step.insert({{"friction", "0.3"}, {"tangential_law", "step"}, {"shear_damping", "100"}});
  EXPECT_EQ(make_type_law(step)->coeffs, step);  // the step law has no asperity form
}

// Read back: a text naming no form (written before issue 40) keeps the published form; one
// naming a form, or using no asperity law, is read as written.
TEST(TypeLaws, OldRestartKeepsThePublishedForm) {
  bool kept = false;
  const auto old = restart_type_law(rough, kept);
  EXPECT_TRUE(kept);
  EXPECT_EQ(form_of(*old), models::AsperityForm::published);
  EXPECT_EQ(old->coeffs.at("asperity_form"), "published");
  const auto again = restart_type_law(from_text(to_text(make_type_law(rough)->coeffs)), kept);
  EXPECT_FALSE(kept);
  EXPECT_EQ(form_of(*again), models::AsperityForm::passive);
  Coeffs step = rough;
  step.erase("asperity");
  step.insert({{"tangential_law", "step"}, {"shear_damping", "100"}});
  EXPECT_FALSE(restart_type_law(step, kept)->coeffs.count("asperity_form"));
  EXPECT_FALSE(kept);
  Coeffs smooth = rough;
  smooth.erase("friction");
  smooth.erase("asperity");
  EXPECT_FALSE(restart_type_law(smooth, kept)->law.tangential);
  EXPECT_FALSE(kept);
}

// Two types mix where their model keys agree, the named default included; a form named on one
// type and not the other is a difference only where they are not the same form.
TEST(TypeLaws, MixingSeesTheNamedForm) {
  Coeffs steel = rough;
  steel["material"] = "steel";
  Coeffs passive = steel;
  passive["asperity_form"] = "passive";
  const auto mixed = mix(*make_type_law(rough), *make_type_law(passive), 1, 2);
  EXPECT_EQ(form_of(*mixed), models::AsperityForm::passive);
  Coeffs published = steel;
  published["asperity_form"] = "published";
  EXPECT_THROW(mix(*make_type_law(rough), *make_type_law(published), 1, 2), CannotMix);
}

}  // namespace
}  // namespace bounce::lammps
