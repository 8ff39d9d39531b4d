"""Type stubs of kreisel (the native module kreisel._native, re-exported)."""

import os
from typing import Any, Literal, Optional, Sequence, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

class KreiselError(ValueError):
    """Bad input to kreisel: the message is the CLI's one line (what is wrong and where); for a bad argument it begins with the argument's name."""

# --- rotations ---------------------------------------------------------------

_Floats = npt.ArrayLike
"""Any array-like of real numbers (read as float64; complex, bool and str are refused)."""
_Array = npt.NDArray[np.float64]
_Frame = Literal["body", "world"]
_Sequence = Literal[
    "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ",
    "xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz",
]
_Representation = Union[
    Literal["quat", "quat-xyzw", "matrix", "rotvec", "axis-angle"],
    str,  # "euler:SEQ", e.g. "euler:ZXZ"
]

def from_euler(seq: Union[_Sequence, str], angles: _Floats, degrees: bool = False) -> _Array:
    """Quaternions (w, x, y, z), shape (..., 4), canonical (w >= 0), of Euler angles (..., 3).

    Uppercase seq is intrinsic ("ZXZ"), lowercase extrinsic ("zxz"). Bit for bit
    `kreisel convert --from euler:SEQ --to quat`. Raises KreiselError.
    """

def as_euler(seq: Union[_Sequence, str], quats: _Floats, degrees: bool = False) -> _Array:
    """Euler angles (..., 3) of quaternions (w, x, y, z) (..., 4) of any non-zero length.

    First and third angle in (-pi, pi], middle in [0, pi] (proper) or [-pi/2, pi/2]
    (Tait-Bryan); exactly at gimbal lock the third angle is 0. Raises KreiselError.
    """

def convert(values: _Floats, src: _Representation, dst: _Representation, degrees: bool = False) -> _Array:
    """Rotations from one representation of `kreisel convert` to another.

    "quat" (..., 4) w,x,y,z; "quat-xyzw" (..., 4); "matrix" (..., 3, 3) active, row-major;
    "rotvec" (..., 3) radians; "axis-angle" (..., 4) x,y,z,angle; "euler:SEQ" (..., 3).
    Raises KreiselError with the CLI's message, naming the bad row's index.
    """

def rates_from_omega(
    seq: Union[_Sequence, str],
    angles: _Floats,
    omega: _Floats,
    frame: _Frame = "body",
    degrees: bool = False,
) -> _Array:
    """Euler-angle rates (..., 3) of an angular velocity (body or world frame, rad per unit time).

    angles and omega broadcast. Raises KreiselError next to gimbal lock (|det| < 1e-9).
    """

def omega_from_rates(
    seq: Union[_Sequence, str],
    angles: _Floats,
    rates: _Floats,
    frame: _Frame = "body",
    degrees: bool = False,
) -> _Array:
    """Angular velocity (..., 3) in the body or world frame of Euler angles and their rates."""

def omega_from_attitudes(quats: _Floats, t: Union[_Floats, float], frame: _Frame = "body") -> _Array:
    """Angular velocity (..., N-1, 3) of an attitude series (..., N, 4) at times t (N,) or step dt.

    omega[i] = log(q[i]^-1 q[i+1]) / (t[i+1] - t[i]) (body), log(q[i+1] q[i]^-1) / dt (world):
    the constant rate over each interval, omega at the interval midpoint to O(dt^2).
    """

# --- mass properties, simulation, heavy top ---------------------------------

_Vec3 = Union[Sequence[float], npt.NDArray[np.floating]]
_Quat = Union[Sequence[float], npt.NDArray[np.floating]]
_Times = Union[float, Sequence[float], npt.NDArray[np.floating]]
_Units = Literal["mm", "cm", "m", "in"]
_Model = Literal["solid", "shell", "hull"]

# --- mass properties: the dict of `kreisel inertia --format json`
# Keys (assembly): file, units, scale, model, thickness (shell only), density,
# density_source, frame, mass, volume, area, triangles (int), center_of_mass
# (3,), inertia (3, 3), principal_moments (3,), principal_axes (3, 3, one axis
# per row), principal_orientation (4,) w x y z, warnings (list[str]), bodies
# (list of dicts: name and the same keys but bodies).

