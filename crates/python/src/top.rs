//! `kreisel.top` (the report of `kreisel top --format json` as a dict) and
//! `kreisel.LagrangeTop` (the same top as an object whose motion is
//! evaluated at numpy arrays of times).
//!
//! No physics here: the arguments become the scene layer's [`TopRequest`],
//! checked and solved by its [`solve_and_summarise`] (so the numbers and
//! messages are the CLI's); the motion is the library's
//! [`kreisel_dynamics::LagrangeTopMotion`].

use kreisel_dynamics::LagrangeTopMotion;
use kreisel_scene::top_summary::{Summary, TopRequest, solve_and_summarise};
use numpy::{IxDyn, PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arguments::number;
use crate::errors::{error, guard, scene_error};

/// Arrays of times at least this long are evaluated without the GIL.
const DETACH_FROM: usize = 1024;

/// An optional argument (0 when absent).
type Rate<'a, 'py> = Option<&'a Bound<'py, PyAny>>;

/// The arguments as the CLI's (numbers, not yet checked: the CLI checks
/// them, naming the option, which [`scene_error`] names by its keyword).
fn args(
    [i1, i3, mgl, theta0]: [&Bound<'_, PyAny>; 4],
    [theta_dot0, phi_dot0, psi_dot0]: [Rate<'_, '_>; 3],
) -> PyResult<TopRequest> {
    let rate = |name, value: Rate<'_, '_>| value.map_or(Ok(0.0), |v| number(name, v));
    Ok(TopRequest {
        i1: number("i1", i1)?,
        i3: number("i3", i3)?,
        mgl: number("mgl", mgl)?,
        theta0: number("theta0", theta0)?,
        theta_dot0: rate("theta_dot0", theta_dot0)?,
        phi_dot0: rate("phi_dot0", phi_dot0)?,
        psi_dot0: rate("psi_dot0", psi_dot0)?,
    })
}

/// The summary as the dict of `kreisel top --format json` (keys in its
/// order; `null` is `None`; `roots` a numpy array).
fn summary_dict<'py>(py: Python<'py>, s: &Summary) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("i1", s.top.i1)?;
    d.set_item("i3", s.top.i3)?;
    d.set_item("mgl", s.top.mgl)?;
    d.set_item("theta0", s.top.theta0)?;
    d.set_item("theta_dot0", s.top.theta_dot0)?;
    d.set_item("phi_dot0", s.top.phi_dot0)?;
    d.set_item("psi_dot0", s.top.psi_dot0)?;
    d.set_item("a", s.a)?;
    d.set_item("b", s.b)?;
    d.set_item("alpha", s.alpha)?;
    d.set_item("beta", s.beta)?;
    d.set_item("omega3", s.omega3)?;
    d.set_item("roots", crate::mass::vector(py, &s.roots))?;
    d.set_item("theta_min", s.theta_min)?;
    d.set_item("theta_max", s.theta_max)?;
    d.set_item("nutation_period", s.nutation_period)?;
    d.set_item("mean_precession_rate", s.mean_precession_rate)?;
    d.set_item("motion", s.motion)?;
    d.set_item("sleeping", s.sleeping)?;
    d.set_item("sleeping_stable", s.sleeping_stable)?;
    Ok(d)
}

