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

Errors: bad input raises ValueError naming the parameter, its value and the allowed
range (TypeError for a value of the wrong type); a numerical failure raises RuntimeError.
"""

from ._bounce import (  # noqa: F401
    ContactLaw,
    Model,
    NormalTable,
    Pair,
    TangentialTable,
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
    materials,
    models,
    sticking,
    sticking_velocity,
    viscoelastic_scales,
)



def curve(pair: Pair, model: Model, velocities, **options):
    """The COR curve over an array of impact speeds [m/s] (the CLI's `bounce curve`).

    The same as ``collide(pair, model, numpy.asarray(velocities, float), **options)``: a dict
    of arrays (velocity, cor, outcome, stick, contact_time, max_overlap, bulk_dissipated,
    crack_dissipated; cor_tangential with a tangential_velocity), the loop in C++.
    """
    import numpy as np

    return collide(pair, model, np.asarray(velocities, dtype=float), **options)


__all__ = [
    "ContactLaw",
    "Model",
    "NormalTable",
    "Pair",
    "TangentialTable",
    "apply_restitution",
    "closed_forms",
    "collide",
    "collide_grains",
    "contact_laws",
    "cor_pade",
    "curve",
    "cor_series",
    "master_cor",
    "material",
    "material_names",
    "materials",
    "models",
    "sticking",
    "sticking_velocity",
    "viscoelastic_scales",
]