def mass_properties(
    path: Union[str, os.PathLike[str]],
    density: Optional[float] = None,
    mass: Optional[float] = None,
    units: _Units = "m",
    model: _Model = "solid",
    thickness: Optional[float] = None,
    *,
    weld: Union[None, float, Literal["off"]] = None,
    merge: bool = False,
    scale: Optional[float] = None,
) -> dict[str, Any]: ...
def mass_properties_from_arrays(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    density: Optional[float] = None,
    mass: Optional[float] = None,
    units: _Units = "m",
    model: _Model = "solid",
    thickness: Optional[float] = None,
    *,
    weld: Union[None, float, Literal["off"]] = None,
    name: str = "mesh",
    scale: Optional[float] = None,
) -> dict[str, Any]: ...

# --- simulation: the rows of `kreisel simulate` by CSV column name
# t, body (str array), qw, qx, qy, qz, wx, wy, wz, energy, lx, ly, lz, x, y, z,
# vx, vy, vz: one entry per body and output time.

# With events=True: (rows, events), events the rows of `--events FILE`:
# (time, body, contact, kind, approach_speed, rebound_speed, accumulation_time),
# contact the [[body.contact]] table's number (1 = the first) or None, the
# speeds and accumulation_time None where the CSV is empty.

_SceneEvent = tuple[float, str, Optional[int], str, Optional[float], Optional[float], Optional[float]]
_TableEvent = tuple[float, Optional[int], str, Optional[float], Optional[float], Optional[float]]

@overload
def simulate(
    scene: Union[str, os.PathLike[str]],
    method: Optional[str] = None,
    threads: Optional[int] = None,
    *,
    events: Literal[False] = False,
) -> dict[str, npt.NDArray[Any]]: ...
@overload
def simulate(
    scene: Union[str, os.PathLike[str]],
    method: Optional[str] = None,
    threads: Optional[int] = None,
    *,
    events: Literal[True],
) -> tuple[dict[str, npt.NDArray[Any]], list[_SceneEvent]]: ...

class World:
    """Rigid bodies (free, on a pivot or on the table) moved by the engine; SI units, radians."""

    def __init__(self, dt: float, gravity: _Vec3 = ..., method: str = "auto") -> None: ...
    def add_body(
        self,
        mass: float,
        moments: Optional[_Vec3] = None,
        inertia: Optional[Union[Sequence[Sequence[float]], npt.NDArray[np.floating]]] = None,
        *,
        attitude: Optional[_Quat] = None,
        omega_body: _Vec3 = ...,
        position: _Vec3 = ...,
        velocity: Optional[_Vec3] = None,
        pivot: Optional[_Vec3] = None,
        torque: Optional[_Vec3] = None,
        torque_body: Optional[_Vec3] = None,
        force: Optional[_Vec3] = None,
        angular_damping: float = 0.0,
        contacts: Optional[Sequence[dict[str, Any]]] = None,
    ) -> int: ...
    def set_inputs(
        self,
        body: int,
        *,
        torque: Optional[_Vec3] = None,
        torque_body: Optional[_Vec3] = None,
        force: Optional[_Vec3] = None,
        angular_damping: float = 0.0,
    ) -> None: ...
    def set_rotation(self, body: int, attitude: _Quat, omega_body: _Vec3) -> None: ...
    def step(self, h: float) -> None: ...
    def advance_steps(self, n: int) -> None: ...
    def advance_to(self, t: float) -> None: ...
    @property
    def time(self) -> float: ...
    @property
    def dt(self) -> float: ...
    @property
    def gravity(self) -> npt.NDArray[np.float64]: ...
    def __len__(self) -> int: ...
    def plan(self, body: int) -> str: ...
    def events(self, body: int) -> list[_TableEvent]:
        """(time, contact (index in contacts, or None), kind, approach_speed, rebound_speed,
        accumulation_time) per event of a body on the table, in time order."""
    def state(self, body: int) -> dict[str, Any]:
        """time, attitude (4,), omega_body (3,), l_world (3,), energy, position (3,), velocity (3,)."""
    def states(self) -> dict[str, Any]:
        """time, and the states of all n bodies stacked: attitude (n, 4), omega_body, l_world,
        position, velocity (n, 3), energy (n,)."""

