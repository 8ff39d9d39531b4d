"""kreisel.stability_map: a steady motion's stability over a grid of one or two
parameters, on threads (default) or through any concurrent.futures.Executor."""

from __future__ import annotations

import math
import numbers
from collections.abc import Mapping
from typing import Any, Optional

import numpy as np

from . import _native

__all__ = ["stability_map", "VERDICT_CODES"]

VERDICT_CODES = {-1: "missing", 0: "stable", 1: "unstable", 2: "neutral"}
"""The codes of a map's ``verdict`` array (-1: no steady motion at that point)."""


def _map_chunk(problem: Any, sweeps: dict, start: int, stop: int) -> tuple:
    """Grid points ``start`` to ``stop - 1`` (flat, axis 0 fastest) of a map,
    computed in Rust: ``(max_real_part, verdict, missing)``.

    A module-level function, so that an executor pickles it by reference and
    runs it in another process (``problem`` pickles as plain numbers).
    """
    mrp, verdict, missing = _native._stability_map_points(problem, sweeps, start, stop)
    return np.asarray(mrp), np.asarray(verdict), list(missing)


def _bisect_chunk(problem: Any, sweeps: dict, edges: list) -> list:
    """The boundary points bisected between grid neighbours ``edges`` of a
    map, computed in Rust: ``(at0, at1, axis, width)`` or ``None`` each
    (module-level, as ``_map_chunk``)."""
    return _native._stability_map_bisect(problem, sweeps, edges)


def stability_map(
    world: Any,
    body: int,
    sweeps: Mapping[str, tuple],
    executor: Optional[Any] = None,
    threads: Optional[int] = None,
    chunk: Optional[int] = None,
) -> dict:
    """The stability of body ``body``'s steady motion (``kreisel.stability``)
    over a grid of one or two of its parameters.

    ``sweeps`` maps a parameter name (``"spin"`` rad/s, ``"tilt"`` rad,
    ``"com_offset"`` m, ``"gravity"`` m/s^2, ``"speed"`` m/s) to ``(from, to,
    n)``: ``n >= 2`` values ``p_k = from + (to - from) k/(n - 1)``, both ends
    included; the first key is axis 0, the second (if any) axis 1. The other
    parameters keep the steady motion's values. At each point: the largest
    real part of the eigenvalues left once every zero eigenvalue is accounted
    for, and the verdict.

    Returns a dict of numpy arrays:

    - ``names``: the swept parameters, axis 0 first; ``values``: their values
      (one array per axis);
    - ``max_real_part`` (1/s; NaN where there is no steady motion) and
      ``verdict`` (int8, ``VERDICT_CODES``: -1 missing, 0 stable, 1 unstable,
      2 neutral): shape ``(n0,)`` for one sweep, ``(n1, n0)`` for two — row
      ``j`` is axis 1's ``values[1][j]``, column ``i`` axis 0's
      ``values[0][i]`` (``max_real_part[j, i]``; axis 0 fastest, as the Rust
      ``StabilityMap``);
    - ``boundaries`` (shape ``(k, number of sweeps)``): the points where the
      verdict turns between unstable and not, located by bisection between
      grid neighbours that differ until the bracket is 4 ulp wide (not read
      off the grid), with ``boundary_axis`` (the axis bisected along) and
      ``boundary_width`` (the final bracket's width);
    - ``missing``: ``(flat index, reason)`` where there is no steady motion;
      ``closed_form``: name -> the boundary values of the closed form where
      there is one (the sleeping top: ``J3^2 spin^2 = 4 J1 M g l``, ``J1``
      about the pivot), ``kind``.

    By default the grid is computed in Rust on ``threads`` threads (default:
    the machine's), the GIL released. With ``executor`` (any
    ``concurrent.futures.Executor``: a ``ThreadPoolExecutor``, a
    ``ProcessPoolExecutor``, ``dask.distributed.Client.get_executor()``) the
    grid is cut into chunks of ``chunk`` points (default: one row of a
    two-parameter map, or a sixteenth of a one-parameter one), each submitted
    as ``kreisel._stability._map_chunk`` with the steady motion (picklable:
    plain numbers); then the bisections of the boundaries, as many tasks
    (``_bisect_chunk``); ``threads`` is not used then. The result is the
    same, bit for bit, as without an executor.

    >>> import kreisel
    >>> w = kreisel.World(dt=0.01, gravity=(0, 0, -9.81))
    >>> top = w.add_body(1.0, moments=(0.02, 0.02, 0.04), omega_body=(0, 0, 30.0),
    ...                  pivot=(0, 0, -0.1))
    >>> m = kreisel.stability_map(w, top, {"spin": (5.0, 30.0, 11)})
    >>> critical = (4 * (0.02 + 1.0 * 0.1**2) * 1.0 * 9.81 * 0.1) ** 0.5 / 0.04
    >>> bool(abs(m["boundaries"][0, 0] / critical - 1) < 1e-12)
    True

    Raises KreiselError (a ValueError) with the library's one line for a
    parameter this motion has not, ``n < 2``, an empty or infinite range, or
    more than two sweeps.
    """
    problem = _native._steady_problem(world, body)
    if isinstance(sweeps, Mapping) and not isinstance(sweeps, dict):
        sweeps = dict(sweeps)
    if executor is None:
        return _native._stability_map(problem, sweeps, threads)
    if not callable(getattr(executor, "submit", None)):
        raise TypeError(
            f"executor: expected a concurrent.futures.Executor (with submit), got {type(executor).__name__}"
        )
    shape = _native._stability_map_size(problem, sweeps)
    total = math.prod(shape)
    if chunk is None:
        chunk = shape[0] if len(shape) == 2 else max(1, -(-shape[0] // 16))
    if isinstance(chunk, bool) or not isinstance(chunk, numbers.Integral):
        raise TypeError(f"chunk: expected an integer (grid points per task), got {type(chunk).__name__}")
    chunk = int(chunk)
    if chunk < 1:
        raise _native.KreiselError(f"chunk: {chunk}: must be a positive integer (grid points per task)")
    starts = range(0, total, chunk)
    futures = [executor.submit(_map_chunk, problem, sweeps, s, min(s + chunk, total)) for s in starts]
    parts = [f.result() for f in futures]
    mrp = np.concatenate([p[0] for p in parts]).astype(np.float64, copy=False)
    verdict = np.concatenate([p[1] for p in parts]).astype(np.int8, copy=False)
    missing = [(int(k), str(r)) for p in parts for (k, r) in p[2]]
    # The boundaries: one bisection (~50 linearisations) per pair of grid
    # neighbours whose verdicts differ, also on the executor.
    edges = _native._stability_map_edges(problem, sweeps, verdict)
    per_task = max(1, -(-len(edges) // max(1, len(futures))))
    futures = [
        executor.submit(_bisect_chunk, problem, sweeps, edges[k : k + per_task])
        for k in range(0, len(edges), per_task)
    ]
    boundaries = [b for f in futures for b in f.result()]
    return _native._stability_map_assemble(problem, sweeps, mrp, verdict, missing, boundaries)
