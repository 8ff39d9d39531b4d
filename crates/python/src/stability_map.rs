//! The native half of `kreisel.stability_map` (`python/kreisel/_stability.py`
//! is the other: the executor): a steady motion's stability over a grid
//! of one or two parameters, on threads ([`StabilityMap::try_new`]) or in
//! chunks of grid points computed anywhere and assembled here, with the
//! same boundaries by bisection — the same numbers either way.

use std::num::NonZeroUsize;

use kreisel_analysis::{
    AnalysisError, BoundaryEdge, BoundaryPoint, GridPoint, Linearisation, Parameter, StabilityMap,
    SteadyProblem, Sweep, Verdict, bisect_boundary, boundary_edges, grid_point,
};
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::arguments::{finite, int, integer, sequence};
use crate::errors::{error, guard};
use crate::stability::{PySteadyProblem, analysis_error, parameter};

/// Verdict codes of the map's `verdict` array.
const MISSING: i8 = -1;
const STABLE: i8 = 0;
const UNSTABLE: i8 = 1;
const NEUTRAL: i8 = 2;

/// The code of a grid point.
fn code(point: &GridPoint) -> i8 {
    match point {
        GridPoint::Missing { .. } => MISSING,
        GridPoint::Analysed { verdict, .. } => match verdict {
            Verdict::Stable { .. } => STABLE,
            Verdict::Unstable { .. } => UNSTABLE,
            Verdict::Neutral { .. } => NEUTRAL,
        },
    }
}

/// The linearisation of `problem` with `parameters` set to `values`.
fn analyse(
    problem: &SteadyProblem,
    parameters: &[Parameter],
    values: &[f64],
) -> Result<Linearisation, AnalysisError> {
    let mut p = problem.clone();
    for (&parameter, &value) in parameters.iter().zip(values) {
        p.set(parameter, value)?;
    }
    p.linearise()
}

/// The swept parameters and their sweeps from the dict ``sweeps`` (name ->
/// ``(from, to, n)``, in its order), each checked against `problem`: a
/// name it does not have, fewer than 2 values, an empty range or an end
/// it cannot be set to is the library's `Sweep` error.
fn sweeps(
    problem: &SteadyProblem,
    sweeps: &Bound<'_, PyAny>,
) -> PyResult<(Vec<Parameter>, Vec<Sweep>)> {
    let dict = sweeps.cast::<PyDict>().map_err(|_| {
        pyo3::exceptions::PyTypeError::new_err(format!(
            "sweeps: expected a dict of name -> (from, to, n), got {}",
            sweeps
                .get_type()
                .name()
                .map_or_else(|_| "?".into(), |n| n.to_string())
        ))
    })?;
    let mut parameters = Vec::new();
    let mut axes = Vec::new();
    for (key, value) in dict.iter() {
        let name: String = key.extract().map_err(|_| {
            pyo3::exceptions::PyTypeError::new_err("sweeps: the keys are parameter names (str)")
        })?;
        let label = format!("sweeps[{name:?}]");
        let items = sequence(&label, &value, 3, "items (from, to, n)", |_, v| {
            Ok(v.clone().unbind())
        })?;
        let item = |k: usize| items[k].bind(value.py());
        let from = finite(&format!("{label}[0]"), item(0))?;
        let to = finite(&format!("{label}[1]"), item(1))?;
        let count = int(&format!("{label}[2]"), item(2))?;
        let p = parameter(&name).map_err(analysis_error)?;
        let count = usize::try_from(count)
            .ok()
            .filter(|&n| n >= 2)
            .ok_or_else(|| {
                analysis_error(AnalysisError::Sweep {
                    name: name.clone(),
                    why: format!("N = {count}: a sweep needs at least 2 values"),
                })
            })?;
        let sweep = Sweep::try_new(name, from, to, count).map_err(analysis_error)?;
        for end in [from, to] {
            problem.clone().set(p, end).map_err(analysis_error)?;
        }
        if parameters.contains(&p) {
            return Err(analysis_error(AnalysisError::Sweep {
                name: p.name().into(),
                why: "swept twice".into(),
            }));
        }
        parameters.push(p);
        axes.push(sweep);
    }
    if axes.is_empty() || axes.len() > 2 {
        let names: Vec<&str> = parameters.iter().map(|p| p.name()).collect();
        return Err(analysis_error(AnalysisError::Sweep {
            name: names.join(", "),
            why: format!("{} parameters: a map sweeps one or two", axes.len()),
        }));
    }
    Ok((parameters, axes))
}

