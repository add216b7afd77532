"""bounce: will two adhesive, viscoelastic grains bounce or stick, and why?

The physics runs in the C++ library; this package exposes it with numpy arrays in and
out. A tour is in docs/python.md::

    import numpy as np, bounce
    pair = bounce.Pair(material="water-ice", radius=1e-6)
    model = bounce.Model("krijt", tvis=1e-11)
    bounce.collide(pair, model, 8.0)["cor"]
    bounce.collide(pair, model, np.geomspace(0.1, 100, 50))["cor"]   # an array, no Python loop

Errors: bad input raises ValueError naming the parameter, its value and the allowed
range; a numerical failure raises RuntimeError.
"""

from ._bounce import (  # noqa: F401
    ContactLaw,
    Model,
    NormalTable,
    Pair,
    apply_restitution,
    closed_forms,
    collide,
    collide_grains,
    contact_laws,
    cor_pade,
    cor_series,
    master_cor,
    material,
    material_names,
    sticking_velocity,
    viscoelastic_scales,
)

__all__ = [
    "ContactLaw",
    "Model",
    "NormalTable",
    "Pair",
    "apply_restitution",
    "closed_forms",
    "collide",
    "collide_grains",
    "contact_laws",
    "cor_pade",
    "cor_series",
    "master_cor",
    "material",
    "material_names",
    "sticking_velocity",
    "viscoelastic_scales",
]
