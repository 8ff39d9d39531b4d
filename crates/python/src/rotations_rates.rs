//! Angular velocity for Python: Euler-angle rates ⇄ angular velocity (body
//! or world frame), and the angular velocity of an attitude series.
//!
//! Thin loops over `kreisel_kinematics` (`EulerSequence::rate_matrix_*`,
//! `rates_from_omega_*`, `omega_*_from_attitudes`); angles and vectors
//! broadcast against each other as numpy arrays do. The GIL is released
//! while the rows are computed.

use glam::{DQuat, DVec3};
use kreisel_kinematics::{
    KinematicsError, omega_body_from_attitudes, omega_world_from_attitudes, try_normalize_quat,
};
use kreisel_scene::line_problem::LineProblem;
use numpy::PyArrayDyn;
use numpy::ndarray::{ArrayViewD, IxDyn};
use pyo3::prelude::*;

use crate::errors::{error, guard};
use crate::rotations::parse_sequence;
use crate::rotations_arrays::{Floats, non_finite, row_name, shape_text, to_numpy};

/// The frame an angular velocity is written in.
#[derive(Clone, Copy)]
enum In {
    Body,
    World,
}

/// Parses `"body"` or `"world"`.
fn parse_frame(text: &str) -> PyResult<In> {
    match text {
        "body" => Ok(In::Body),
        "world" => Ok(In::World),
        _ => Err(error(format!("frame `{text}`: expected `body` or `world`"))),
    }
}

/// `(..., 3)` arrays `a` and `b` broadcast against each other: the common
/// leading shape and both arrays' values in C order of that shape.
fn broadcast_pair(a: &Floats<'_>, b: &Floats<'_>) -> PyResult<(Vec<usize>, Vec<f64>, Vec<f64>)> {
    let lead_a = a.leading_shape(&[3], "3 numbers")?;
    let lead_b = b.leading_shape(&[3], "3 numbers")?;
    let k = lead_a.len().max(lead_b.len());
    let mut shape = vec![0; k];
    for (n, slot) in shape.iter_mut().enumerate() {
        let size = |lead: &[usize]| (n + lead.len()).checked_sub(k).map_or(1, |i| lead[i]);
        let (x, y) = (size(&lead_a), size(&lead_b));
        *slot = match (x, y) {
            _ if x == y => x,
            (1, _) => y,
            (_, 1) => x,
            _ => {
                return Err(error(format!(
                    "{} of shape {} and {} of shape {} do not broadcast together",
                    a.name(),
                    shape_text(&a.shape()),
                    b.name(),
                    shape_text(&b.shape())
                )));
            }
        };
    }
    shape.push(3);
    let spread = |x: &Floats<'_>| -> PyResult<Vec<f64>> {
        let values = x.values();
        let view = ArrayViewD::from_shape(IxDyn(&x.shape()), &values)
            .map_err(|e| error(format!("internal error (please report): {e}")))?;
        let wide = view
            .broadcast(IxDyn(&shape))
            .ok_or_else(|| error("internal error (please report): broadcast"))?;
        Ok(wide.iter().copied().collect())
    };
    Ok((shape.clone(), spread(a)?, spread(b)?))
}

/// Maps each row pair `(angles, v)` through `f`, the GIL released; errors
/// name the row of `angles`.
fn map_rows<'py>(
    py: Python<'py>,
    angles: &Floats<'py>,
    vectors: &Floats<'py>,
    f: impl Fn(DVec3, DVec3) -> Result<DVec3, KinematicsError> + Send + Sync,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let (shape, a, v) = broadcast_pair(angles, vectors)?;
    let result = py.detach(|| -> Result<Vec<f64>, (usize, &'static str, String)> {
        let mut out = vec![0.0; a.len()];
        let rows = a.chunks_exact(3).zip(v.chunks_exact(3));
        for (i, ((ra, rv), slot)) in rows.zip(out.chunks_exact_mut(3)).enumerate() {
            if let Some(problem) = non_finite(ra) {
                return Err((i, "angles", problem.to_string()));
            }
            if let Some(problem) = non_finite(rv) {
                return Err((i, "vector", problem.to_string()));
            }
            let w = f(DVec3::from_slice(ra), DVec3::from_slice(rv))
                .map_err(|e| (i, "angles", e.to_string()))?;
            if !w.is_finite() {
                return Err((i, "vector", format!("result overflows: {w}")));
            }
            slot.copy_from_slice(&w.to_array());
        }
        Ok(out)
    });
    match result {
        Ok(out) => to_numpy(py, shape, out),
        Err((row, which, problem)) => {
            let name = if which == "angles" {
                angles.name()
            } else {
                vectors.name()
            };
            let lead = &shape[..shape.len() - 1];
            Err(error(format!("{}: {problem}", row_name(name, lead, row))))
        }
    }
}

/// Radians from the user's unit.
fn radians(x: DVec3, degrees: bool) -> DVec3 {
    if degrees {
        DVec3::new(x.x.to_radians(), x.y.to_radians(), x.z.to_radians())
    } else {
        x
    }
}

