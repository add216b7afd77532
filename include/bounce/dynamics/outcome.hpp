#pragma once
// What a collision produces: restitution, outcome, times, energy budget and,
// on request, the trajectory. SI units.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace bounce::dynamics {

enum class Outcome { bounce, stick };
std::string_view to_string(Outcome outcome);

/// Where the initial kinetic energy went [J]. initial_kinetic = final_kinetic +
/// bulk_dissipated + crack_dissipated + plastic_dissipated + elastic_remaining +
/// surface_remaining up to the integration error (closure_error).
struct EnergyBudget {
  double initial_kinetic = 0.0;     ///< (1/2) m_eff g^2
  double final_kinetic = 0.0;       ///< (1/2) m_eff (e g)^2 after separation; sticking: the relative
                                    ///< kinetic energy where the integration stopped (kinetic_at_stop)
  double bulk_dissipated = 0.0;     ///< work of the bulk viscous force, K13 (C.3)
  double crack_dissipated = 0.0;    ///< work at the crack tip, K13 (C.2)
  double plastic_dissipated = 0.0;  ///< plastic loss (added when --yield is given)
  double elastic_remaining = 0.0;   ///< elastic energy still stored when the contact ends
  double surface_remaining = 0.0;   ///< surface energy -pi a^2 gamma (a force law's adhesive part) then
  /// initial minus the sum of the others; where final_kinetic comes from the energy balance
  /// (a contact held on its adhesive branch), the integrated trajectory's kinetic energy at
  /// the release takes its place here
  double closure_error = 0.0;

  /// Sets closure_error: what the other terms leave of the initial kinetic energy (zero up
  /// to the integration error, K13 appendix C).
  void close();
};

/// One sample of the trajectory (SI).
struct TrajectorySample {
  double time = 0.0;               ///< [s]
  double overlap = 0.0;            ///< xi (delta) [m]
  double rate = 0.0;               ///< d xi/dt [m/s]
  double contact_radius = 0.0;     ///< a [m] (Hertz a = sqrt(R xi) for non-adhesive models)
  double elastic_force = 0.0;      ///< conservative part [N]
  double dissipative_force = 0.0;  ///< rate-dependent part [N]
  double effective_surface_energy_ratio = 0.0;  ///< beta = G_eff/gamma (adhesive models)
  double kinetic = 0.0;            ///< U_K [J]
  double elastic = 0.0;            ///< U_E [J]
  double surface = 0.0;            ///< U_S [J]
  double bulk_dissipated = 0.0;    ///< U_BD so far [J]
  double crack_dissipated = 0.0;   ///< U_CD so far [J]
};

/// A trajectory has at most this many rows, whatever the collision's duration and the samples
/// asked for (`--trajectory-points` samples per ~2 contact times, every step of krijt, a
/// `--follow` time): memory stays bounded (docs/cli.md, "Memory"). Beyond it the rows are
/// thinned in time (TrajectoryRecorder), the first and the last kept.
inline constexpr std::size_t max_trajectory_rows = 200000;

/// Collects an engine's trajectory samples into `rows`, at most max_trajectory_rows of them.
/// Until the bound every sample is kept. At the bound the rows are thinned: a least spacing in
/// time between rows (doubled until at most half the rows remain; the first row kept), and from
/// then on a sample closer than it to the last row is dropped. An engine sampling on a grid in
/// time steps it by spacing(), so that a long run (a `--follow` time of hours) costs samples in
/// proportion to the bound, not to its duration.
class TrajectoryRecorder {
 public:
  /// `thinning`: where the least spacing is reported (CollisionOutcome::trajectory_thinning).
  TrajectoryRecorder(std::vector<TrajectorySample>& rows, double& thinning, std::size_t max_rows = max_trajectory_rows);
  /// A sample, dropped if closer than the least spacing to the last row.
  void add(const TrajectorySample& sample);
  /// The last rows of a run (the end state, a release): always kept.
  void add_end(const TrajectorySample& sample);
  /// The step of a sampling grid that asks for `wanted` in units of `time_unit` seconds: at
  /// least the least spacing.
  double step(double wanted, double time_unit = 1.0) const;

 private:
  void thin();
  std::vector<TrajectorySample>* rows_;
  double* thinning_;
  std::size_t max_rows_;
};

/// `rows` thinned as TrajectoryRecorder does, to at most `max_rows` (a trajectory joined from
/// two runs); `thinning` raised to the spacing used.
void limit_trajectory(std::vector<TrajectorySample>& rows, double& thinning, std::size_t max_rows = max_trajectory_rows);

/// The tangential part of an oblique collision (dynamics/tangential.hpp). Energies in
/// J; the tangential kinetic energy is (1/2) m_eff kappa (g^T)^2 (BSHP96 (11)).
struct TangentialOutcome {
  double cor = 1.0;                  ///< eps^T = g^T' / g^T, BSHP96 (2), (38); -1 <= eps^T <= 1 in BSHP96
  double initial_kinetic = 0.0;      ///< (1/2) m_eff kappa (g^T)^2
  double final_kinetic = 0.0;        ///< (1/2) m_eff kappa (eps^T g^T)^2
  double asperity_dissipated = 0.0;  ///< energy of the broken asperities (and the sliding in averaged mode)
  double stored_at_end = 0.0;        ///< elastic energy left in the asperity spring at separation (lost)
  /// final + asperity_dissipated + stored_at_end - initial: energy the asperity spring
  /// gained (> 0) or lost because its stiffness mu F^N / zeta0 followed F^N(t) with the
  /// extension held (the published form); 0 for the passive form and the step law up
  /// to the integration error.
  double stiffness_work = 0.0;
  long breaks = 0;                   ///< asperity breaks resolved one by one
  double averaged_time = 0.0;        ///< time spent with the sawtooth averaged (dense breaking) [s]
  long steps = 0;
};

/// The terms of the budget by name (the keys of the CLI's "energy" JSON and Python's dict).
std::vector<std::pair<std::string, double>> named_values(const EnergyBudget& energy);
/// The tangential energies, eps^T and the averaged time by name (breaks and steps are counts,
/// apart).
std::vector<std::pair<std::string, double>> named_values(const TangentialOutcome& tangential);

struct CollisionOutcome {
  double cor = 0.0;                  ///< coefficient of normal restitution (0 when sticking)
  Outcome outcome = Outcome::bounce;
  double contact_time = 0.0;         ///< [s]; for sticking: the time integrated (when sticking was
                                     ///< certain, or the end of --follow), not a contact time
  double max_overlap = 0.0;          ///< [m]
  double time_of_max_overlap = 0.0;  ///< [s]
  /// Sticking was certain before the maximum compression: max_overlap is the overlap then, not
  /// a maximum (the records give null).
  bool compression_unfinished = false;
  EnergyBudget energy;
  std::vector<TrajectorySample> trajectory;  ///< empty unless requested; at most max_trajectory_rows
  /// The least time between rows of a trajectory that reached max_trajectory_rows and was
  /// thinned [s] (TrajectoryRecorder); 0 when every sample was kept.
  double trajectory_thinning = 0.0;
  std::vector<std::string> warnings;         ///< validity conditions that do not hold
  std::vector<std::string> notes;            ///< how the result was obtained, when not obvious
  std::string method;                        ///< "integrate", "master" or "closed-form"
  long steps = 0;                            ///< integration steps taken (0 for master)
  std::optional<TangentialOutcome> tangential;  ///< with a tangential velocity (and a bounce)
};

}  // namespace bounce::dynamics
