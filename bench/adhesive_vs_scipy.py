#!/usr/bin/python3
"""K13's model in bounce against a scipy implementation of the same equations.

The scipy side re-implements, in the same scaled variables, K13 (2), (14), (16)-(17)
with bounce's join of (16)/(17) and its C2 join at beta = 1 (docs/adhesive.md),
(19), (20), (C.2), (C.3), the appendix-B start and the same two events (the crack
runs away at beta = (1 - 1e-6)/k; the mechanical energy turns negative), and
integrates with solve_ivp's Radau (and LSODA) using the analytic Jacobian.
It uses bounce's phases too (the contact radius as the independent variable where the
crack races, see SwappedIndependent). Errors are measured against bounce's CVODE engine at
tolerance 1e-12; scipy's tolerance is lowered until its error is at most bounce's, so the
times compare at equal accuracy.
Prints Markdown tables (recorded in docs/benchmarks.md).

    adhesive_vs_scipy.py [BUILD]          the tables of single collisions
    adhesive_vs_scipy.py BUILD curve      a 40-velocity curve, in-process on both sides
"""
import json
import math
import os
import subprocess
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

PI = math.pi
K = 0.02
W = 1e-4  # half-width of the C2 join around beta = 1


def high(beta):  # K13 (16) and its derivative
    if beta < 1:
        l = math.log((1 - K) / (1 - beta)); f = 0.15 / (beta * l)
        return f, -f * (1 / beta + 1 / ((1 - beta) * l))
    if beta > 1:
        l = math.log((1 - K) / (1 - 1 / beta)); f = -0.24 * beta / l
        return f, f / beta + f / (l * beta * (beta - 1))
    return 0.0, 0.0


def low(beta):  # K13 (17) (k = 0.02) and its derivative
    if beta < 1:
        x = 1 / beta - 1; p = x ** 1.116; f = (0.1035 * x + 0.3421) * p
        return f, -(0.1035 * p + (0.1035 * x + 0.3421) * 1.116 * p / x) / beta ** 2
    if beta > 1:
        x = beta - 1; p = x ** 1.1403; f = -(0.2112 * x + 0.3939) * p
        return f, -(0.2112 * p + (0.2112 * x + 0.3939) * 1.1403 * p / x)
    return 0.0, 0.0


def blend(a, b, s, ds):
    w = s * s * (3 - 2 * s); dw = 6 * s * (1 - s) * ds
    return a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]) + dw * (b[0] - a[0])


def piecewise(beta):
    if beta <= 0.29 or beta >= 3.7:
        return high(beta)
    if 0.31 <= beta <= 3.6:
        return low(beta)
    if beta < 0.31:
        return blend(high(beta), low(beta), (beta - 0.29) / 0.02, 50.0)
    return blend(low(beta), high(beta), (beta - 3.6) / 0.1, 10.0)


def jet(beta):
    h = 1e-3 * W
    f, d1 = piecewise(beta)
    return f, d1, (piecewise(beta + h)[1] - piecewise(beta - h)[1]) / (2 * h)


JOIN = (jet(1 - W), jet(1 + W))


def crack(beta):
    # Outside k < beta < 1/k (where bounce rejects the step) continue linearly from just
    # inside: LSODA cannot reject a step, and needs finite values there; the events end
    # every phase before beta leaves the domain.
    lo, hi = K * (1 + 1e-7), (1 - 1e-7) / K
    if beta < lo or beta > hi:
        edge = lo if beta < lo else hi
        f, d = crack(edge)
        return f + d * (beta - edge), d
    if abs(beta - 1) >= W:
        return piecewise(beta)
    (fa, ga, ca), (fb, gb, cb) = JOIN
    x0 = 1 - W; h = 2 * W
    c = [fa, h * ga, h * h * ca, fb, h * gb, h * h * cb]

    def hermite(t):
        t2, t3, t4, t5 = t * t, t ** 3, t ** 4, t ** 5
        hb = [1 - 10 * t3 + 15 * t4 - 6 * t5, t - 6 * t3 + 8 * t4 - 3 * t5, 0.5 * (t2 - 3 * t3 + 3 * t4 - t5),
              10 * t3 - 15 * t4 + 6 * t5, -4 * t3 + 7 * t4 - 3 * t5, 0.5 * (t3 - 2 * t4 + t5)]
        db = [-30 * t2 + 60 * t3 - 30 * t4, 1 - 18 * t2 + 32 * t3 - 15 * t4,
              0.5 * (2 * t - 9 * t2 + 12 * t3 - 5 * t4), 30 * t2 - 60 * t3 + 30 * t4,
              -12 * t2 + 28 * t3 - 15 * t4, 0.5 * (3 * t2 - 8 * t3 + 5 * t4)]
        return sum(x * y for x, y in zip(hb, c)), sum(x * y for x, y in zip(db, c))

    t = (beta - x0) / h; u = t * (1 - t)
    bump = -64 * hermite(0.5)[0]  # + bump t^3 (1-t)^3: f(1) = 0
    f, df = hermite(t)
    return f + bump * u ** 3, (df + bump * 3 * u * u * (1 - 2 * t)) / h


