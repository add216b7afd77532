#!/usr/bin/python3
"""The validation tables of docs/lammps.md, measured: pair_style bounce (and the stock lines of
`bounce lammps`) in LAMMPS against `bounce collide`, over time steps. Not a test (the tests
assert the bounds); run by hand after `make lammps`:

    BOUNCE_LMP=build/lammps/lmp BOUNCE_PLUGIN=build/lammps/bounceplugin.so \\
    BOUNCE_CLI=build/bin/bounce /usr/bin/python3 tests/lammps/report.py
"""
import json
import math
import subprocess

import lammps_runs as L

ICE_QUARTZ = dict(material="ice-bshp96", material2="quartz", radius=0.01, radius2=0.004)
ICE = dict(material="ice-bshp96", radius=0.01)
STEPS = (250, 500, 1000, 2000, 4000)


def orders(errors, factor=2.0):
    return " ".join(f"{o:.2f}" for o in L.order(errors, factor))


def head_on_table():
    print("| model | pair | eps (bounce) | error at t_c/250 | t_c/500 | t_c/1000 | t_c/2000 | t_c/4000 | orders |")
    print("|---|---|---|---|---|---|---|---|---|")
    cases = [("viscoelastic", ICE_QUARTZ, dict(model="viscoelastic", A=1e-5), 1.0),
             ("viscoelastic, force", ICE_QUARTZ, dict(model="viscoelastic", A=1e-5, contact_end="force"), 1.0),
             ("viscoelastic", ICE, dict(model="viscoelastic", A=2e-6), 1.0),
             ("hertz", ICE_QUARTZ, dict(model="hertz"), 1.0),
             ("viscoelastic-shifted", ICE_QUARTZ, dict(model="viscoelastic-shifted", A=1e-5), 1.0),
             ("viscoelastic-shifted, force", ICE_QUARTZ,
              dict(model="viscoelastic-shifted", A=1e-5, contact_end="force"), 1.0)]
    for name, pair, model, v in cases:
        errors, ref = [], None
        for n in STEPS:
            eps, _, ref = L.head_on(pair, model, v, n)
            errors.append(eps - ref["cor"])
        label = "ice/quartz 10/4 mm" if pair is ICE_QUARTZ else "ice/ice 10 mm"
        print(f"| {name} (A = {model.get('A', 0)} s) | {label} | {ref['cor']:.6f} | " +
              " | ".join(f"{e:.1e}" for e in errors) + f" | {orders(errors)} |")


def jkr_table():
    print("| end | pair | v / v_s | eps (bounce) | error at t_c/250 | t_c/1000 | t_c/4000 | orders |")
    print("|---|---|---|---|---|---|---|---|")
    for end in ("fold", "pull-off"):
        for pair, label in ((dict(material="water-ice", radius=1e-6), "ice 1 µm"),
                            (dict(material="water-ice", material2="quartz", radius=1e-6, radius2=2e-6),
                             "ice/quartz 1/2 µm")):
            model = dict(model="jkr-viscoelastic", tvis=1e-11, contact_end=end)
            out = subprocess.run([L.CLI, "sticking", *L.cli_args(dict(pair, **model)), "--json"],
                                 capture_output=True, text=True, check=True)
            v_s = json.loads(out.stdout)["sticking_velocity"]
            for factor in (1.1, 2.0):
                errors = []
                for n in (250, 1000, 4000):
                    eps, _, ref = L.head_on(pair, model, factor * v_s, n)
                    errors.append(eps - ref["cor"])
                print(f"| {end} | {label} | {factor} (v_s = {v_s:.4g} m/s) | {ref['cor']:.5f} | " +
                      " | ".join(f"{e:.1e}" for e in errors) + f" | {orders(errors, 4.0)} |")


