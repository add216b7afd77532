#!/usr/bin/python3
"""The homogeneous cooling state of a granular gas in LAMMPS with pair_style bounce
(docs/lammps.md, The homogeneous cooling state; `make lammps-demo`).

Two gases of 10 648 grains (R = 1 mm, density 1000 kg/m^3, volume fraction 0.03, periodic box,
Gaussian velocities of rms 1 m/s, frictionless) cool on 2 MPI ranks:

* constant restitution: `power-law` with alpha = 1, gamma = 0, beta = 1 is the linear
  spring-dashpot F = m_eff (D1 xi + D2 xi'), whose COR is the same for every speed and pair,
  eps = exp(-pi zeta / sqrt(1 - zeta^2)), zeta = D2 / (2 sqrt(D1)); eps = 0.9 here. Kinetic
  theory gives Haff's law T = T0 / (1 + t/tau0)^2 (Haff 1983);
* viscoelastic grains (BSHP96, E = 2e5 Pa, nu = 0.3, A = 1e-5 s): eps(g) -> 1 as g^{1/5}, and
  the gas cools as t^{-5/3} at late times (Schwager & Poeschel 1998; Brilliantov & Poeschel 2004).

The theory lines integrate, for each gas, the cooling rate of a dilute gas of smooth spheres with
a Maxwellian velocity distribution and molecular chaos (Enskog's factor g2 at contact,
Carnahan-Starling), for any eps(g) (docs/lammps.md derives it):

    dT/dt = -(pi/3) n g2 sigma^2 m  int_0^inf g^3 (1 - eps(g)^2) p(g) dg,   p: N(0, 2T/m),

with T the granular temperature, (3/2) T = <m v^2 / 2>. For constant eps it is Haff's law with
1/tau0 = (2/3) sqrt(pi) (1 - eps^2) n g2 sigma^2 sqrt(T0/m), a sixth of (1 - eps^2) times the
collision frequency. The exponents are fitted, T = C (t + t0)^alpha with t0 free, over more than
a decade of time; that the gas stayed homogeneous is checked on snapshots (density and flow
fluctuations over 6^3 cells against their values for uncorrelated grains).

    /usr/bin/python3 tools/hcs.py [--build build] [--out out] [--quick]
"""
import json
import math
import os
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
sys.path.insert(0, os.path.join(ROOT, "tests", "lammps"))
import lammps_runs  # noqa: E402

RADIUS, DENSITY, PHI, SPEED, CELLS = 1e-3, 1000.0, 0.03, 1.0, 22
MASS = 4.0 / 3.0 * math.pi * RADIUS ** 3 * DENSITY
SIGMA = 2 * RADIUS
N = CELLS ** 3
NUMBER_DENSITY = PHI / (4.0 / 3.0 * math.pi * RADIUS ** 3)
G2 = (1 - PHI / 2) / (1 - PHI) ** 3  # Carnahan-Starling contact value
T0 = MASS * SPEED ** 2 / 3.0
COLLISION_FREQUENCY = 4 * math.sqrt(math.pi) * NUMBER_DENSITY * G2 * SIGMA ** 2 * math.sqrt(T0 / MASS)
EPS = 0.9
E, NU, A = 2e5, 0.3, 1e-5


def linear_dashpot():
    """D1, D2 of the power-law model for COR EPS and a contact time of a tenth of the initial
    free time (t_c = pi / (omega0 sqrt(1 - zeta^2)))."""
    t_c = 0.1 / COLLISION_FREQUENCY
    zeta = -math.log(EPS) / math.sqrt(math.pi ** 2 + math.log(EPS) ** 2)
    omega = math.pi / (t_c * math.sqrt(1 - zeta ** 2))
    return omega ** 2, 2 * zeta * omega, t_c


def haff_tau0():
    return 6.0 / ((1 - EPS ** 2) * COLLISION_FREQUENCY)


def cooling_rate(loss, temperature):
    """dT/dt of the dilute gas for 1 - eps(g)^2 = loss(g) (Maxwellian, molecular chaos)."""
    from scipy.integrate import quad
    s = math.sqrt(2 * temperature / MASS)
    integrand = lambda g: g ** 3 * loss(g) * math.exp(-g * g / (2 * s * s)) / (math.sqrt(2 * math.pi) * s)
    value = quad(integrand, 0.0, 12 * s, limit=200)[0]
    return -(math.pi / 3) * NUMBER_DENSITY * G2 * SIGMA ** 2 * MASS * value