/// Euler-angle rates of an angular velocity: `(..., 3)` angles and
/// `(..., 3)` angular velocities (broadcast against each other) → `(..., 3)`
/// rates `(ȧ0, ȧ1, ȧ2)`.
///
/// ```text
/// rates = M(angles)⁻¹ · omega,   omega_body = M_body · rates,  omega_world = M_world · rates
/// ```
///
/// `frame` says whether `omega` is in the body (`"body"`, the default) or
/// the world frame (`"world"`). With `degrees=True` the angles and the rates
/// are in degrees (degrees per unit time); `omega` is always in radians per
/// unit time. Sequences as in `from_euler`.
///
/// Raises `KreiselError` at or next to gimbal lock (`|sin a1|` or
/// `|cos a1|` below 1e-9, where the rates are undefined), for a non-finite
/// number, shapes that do not broadcast, or an unknown `seq` or `frame`.
///
/// >>> import kreisel
/// >>> kreisel.rates_from_omega("ZXZ", [0.1, 0.5, 0.2], [0.0, 0.0, 3.0]).round(12).tolist()
/// [0.0, 0.0, 3.0]
/// >>> kreisel.rates_from_omega("ZXZ", [0.1, 0.5, 0.2], [0.0, 0.0, 3.0], frame="world").round(12).tolist()
/// [3.0, 0.0, 0.0]
#[pyfunction]
#[pyo3(signature = (seq, angles, omega, frame = "body", degrees = false))]
fn rates_from_omega<'py>(
    py: Python<'py>,
    seq: &str,
    angles: &Bound<'py, PyAny>,
    omega: &Bound<'py, PyAny>,
    frame: &str,
    degrees: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    guard(|| {
        let sequence = parse_sequence(seq)?;
        let frame = parse_frame(frame)?;
        let angles = Floats::read("angles", angles)?;
        let omega = Floats::read("omega", omega)?;
        map_rows(py, &angles, &omega, |a, w| {
            let a = radians(a, degrees);
            let rates = match frame {
                In::Body => sequence.rates_from_omega_body(a, w)?,
                In::World => sequence.rates_from_omega_world(a, w)?,
            };
            Ok(if degrees {
                rates.map(f64::to_degrees)
            } else {
                rates
            })
        })
    })
}

/// Angular velocity of Euler-angle rates: `(..., 3)` angles and `(..., 3)`
/// rates (broadcast against each other) → `(..., 3)` angular velocities in
/// the body (`frame="body"`, the default) or world frame (`"world"`).
///
/// ```text
/// intrinsic ABC:  omega_body  = [R_C(a2)ᵀR_B(a1)ᵀ e_A | R_C(a2)ᵀ e_B | e_C] · rates
///                 omega_world = R(angles) · omega_body
/// ```
///
/// Defined everywhere, gimbal lock included. With `degrees=True` the
/// angles and rates are in degrees; `omega` is in radians per unit time.
///
/// >>> import kreisel
/// >>> kreisel.omega_from_rates("ZXZ", [0.0, 0.0, 0.0], [1.0, 0.0, 2.0]).round(12).tolist()
/// [0.0, 0.0, 3.0]
#[pyfunction]
#[pyo3(signature = (seq, angles, rates, frame = "body", degrees = false))]
fn omega_from_rates<'py>(
    py: Python<'py>,
    seq: &str,
    angles: &Bound<'py, PyAny>,
    rates: &Bound<'py, PyAny>,
    frame: &str,
    degrees: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    guard(|| {
        let sequence = parse_sequence(seq)?;
        let frame = parse_frame(frame)?;
        let angles = Floats::read("angles", angles)?;
        let rates = Floats::read("rates", rates)?;
        map_rows(py, &angles, &rates, |a, r| {
            let (a, r) = (radians(a, degrees), radians(r, degrees));
            Ok(match frame {
                In::Body => sequence.rate_matrix_body(a) * r,
                In::World => sequence.rate_matrix_world(a) * r,
            })
        })
    })
}

/// The time steps of a series of `n` attitudes: from an array of `n`
/// strictly increasing finite times, or a positive step `dt` (a number).
fn read_steps(t: &Bound<'_, PyAny>, n: usize) -> PyResult<Vec<f64>> {
    let t = Floats::read("t", t)?;
    let shape = t.shape();
    let values = t.values();
    if shape.is_empty() {
        let dt = values[0];
        if !(dt.is_finite() && dt > 0.0) {
            return Err(error(format!(
                "t: a time step must be positive and finite, found {dt}"
            )));
        }
        return Ok(vec![dt; n - 1]);
    }
    if shape != [n] {
        return Err(error(format!(
            "t: expected {n} times (one per attitude), found shape {}",
            shape_text(&shape)
        )));
    }
    if let Some(i) = values.iter().position(|v| !v.is_finite()) {
        let token = values[i].to_string();
        return Err(error(format!(
            "t[{i}]: {}",
            LineProblem::NonFinite { token }
        )));
    }
    let mut steps = Vec::with_capacity(n - 1);
    for (i, w) in values.windows(2).enumerate() {
        let dt = w[1] - w[0];
        if !(dt > 0.0 && dt.is_finite()) {
            return Err(error(format!(
                "t[{}]: times must increase strictly by finite steps, found {} after {}",
                i + 1,
                w[1],
                w[0]
            )));
        }
        steps.push(dt);
    }
    Ok(steps)
}

