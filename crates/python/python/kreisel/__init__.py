"""kreisel: rigid-body rotations done right (Rust, via PyO3)."""

from ._native import *  # noqa: F401,F403
from ._native import __version__  # noqa: F401
from ._stability import VERDICT_CODES, stability_map  # noqa: F401
