#pragma once
// Private: what the two adhesive engines (krijt_collision.cpp, jkr_viscoelastic_collision.cpp)
// share: how a collision ends, in energy and outcome.

#include <string>

#include <fmt/format.h>

#include "bounce/dynamics/outcome.hpp"
#include "bounce/models/krijt.hpp"
#include "krijt_system.hpp"

namespace bounce::dynamics::detail {

inline constexpr const char* before_max_compression_note =
    "sticking was certain before the maximum compression, which max_overlap (null) therefore does not give "
    "(--follow integrates the settling)";

/// What a followed sticking collision says about its end (`--follow T`): it ran to T, or,
/// when the outcome was still open at T, on until sticking became certain.
inline std::string followed_note(double follow_time, double end) {
  if (end <= follow_time * (1.0 + 1e-9)) {
    return fmt::format("followed until {:.6g} s without breaking off: integrated_time is that end", end);
  }
  return fmt::format("the outcome was still open at the followed time {:.6g} s: integrated on until sticking "
                     "became certain at {:.6g} s (integrated_time)", follow_time, end);
}

/// The end of an adhesive collision at scaled rate v = delta'/g with the contact's elastic and
/// surface energies U_E and U_S there (the bulk and crack dissipation already in out.energy). A
/// break releases what U_E + U_S held (K13's run-away to a = 0, or the jump off an adhesive
/// branch, is instantaneous, K13 (C.2)): e = -v; sticking grains keep U_E and U_S.
inline void finish_adhesive(CollisionOutcome& out, const Scales& s, double v, double elastic, double surface,
                            bool bounced) {
  EnergyBudget& e = out.energy;
  e.initial_kinetic = s.energy;
  e.final_kinetic = s.energy * v * v;  // for sticking: the kinetic energy where the integration stopped
  if (bounced) {
    out.outcome = Outcome::bounce;
    out.cor = -v;
    e.crack_dissipated += elastic + surface;
  } else {
    out.outcome = Outcome::stick;
    out.cor = 0.0;
    e.elastic_remaining = elastic;
    e.surface_remaining = surface;
  }
  e.close();
}

}  // namespace bounce::dynamics::detail
