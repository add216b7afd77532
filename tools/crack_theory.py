#!/usr/bin/python3
"""The viscoelastic crack law from its theory, beside K13's (16) and (17) (docs/adhesive.md).

K13 takes its crack law from Greenwood 2004: a Barenblatt-Schapery crack with a Maugis-Dugdale
cohesive zone (stress sigma0 = gamma/z0 over a zone of length b) in a three-element solid of
creep compliance C(t) = (1 - (1 - k) exp(-t/T_vis)) / E (E the relaxed modulus). This script
derives the law of that model in the steady state and compares it with the printed fits. It is
the evidence behind bounce's crack law at k != 0.02 (models/crack.hpp, "third decision").

Opening crack (beta > 1, the contact shrinks). The stresses are the elastic ones (the region
where displacements are prescribed, the contact, only shrinks), the opening follows by the
creep compliance (Schapery). A surface point crosses the zone in tau = b/|v|; with x = tau/T_vis
and phi(rho) = sqrt(rho) - ((1 - rho)/2) ln((1 + sqrt rho)/(1 - sqrt rho)) the Dugdale opening
profile, normalised (rho the position across the zone from its leading edge):
    1/beta = 1 - (1 - k) J(x),   J(x) = int_0^1 exp(-x (1 - rho)) phi'(rho) d rho,
    phi'(rho) = (1/2) ln((1 + sqrt rho)/(1 - sqrt rho)),
and b = (pi/4) E* beta gamma / sigma0^2, so
    (sigma0^2 T_vis / (E* gamma)) |a'| = (pi/4) beta / x.
So f/beta depends on y = (1 - 1/beta)/(1 - k) alone, for any k (J is the same function).

Closing crack (beta < 1, the contact grows). Displacements are prescribed where the contact
grows into the zone, so the displacements are the elastic ones for pseudo-tractions (the creep
integral of the traction history): a surface point entered the zone (1 - s) x relaxation times
ago (s its place across the zone from the contact edge), so its pseudo-traction is
sigma0 h(s), h(s) = 1 - (1 - k) exp(-(1 - s) x). No stress singularity at the edge and the gap
h0 = gamma/sigma0 at the zone's outer end give, with H1 = int h(s) s^-1/2 ds and
H2 = int h(s) ln((1 + sqrt s)/(1 - sqrt s)) ds,
    beta = H1^2 / (2 (2 H1 - H2)),   (sigma0^2 T_vis / (E* gamma)) a' = pi beta / (H1^2 x).
Both limits hold: beta -> 1 at x -> inf (slow) and beta -> k at x -> 0 (fast).

Run it for the comparison tables of docs/adhesive.md: `/usr/bin/python3 tools/crack_theory.py`.
"""

import math

from scipy.integrate import quad
from scipy.optimize import brentq

REFERENCE_K = 0.02  # K13 (17)'s k


def _log_ratio(u):
    q = math.sqrt(u)
    return math.log((1.0 + q) / (1.0 - q))


def opening(x, k):
    """(beta, scaled crack speed |a'|) of the opening crack at x = tau / T_vis."""
    j = quad(lambda r: math.exp(-x * (1.0 - r)) * 0.5 * _log_ratio(r), 0.0, 1.0, limit=200, points=[0.999])[0]
    beta = 1.0 / (1.0 - (1.0 - k) * j)
    return beta, math.pi / 4.0 * beta / x


def closing(x, k):
    """(beta, scaled crack speed a') of the closing crack at x = tau / T_vis."""
    def h(s):
        return 1.0 - (1.0 - k) * math.exp(-(1.0 - s) * x)

    h1 = quad(lambda s: h(s) / math.sqrt(s), 0.0, 1.0, limit=200)[0]
    h2 = quad(lambda s: h(s) * _log_ratio(s), 0.0, 1.0, limit=200, points=[0.999])[0]
    beta = h1 * h1 / (2.0 * (2.0 * h1 - h2))
    return beta, math.pi * beta / (h1 * h1 * x)


def theory_speed(beta, k):
    """The theory's signed scaled crack speed at beta (k < beta < 1/k)."""
    branch = closing if beta < 1.0 else opening
    log_x = brentq(lambda lx: branch(math.exp(lx), k)[0] - beta, -14.0, 14.0, xtol=1e-13)
    speed = branch(math.exp(log_x), k)[1]
    return speed if beta < 1.0 else -speed


def k13_16(beta, k):
    """K13 (16)."""
    if beta < 1.0:
        return 0.15 / (beta * math.log((1.0 - k) / (1.0 - beta)))
    return -0.24 * beta / math.log((1.0 - k) / (1.0 - 1.0 / beta))


def k13_17(beta):
    """K13 (17), for k = 0.02 and 0.29 < beta < 3.7."""
    if beta < 1.0:
        x = 1.0 / beta - 1.0
        return (0.1035 * x + 0.3421) * x ** 1.116
    x = beta - 1.0
    return -(0.2112 * x + 0.3939) * x ** 1.1403


def carried(beta, k, law):
    """law (at REFERENCE_K) carried to k at equal y, as bounce's crack law carries K13's."""
    c = (1.0 - REFERENCE_K) / (1.0 - k)
    if beta < 1.0:
        beta_ref = 1.0 - c * (1.0 - beta)
        return beta_ref / beta * law(beta_ref)
    beta_ref = 1.0 / (1.0 - c * (1.0 - 1.0 / beta))
    return beta / beta_ref * law(beta_ref)


def against_k13(betas):
    """(beta, theory, (16), (17)) at k = 0.02."""
    return [(b, theory_speed(b, REFERENCE_K), k13_16(b, REFERENCE_K), k13_17(b)) for b in betas]


def carried_error(k, betas):
    """Largest |theory carried from 0.02 to k / theory at k - 1| on each branch."""
    worst = {"closing": 0.0, "opening": 0.0}
    for b in betas:
        exact = theory_speed(b, k)
        moved = carried(b, k, lambda br: theory_speed(br, REFERENCE_K))
        side = "closing" if b < 1.0 else "opening"
        worst[side] = max(worst[side], abs(moved / exact - 1.0))
    return worst


def main():
    print("k = 0.02: the theory against K13 (16) and (17)")
    print(f"{'beta':>6} {'theory':>11} {'(16)':>11} {'(17)':>11} {'th/(16)':>8} {'th/(17)':>8}")
    betas = [0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.99,
             1.01, 1.05, 1.1, 1.3, 1.6, 2.0, 2.5, 3.0, 3.6, 5.0, 10.0, 30.0]
    for b, th, f16, f17 in against_k13(betas):
        r17 = f"{th / f17:8.4f}" if 0.29 < b < 3.7 else f"{'':8}"
        print(f"{b:6.3g} {th:11.5g} {f16:11.5g} {f17:11.5g} {th / f16:8.4f} {r17}")
    print("\nthe theory at k carried from k = 0.02 at equal y, against the theory at k (largest error)")
    for k in (0.001, 0.1, 0.3, 0.5):
        grid = [1.0 - (1.0 - k) * y for y in (0.05, 0.2, 0.4, 0.6, 0.8, 0.9)]
        grid += [1.0 / (1.0 - (1.0 - k) * y) for y in (0.05, 0.2, 0.4, 0.6, 0.8, 0.9)]
        worst = carried_error(k, grid)
        print(f"k = {k:5g}: closing {worst['closing']:.3g}, opening {worst['opening']:.2g}")


if __name__ == "__main__":
    main()