/// Angular velocity of an attitude series: `(..., N, 4)` quaternions
/// `(w, x, y, z)` at times `t` → `(..., N-1, 3)`, one angular velocity per
/// interval.
///
/// ```text
/// omega_body[i]  = log(q[i]⁻¹ ⊗ q[i+1]) / (t[i+1] − t[i])
/// omega_world[i] = log(q[i+1] ⊗ q[i]⁻¹) / (t[i+1] − t[i])
/// ```
///
/// The choice: each value is the *constant* angular velocity that turns
/// `q[i]` into `q[i+1]` along the shortest path (exact for piecewise
/// constant ω, no small-angle approximation, `q` and `−q` alike); for a
/// smooth motion it is ω at the interval's midpoint `(t[i] + t[i+1]) / 2`
/// to O(Δt²). Central differences would give N values but smooth over two
/// intervals; they are the mean of neighbouring values here. Attitudes
/// more than π apart within one interval alias (sample faster).
///
/// `t` is an array of `N` strictly increasing times, or a number: the
/// constant step. Quaternions may have any non-zero length (normalised).
/// `frame` is `"body"` (default) or `"world"`.
///
/// >>> import kreisel, numpy as np
/// >>> q = kreisel.from_euler("ZYX", np.outer([0.0, 0.1, 0.3], [1.0, 0.0, 0.0]))
/// >>> kreisel.omega_from_attitudes(q, [0.0, 0.5, 1.5]).round(12).tolist()
/// [[0.0, 0.0, 0.2], [0.0, 0.0, 0.2]]
#[pyfunction]
#[pyo3(signature = (quats, t, frame = "body"))]
fn omega_from_attitudes<'py>(
    py: Python<'py>,
    quats: &Bound<'py, PyAny>,
    t: &Bound<'py, PyAny>,
    frame: &str,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    guard(|| {
        let frame = parse_frame(frame)?;
        let quats = Floats::read("quats", quats)?;
        let shape = quats.shape();
        if shape.len() < 2 || shape[shape.len() - 1] != 4 {
            return Err(error(format!(
                "quats: expected shape (..., N, 4) (a series of N quaternions w, x, y, z), found {}",
                shape_text(&shape)
            )));
        }
        let n = shape[shape.len() - 2];
        if n < 2 {
            return Err(error(format!(
                "quats: an angular velocity needs at least 2 attitudes along axis -2, found {n}"
            )));
        }
        let steps = read_steps(t, n)?;
        let data = quats.values();
        let data: &[f64] = &data;
        let result = py.detach(|| -> Result<Vec<f64>, (usize, String)> {
            let mut unit = Vec::with_capacity(data.len() / 4);
            for (i, row) in data.chunks_exact(4).enumerate() {
                if let Some(problem) = non_finite(row) {
                    return Err((i, problem.to_string()));
                }
                let q = DQuat::from_xyzw(row[1], row[2], row[3], row[0]);
                unit.push(try_normalize_quat(q).map_err(|e| (i, e.to_string()))?);
            }
            let mut out = Vec::with_capacity(unit.len() / n * (n - 1) * 3);
            for (s, series) in unit.chunks_exact(n).enumerate() {
                let series_start = s * n;
                for (k, pair) in series.windows(2).enumerate() {
                    let dt = steps[k];
                    let w = match frame {
                        In::Body => omega_body_from_attitudes(pair[0], pair[1], dt),
                        In::World => omega_world_from_attitudes(pair[0], pair[1], dt),
                    };
                    if !w.is_finite() {
                        let problem = format!("angular velocity overflows (time step {dt})");
                        return Err((series_start + k, problem));
                    }
                    out.extend_from_slice(&w.to_array());
                }
            }
            Ok(out)
        });
        match result {
            Ok(out) => {
                let mut out_shape = shape.clone();
                let k = out_shape.len();
                out_shape[k - 2] = n - 1;
                out_shape[k - 1] = 3;
                to_numpy(py, out_shape, out)
            }
            Err((row, problem)) => Err(error(format!(
                "{}: {problem}",
                row_name("quats", &shape[..shape.len() - 1], row)
            ))),
        }
    })
}

/// Adds this part's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(rates_from_omega, m)?)?;
    m.add_function(wrap_pyfunction!(omega_from_rates, m)?)?;
    m.add_function(wrap_pyfunction!(omega_from_attitudes, m)?)?;
    Ok(())
}