def oblique_table():
    print("| zeta0 / R_eff | form | g^N, g^T [m/s] | eps^T (bounce) | error at t_c/1000 | t_c/2000 | t_c/4000 |")
    print("|---|---|---|---|---|---|---|")
    for z, form, gn, gt in [(2e-4, "published", 0.1, 0.1), (2e-4, "published", 0.1, 0.001),
                            (1e-3, "published", 0.1, 0.001), (2e-4, "passive", 0.1, 0.001),
                            (2e-4, "published", 1.0, 0.1), (2e-4, "published", 1.0, 0.01),
                            (2e-4, "passive", 1.0, 0.01), (1e-3, "published", 1.0, 0.01)]:
        model = dict(model="viscoelastic", A=1e-6, friction=math.sqrt(z), asperity=z * 0.005, asperity_form=form)
        errors, ref = [], None
        for n in (1000, 2000, 4000):
            _, et, ref = L.head_on(ICE, model, gn, n, tangential_velocity=gt)
            errors.append(et - ref["cor_tangential"])
        print(f"| {z} | {form} | {gn}, {gt} | {ref['cor_tangential']:.4f} | " +
              " | ".join(f"{e:.1e}" for e in errors) + " |")


def export_table():
    print("| model | pair | error at t_c/1000 | t_c/2000 | t_c/4000 | extrapolated |")
    print("|---|---|---|---|---|---|")
    for pair, model, v, label in [
            (ICE, dict(model="viscoelastic", A=1e-5), 1.0, "ice 10 mm"),
            (ICE, dict(model="viscoelastic", A=1e-5, contact_end="force"), 1.0, "ice 10 mm"),
            (ICE_QUARTZ, dict(model="viscoelastic", A=1e-5), 1.0, "ice/quartz"),
            (dict(material="water-ice", radius=1e-6), dict(model="jkr-viscoelastic", tvis=1e-11, contact_end="pull-off"),
             2.0, "ice 1 µm, 2 m/s")]:
        out = subprocess.run([L.CLI, "lammps", *L.cli_args(dict(pair, **model)), "--json"], capture_output=True,
                             text=True, check=True)
        coeff = "granular " + json.loads(out.stdout)["pair_coeff"][0].split(" ", 3)[3]
        errors = []
        for n in (1000, 2000, 4000):
            eps, _, ref = L.head_on(pair, model, v, n, pair_style="granular", coeff=coeff)
            errors.append(eps - ref["cor"])
        name = model["model"] + (f" ({model['contact_end']})" if "contact_end" in model else "")
        print(f"| {name} | {label} | " + " | ".join(f"{e:.2e}" for e in errors) +
              f" | {2 * errors[2] - errors[1]:.1e} |")


def krijt_table():
    """krijt (1 um water ice) over T_vis, z0 and speeds in units of the sticking velocity: the COR's
    error and the energy budget's closure at t_H/100 and t_H/400 (K13's Hertz time (22))."""
    ice = dict(material="water-ice", radius=1e-6)
    print("| T_vis [s] | z0 [nm] | v_s [m/s] | v / v_s | COR (bounce) | COR error t_H/100 | t_H/400 | order | "
          "closure t_H/100 | t_H/400 |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for tvis in (1e-14, 1e-13, 1e-12, 1e-11):
        for z0 in (1e-10, 2e-10, 3e-10):
            model = dict(model="krijt", tvis=tvis, z0=z0)
            out = subprocess.run([L.CLI, "sticking", *L.cli_args(dict(ice, **model)), "--json"], capture_output=True,
                                 text=True, check=True)
            v_s = json.loads(out.stdout)["sticking_velocity"]
            for factor in (0.5, 1.5, 3.0, 5.0):
                runs = [L.krijt_collision(ice, model, factor * v_s, n) for n in (100, 400)]
                ref = runs[0]["ref"]["cor"]
                errors = [r["cor"] - ref for r in runs]
                order = f"{math.log(abs(errors[0] / errors[1])) / math.log(4.0):.1f}" if errors[1] else "-"
                print(f"| {tvis:g} | {z0 * 1e9:g} | {v_s:.3f} | {factor:g} | {ref:.5f} | {errors[0]:+.1e} | "
                      f"{errors[1]:+.1e} | {order} | {runs[0]['closure']:+.1e} | {runs[1]['closure']:+.1e} |")


if __name__ == "__main__":
    for title, table in (("head-on force laws", head_on_table), ("jkr-viscoelastic", jkr_table),
                         ("oblique", oblique_table), ("bounce lammps export", export_table), ("krijt", krijt_table)):
        print(f"\n### {title}\n")
        table()
