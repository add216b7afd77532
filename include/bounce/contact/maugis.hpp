#pragma once
// Maugis-Dugdale adhesive contact of elastic spheres (Maugis 1992, cited as
// BP04 ref. [19]; not derived in the seed papers). A Dugdale stress sigma0 acts
// over a gap h0 = gamma/sigma0 around the contact (radius a) out to radius c = m a.
//
// Non-dimensional form (Johnson & Greenwood 1997), with K = 4E*/3:
//   A = a (K/(pi gamma R^2))^{1/3},  P = F/(pi gamma R),  Delta = delta (K^2/(pi^2 gamma^2 R))^{1/3},
//   lambda = 2 sigma0 (R/(pi gamma K^2))^{1/3};
//   (lambda A^2/2)[(m^2-2) arcsec m + sqrt(m^2-1)]
//       + (4 lambda^2 A/3)[sqrt(m^2-1) arcsec m - m + 1] = 1,        (MD1)
//   P = A^3 - lambda A^2 [sqrt(m^2-1) + m^2 arcsec m],                (MD2)
//   Delta = A^2 - (4/3) lambda A sqrt(m^2-1).                         (MD3)
// lambda -> inf gives JKR (P = A^3 - sqrt(6) A^{3/2}), lambda -> 0 gives DMT (P = A^3 - 2).
// We solve (MD1) for s = sqrt(m^2-1) (arcsec m = atan s), which keeps both limits
// free of cancellation.

namespace bounce::contact::maugis {

/// A point on the non-dimensional Maugis-Dugdale curve.
struct Point {
  double contact_radius = 0.0;  ///< A
  double force = 0.0;           ///< P
  double overlap = 0.0;         ///< Delta
  double zone_ratio = 1.0;      ///< m = c/a
};

/// Solve (MD1) for m at contact radius A >= 0 and evaluate (MD2), (MD3).
/// At A = 0 the limit (zone radius c finite) is returned.
Point at_contact_radius(double lambda, double contact_radius);

/// The Maugis-Dugdale curve for one lambda, with its two minima found once
/// (each needs a global search), so that repeated queries cost one root solve.
class Curve {
 public:
  explicit Curve(double lambda);
  double lambda() const noexcept { return lambda_; }
  Point at_contact_radius(double contact_radius) const;
  /// Smallest P over A >= 0: the pull-off under force control.
  const Point& pull_off() const noexcept { return pull_off_; }
  /// Smallest Delta over A >= 0 (where the contact breaks under displacement control).
  const Point& min_overlap() const noexcept { return min_overlap_; }
  /// Largest-A point with P = force (stable under force control); force >= pull_off().force.
  Point at_force(double force) const;
  /// Largest-A point with Delta = overlap (stable under displacement control).
  Point at_overlap(double overlap) const;

 private:
  double lambda_;
  Point pull_off_;
  Point min_overlap_;
};

// One-off conveniences (each builds a Curve).
Point pull_off(double lambda);
Point min_overlap(double lambda);
Point at_force(double lambda, double force);
Point at_overlap(double lambda, double overlap);

/// Scales that turn the non-dimensional variables into SI.
struct Scales {
  double length = 0.0;   ///< a = A * length,  length = (pi gamma R^2 / K)^{1/3} [m]
  double force = 0.0;    ///< F = P * force,   force = pi gamma R [N]
  double overlap = 0.0;  ///< delta = Delta * overlap, overlap = length^2 / R [m]
};
Scales scales(double effective_radius, double effective_modulus, double gamma);

}  // namespace bounce::contact::maugis
