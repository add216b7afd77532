#pragma once
// Private: the factories of each model of the checked-in registry table (registry.cpp), one
// file per model's physics (src/models/<model>.cpp). Each takes the model's parameter struct
// (model_parameters.hpp, read by its field table) and the context every model has.

#include "bounce/models/contact_law.hpp"
#include "bounce/models/model.hpp"
#include "bounce/models/model_parameters.hpp"
#include "bounce/pair/pair.hpp"
#include "catalogue.hpp"

namespace bounce::models {

using catalogue::NoParameters;
using Context = ModelContext;

// viscoelastic.cpp
Model make_hertz(const Pair& pair, const NoParameters& p, const Context& c);
std::shared_ptr<const ContactLaw> hertz_contact(const Pair& pair, const NoParameters& p, const Context& c);
Model make_viscoelastic(const Pair& pair, const ViscousParameters& p, const Context& c);
std::shared_ptr<const ContactLaw> viscoelastic_contact(const Pair& pair, const ViscousParameters& p, const Context& c);
// viscoelastic_shifted.cpp
Model make_viscoelastic_shifted(const Pair& pair, const ViscousParameters& p, const Context& c);
std::shared_ptr<const ContactLaw> viscoelastic_shifted_contact(const Pair& pair, const ViscousParameters& p,
                                                               const Context& c);
// power_law.cpp
Model make_power_law(const Pair& pair, const PowerLawParameters& p, const Context& c);
std::shared_ptr<const ContactLaw> power_law_contact(const Pair& pair, const PowerLawParameters& p, const Context& c);
// adhesive_viscoelastic.cpp
Model make_adhesive_viscoelastic(const Pair& pair, const AdhesiveViscousParameters& p, const Context& c);
std::shared_ptr<const ContactLaw> adhesive_viscoelastic_contact(const Pair& pair, const AdhesiveViscousParameters& p,
                                                                const Context& c);
// krijt.cpp
Model make_jkr_viscoelastic(const Pair& pair, const ContactModelParameters& p, const Context& c);
std::shared_ptr<const ContactLaw> jkr_viscoelastic_contact(const Pair& pair, const ContactModelParameters& p,
                                                           const Context& c);
Model make_krijt(const Pair& pair, const CrackModelParameters& p, const Context& c);
std::shared_ptr<const CrackContactLaw> krijt_crack_law(const Pair& pair, const CrackModelParameters& p, const Context& c);
// maugis_viscoelastic.cpp
Model make_maugis_viscoelastic(const Pair& pair, const ContactModelParameters& p, const Context& c);
std::shared_ptr<const ContactLaw> maugis_viscoelastic_contact(const Pair& pair, const ContactModelParameters& p,
                                                              const Context& c);

}  // namespace bounce::models