/// The heavy symmetric (Lagrange) top: the report of ``kreisel top
/// --format json`` as a dict with the same keys: the parameters, ``a``,
/// ``b``, ``alpha``, ``beta``, ``omega3``, ``roots`` (of f(u), ascending,
/// numpy), ``theta_min``, ``theta_max``, ``nutation_period`` and
/// ``mean_precession_rate`` (None for a sleeping top; the period also for
/// a steady precession and the axis on the vertical, θ₀ = π), ``motion``
/// ("no_loops", "loops", "cusps" or None), ``sleeping``,
/// ``sleeping_stable``.
///
/// i1: transverse moment about the pivot, i3: about the symmetry axis
/// (kg m^2), mgl = M g l (J); theta0 (rad, from the upward vertical) and
/// the initial rates (rad/s) of theta, phi (precession) and psi (spin).
/// Raises KreiselError with the CLI's message, naming the argument (``i3:
/// 0.7: exceeds 2 i1 …``); TypeError for an argument that is not a number.
///
/// >>> import kreisel
/// >>> r = kreisel.top(0.3, 0.1, 2.0, 0.5, psi_dot0=60.0)
/// >>> r["motion"], r["sleeping"]
/// ('cusps', False)
#[pyfunction]
#[pyo3(signature = (i1, i3, mgl, theta0, theta_dot0=None, phi_dot0=None, psi_dot0=None))]
#[pyo3(text_signature = "(i1, i3, mgl, theta0, theta_dot0=0.0, phi_dot0=0.0, psi_dot0=0.0)")]
#[allow(clippy::too_many_arguments)] // the Python keywords, one each
fn top<'py>(
    py: Python<'py>,
    i1: &Bound<'py, PyAny>,
    i3: &Bound<'py, PyAny>,
    mgl: &Bound<'py, PyAny>,
    theta0: &Bound<'py, PyAny>,
    theta_dot0: Rate<'_, 'py>,
    phi_dot0: Rate<'_, 'py>,
    psi_dot0: Rate<'_, 'py>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let args = args([i1, i3, mgl, theta0], [theta_dot0, phi_dot0, psi_dot0])?;
        let (_, summary) = solve_and_summarise(&args).map_err(scene_error)?;
        summary_dict(py, &summary)
    })
}

/// The heavy symmetric top as an object: ``LagrangeTop(i1, i3, mgl,
/// theta0, theta_dot0=0, phi_dot0=0, psi_dot0=0)`` (as ``kreisel.top``),
/// its ``summary`` (the dict of ``kreisel.top``) and its exact motion at
/// any numpy array of times (phi(0) = psi(0) = 0).
///
/// >>> import numpy as np, kreisel
/// >>> top = kreisel.LagrangeTop(0.3, 0.1, 2.0, 0.5, psi_dot0=60.0)
/// >>> e = top.euler_at(np.linspace(0.0, 1.0, 5))
/// >>> e["theta"].shape, round(float(e["theta"][0]), 12)
/// ((5,), 0.5)
/// >>> top.world_from_body_at([[0.0, 1.0]]).shape
/// (1, 2, 4)
#[pyclass(module = "kreisel", name = "LagrangeTop", frozen)]
pub struct PyLagrangeTop {
    motion: LagrangeTopMotion,
    summary: Summary,
}

impl PyLagrangeTop {
    /// `f` at every time of `t` (any shape), `width` numbers each: an
    /// array of shape `t.shape + (width,)` (no trailing axis for width 0).
    fn evaluate<'py, const N: usize>(
        &self,
        t: &Bound<'py, PyAny>,
        f: impl Fn(&LagrangeTopMotion, f64) -> [f64; N] + Sync,
    ) -> PyResult<(Vec<usize>, Vec<f64>)> {
        let py = t.py();
        let np = py.import("numpy")?;
        let bad = |what: String| error(format!("t must be an array of times (s): {what}"));
        let times = np
            .call_method1("asarray", (t, "float64"))
            .map_err(|e| bad(e.to_string()))?;
        let times = times
            .cast::<PyArrayDyn<f64>>()
            .map_err(|e| bad(e.to_string()))?;
        let view = times.readonly();
        let shape = view.shape().to_vec();
        let values: Vec<f64> = view.as_array().iter().copied().collect();
        if let Some(bad_t) = values.iter().find(|x| !x.is_finite()) {
            return Err(bad(format!("{bad_t} is not finite")));
        }
        let run = || -> Vec<f64> { values.iter().flat_map(|&t| f(&self.motion, t)).collect() };
        let out = if values.len() >= DETACH_FROM {
            py.detach(run)
        } else {
            run()
        };
        Ok((shape, out))
    }
}

