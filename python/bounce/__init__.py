"""bounce: will two adhesive, viscoelastic grains bounce or stick, and why?

The physics runs in the C++ library; this package exposes it with numpy arrays in and
out. A tour is in docs/python.md::

    import numpy as np, bounce
    pair = bounce.Pair(material="water-ice", radius=1e-6)
    model = bounce.Model("krijt", tvis=1e-11)
    bounce.collide(pair, model, 8.0)["cor"]
    bounce.collide(pair, model, np.geomspace(0.1, 100, 50))["cor"]   # an array, no Python loop

The parameters are those of the command line (`bounce models` / bounce.models() lists each
model's), as keywords: bounce.Model("power-law", power_d1=..., power_d2=...). Results are
dicts with the keys of the CLI's JSON.

Errors follow one rule, "NAME = VALUE is invalid: expected ...": a value out of its allowed
range (or one whose results would be inf or NaN) raises ValueError, a value of the wrong
type (a bool, a str or None where a number is expected) TypeError; a numerical failure
raises RuntimeError. Ctrl-C interrupts the long calls (KeyboardInterrupt).
"""

from ._bounce import (  # noqa: F401
    ContactLaw,
    Model,
    NormalTable,
    Pair,
    TangentialTable,
    ValidityWarning,
    apply_restitution,
    build_aggregate,
    closed_forms,
    collide,
    collide_grains,
    contact_laws,
    contact_resistance,
    cor_pade,
    cor_series,
    curve,
    fit,
    master_cor,
    material,
    material_names,
    materials,
    models,
    sticking,
    sticking_velocity,
    viscoelastic_scales,
)
from ._bounce import __version__  # noqa: F401  (the library's, the CMake project's version)
from .posterior import posterior  # noqa: F401  (emcee over a fit's parameters)


__all__ = [
    "ContactLaw",
    "Model",
    "NormalTable",
    "Pair",
    "TangentialTable",
    "ValidityWarning",
    "apply_restitution",
    "build_aggregate",
    "closed_forms",
    "collide",
    "collide_grains",
    "contact_laws",
    "contact_resistance",
    "cor_pade",
    "curve",
    "fit",
    "cor_series",
    "master_cor",
    "material",
    "material_names",
    "materials",
    "models",
    "posterior",
    "sticking",
    "sticking_velocity",
    "viscoelastic_scales",
]
