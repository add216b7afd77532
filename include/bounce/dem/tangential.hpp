#pragma once
// The tangential sub-model: BSHP96's tangential laws on a spring the contact keeps
// (models::tangential_step; docs/tangential.md).

#include <array>

#include "bounce/dem/step_types.hpp"

namespace bounce::dem {

struct Tangential {
  /// The spring, in the tangent plane: its extension s [m] (published asperity form) or sqrt(k) s
  /// [N^1/2 m^1/2] (passive form).
  struct State {
    static constexpr int size = 3;
    std::array<double, 3> spring{};
    void write(double* out) const { out[0] = spring[0], out[1] = spring[1], out[2] = spring[2]; }
    static State read(const double* in) { return {{in[0], in[1], in[2]}}; }
    /// Seen from the other body the sliding is reversed, and so is the spring.
    State reversed() const { return {{-spring[0], -spring[1], -spring[2]}}; }
  };
  /// In every contact's state, with friction or without: pair_style bounce's restart files have
  /// kept these three values for every contact since it was written.
  static bool used_by(const models::DemModel&) { return true; }
  /// The tangential force at the contact point, of the law's friction (none without).
  static void step(const SubContext& c, State& state, ContactForce& out);
};

}  // namespace bounce::dem