/// The number of grid points.
fn total(axes: &[Sweep]) -> usize {
    axes.iter().map(|a| a.count).product()
}

/// A grid's columns: largest real part, verdict code, and the reason of
/// each missing point (flat index, words).
struct Grid {
    max_real_part: Vec<f64>,
    verdict: Vec<i8>,
    missing: Vec<(usize, String)>,
}

impl Grid {
    fn of(points: &[GridPoint], offset: usize) -> Self {
        let missing = points
            .iter()
            .enumerate()
            .filter_map(|(k, p)| match p {
                GridPoint::Missing { reason } => Some((offset + k, reason.clone())),
                GridPoint::Analysed { .. } => None,
            })
            .collect();
        Self {
            max_real_part: points.iter().map(GridPoint::max_real_part).collect(),
            verdict: points.iter().map(code).collect(),
            missing,
        }
    }
}

/// The map's dict (see `kreisel.stability_map`).
fn map_dict<'py>(
    py: Python<'py>,
    problem: &SteadyProblem,
    axes: &[Sweep],
    parameters: &[Parameter],
    grid: Grid,
    boundaries: &[BoundaryPoint],
) -> PyResult<Bound<'py, PyDict>> {
    let dims = axes.len();
    let shape: Vec<usize> = axes.iter().rev().map(|a| a.count).collect();
    let dict = PyDict::new(py);
    dict.set_item("kind", problem.kind())?;
    let names: Vec<&str> = parameters.iter().map(|p| p.name()).collect();
    dict.set_item("names", names)?;
    let values = PyList::empty(py);
    for a in axes {
        let v: Vec<f64> = (0..a.count).map(|k| a.value(k)).collect();
        values.append(PyArray1::from_vec(py, v))?;
    }
    dict.set_item("values", values)?;
    dict.set_item(
        "max_real_part",
        PyArray1::from_vec(py, grid.max_real_part).reshape(shape.clone())?,
    )?;
    dict.set_item(
        "verdict",
        PyArray1::from_vec(py, grid.verdict).reshape(shape)?,
    )?;
    let missing: Vec<(usize, String)> = grid.missing;
    dict.set_item("missing", missing)?;
    let at: Vec<f64> = boundaries
        .iter()
        .flat_map(|b| b.at[..dims].to_vec())
        .collect();
    dict.set_item(
        "boundaries",
        PyArray1::from_vec(py, at).reshape([boundaries.len(), dims])?,
    )?;
    let axis: Vec<i64> = boundaries.iter().map(|b| b.axis as i64).collect();
    dict.set_item("boundary_axis", PyArray1::from_vec(py, axis))?;
    let width: Vec<f64> = boundaries.iter().map(|b| b.width).collect();
    dict.set_item("boundary_width", PyArray1::from_vec(py, width))?;
    let closed = PyDict::new(py);
    for &p in parameters {
        if let Some(v) = problem.closed_form_boundary(p) {
            closed.set_item(p.name(), PyArray1::from_vec(py, v))?;
        }
    }
    dict.set_item("closed_form", closed)?;
    Ok(dict)
}

/// The map on threads (``threads``: default the machine's), the GIL
/// released: [`StabilityMap::try_new`].
#[pyfunction]
#[pyo3(signature = (problem, sweeps, threads=None))]
fn _stability_map<'py>(
    py: Python<'py>,
    problem: PyRef<'py, PySteadyProblem>,
    sweeps: &Bound<'py, PyAny>,
    threads: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let problem = &problem.problem;
        let (parameters, axes) = self::sweeps(problem, sweeps)?;
        let threads = threads
            .map(|t| integer("threads", t, 1u32, 4096).map(|t| NonZeroUsize::new(t as usize)))
            .transpose()?
            .flatten();
        let map = py
            .detach(|| StabilityMap::try_new(&axes, threads, |p| analyse(problem, &parameters, p)))
            .map_err(analysis_error)?;
        let grid = Grid::of(&map.points, 0);
        map_dict(py, problem, &axes, &parameters, grid, &map.boundaries)
    })
}

