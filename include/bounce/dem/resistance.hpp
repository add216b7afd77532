#pragma once
// The rolling, sliding and twisting sub-model (docs/resistance.md, "In a DEM"): W07's springs on
// two contact pointers, each fixed in its body and turning with it, and on the twist angle, for
// two spheres (a wall contact has none).

#include <array>

#include "bounce/dem/step_types.hpp"

namespace bounce::dem {

struct Resistance {
  struct State {
    static constexpr int size = 7;
    /// Unit vectors from each centre to the contact point, turning with their bodies (zero: not
    /// set yet; set to -n and n where the contact forms).
    std::array<double, 3> pointer1{}, pointer2{};
    double twist = 0.0;  ///< phi = int (omega1 - omega2) . n dt [rad]
    void write(double* out) const {
      for (int d = 0; d < 3; d++) out[d] = pointer1[d], out[3 + d] = pointer2[d];
      out[6] = twist;
    }
    static State read(const double* in) { return {{in[0], in[1], in[2]}, {in[3], in[4], in[5]}, in[6]}; }
    /// Seen from the other body the pointers trade places; n and omega1 - omega2 both turn over,
    /// so the twist stays.
    State reversed() const { return {pointer2, pointer1, twist}; }
  };
  static bool used_by(const models::DemModel& law) { return law.resistance.has_value(); }
  /// The springs' force and torques, after the pointers and the twist have turned with the bodies
  /// over the step and been held at their critical displacements.
  static void step(const SubContext& c, State& state, ContactForce& out);
};

}  // namespace bounce::dem
