#pragma once
// Private: the factory of each model of the checked-in registry table (registry.cpp), one
// per file (src/models/<model>.cpp).

#include "bounce/core/parameters.hpp"
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

}  // namespace bounce::models
