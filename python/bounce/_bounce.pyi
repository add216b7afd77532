"""Type stubs of the C++ extension (python/src/module.cpp)."""
from typing import Any, Dict, List, Optional, Sequence, Union, overload

import numpy as np
import numpy.typing as npt

ArrayLike = Union[float, Sequence[float], npt.NDArray[np.float64]]

def material_names() -> List[str]: ...
def material(name: str) -> Dict[str, Any]: ...

class Pair:
    def __init__(
        self,
        *,
        material: Optional[str] = ...,
        radius: Optional[float] = ...,
        E: Optional[float] = ...,
        nu: Optional[float] = ...,
        density: Optional[float] = ...,
        gamma: Optional[float] = ...,
        material2: Optional[str] = ...,
        radius2: Optional[float] = ...,
        E2: Optional[float] = ...,
        nu2: Optional[float] = ...,
        density2: Optional[float] = ...,
        gamma2: Optional[float] = ...,
        wall: str = ...,
        inertia: float = ...,
        inertia2: Optional[float] = ...,
    ) -> None: ...
    @property
    def effective_radius(self) -> float: ...
    @property
    def effective_mass(self) -> float: ...
    @property
    def effective_modulus(self) -> float: ...
    @property
    def surface_energy(self) -> Optional[float]: ...
    @property
    def kappa(self) -> float: ...

class Model:
    name: str
    def __init__(
        self,
        name: str = ...,
        *,
        A: Optional[float] = ...,
        eta1: Optional[float] = ...,
        eta2: Optional[float] = ...,
        contact_end: str = ...,
        tvis: Optional[float] = ...,
        z0: float = ...,
        k: float = ...,
        B: Optional[float] = ...,
        yield_strength: Optional[float] = ...,
        tangential_law: str = ...,
        asperity_form: str = ...,
        friction: Optional[float] = ...,
        asperity: Optional[float] = ...,
        shear_damping: Optional[float] = ...,
    ) -> None: ...

@overload
def collide(pair: Pair, model: Model, velocity: float, *, tangential_velocity: float = ..., method: str = ...) -> Dict[str, Any]: ...
@overload
def collide(pair: Pair, model: Model, velocity: npt.ArrayLike, *, tangential_velocity: float = ..., method: str = ...) -> Dict[str, npt.NDArray[Any]]: ...
def sticking_velocity(pair: Pair, model: Model, relative_tolerance: float = ...) -> float: ...
def master_cor(kappa: npt.ArrayLike, contact_end: str = ...) -> npt.NDArray[np.float64]: ...

class NormalTable:
    g_min: float
    g_max: float
    sticking_velocity: float
    bound: float
    @staticmethod
    def build(pair: Pair, model: Model, g_min: float, g_max: float, bound: float = ...) -> "NormalTable": ...
    @staticmethod
    def from_json(text: str) -> "NormalTable": ...
    def cor(self, velocity: ArrayLike) -> Any: ...
    def sticks(self, velocity: ArrayLike) -> Any: ...
    def to_json(self) -> str: ...
    def to_csv(self) -> str: ...
    def to_c_header(self, prefix: str) -> str: ...

def apply_restitution(pair: Pair, normal: Sequence[float], velocity1: Sequence[float], angular_velocity1: Sequence[float],
                      velocity2: Sequence[float], angular_velocity2: Sequence[float], cor: float,
                      cor_tangential: float = ...) -> Dict[str, Any]: ...
def collide_grains(pair: Pair, model: Model, normal: Sequence[float], velocity1: Sequence[float],
                   angular_velocity1: Sequence[float], velocity2: Sequence[float],
                   angular_velocity2: Sequence[float]) -> Dict[str, Any]: ...
