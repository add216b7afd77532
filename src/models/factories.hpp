#pragma once
// Private: the factories of each model of the checked-in registry table (registry.cpp), one
// file per model's physics (src/models/<model>.cpp). Each takes the model's parameter struct
// (model_parameters.hpp, read by its field table, its rules checked) and the context every
// model has, and makes the model's physics: its normal interaction, whose kind is its engine,
// with the same law for DEM contacts.

#include "bounce/models/model.hpp"
#include "bounce/models/model_parameters.hpp"
#include "bounce/pair/pair.hpp"
#include "catalogue.hpp"

namespace bounce::models {

using catalogue::NoParameters;
using Context = ModelContext;

// viscoelastic.cpp
Made<ForceLaw> make_hertz(const Pair& pair, const NoParameters& p, const Context& c);
Made<ForceLaw> make_viscoelastic(const Pair& pair, const ViscousParameters& p, const Context& c);
// viscoelastic_shifted.cpp
Made<ForceLaw> make_viscoelastic_shifted(const Pair& pair, const ViscousParameters& p, const Context& c);
// power_law.cpp
Made<ForceLaw> make_power_law(const Pair& pair, const PowerLawParameters& p, const Context& c);
// adhesive_viscoelastic.cpp
Made<ForceLaw> make_adhesive_viscoelastic(const Pair& pair, const AdhesiveViscousParameters& p, const Context& c);
// krijt.cpp
Made<AdhesiveContact> make_jkr_viscoelastic(const Pair& pair, const ContactModelParameters& p, const Context& c);
Made<CrackContact> make_krijt(const Pair& pair, const CrackModelParameters& p, const Context& c);
// maugis_viscoelastic.cpp
Made<AdhesiveContact> make_maugis_viscoelastic(const Pair& pair, const ContactModelParameters& p, const Context& c);

}  // namespace bounce::models
