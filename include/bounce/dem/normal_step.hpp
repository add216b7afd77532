#pragma once
// The normal sub-model's step: a force law's (with its end rule) or a crack law's (krijt). It
// decides whether the contact holds, and its normal force, which the other sub-models are given.

#include "bounce/dem/state.hpp"
#include "bounce/dem/step_types.hpp"

namespace bounce::dem {

struct NormalStep {
  bool holds = false;     ///< the contact holds at the step's end (else its state is to be reset)
  double force = 0.0;     ///< the normal force now [N]
  double previous = 0.0;  ///< the last step's (the force now where the contact formed in this step)
};

/// Steps the normal law of a contact that exists (overlap > the law's snap overlap, or touching and
/// not beyond its release overlap) or has just ended inside this step: writes the normal force, the
/// step check and a crack law's energies into `out`; updates `touching` and the states.
NormalStep normal_step(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                       const StepSettings& s, bool& touching, NormalState& normal, CrackStepState& crack,
                       ContactForce& out);

}  // namespace bounce::dem
