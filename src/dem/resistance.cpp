// The rolling, sliding and twisting sub-model's step (resistance.hpp, docs/resistance.md). Each
// spring's force and torques are the exact gradients of its energy (derived in the docs), so an
// elastic contact conserves energy and angular momentum.
#include "bounce/dem/resistance.hpp"

#include <cmath>

#include "bounce/contact/resistance.hpp"

namespace bounce::dem {

namespace {

using Vec = std::array<double, 3>;

Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }
Vec scaled(const Vec& a, double s) { return {s * a[0], s * a[1], s * a[2]}; }

// Rodrigues' rotation of v by `angle` about the unit `axis`.
void turn(Vec& v, const Vec& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), along = dot(axis, v) * (1.0 - c);
  const Vec across = cross(axis, v);
  for (int d = 0; d < 3; d++) v[d] = v[d] * c + across[d] * s + axis[d] * along;
}

// A pointer turned with its body over the step: by |omega| dt about omega.
void turn_with(Vec& v, const double* omega, double dt) {
  const Vec w{omega[0], omega[1], omega[2]};
  const double rate = norm(w);
  if (rate > 0.0) turn(v, scaled(w, 1.0 / rate), rate * dt);
}

// W07's correction beyond a critical displacement: both pointers turned about n x (the
// displacement) until its length is `critical` (a few passes: each leaves the square of the last
// miss), `sign2` = -1 turning the second pointer back (rolling), +1 with the first (sliding).
// The spring energy it released [J].
template <class Displacement>
double hold(Vec& p1, Vec& p2, const Vec& n, double k, double critical, double per_angle, double sign2,
            const Displacement& displacement) {
  Vec x = displacement(p1, p2);
  const double before = 0.5 * k * dot(x, x);
  for (int pass = 0; pass < 4 && norm(x) > critical; pass++) {
    const Vec axis = cross(n, x);
    const double length = norm(axis);
    if (!(length > 0.0)) break;  // along n: no tangential displacement to hold
    const double angle = (norm(x) - critical) / per_angle;
    turn(p1, scaled(axis, 1.0 / length), angle);
    turn(p2, scaled(axis, 1.0 / length), sign2 * angle);
    x = displacement(p1, p2);
  }
  return before - 0.5 * k * dot(x, x);
}

}  // namespace

void Resistance::step(const SubContext& c, State& state, ContactForce& out) {
  if (!c.law.resistance || c.k.omega2 == nullptr) return;
  const models::ResistanceModel& m = *c.law.resistance;
  const Kinematics& k = c.k;
  const Vec n{k.n[0], k.n[1], k.n[2]};  // from body 2 to body 1: body 1's pointer starts at -n
  Vec &p1 = state.pointer1, &p2 = state.pointer2;
  const bool forms = dot(p1, p1) == 0.0;  // the pointers start where the contact is now: no turn yet
  if (forms) p1 = scaled(n, -1.0), p2 = n, state.twist = 0.0;
  const double r1 = k.radius1, r2 = k.radius2, R = c.g.effective_radius, dt = c.s.dt;
  const contact::resistance::Resistance springs = contact::resistance::contact_resistance(m.materials, R, m.xi_crit);
  const double k_r = springs.rolling.stiffness, k_s = springs.sliding.stiffness, k_t = springs.twisting.stiffness;
  const auto rolling = [R](const Vec& a, const Vec& b) { return Vec{R * (a[0] + b[0]), R * (a[1] + b[1]), R * (a[2] + b[2])}; };
  const auto sliding = [&](const Vec& a, const Vec& b) {  // the tangential part of r1 p1 - r2 p2
    const Vec u{r1 * a[0] - r2 * b[0], r1 * a[1] - r2 * b[1], r1 * a[2] - r2 * b[2]};
    const double along = dot(u, n);
    return Vec{u[0] - along * n[0], u[1] - along * n[1], u[2] - along * n[2]};
  };
  if (c.s.update_history && !forms) {
    turn_with(p1, k.omega1, dt), turn_with(p2, k.omega2, dt);
    state.twist += ((k.omega1[0] - k.omega2[0]) * n[0] + (k.omega1[1] - k.omega2[1]) * n[1] +
                    (k.omega1[2] - k.omega2[2]) * n[2]) * dt;
    if (m.rolling) out.rolling_dissipated = hold(p1, p2, n, k_r, m.xi_crit, 2.0 * R, -1.0, rolling);
    if (m.sliding) out.sliding_dissipated = hold(p1, p2, n, k_s, springs.sliding.critical_displacement, r1 + r2, 1.0, sliding);
    const double phi_crit = springs.twisting.critical_displacement;
    if (m.twisting && std::abs(state.twist) > phi_crit) {
      out.twisting_dissipated = 0.5 * k_t * (state.twist * state.twist - phi_crit * phi_crit);
      state.twist = std::copysign(phi_crit, state.twist);
    }
  }
  if (m.rolling) {  // W07: U = k_r xi^2 / 2, xi = R (p1 + p2); torque_i = -k_r R p_i x xi
    const Vec xi = rolling(p1, p2), t1 = cross(p1, xi), t2 = cross(p2, xi);
    for (int d = 0; d < 3; d++) out.torque1[d] -= k_r * R * t1[d], out.torque2[d] -= k_r * R * t2[d];
    out.spring_energy += 0.5 * k_r * dot(xi, xi);
  }
  if (m.sliding) {  // W07: U = k_s zeta^2 / 2; the force on body 1 k_s (u.n / d) zeta, tangential
    const Vec zeta = sliding(p1, p2);
    const double along = r1 * dot(p1, n) - r2 * dot(p2, n);
    const Vec f = scaled(zeta, k_s * along / k.distance), lever = cross(n, f);
    const Vec t1 = cross(p1, zeta), t2 = cross(p2, zeta);
    for (int d = 0; d < 3; d++) {
      out.tangential[d] += f[d];
      // the exact torques, -k_s r1 p1 x zeta and k_s r2 p2 x zeta, less the lever arm's of f
      out.torque1[d] += -k_s * r1 * t1[d] + r1 * lever[d];
      out.torque2[d] += k_s * r2 * t2[d] + r2 * lever[d];
    }
    out.spring_energy += 0.5 * k_s * dot(zeta, zeta);
  }
  if (m.twisting) {  // W07: U = k_t phi^2 / 2; torque -k_t phi n on body 1, +k_t phi n on body 2
    for (int d = 0; d < 3; d++) out.torque1[d] -= k_t * state.twist * n[d], out.torque2[d] += k_t * state.twist * n[d];
    out.spring_energy += 0.5 * k_t * state.twist * state.twist;
  }
}

}  // namespace bounce::dem
