"""Type stubs of kreisel (the native module kreisel._native, re-exported)."""

from typing import Literal, Union

import numpy as np
import numpy.typing as npt

__version__: str

class KreiselError(ValueError):
    """Bad input to kreisel: the message is the CLI's one line (what is wrong and where)."""

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
# (written by the helper who owns mass.rs, simulation.rs and top.rs)