/// A chunk of a grid: largest real parts, verdict codes, missing points.
type Chunk<'py> = (
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<i8>>,
    Vec<(usize, String)>,
);

/// The grid points ``start`` to ``stop - 1`` (flat, axis 0 fastest) of the
/// map: ``(max_real_part, verdict, missing)`` — what an executor's worker
/// computes for ``kreisel.stability_map``.
#[pyfunction]
fn _stability_map_points<'py>(
    py: Python<'py>,
    problem: PyRef<'py, PySteadyProblem>,
    sweeps: &Bound<'py, PyAny>,
    start: &Bound<'py, PyAny>,
    stop: &Bound<'py, PyAny>,
) -> PyResult<Chunk<'py>> {
    guard(|| {
        let problem = &problem.problem;
        let (parameters, axes) = self::sweeps(problem, sweeps)?;
        let n = total(&axes);
        let index = |name: &str, value: &Bound<'py, PyAny>, lo: usize| -> PyResult<usize> {
            let hi = u64::try_from(n).unwrap_or(u64::MAX);
            let lo = u64::try_from(lo).unwrap_or(u64::MAX);
            let k = integer(name, value, lo, hi)?;
            usize::try_from(k).map_err(|_| error(format!("{name}: {k} is out of range")))
        };
        let start = index("start", start, 0)?;
        let stop = index("stop", stop, start)?;
        let points: Vec<GridPoint> = py.detach(|| {
            (start..stop)
                .map(|index| point(problem, &parameters, &grid_point(&axes, index)))
                .collect()
        });
        let grid = Grid::of(&points, start);
        Ok((
            PyArray1::from_vec(py, grid.max_real_part),
            PyArray1::from_vec(py, grid.verdict),
            grid.missing,
        ))
    })
}

/// One grid point, as [`StabilityMap::try_new`] makes it.
fn point(problem: &SteadyProblem, parameters: &[Parameter], values: &[f64]) -> GridPoint {
    match analyse(problem, parameters, values) {
        Ok(lin) => GridPoint::Analysed {
            max_real_part: lin.max_real_part(),
            verdict: lin.verdict,
        },
        Err(e) => GridPoint::Missing {
            reason: e.to_string(),
        },
    }
}

/// Grid neighbours to bisect between: `(index, next, axis, whether
/// index is unstable)`.
type Edge = (usize, usize, usize, bool);

/// The grid neighbours to bisect between ([`boundary_edges`]), as plain
/// numbers.
fn edges(axes: &[Sweep], verdict: &[i8]) -> Vec<Edge> {
    let unstable: Vec<Option<bool>> = verdict
        .iter()
        .map(|&code| (code != MISSING).then_some(code == UNSTABLE))
        .collect();
    boundary_edges(axes, &unstable)
        .into_iter()
        .map(|e| (e.from, e.to, e.axis, e.from_unstable))
        .collect()
}

/// The verdict codes of a whole grid (`n` points), checked.
fn grid_codes(verdict: &PyReadonlyArray1<'_, i8>, n: usize) -> PyResult<Vec<i8>> {
    let codes = verdict.as_slice()?.to_vec();
    if codes.len() != n {
        return Err(error(format!(
            "verdict: {} values for a grid of {n} points",
            codes.len()
        )));
    }
    Ok(codes)
}

/// The grid neighbours of a gathered grid (its ``verdict`` codes, every
/// point, axis 0 fastest) to bisect between: ``(index, next, axis,
/// index_unstable)``.
#[pyfunction]
fn _stability_map_edges(
    problem: PyRef<'_, PySteadyProblem>,
    sweeps: &Bound<'_, PyAny>,
    verdict: PyReadonlyArray1<'_, i8>,
) -> PyResult<Vec<Edge>> {
    guard(|| {
        let (_, axes) = self::sweeps(&problem.problem, sweeps)?;
        let codes = grid_codes(&verdict, total(&axes))?;
        Ok(edges(&axes, &codes))
    })
}