# --- stability: is this motion stable? (kreisel-analysis) ---------------------

VERDICT_CODES: dict[int, str]
"""The codes of a stability map's ``verdict`` array: -1 missing (no steady motion), 0 stable, 1 unstable, 2 neutral."""

def stability(world: World, body: int) -> dict[str, Any]:
    """The linear stability of the steady motion nearest body ``body``'s state (free, or on a pivot).

    kind (str), parameters (name -> value), state (n,), state_names (n), frame ("body"/"space"),
    eigenvalues (m,) complex128 (1/s), modes (m, n) complex128 (one row per eigenvalue),
    space_frequencies (m,) rad/s (NaN where none), zero_modes [(kind, name)], dependent,
    reduced_by, residual, max_real_part, verdict ("stable"/"unstable"/"neutral") with
    asymptotic (stable), growth_rate (unstable, 1/s) or reason (neutral).

    Sleeping top (J1 about the pivot): stable iff I3^2 w3^2 > 4 J1 M g l; growth rate
    sqrt(4 J1 M g l - I3^2 w3^2)/(2 J1); precession in space (I3 w3 +- sqrt(I3^2 w3^2 - 4 J1 M g l))/(2 J1).
    T-handle: growth w sqrt((I2 - I1)(I3 - I2)/(I1 I3)). Raises KreiselError (the library's line).
    """

def stability_map(
    world: World,
    body: int,
    sweeps: dict[Literal["spin", "tilt", "com_offset", "gravity", "speed"], tuple[float, float, int]],
    executor: Optional[Any] = None,
    threads: Optional[int] = None,
    chunk: Optional[int] = None,
) -> dict[str, Any]:
    """The stability of body ``body``'s steady motion over one or two parameters: name -> (from, to, n).

    names, values (one array per axis), max_real_part and verdict (int8, VERDICT_CODES):
    shape (n0,), or (n1, n0) for two sweeps ([j, i] = (values[0][i], values[1][j])),
    boundaries (k, number of sweeps) by bisection to 4 ulp, boundary_axis (k,),
    boundary_width (k,), missing [(flat index, reason)], closed_form (name -> values), kind.
    On threads by default; with ``executor`` (any concurrent.futures.Executor, e.g.
    dask.distributed's Client.get_executor()) in chunks of ``chunk`` grid points,
    the same numbers bit for bit. A bad sweep raises KreiselError (a ValueError).
    """

# --- the heavy symmetric top: the dict of `kreisel top --format json`
# i1, i3, mgl, theta0, theta_dot0, phi_dot0, psi_dot0, a, b, alpha, beta,
# omega3, roots (array), theta_min, theta_max, nutation_period (None when
# sleeping, precessing steadily or on the vertical), mean_precession_rate
# (None when sleeping or on the vertical), motion ("no_loops",
# "loops", "cusps" or None), sleeping, sleeping_stable.

def top(
    i1: float,
    i3: float,
    mgl: float,
    theta0: float,
    theta_dot0: float = 0.0,
    phi_dot0: float = 0.0,
    psi_dot0: float = 0.0,
) -> dict[str, Any]: ...

class LagrangeTop:
    def __init__(
        self,
        i1: float,
        i3: float,
        mgl: float,
        theta0: float,
        theta_dot0: float = 0.0,
        phi_dot0: float = 0.0,
        psi_dot0: float = 0.0,
    ) -> None: ...
    @property
    def summary(self) -> dict[str, Any]: ...
    def euler_at(self, t: _Times) -> dict[str, npt.NDArray[np.float64]]:
        """phi, theta, psi, phi_dot, theta_dot, psi_dot, each of t's shape."""
    def world_from_body_at(self, t: _Times) -> npt.NDArray[np.float64]:
        """Shape t.shape + (4,), w x y z."""
    def omega_body_at(self, t: _Times) -> npt.NDArray[np.float64]:
        """Shape t.shape + (3,), body axes."""
