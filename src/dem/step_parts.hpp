#pragma once
// The crack law's normal step (crack_step.cpp), which normal_step (normal_step.cpp) hands a crack
// law's contact to.

#include "bounce/dem/normal_step.hpp"

namespace bounce::dem::detail {

NormalStep crack_step(const models::DemModel& law, const models::ContactGeometry& g, const Kinematics& k,
                      const StepSettings& s, bool& touching, NormalState& normal, CrackStepState& crack,
                      ContactForce& out);

}  // namespace bounce::dem::detail