/// A boundary point as plain numbers: `(at₀, at₁, axis, width)` (`at₁`
/// NaN for one sweep).
type Boundary = (f64, f64, usize, f64);

/// The boundary points bisected between each of ``edges`` (from
/// ``_stability_map_edges``), ``None`` where the
/// bisection met a missing point — what an executor's worker computes
/// for ``kreisel.stability_map``.
#[pyfunction]
fn _stability_map_bisect(
    py: Python<'_>,
    problem: PyRef<'_, PySteadyProblem>,
    sweeps: &Bound<'_, PyAny>,
    edges: Vec<Edge>,
) -> PyResult<Vec<Option<Boundary>>> {
    guard(|| {
        let problem = &problem.problem;
        let (parameters, axes) = self::sweeps(problem, sweeps)?;
        let n = total(&axes);
        let unstable = |p: &[f64]| {
            analyse(problem, &parameters, p)
                .ok()
                .map(|lin| matches!(lin.verdict, Verdict::Unstable { .. }))
        };
        if let Some(&(index, next, axis, _)) = edges
            .iter()
            .find(|&&(index, next, axis, _)| index >= n || next >= n || axis >= axes.len())
        {
            return Err(error(format!(
                "edges: ({index}, {next}, {axis}) is not an edge of a grid of {n} points"
            )));
        }
        Ok(py.detach(|| {
            edges
                .iter()
                .map(|&(from, to, axis, from_unstable)| {
                    let edge = BoundaryEdge {
                        from,
                        to,
                        axis,
                        from_unstable,
                    };
                    bisect_boundary(&axes, edge, unstable)
                        .map(|b| (b.at[0], b.at[1], b.axis, b.width))
                })
                .collect()
        }))
    })
}

/// The map of gathered grid columns (every point, axis 0 fastest) and the
/// gathered bisections of its edges (``None`` dropped), as
/// [`StabilityMap::try_new`] makes it.
#[pyfunction]
fn _stability_map_assemble<'py>(
    py: Python<'py>,
    problem: PyRef<'py, PySteadyProblem>,
    sweeps: &Bound<'py, PyAny>,
    max_real_part: PyReadonlyArray1<'py, f64>,
    verdict: PyReadonlyArray1<'py, i8>,
    missing: Vec<(usize, String)>,
    boundaries: Vec<Option<Boundary>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let problem = &problem.problem;
        let (parameters, axes) = self::sweeps(problem, sweeps)?;
        let n = total(&axes);
        let verdict = grid_codes(&verdict, n)?;
        let max_real_part = max_real_part.as_slice()?.to_vec();
        if max_real_part.len() != n {
            return Err(error(format!(
                "max_real_part: {} values for a grid of {n} points",
                max_real_part.len()
            )));
        }
        let boundaries: Vec<BoundaryPoint> = boundaries
            .into_iter()
            .flatten()
            .map(|(a0, a1, axis, width)| BoundaryPoint {
                at: [a0, a1],
                axis,
                width,
            })
            .collect();
        let grid = Grid {
            max_real_part,
            verdict,
            missing,
        };
        map_dict(py, problem, &axes, &parameters, grid, &boundaries)
    })
}

/// The number of grid points of ``sweeps`` for ``problem`` (checked as the
/// map checks them).
#[pyfunction]
fn _stability_map_size(
    problem: PyRef<'_, PySteadyProblem>,
    sweeps: &Bound<'_, PyAny>,
) -> PyResult<Vec<usize>> {
    guard(|| {
        let (_, axes) = self::sweeps(&problem.problem, sweeps)?;
        Ok(axes.iter().map(|a| a.count).collect())
    })
}

/// Adds the functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_stability_map, m)?)?;
    m.add_function(wrap_pyfunction!(_stability_map_points, m)?)?;
    m.add_function(wrap_pyfunction!(_stability_map_edges, m)?)?;
    m.add_function(wrap_pyfunction!(_stability_map_bisect, m)?)?;
    m.add_function(wrap_pyfunction!(_stability_map_assemble, m)?)?;
    m.add_function(wrap_pyfunction!(_stability_map_size, m)?)
}