def viscoelastic_loss(build):
    """1 - eps(g)^2 of the viscoelastic grains from bounce's master curve (kappa ~ g^{1/5})."""
    sys.path.insert(0, os.path.join(build, "python"))
    import bounce
    pair = bounce.Pair(E=E, nu=NU, density=DENSITY, radius=RADIUS)
    scales = bounce.viscoelastic_scales(pair, bounce.Model("viscoelastic", A=A), 1.0)
    kappa1 = scales["kappa"]
    speeds = np.logspace(-8, 2, 500)
    table = np.array([1 - float(bounce.master_cor(kappa1 * g ** 0.2)) ** 2 for g in speeds])
    return lambda g: float(np.interp(math.log(max(g, 1e-8)), np.log(speeds), table)), scales["hertz_contact_time"]


def viscoelastic_tau(build):
    """tau' of the leading order, T = T0 (1 + t/tau')^{-5/3}: with 1 - eps^2 = 2 (g/g*)^{1/5} (BP04
    (8.89), a1 = 1), dT/dt = -B T^{8/5}, B = (pi/3) n g2 sigma^2 m 2 g*^{-1/5} (1/2) (4/m)^{8/5}
    Gamma(21/10) / sqrt(pi), and tau' = 5 / (3 B T0^{3/5})."""
    sys.path.insert(0, os.path.join(build, "python"))
    import bounce
    pair = bounce.Pair(E=E, nu=NU, density=DENSITY, radius=RADIUS)
    g_star = bounce.viscoelastic_scales(pair, bounce.Model("viscoelastic", A=A), 1.0)["characteristic_velocity"]
    b = ((math.pi / 3) * NUMBER_DENSITY * G2 * SIGMA ** 2 * MASS * 2 * g_star ** -0.2 * 0.5 * (4 / MASS) ** 1.6 *
         math.gamma(2.1) / math.sqrt(math.pi))
    return 5.0 / (3.0 * b * T0 ** 0.6), g_star


def theory(loss, times):
    from scipy.integrate import solve_ivp
    sol = solve_ivp(lambda t, y: [cooling_rate(loss, y[0])], [0, times[-1]], [T0], t_eval=times, rtol=1e-8,
                    atol=T0 * 1e-14, method="LSODA")
    return sol.y[0]


def script(coeff, segments, dumps, plugin):
    """The LAMMPS input: the gas, then runs of (timestep, steps), a snapshot after those in `dumps`."""
    spacing = RADIUS * (4.0 * math.pi / (3.0 * PHI)) ** (1.0 / 3.0)
    temperature = MASS * SPEED ** 2 / (3.0 * 1.380649e-23)
    lines = [f"""units si
atom_style sphere
boundary p p p
comm_modify vel yes
lattice sc {spacing!r}
region box block 0 {CELLS} 0 {CELLS} 0 {CELLS}
create_box 1 box
create_atoms 1 box
set type 1 diameter {SIGMA!r}
set type 1 mass {MASS!r}
velocity all create {temperature!r} 4927 dist gaussian mom yes rot no loop geom
plugin load {plugin}
pair_style bounce
pair_coeff * * {coeff}
neighbor {RADIUS!r} bin
neigh_modify delay 0 every 1 check yes
fix 1 all nve/sphere
compute ke all ke
thermo_style custom step time c_ke
thermo_modify format float %.17g norm no"""]
    for k, (dt, steps) in enumerate(segments):
        lines.append(f"timestep {dt!r}\nthermo {max(steps // 40, 1)}\nrun {steps}")
        if k in dumps:
            lines.append(f"write_dump all custom snap{k}.dump id x y z vx vy vz modify sort id format float %.17g")
    return "\n".join(lines) + "\n"


def segments_for(t_end, dt_of_speed, count=24, first=None):
    """Runs covering [0, t_end], geometric in time, each with the time step for the thermal speed
    at its start (the gas cools: its contacts get longer for Hertz-type laws)."""
    first = first or t_end * 1e-3
    edges = [0.0] + list(np.geomspace(first, t_end, count))
    return edges


