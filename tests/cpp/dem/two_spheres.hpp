#pragma once
// Two spheres stepped as LAMMPS steps them with pair_style bounce, without LAMMPS: fix nve/sphere's
// velocity Verlet (half kick, drift, force, half kick) around the library's contact step
// (dem::step on the contact's typed state), with the setup's force computation first.

#include <cmath>
#include <functional>

#include "bounce/dem/contact.hpp"

namespace bounce::test {

struct Sphere {
  double x[3] = {0, 0, 0}, v[3] = {0, 0, 0}, omega[3] = {0, 0, 0};
  double f[3] = {0, 0, 0}, torque[3] = {0, 0, 0};
  double radius = 0.0, mass = 0.0;
  double inertia() const { return 0.4 * mass * radius * radius; }  // a solid sphere
  dem::Motion motion() const { return {x, v, omega, radius}; }
};

/// `Contact`: the composition stepped (bounce's, or a test's own).
template <class Contact = dem::Contact>
class TwoSpheres {
 public:
  TwoSpheres(const models::DemModel& law, Sphere one, Sphere two, double dt, bool corrected = true)
      : law_(law), s_{one, two}, dt_(dt), corrected_(corrected) {
    layout_.add(law);
  }
  /// The setup's forces (no history update), as LAMMPS's `run` starts.
  void setup() { forces({dt_, false, false}); }
  /// One step of velocity Verlet.
  void step() {
    for (Sphere& b : s_) kick(b), drift(b);
    forces({dt_, true, corrected_});
    for (Sphere& b : s_) kick(b);
  }
  void run(int steps, const std::function<void(int)>& each = {}) {
    for (int n = 0; n < steps; n++) {
      step();
      if (each) each(n);
    }
  }
  const Sphere& sphere(int k) const { return s_[k]; }
  typename Contact::State& state() { return state_; }
  const typename Contact::Layout& layout() const { return layout_; }
  /// The energies of the contact: stored at the last step (a crack law's elastic + surface, and the
  /// rolling, sliding and twisting springs'), and what the crack, the bulk force and those springs
  /// dissipated, summed over the steps [J].
  double stored() const { return stored_; }
  double dissipated() const { return dissipated_; }
  double kinetic() const {
    double e = 0.0;
    for (const Sphere& b : s_)
      for (int d = 0; d < 3; d++) e += 0.5 * b.mass * b.v[d] * b.v[d] + 0.5 * b.inertia() * b.omega[d] * b.omega[d];
    return e;
  }
  models::ContactGeometry geometry() const {
    const double r1 = s_[0].radius, r2 = s_[1].radius, m1 = s_[0].mass, m2 = s_[1].mass;
    return {r1 * r2 / (r1 + r2), m1 * m2 / (m1 + m2)};
  }
  /// The contact's step as pair_style bounce's loop has it (no call where the pair is out of reach).
  dem::ContactForce contact(const dem::StepSettings& s, dem::Kinematics& k) {
    const double d[3] = {s_[0].x[0] - s_[1].x[0], s_[0].x[1] - s_[1].x[1], s_[0].x[2] - s_[1].x[2]};
    const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const models::ContactGeometry g = geometry();
    if (!state_.touching && !dem::within_reach(law_, g, s_[0].radius + s_[1].radius - r)) return {};
    k = dem::pair_kinematics(s_[0].motion(), s_[1].motion(), r);
    return Contact::step(law_, g, k, s, state_);
  }

 private:
  void kick(Sphere& b) const {
    const double half = 0.5 * dt_;
    for (int d = 0; d < 3; d++) {
      b.v[d] += half / b.mass * b.f[d];
      b.omega[d] += half / b.inertia() * b.torque[d];
    }
  }
  void drift(Sphere& b) const {
    for (int d = 0; d < 3; d++) b.x[d] += dt_ * b.v[d];
  }
  void forces(const dem::StepSettings& s) {
    for (Sphere& b : s_)
      for (int d = 0; d < 3; d++) b.f[d] = b.torque[d] = 0.0;
    dem::Kinematics k{};
    const dem::ContactForce c = contact(s, k);
    const dem::Loads l = dem::loads(c, k, s_[0].radius, s_[1].radius);
    for (int d = 0; d < 3; d++) {
      s_[0].f[d] += l.force[d], s_[1].f[d] -= l.force[d];
      s_[0].torque[d] += l.torque1[d], s_[1].torque[d] += l.torque2[d];
    }
    stored_ = c.elastic + c.surface + c.spring_energy;
    dissipated_ += c.crack_dissipated + c.bulk_dissipated + c.rolling_dissipated + c.sliding_dissipated +
                   c.twisting_dissipated;
  }

  const models::DemModel& law_;
  Sphere s_[2];
  double dt_;
  bool corrected_;
  typename Contact::Layout layout_;
  typename Contact::State state_;
  double stored_ = 0.0, dissipated_ = 0.0;
};

}  // namespace bounce::test
