# Type hints for editors and type checkers (PEP 561): the functions' keyword arguments are the
# programs' keys (docs/inputs.md: trebuchet.fields() and trebuchet.settings(), each setting under
# its flag's word, its aliases read too); values are numbers or texts with units. Each function
# names every keyword it takes, so that a type checker catches a misspelt one (relase=).
from typing import Any, Literal, Mapping, Optional, Sequence, Union

import numpy as np
import pandas

Value = Union[float, int, str, np.generic]
Design = Mapping[str, Any]
Record = dict[str, Any]
Quality = Literal["Q", "eps", "range"]
Air = Union[bool, Literal["vacuum"], Mapping[str, Value]]
Machine = Literal["hinged", "fixed", "floating-arm", "whipper"]

__version__: str
__commit__: str

class TrebuchetError(ValueError):
    kind: str
    names: list[str]
    def __init__(self, message: str, kind: str, names: list[str]) -> None: ...

class TrebuchetWarning(UserWarning): ...

def design(**givens: Value) -> Record: ...
def shot(design: Design, *, series: bool = ..., quality: Quality = ..., release: Quality = ..., n: float = ..., tol: float = ...,
         tolerance: float = ..., stepper: str = ..., rtol: float = ..., atol: float = ..., target_level: Value = ...,
         range_from: Literal["pivot", "release"] = ..., air: Air = ..., air_density: Value = ..., cd: Union[float, str] = ...,
         projectile: Value = ..., wind: Value = ..., drag_in_sling: bool = ..., g: Value = ..., youngs_modulus: Value = ...,
         wood_density: Value = ..., modulus_of_rupture: Value = ..., rupture: Value = ..., beta2: Value = ..., release_time: Value = ...,
         release_angle_deg: Value = ..., release_angle: Value = ..., pin_angle_deg: Value = ..., pin_angle: Value = ..., machine: Machine = ...,
         L1: Value = ..., L2: Value = ..., L3: Value = ..., F: Value = ..., L4: Value = ..., M: Value = ..., m: Value = ..., mb: Value = ...,
         D: Value = ..., theta_i_deg: Value = ..., theta: Value = ..., psi_i_deg: Value = ..., psi_i: Value = ..., H: Value = ...,
         beam_cm: Value = ..., beam_inertia: Value = ..., beam_gyration: Value = ..., D_hinge: Value = ..., D_tip: Value = ...,
         counterweight_inertia: Value = ..., box_width: Value = ..., box_height: Value = ..., axle_friction: Value = ..., axle_radius: Value = ...,
         hinge_friction: Value = ..., hinge_radius: Value = ..., trough_friction: Value = ..., rope_diameter: Value = ..., rope_mass: Value = ...,
         pouch_mass: Value = ..., slingMass: Value = ..., pin_friction: Value = ..., rope_cd: Value = ..., rope_angle_deg: Value = ...,
         rope_angle: Value = ..., projectile_diameter: Value = ...) -> Record: ...
def fit(design: Design, R: Value, T: Value, *, quality: Quality = ..., release: Quality = ..., n: float = ..., tol: float = ...,
        tolerance: float = ..., stepper: str = ..., rtol: float = ..., atol: float = ..., target_level: Value = ...,
        range_from: Literal["pivot", "release"] = ..., air: Air = ..., air_density: Value = ..., cd: Union[float, str] = ..., projectile: Value = ...,
        wind: Value = ..., drag_in_sling: bool = ..., g: Value = ..., youngs_modulus: Value = ..., wood_density: Value = ...,
        modulus_of_rupture: Value = ..., rupture: Value = ..., beta2: Value = ..., release_time: Value = ..., release_angle_deg: Value = ...,
        release_angle: Value = ..., pin_angle_deg: Value = ..., pin_angle: Value = ..., machine: Machine = ..., L1: Value = ..., L2: Value = ...,
        L3: Value = ..., F: Value = ..., L4: Value = ..., M: Value = ..., m: Value = ..., mb: Value = ..., D: Value = ..., theta_i_deg: Value = ...,
        theta: Value = ..., psi_i_deg: Value = ..., psi_i: Value = ..., H: Value = ..., beam_cm: Value = ..., beam_inertia: Value = ...,
        beam_gyration: Value = ..., D_hinge: Value = ..., D_tip: Value = ..., counterweight_inertia: Value = ..., box_width: Value = ...,
        box_height: Value = ..., axle_friction: Value = ..., axle_radius: Value = ..., hinge_friction: Value = ..., hinge_radius: Value = ...,
        trough_friction: Value = ..., rope_diameter: Value = ..., rope_mass: Value = ..., pouch_mass: Value = ..., slingMass: Value = ...,
        pin_friction: Value = ..., rope_cd: Value = ..., rope_angle_deg: Value = ..., rope_angle: Value = ...,
        projectile_diameter: Value = ...) -> Record: ...
