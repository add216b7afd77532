#!/usr/bin/python3
"""How well the warning "the outcome rests on T_vis" predicts what T_vis does (issue 40 point 20).

krijt's collisions of water ice and quartz over radii 0.1-100 um, T_vis 1e-14-1e-10 s and twelve
speeds 0.3-100 m/s, each run again at T_vis/10, T_vis/2, 2 T_vis and 10 T_vis. A change is
material when the outcome flips (stick against bounce) or e moves by more than 0.1. The counts it
prints are what docs/adhesive-models.md, "When an outcome rests on T_vis", records (~3 s).

    PYTHONPATH=build/python /usr/bin/python3 tools/tvis_dependence.py
"""
import warnings

import numpy as np

import bounce

MATERIALS = ["water-ice", "quartz"]
RADII = [1e-7, 3e-7, 1e-6, 1e-5, 1e-4]
TVIS = [1e-14, 1e-13, 1e-12, 1e-11, 1e-10]
FACTORS = [0.1, 0.5, 1.0, 2.0, 10.0]
SPEEDS = np.geomspace(0.3, 100.0, 12)
MARKER = "the outcome rests on T_vis"


def runs(pair, tvis):
    """e, stick and whether the warning was given, at each speed, for each factor of T_vis."""
    out = {}
    for f in FACTORS:
        c = bounce.curve(pair, bounce.Model("krijt", tvis=tvis * f), SPEEDS)
        out[f] = (np.asarray(c["cor"]), np.asarray(c["stick"]))
    return out


def warned(pair, tvis, speed):
    """Whether the collision carries the warning, and its 5.57 A/t_H (K13 (26))."""
    r = bounce.collide(pair, bounce.Model("krijt", tvis=tvis), float(speed))
    c = r["closed_forms"]
    return any(w.startswith(MARKER) for w in r["warnings"]), 5.57 * c["dissipative_constant"] / c["hertz_time_k13_22"]


def material(e, stick, i, f):
    """Whether T_vis * f changes the outcome at speed i materially."""
    return stick[f][i] != stick[1.0][i] or abs(e[f][i] - e[1.0][i]) > 0.1


def main():
    warnings.simplefilter("ignore")
    rows = []
    for name in MATERIALS:
        for radius in RADII:
            pair = bounce.Pair(material=name, radius=radius)
            for tvis in TVIS:
                r = runs(pair, tvis)
                e = {f: r[f][0] for f in FACTORS}
                stick = {f: r[f][1] for f in FACTORS}
                for i, v in enumerate(SPEEDS):
                    said, damping = warned(pair, tvis, v)
                    rows.append({
                        "warned": said, "stick": bool(stick[1.0][i]), "damping": damping,
                        "rise_at_half": e[0.5][i] - e[1.0][i],
                        "bounce_at_half": not stick[0.5][i], "bounce_at_tenth": not stick[0.1][i],
                        "factor2": material(e, stick, i, 0.5) or material(e, stick, i, 2.0),
                        "factor10": material(e, stick, i, 0.1) or material(e, stick, i, 10.0),
                    })
    report(rows)


def report(rows):
    bounces = [r for r in rows if r["warned"] and not r["stick"]]
    sticks = [r for r in rows if r["warned"] and r["stick"]]
    quiet = [r for r in rows if not r["warned"]]
    print(f"{len(rows)} collisions, {len(bounces)} warned bounces, {len(sticks)} warned sticks")
    if bounces:
        print(f"warned bounces: e at T_vis/2 higher by {min(r['rise_at_half'] for r in bounces):.3f} at least")
    held = [r for r in sticks if not r["bounce_at_tenth"]]
    print(f"warned sticks: {sum(r['bounce_at_half'] for r in sticks)} bounce at T_vis/2, "
          f"{sum(r['bounce_at_tenth'] for r in sticks)} at T_vis/10; the {len(held)} others have 5.57 A/t_H >= "
          f"{min((r['damping'] for r in held), default=float('nan')):.2f}")
    print(f"not warned: {sum(r['factor2'] for r in quiet)} of {len(quiet)} change materially within a factor 2, "
          f"{sum(r['factor10'] for r in quiet)} within a factor 10")


if __name__ == "__main__":
    main()