def run_gas(name, coeff, edges, dt_at, dumps, plugin, work, cores):
    segments = []
    for a, b in zip(edges, edges[1:]):
        dt = dt_at(a)
        segments.append((dt, max(int(round((b - a) / dt)), 1)))
    started = time.time()
    print(f"hcs: {name}: {sum(s for _, s in segments)} steps on {cores} ranks ...", flush=True)
    try:
        log = lammps_runs.run_in(work, script(coeff, segments, dumps, plugin), cores, "in.hcs")
    except RuntimeError as e:
        sys.exit(f"hcs: {e}")
    print(f"hcs: {name}: {time.time() - started:.0f} s", flush=True)
    rows = {int(step): (t, ke) for step, t, ke in lammps_runs.thermo_rows(log)}  # runs repeat a step
    data = np.array(sorted(rows.values()))
    snaps = {}
    for k in dumps:
        snaps[edges[k + 1]] = read_snapshot(os.path.join(work, f"snap{k}.dump"))
    return data[:, 0], 2.0 * data[:, 1] / (3.0 * N), snaps


def read_snapshot(path):
    lines = open(path).read().splitlines()
    box = [float(v) for v in lines[5].split()]
    length = box[1] - box[0]
    atoms = np.array([[float(v) for v in line.split()[1:]] for line in lines[9:]])
    return length, atoms


def homogeneity(length, atoms, cells=6):
    """(density ratio, flow ratio): the variance of the counts in cells^3 cells over their mean,
    and the kinetic energy of the cells' mean velocities over the value for uncorrelated grains
    (cells^3 / N of the total). A homogeneous gas: about 0.8 (hard spheres at phi = 0.03,
    Carnahan-Starling S(0)) and 1; clusters or vortices: far above."""
    index = np.floor((atoms[:, :3] % length) / length * cells).astype(int).clip(0, cells - 1)
    flat = (index[:, 0] * cells + index[:, 1]) * cells + index[:, 2]
    counts = np.bincount(flat, minlength=cells ** 3).astype(float)
    density = counts.var() / counts.mean()
    flow = 0.0
    for d in range(3):
        sums = np.bincount(flat, weights=atoms[:, 3 + d], minlength=cells ** 3)
        mean = np.divide(sums, counts, out=np.zeros_like(sums), where=counts > 0)
        flow += 0.5 * MASS * (counts * mean ** 2).sum()
    total = 0.5 * MASS * (atoms[:, 3:6] ** 2).sum()
    return density, flow / (total * cells ** 3 / len(atoms))


def fit(times, temperature, lo, hi):
    """alpha and t0 of T = C (t + t0)^alpha over lo <= t <= hi (least squares in log T)."""
    from scipy.optimize import curve_fit
    keep = (times >= lo) & (times <= hi)
    t, logt = times[keep], np.log(temperature[keep])
    model = lambda x, c, alpha, t0: c + alpha * np.log(x + t0)
    (c, alpha, t0), cov = curve_fit(model, t, logt, p0=[logt[0], -2.0, 0.1 * lo], bounds=([-np.inf, -5, -0.9 * lo],
                                                                                       [np.inf, 0, 10 * hi]))
    return alpha, t0, math.sqrt(cov[1, 1])