class K13:
    def __init__(self, r_sphere, v, tvis, e=7e9, nu=0.25, rho=1000.0, gamma=0.37, z0=0.2e-9):
        self.R = r_sphere / 2; self.E = e / (2 * (1 - nu * nu)); self.m = 4 / 3 * PI * r_sphere ** 3 * rho / 2
        self.g = gamma; self.A = tvis / nu ** 2; self.c = self.E * z0 * z0 / (gamma * tvis)
        rho_h = 4 / 3 * self.E * math.sqrt(self.R)
        xi0 = (1.25 * self.m * v * v / rho_h) ** 0.4
        delta_c = 0.75 * (PI * PI * gamma * gamma * self.R / self.E ** 2) ** (1 / 3)
        a_eq = (9 * PI * gamma * self.R ** 2 / (2 * self.E)) ** (1 / 3)
        self.L = max(xi0, delta_c); self.La = max(math.sqrt(self.R * xi0), a_eq)
        self.v = v; self.T = self.L / v; self.E0 = 0.5 * self.m * v * v
        self.beta_break = (1 - 1e-6) / K
        # The JKR fold (a_c = a_eq / 36^(1/3), delta_c from K13 (8)) and its energy: bounce's
        # sharper sticking criterion.
        self.fold_a = a_eq / 36 ** (1 / 3)
        self.fold_delta = self.fold_a ** 2 / self.R - math.sqrt(2 * PI * gamma * self.fold_a / self.E)
        self.fold_energy = self.energy(self.fold_a, self.fold_delta) / self.E0
        # bounce tightens the tolerance by the adhesion / impact energy ratio
        self.tolerance_factor = min(1.0, self.E0 / (2 * PI * a_eq * a_eq * gamma))

    def phys(self, y):
        d, r, a = y[0] * self.L, y[1] * self.v, y[2] * self.La
        beta = self.E * (a * a - d * self.R) ** 2 / (2 * PI * a * self.R ** 2 * self.g) if a > 0 else 0.0
        return d, r, a, beta

    def energy(self, a, d):  # K13 (3) + (6)
        return self.E * (a * d * d - 2 * a ** 3 * d / (3 * self.R) + a ** 5 / (5 * self.R ** 2)) - PI * a * a * self.g

    def crack_rate(self, y):  # a'/a per scaled time unit
        _, _, a, beta = self.phys(y)
        return self.c * crack(beta)[0] / a * self.T

    def stick(self, y):  # mechanical energy minus the threshold below which separation is impossible
        d, _, a, _ = self.phys(y)
        threshold = self.fold_energy if d >= self.fold_delta and a >= self.fold_a else 0.0
        return y[1] ** 2 + self.energy(a, d) / self.E0 - threshold

    def in_domain(self, a, beta):
        return a > 0  # beta outside (k, 1/k): see crack()

    def rhs(self, t, y):
        d, r, a, beta = self.phys(y)
        if not self.in_domain(a, beta):
            return [math.nan] * 5
        fe = 2 * self.E / (3 * self.R) * (3 * a * d * self.R - a ** 3)
        fd = 2 * self.A * self.E * a * r
        adot = self.c * crack(beta)[0]
        return [y[1], -(fe + fd) / self.m * self.T / self.v, adot * self.T / self.La,
                2 * PI * a * self.g * (1 - beta) * adot * self.T / self.E0, fd * r * self.T / self.E0]

    def jac(self, t, y):
        d, r, a, beta = self.phys(y)
        if not self.in_domain(a, beta):
            return np.full((5, 5), math.nan)
        R, E, m, g, A = self.R, self.E, self.m, self.g, self.A
        f, fp = crack(beta)
        mis = a * a - d * R
        bd = -E * mis / (PI * a * R * g); ba = E * mis * (3 * a * a + d * R) / (2 * PI * a * a * R * R * g)
        adot = self.c * f; add = self.c * fp * bd; ada = self.c * fp * ba
        J = np.zeros((5, 5))
        J[0, 1] = 1
        J[1, 0] = -2 * E * a / m; J[1, 1] = -2 * A * E * a / m; J[1, 2] = -(2 * E * (d - a * a / R) + 2 * A * E * r) / m
        J[2, 0] = add; J[2, 2] = ada
        w = 2 * PI * g
        J[3, 0] = w * a * (-bd * adot + (1 - beta) * add)
        J[3, 2] = w * ((1 - beta) * adot - a * ba * adot + a * (1 - beta) * ada)
        J[4, 1] = 4 * A * E * a * r; J[4, 2] = 2 * A * E * r * r
        scale = [self.L, self.v, self.La, self.E0, self.E0]
        return J * self.T / np.array(scale)[:, None] * np.array(scale)[None, :]

    def swapped(self, sign):
        """The system with s = sign * a as independent variable, t in place of a (bounce's
        SwappedIndependent): dz/ds = sign f / f_a, dt/ds = sign / f_a."""
        def full(s, z):
            y = list(z); y[2] = sign * s
            return y

        def rhs(s, z):
            f = self.rhs(0.0, full(s, z))
            fa = f[2]
            if not np.isfinite(fa) or fa == 0:
                return [math.nan] * 5
            out = [sign * x / fa for x in f]; out[2] = sign / fa
            return out

        def jac(s, z):
            y = full(s, z)
            f = np.array(self.rhs(0.0, y)); J = self.jac(0.0, y)
            fa = f[2]; fi = f.copy(); fi[2] = 1.0
            Jz = J.copy(); Jz[2, :] = 0.0
            out = sign * (Jz - np.outer(fi, J[2, :]) / fa) / fa
            out[:, 2] = 0.0
            return out
        return full, rhs, jac

    def run(self, method, tol):
        """bounce's algorithm: phases closing (beta < 0.25, a independent), time, opening
        (beta > 4, -a independent), hysteresis 0.2 / 3; break at (1 - 1e-6)/k."""
        a0 = (2 * PI * self.R ** 2 * 1.01 * K * self.g / self.E) ** (1 / 3)
        y = [0.0, 1.0, a0 / self.La, -self.energy(a0, 0.0) / self.E0, 0.0]
        t = 0.0
        t_h = 3 * (1.25 * self.m / (4 / 3 * self.E * math.sqrt(self.R))) ** 0.4 * self.v ** -0.2 / self.T
        phase = "closing"

        def event(fn):
            fn.terminal = True; fn.direction = -1
            return fn

        while True:
            if phase == "time":
                full = lambda s, z: list(z)
                rhs, jac, z, span = self.rhs, self.jac, list(y), (t, 1e4 * t_h)
            else:
                sign = 1.0 if phase == "closing" else -1.0
                full, rhs, jac = self.swapped(sign)
                z = list(y); z[2] = t
                # Opening: a decreases toward the break, well before a = 1e-6 a(start).
                span = (sign * y[2], 1e6 if phase == "closing" else -1e-6 * y[2])
            beta = lambda s, z: self.phys(full(s, z))[3]
            brk = event(lambda s, z: self.beta_break - beta(s, z))
            stick = event(lambda s, z: self.stick(full(s, z)))
            if phase == "time":
                switches = [event(lambda s, z: beta(s, z) - 0.2),
                            event(lambda s, z: min(4.0 - beta(s, z), self.crack_rate(full(s, z)) + 1e3))]
                targets = ["closing", "opening"]
            elif phase == "closing":
                switches, targets = [event(lambda s, z: 0.25 - beta(s, z))], ["time"]
            else:
                switches = [event(lambda s, z: max(beta(s, z) - 3.0, -(self.crack_rate(full(s, z)) + 1e2)))]
                targets = ["time"]
            # A first step well inside the domain (LSODA's own estimate can leave it,
            # and LSODA, unlike Radau, cannot recover from a NaN).
            tol_eff = tol * self.tolerance_factor
            sol = solve_ivp(rhs, span, z, method=method, rtol=tol_eff, atol=tol_eff * 1e-2, jac=jac,
                            events=[brk, stick] + switches, first_step=1e-6 * abs(span[0]))
            if sol.status != 1:
                raise RuntimeError(f"{method} at tol {tol}: {sol.message}")
            if sol.t_events[0].size:
                return -sol.y_events[0][0][1]
            if sol.t_events[1].size:
                return 0.0
            for i, target in enumerate(targets):
                if sol.t_events[2 + i].size:
                    s_end, z_end = sol.t_events[2 + i][0], sol.y_events[2 + i][0]
                    y = full(s_end, z_end)
                    t = s_end if phase == "time" else z_end[2]
                    phase = target
                    break