def optimize(R: Value, T: Optional[Value] = ..., *, m: Optional[Value] = ..., theta_i_deg: Value = ..., theta: Value = ..., F: Value = ...,
             l: Value = ..., machine: Machine = ..., quality: Quality = ..., release: Quality = ..., n: float = ..., stepper: str = ...,
             rtol: float = ..., atol: float = ..., range_from: Literal["pivot", "release"] = ..., air: Air = ..., air_density: Value = ...,
             cd: Union[float, str] = ..., projectile: Value = ..., wind: Value = ..., drag_in_sling: bool = ..., g: Value = ...,
             youngs_modulus: Value = ..., wood_density: Value = ..., modulus_of_rupture: Value = ..., rupture: Value = ...,
             beta2: Value = ...) -> list[Record]: ...
def sweep(design: Design, vary: str, *, points: int = ..., quality: Quality = ..., release: Quality = ..., n: float = ..., stepper: str = ...,
          rtol: float = ..., atol: float = ..., target_level: Value = ..., range_from: Literal["pivot", "release"] = ..., air: Air = ...,
          air_density: Value = ..., cd: Union[float, str] = ..., projectile: Value = ..., wind: Value = ..., drag_in_sling: bool = ...,
          g: Value = ..., youngs_modulus: Value = ..., wood_density: Value = ..., modulus_of_rupture: Value = ..., rupture: Value = ...,
          beta2: Value = ..., release_time: Value = ..., release_angle_deg: Value = ..., release_angle: Value = ..., pin_angle_deg: Value = ...,
          pin_angle: Value = ..., machine: Machine = ..., L1: Value = ..., L2: Value = ..., L3: Value = ..., F: Value = ..., L4: Value = ...,
          M: Value = ..., m: Value = ..., mb: Value = ..., D: Value = ..., theta_i_deg: Value = ..., theta: Value = ..., psi_i_deg: Value = ...,
          psi_i: Value = ..., H: Value = ..., beam_cm: Value = ..., beam_inertia: Value = ..., beam_gyration: Value = ..., D_hinge: Value = ...,
          D_tip: Value = ..., counterweight_inertia: Value = ..., box_width: Value = ..., box_height: Value = ..., axle_friction: Value = ...,
          axle_radius: Value = ..., hinge_friction: Value = ..., hinge_radius: Value = ..., trough_friction: Value = ..., rope_diameter: Value = ...,
          rope_mass: Value = ..., pouch_mass: Value = ..., slingMass: Value = ..., pin_friction: Value = ..., rope_cd: Value = ...,
          rope_angle_deg: Value = ..., rope_angle: Value = ..., projectile_diameter: Value = ...) -> Record: ...
def compare(design: Design, *, max_width: Value = ..., max_height: Value = ..., max_M: Value = ..., max_axle_load: Value = ...,
            max_acceleration: Value = ..., min_clearance: Value = ..., quality: Quality = ..., release: Quality = ..., n: float = ...,
            stepper: str = ..., rtol: float = ...,
            atol: float = ..., target_level: Value = ..., range_from: Literal["pivot", "release"] = ..., air: Air = ..., air_density: Value = ...,
            cd: Union[float, str] = ..., projectile: Value = ..., wind: Value = ..., drag_in_sling: bool = ..., g: Value = ...,
            youngs_modulus: Value = ..., wood_density: Value = ..., modulus_of_rupture: Value = ..., rupture: Value = ..., beta2: Value = ...,
            release_time: Value = ..., release_angle_deg: Value = ..., release_angle: Value = ..., pin_angle_deg: Value = ..., pin_angle: Value = ...,
            L1: Value = ..., L2: Value = ..., L3: Value = ..., F: Value = ..., L4: Value = ..., M: Value = ..., m: Value = ..., mb: Value = ...,
            D: Value = ..., theta_i_deg: Value = ..., theta: Value = ..., psi_i_deg: Value = ..., psi_i: Value = ..., H: Value = ...,
            beam_cm: Value = ..., beam_inertia: Value = ..., beam_gyration: Value = ..., D_hinge: Value = ..., D_tip: Value = ...,
            counterweight_inertia: Value = ..., box_width: Value = ..., box_height: Value = ..., axle_friction: Value = ..., axle_radius: Value = ...,
            hinge_friction: Value = ..., hinge_radius: Value = ..., trough_friction: Value = ..., rope_diameter: Value = ..., rope_mass: Value = ...,
            pouch_mass: Value = ..., slingMass: Value = ..., pin_friction: Value = ..., rope_cd: Value = ..., rope_angle_deg: Value = ...,
            rope_angle: Value = ..., projectile_diameter: Value = ...) -> list[Record]: ...
