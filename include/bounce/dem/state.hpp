#pragma once
// The normal law's per-contact state, typed (docs/architecture.md, The DEM layer). Every
// sub-model's State is a struct with named fields that declares its size in doubles, how it is
// written to and read from a flat array (LAMMPS's per-contact history, restart files), how it looks
// from the other body, and which laws use it.

#include "bounce/models/dem_law.hpp"

namespace bounce::dem {

/// The normal law's memory: its last force (the corrected rate's predictor, the released
/// contact's impulse) and the overlap at which the time step was last checked (step_check.hpp).
struct NormalState {
  static constexpr int size = 2;
  double last_force = 0.0;       ///< [N], positive: repulsive
  double checked_overlap = 0.0;  ///< [m] (0: not checked yet)
  static bool used_by(const models::DemModel&) { return true; }
  void write(double* out) const { out[0] = last_force, out[1] = checked_overlap; }
  static NormalState read(const double* in) { return {in[0], in[1]}; }
  NormalState reversed() const { return *this; }
};

/// A crack law's contact (krijt): the crack's own state and what the step's energy bookkeeping
/// needs of the step before.
struct CrackStepState {
  static constexpr int size = 8;
  models::CrackState crack;      ///< a, and its earlier values for the second-order update
  double lent_force = 0.0;       ///< the displacement the forming step lent, as a force [N]
  double last_bulk_force = 0.0;  ///< D xi' at the last step [N]
  double last_rate = 0.0;        ///< xi' at the last step [m/s]
  double last_stored = 0.0;      ///< elastic + surface energy at the last step [J]
  static bool used_by(const models::DemModel& law) { return law.crack != nullptr; }
  void write(double* out) const {
    out[0] = crack.contact_radius, out[1] = crack.previous_radius, out[2] = crack.previous_step;
    out[3] = crack.older_radius, out[4] = lent_force, out[5] = last_bulk_force, out[6] = last_rate;
    out[7] = last_stored;
  }
  static CrackStepState read(const double* in) {
    return {{in[0], in[1], in[2], in[3]}, in[4], in[5], in[6], in[7]};
  }
  CrackStepState reversed() const { return *this; }
};

}  // namespace bounce::dem