def bounce_reference(build, r, v, tvis):
    """bounce's CVODE engine at tolerance 1e-12: the reference of every error here."""
    out = subprocess.run([f"{build}/bin/bounce", "collide", "--material", "water-ice", "--radius", repr(r), "--model",
                          "krijt", "--tvis", repr(tvis), "--velocity", repr(v), "--stiff-engine", "cvode",
                          "--adhesive-tolerance", "1e-12", "--json"], capture_output=True, text=True, check=True).stdout
    return json.loads(out)["cor"]


def scipy_at_matched_accuracy(method, r, v, tvis, ref, target):
    """The loosest tolerance whose error is at most `target`, and its best-of-3 time."""
    for tol in (1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11):
        best = math.inf
        for _ in range(3):
            start = time.perf_counter()
            e = K13(r, v, tvis).run(method, tol)
            best = min(best, time.perf_counter() - start)
        if abs(e - ref) <= target:
            return tol, best, abs(e - ref)
    return tol, best, abs(e - ref)


def curve(build):
    """The 40-velocity K13 curve (T_vis = 1e-11 s, 0.3-100 m/s geometric, sticking and bouncing
    collisions; below 0.25 m/s the scipy side's closing phase runs out of its span), in-process
    on both sides, one thread: bounce.curve (RODAS, its default tolerance) against the scipy
    LSODA loop at the loosest tolerance whose largest COR error over the curve is at most
    bounce's. Both errors against bounce's CVODE engine at 1e-12."""
    sys.path.insert(0, f"{build}/python")
    import bounce
    r, tvis = 2.0353e-6, 1e-11
    velocities = np.geomspace(0.3, 100.0, 40)
    pair = bounce.Pair(material="water-ice", radius=r)
    model = bounce.Model("krijt", tvis=tvis)
    reference = bounce.curve(pair, bounce.Model("krijt", tvis=tvis, stiff_engine="cvode", adhesive_tolerance=1e-12),
                             velocities)["cor"]
    ours, cor = math.inf, None
    for _ in range(5):
        start = time.perf_counter()
        cor = bounce.curve(pair, model, velocities)["cor"]
        ours = min(ours, time.perf_counter() - start)
    ours_error = float(np.max(np.abs(cor - reference)))
    sticks = int(np.sum(cor == 0.0))
    print(f"K13 curve, T_vis = {tvis:g} s, {len(velocities)} velocities 0.3-100 m/s ({sticks} stick), in-process, one thread:")
    print("(scipy's errors leave out the speeds where its run ends in a break while the grains approach)")
    print()
    print("| side | tolerance | time | per collision | largest COR error | ratio |")
    print("|---|---|---|---|---|---|")
    print(f"| bounce (RODAS) | default 1e-8 | {ours * 1e3:.1f} ms | {ours / len(velocities) * 1e3:.3f} ms | "
          f"{ours_error:.1e} | 1 |")
    for tol in (1e-7, 1e-8, 1e-9, 1e-10, 1e-11):
        start = time.perf_counter()
        theirs = np.array([K13(r, v, tvis).run("LSODA", tol) for v in velocities])
        seconds = time.perf_counter() - start
        # A break while the grains approach (the neck pulled them back) ends the scipy run with a
        # negative COR; bounce follows them into their next contact (at 1.79 m/s they stick): the
        # errors compare the other speeds.
        error = float(np.max(np.abs(theirs - reference)[theirs >= 0.0]))
        print(f"| scipy LSODA | {tol:g} | {seconds * 1e3:.0f} ms | {seconds / len(velocities) * 1e3:.2f} ms | "
              f"{error:.1e} | {seconds / ours:.0f}x |")
        if error <= ours_error:
            break


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    if len(sys.argv) > 3 or (len(sys.argv) == 3 and sys.argv[2] != "curve"):
        print(f"usage: adhesive_vs_scipy.py [BUILD [curve]]; got {' '.join(map(repr, sys.argv[1:]))}", file=sys.stderr)
        sys.exit(2)
    if not os.path.isfile(f"{build}/bin/bounce"):
        print(f"adhesive_vs_scipy.py: BUILD = {build!r} holds no bin/bounce (a configured and built bounce build)",
              file=sys.stderr)
        sys.exit(2)
    if len(sys.argv) == 3:
        curve(build)
        return
    raw = subprocess.run([f"{build}/bin/bench_adhesive", "--benchmark_format=json", "--benchmark_min_time=0.2"],
                         capture_output=True, text=True, check=True).stdout
    runs = json.loads(raw)["benchmarks"]
    r = 2.0353e-6
    collisions = [x for x in runs if x["name"].startswith("collision")]

    print("K13 collisions (T_vis = 1e-11 s) with bounce (RODAS, default tolerance 1e-8) and scipy at matched accuracy:")
    print()
    print("| v [m/s] | bounce | its error | scipy Radau (tol) | its error | ratio | scipy LSODA (tol) | its error | ratio |")
    print("|---|---|---|---|---|---|---|---|---|")
    seen = set()
    for run in collisions:
        if run["tvis"] != 1e-11 or run["engine"] != 0 or run["tolerance"] != 1e-8 or run["velocity"] in seen:
            continue
        seen.add(run["velocity"])
        v, ours = run["velocity"], run["real_time"] * 1e-3
        target = max(run["error"], 1e-11)
        ref = bounce_reference(build, r, v, 1e-11)
        row = f"| {v:g} | {ours * 1e3:.2f} ms ({int(run['steps'])} steps) | {run['error']:.1e} |"
        for method in ("Radau", "LSODA"):
            tol, t, err = scipy_at_matched_accuracy(method, r, v, 1e-11, ref, target)
            row += f" {t * 1e3:.0f} ms ({tol:g}) | {err:.1e} | {t / ours:.0f}x |"
        print(row)

    print()
    print("One collision at 8 m/s across T_vis, both engines (time, steps, COR error against CVODE at 1e-12):")
    print()
    print("| T_vis [s] | outcome | RODAS 1e-8 | error | RODAS 1e-9 | error | CVODE 1e-8 | error | CVODE 1e-9 | error |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    by_key = {(x["velocity"], x["tvis"], x["engine"], x["tolerance"]): x for x in collisions}
    for tvis in sorted({x["tvis"] for x in collisions if x["velocity"] == 8.0}, reverse=True):
        cells = []
        outcome = None
        for eng in (0, 1):
            for tol in (1e-8, 1e-9):
                x = by_key.get((8.0, tvis, eng, tol))
                if x is None:
                    cells += ["", ""]
                    continue
                outcome = "stick" if x["stick"] else f"e = {x['cor']:.4f}"
                err = x["closure"] if x["stick"] else x["error"]
                cells += [f"{x['real_time']:.2f} ms ({int(x['steps'])})", f"{err:.0e}"]
        print(f"| {tvis:g} | {outcome} | " + " | ".join(cells) + " |")
    print()
    print("(For sticking collisions the error column is the energy closure instead.)")

    curves = [x for x in runs if x["name"].startswith("fig4_curve")]
    print()
    print("K13 fig. 4 curve (100 velocities, 0.1-100 m/s) per T_vis; its time / 100 is the mean cost of a collision:")
    print()
    print("| T_vis [s] | curve | per collision |")
    print("|---|---|---|")
    for x in curves:
        print(f"| {x['tvis']:g} | {x['real_time']:.0f} ms | {x['real_time'] / 100:.2f} ms |")
    mean = [x["real_time"] for x in curves]
    print()
    print(f"Largest / smallest mean cost across T_vis: {max(mean) / min(mean):.1f}")


if __name__ == "__main__":
    main()