def contest(m: Value, *, machine: Union[Machine, Literal["all"]] = ..., D: Value = ..., mb_per_m: float = ..., theta_i_deg: Value = ...,
            theta: Value = ..., box_width: Value = ..., box_height: Value = ..., rope_mass: Value = ..., pouch_mass: Value = ...,
            pin_friction: float = ..., projectile_diameter: Value = ..., max_width: Value = ..., max_height: Value = ..., max_M: Value = ...,
            max_axle_load: Value = ..., max_acceleration: Value = ..., min_clearance: Value = ..., objective: Literal["range", "eps"] = ...,
            pareto: int = ..., stepper: str = ..., rtol: float = ..., atol: float = ..., target_level: Value = ...,
            range_from: Literal["pivot", "release"] = ..., air: Air = ..., air_density: Value = ..., cd: Union[float, str] = ...,
            projectile: Value = ..., wind: Value = ..., drag_in_sling: bool = ..., g: Value = ..., youngs_modulus: Value = ...,
            wood_density: Value = ..., modulus_of_rupture: Value = ..., rupture: Value = ..., beta2: Value = ...) -> Any: ...
def complete(attested: Design, *, quality: Quality = ..., release: Quality = ..., n: float = ..., stepper: str = ..., rtol: float = ...,
             atol: float = ..., target_level: Value = ..., range_from: Literal["pivot", "release"] = ..., air: Air = ..., air_density: Value = ...,
             cd: Union[float, str] = ..., projectile: Value = ..., wind: Value = ..., drag_in_sling: bool = ..., g: Value = ...,
             youngs_modulus: Value = ..., wood_density: Value = ..., modulus_of_rupture: Value = ..., rupture: Value = ..., beta2: Value = ...,
             L1: Value = ..., L2: Value = ..., F: Value = ..., L4: Value = ..., M: Value = ..., m: Value = ..., mb: Value = ..., D: Value = ...,
             theta_i_deg: Value = ..., theta: Value = ..., Lb: Value = ..., H: Value = ..., drop: Value = ..., l: Value = ...,
             counterweight_inertia: Value = ..., axle_friction: Value = ..., axle_radius: Value = ..., hinge_friction: Value = ...,
             hinge_radius: Value = ...,
             trough_friction: Value = ..., rope_diameter: Value = ..., rope_mass: Value = ..., pouch_mass: Value = ..., slingMass: Value = ...,
             rope_cd: Value = ..., projectile_diameter: Value = ...) -> Record: ...
def monte_carlo(design: Optional[Design] = ..., *, attested: Optional[Design] = ..., samples: Optional[int] = ..., seed: Optional[int] = ...,
                threads: Optional[int] = ..., progress: bool = ..., claim: Value = ..., draws_csv: bool = ..., quality: Quality = ...,
                release: Quality = ..., n: float = ..., stepper: str = ..., rtol: float = ..., atol: float = ..., target_level: Value = ...,
                range_from: Literal["pivot", "release"] = ..., air: Air = ..., air_density: Value = ..., cd: Union[float, str] = ...,
                projectile: Value = ..., wind: Value = ..., drag_in_sling: bool = ..., g: Value = ..., youngs_modulus: Value = ...,
                wood_density: Value = ..., modulus_of_rupture: Value = ..., rupture: Value = ..., beta2: Value = ..., release_time: Value = ...,
                release_angle_deg: Value = ..., release_angle: Value = ..., pin_angle_deg: Value = ..., pin_angle: Value = ...,
                machine: Machine = ..., L1: Value = ..., L2: Value = ..., L3: Value = ..., F: Value = ..., L4: Value = ..., M: Value = ...,
                m: Value = ..., mb: Value = ..., D: Value = ..., theta_i_deg: Value = ..., theta: Value = ..., psi_i_deg: Value = ...,
                psi_i: Value = ..., H: Value = ..., beam_cm: Value = ..., beam_inertia: Value = ..., beam_gyration: Value = ..., D_hinge: Value = ...,
                D_tip: Value = ..., counterweight_inertia: Value = ..., box_width: Value = ..., box_height: Value = ..., axle_friction: Value = ...,
                axle_radius: Value = ..., hinge_friction: Value = ..., hinge_radius: Value = ..., trough_friction: Value = ...,
                rope_diameter: Value = ..., rope_mass: Value = ..., pouch_mass: Value = ..., slingMass: Value = ..., pin_friction: Value = ...,
                rope_cd: Value = ..., rope_angle_deg: Value = ..., rope_angle: Value = ..., projectile_diameter: Value = ..., Lb: Value = ...,
                drop: Value = ..., l: Value = ...) -> Record: ...
def fields() -> list[Record]: ...
def settings() -> list[Record]: ...
def to_frame(answer: Union[Record, Sequence[Record]]) -> pandas.DataFrame: ...
