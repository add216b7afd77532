#pragma once
// Private: the factory of each model of the checked-in registry table (registry.cpp), one
// per file (src/models/<model>.cpp).

#include "bounce/core/parameters.hpp"
#include "bounce/models/contact_law.hpp"
#include "bounce/models/model.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::models {

Model make_hertz(const Pair& pair, const Parameters& p);                  // viscoelastic.cpp
Model make_viscoelastic(const Pair& pair, const Parameters& p);           // viscoelastic.cpp
Model make_viscoelastic_shifted(const Pair& pair, const Parameters& p);   // viscoelastic_shifted.cpp
Model make_power_law(const Pair& pair, const Parameters& p);              // power_law.cpp
Model make_adhesive_viscoelastic(const Pair& pair, const Parameters& p);  // adhesive_viscoelastic.cpp
Model make_jkr_viscoelastic(const Pair& pair, const Parameters& p);       // krijt.cpp
Model make_krijt(const Pair& pair, const Parameters& p);                  // krijt.cpp
Model make_maugis_viscoelastic(const Pair& pair, const Parameters& p);    // maugis_viscoelastic.cpp

// The same models as DEM contact laws (contact_law.hpp), in the same files; krijt has none yet.
std::shared_ptr<const ContactLaw> hertz_contact(const Pair& pair, const Parameters& p);
std::shared_ptr<const ContactLaw> viscoelastic_contact(const Pair& pair, const Parameters& p);
std::shared_ptr<const ContactLaw> viscoelastic_shifted_contact(const Pair& pair, const Parameters& p);
std::shared_ptr<const ContactLaw> power_law_contact(const Pair& pair, const Parameters& p);
std::shared_ptr<const ContactLaw> adhesive_viscoelastic_contact(const Pair& pair, const Parameters& p);
std::shared_ptr<const ContactLaw> jkr_viscoelastic_contact(const Pair& pair, const Parameters& p);
std::shared_ptr<const CrackContactLaw> krijt_crack_law(const Pair& pair, const Parameters& p);
std::shared_ptr<const ContactLaw> maugis_viscoelastic_contact(const Pair& pair, const Parameters& p);

}  // namespace bounce::models
