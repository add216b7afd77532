#pragma once
// bounce's DEM contact (docs/architecture.md, The DEM layer): the normal law and the sub-models
// registered below, one row each. A DEM code (LAMMPS's pair_style bounce and fix wall/bounce) maps
// its atoms onto Motion and its per-contact history onto a ContactState through a Layout, and
// calls step().

#include "bounce/dem/composition.hpp"
#include "bounce/dem/resistance.hpp"
#include "bounce/dem/tangential.hpp"

namespace bounce::dem {

/// The registration: a sub-model is added by its file and a row here. Its place in the list is
/// its state's place in the flat history, before the normal law's.
using Contact = Composition<Tangential, Resistance>;

using ContactState = Contact::State;
using Layout = Contact::Layout;

/// One step of a contact that exists or has just ended (Composition::step).
inline ContactForce step(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                         const StepSettings& s, ContactState& state) {
  return Contact::step(law, g, k, s, state);
}

}  // namespace bounce::dem