def main():
    args, build = lammps_runs.demo_setup(__doc__.splitlines()[0], ROOT, "hcs")
    plugin = lammps_runs.PLUGIN
    scale = 0.1 if args.quick else 1.0

    d1, d2, t_c_linear = linear_dashpot()
    tau0 = haff_tau0()
    loss_visco, t_c_hertz = viscoelastic_loss(build)
    gases = {
        "constant": dict(coeff=f"power-law power_d1 {d1!r} power_alpha 1 power_d2 {d2!r} power_beta 1 power_gamma 0 "
                               f"E {E!r} nu {NU}",
                         t_end=40 * tau0 * scale, window=(3 * tau0 * scale, 40 * tau0 * scale),
                         dt=lambda t: t_c_linear / 25, loss=lambda g: 1 - EPS ** 2, exponent=-2.0),
        "viscoelastic": dict(coeff=f"viscoelastic E {E!r} nu {NU} A {A!r}", t_end=30.0 * scale,
                             window=(2.0 * scale, 30.0 * scale), loss=loss_visco, exponent=-5.0 / 3.0,
                             # Hertz: t_c ~ g^{-1/5}; the thermal relative speed at time t from the
                             # theory (conservative: its value at the run's start)
                             dt=None),
    }
    tau_prime, g_star = viscoelastic_tau(build)
    results = {"N": N, "phi": PHI, "radius": RADIUS, "T0": T0, "collision_frequency": COLLISION_FREQUENCY,
               "haff_tau0": tau0, "eps": EPS, "viscoelastic_tau": tau_prime, "g_star": g_star, "quick": args.quick}
    curves = {}
    for name, gas in gases.items():
        grid = np.concatenate([[0.0], np.geomspace(gas["t_end"] * 1e-4, gas["t_end"], 400)])
        t_theory = theory(gas["loss"], grid)
        if gas["dt"] is None:
            def dt_at(t, grid=grid, t_theory=t_theory):
                speed = math.sqrt(16 * np.interp(t, grid, t_theory) / (math.pi * MASS))  # mean relative speed
                return t_c_hertz * (1.0 / max(speed, 1e-6)) ** 0.2 / 25  # t_c at 1 m/s scaled
            gas["dt"] = dt_at
        edges = segments_for(gas["t_end"], gas["dt"])
        dumps = [k for k, b in enumerate(edges[1:]) if b >= gas["window"][0] * 0.99]
        dumps = [dumps[0], dumps[len(dumps) // 2], dumps[-1]] if dumps else []
        with tempfile.TemporaryDirectory() as work:
            times, temperature, snaps = run_gas(name, gas["coeff"], edges, gas["dt"], dumps, plugin, work,
                                                args.cores)
        alpha, t0, err = fit(times, temperature, *gas["window"])
        checks = {f"{t:.4g}": dict(zip(("density", "flow"), homogeneity(*snap))) for t, snap in snaps.items()}
        late = times >= gas["window"][0]
        ratio = float(np.median(temperature[late] / np.interp(times[late], grid, t_theory)))
        results[name] = dict(alpha=alpha, alpha_error=err, t0=t0, window=gas["window"], expected=gas["exponent"],
                             homogeneity=checks, measured_over_theory=ratio)
        curves[name] = (times, temperature, grid, t_theory)
        print(f"hcs: {name}: alpha = {alpha:.4f} +- {err:.4f} (t0 = {t0:.4g} s) over t = {gas['window'][0]:.3g} .. "
              f"{gas['window'][1]:.3g} s; expected {gas['exponent']:.4f}; T / theory = {ratio:.3f} late; "
              f"homogeneity {checks}", flush=True)
    with open(os.path.join(args.out, "hcs", "results.json"), "w") as f:
        json.dump(results, f, indent=1)
    plot(curves, results, os.path.join(args.out, "figures", "hcs-cooling"))


def plot(curves, results, stem):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    colours = {"constant": "tab:blue", "viscoelastic": "tab:red"}
    labels = {"constant": f"constant $\\varepsilon$ = {EPS}", "viscoelastic": "viscoelastic $\\varepsilon(g)$"}
    for name, (times, temperature, grid, t_theory) in curves.items():
        r = results[name]
        keep = times > 0
        ax.loglog(times[keep], temperature[keep] / T0, ".", ms=2.5, color=colours[name],
                  label=f"LAMMPS, {labels[name]}: $\\alpha$ = {r['alpha']:.3f}")
        ax.loglog(grid[1:], t_theory[1:] / T0, "-", lw=1, color="k" if name == "constant" else "0.4",
                  label="kinetic theory" + (" (Haff)" if name == "constant" else ", $\\varepsilon(g)$ of bounce"))
        lo, hi = r["window"]
        span = np.geomspace(lo, hi, 20)
        ref = float(np.interp(hi, grid, t_theory)) / T0
        ax.loglog(span, 1.8 * ref * (span / hi) ** r["expected"], "--", color=colours[name], lw=1,
                  label=f"$t^{{{'-2' if name == 'constant' else '-5/3'}}}$")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("T / T$_0$")
    ax.set_title(f"Homogeneous cooling, {N} grains, $\\phi$ = {PHI}, pair_style bounce")
    ax.legend(fontsize=7)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(f"{stem}.{ext}", dpi=150)
    print(f"hcs: {stem}.png")


if __name__ == "__main__":
    main()