/// `values` as an array of `shape` plus a trailing axis of `width`.
fn shaped<'py>(
    py: Python<'py>,
    mut shape: Vec<usize>,
    width: usize,
    values: Vec<f64>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    if width > 1 {
        shape.push(width);
    }
    numpy::PyArray1::from_vec(py, values).reshape(IxDyn(&shape))
}

#[pymethods]
impl PyLagrangeTop {
    #[new]
    #[pyo3(signature = (i1, i3, mgl, theta0, theta_dot0=None, phi_dot0=None, psi_dot0=None))]
    #[pyo3(text_signature = "(i1, i3, mgl, theta0, theta_dot0=0.0, phi_dot0=0.0, psi_dot0=0.0)")]
    fn new(
        i1: &Bound<'_, PyAny>,
        i3: &Bound<'_, PyAny>,
        mgl: &Bound<'_, PyAny>,
        theta0: &Bound<'_, PyAny>,
        theta_dot0: Rate<'_, '_>,
        phi_dot0: Rate<'_, '_>,
        psi_dot0: Rate<'_, '_>,
    ) -> PyResult<Self> {
        guard(|| {
            let args = args([i1, i3, mgl, theta0], [theta_dot0, phi_dot0, psi_dot0])?;
            let (motion, summary) = solve_and_summarise(&args).map_err(scene_error)?;
            Ok(Self { motion, summary })
        })
    }

    /// The report of ``kreisel top --format json`` (as ``kreisel.top``).
    #[getter]
    fn summary<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        guard(|| summary_dict(py, &self.summary))
    }

    /// The Euler angles z-x-z (rad) and their rates (rad/s) at the times
    /// ``t`` (s, any shape): a dict of arrays of t's shape, ``phi``,
    /// ``theta`` (in [0, pi]), ``psi``, ``phi_dot``, ``theta_dot``,
    /// ``psi_dot``; phi and psi continuous in t (not wrapped).
    fn euler_at<'py>(&self, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
        guard(|| {
            let py = t.py();
            let (shape, values) = self.evaluate(t, |m, t| {
                let e = m.euler_at(t);
                [e.phi, e.theta, e.psi, e.phi_dot, e.theta_dot, e.psi_dot]
            })?;
            let d = PyDict::new(py);
            let names = ["phi", "theta", "psi", "phi_dot", "theta_dot", "psi_dot"];
            for (k, name) in names.into_iter().enumerate() {
                let column: Vec<f64> = values.iter().skip(k).step_by(6).copied().collect();
                d.set_item(name, shaped(py, shape.clone(), 1, column)?)?;
            }
            Ok(d)
        })
    }

    /// The attitude world_from_body (w, x, y, z) at the times ``t``: shape
    /// ``t.shape + (4,)``.
    fn world_from_body_at<'py>(
        &self,
        t: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        guard(|| {
            let (shape, values) = self.evaluate(t, |m, t| {
                let q = m.world_from_body_at(t);
                [q.w, q.x, q.y, q.z]
            })?;
            shaped(t.py(), shape, 4, values)
        })
    }

    /// The angular velocity in body axes (rad/s) at the times ``t``: shape
    /// ``t.shape + (3,)``.
    fn omega_body_at<'py>(&self, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        guard(|| {
            let (shape, values) = self.evaluate(t, |m, t| m.omega_body_at(t).to_array())?;
            shaped(t.py(), shape, 3, values)
        })
    }

    fn __repr__(&self) -> String {
        let s = &self.summary;
        format!(
            "LagrangeTop(i1={}, i3={}, mgl={}, theta0={}, theta_dot0={}, phi_dot0={}, psi_dot0={})",
            s.top.i1,
            s.top.i3,
            s.top.mgl,
            s.top.theta0,
            s.top.theta_dot0,
            s.top.phi_dot0,
            s.top.psi_dot0
        )
    }
}

/// Adds this part's functions and classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(top, m)?)?;
    m.add_class::<PyLagrangeTop>()
}
