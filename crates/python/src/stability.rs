//! `kreisel.stability(world, body)`: is this body's motion stable? The
//! steady motion nearest its state ([`SteadyProblem::near`]), linearised
//! with exact derivatives ([`SteadyProblem::linearise`]), as a dict of
//! numpy arrays; and `kreisel._native._SteadyProblem`, that steady motion
//! as a picklable object (plain numbers), which `kreisel.stability_map`
//! ships to an executor's workers (`stability_map.rs`).

use glam::{DMat3, DVec3};
use kreisel_analysis::{
    AnalysisError, Frame, Linearisation, Parameter, PivotBody, Precession, SteadyProblem, Verdict,
};
use kreisel_inertia::MassProperties;
use numpy::{Complex64, PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use crate::errors::{error, guard};
use crate::simulation::PyWorld;

/// A library error as the package's `KreiselError` (a `ValueError`), its
/// one line.
pub fn analysis_error(e: AnalysisError) -> PyErr {
    error(e)
}

/// The steady motion of body ``body`` of ``world`` nearest its state now,
/// as a picklable object (``kreisel.stability_map`` ships it to workers).
///
/// Its state is plain numbers (``__reduce__``): the kind's tag, the
/// body's mass properties, pivot and gravity, and the parameters.
#[pyclass(module = "kreisel._native", name = "_SteadyProblem", frozen)]
pub struct PySteadyProblem {
    /// The steady motion.
    pub problem: SteadyProblem,
}

/// Tags of the state's first number.
const FREE: f64 = 0.0;
const SLEEPING: f64 = 1.0;
const PRECESSION: f64 = 2.0;

/// The numbers of a top on a pivot: mass, centre of mass (3), inertia
/// about it (9, by columns), pivot (3), gravity (3).
fn top_numbers(top: &PivotBody) -> Vec<f64> {
    let m = &top.mass_properties;
    let mut v = vec![m.mass];
    v.extend(m.center_of_mass.to_array());
    v.extend(m.inertia.to_cols_array());
    v.extend(top.pivot_body.to_array());
    v.extend(top.gravity_world.to_array());
    v
}

/// How many numbers [`top_numbers`] writes.
const TOP_NUMBERS: usize = 19;

/// The top of [`top_numbers`].
fn top_from(v: &[f64]) -> PivotBody {
    let vec3 = |k: usize| DVec3::new(v[k], v[k + 1], v[k + 2]);
    let mut cols = [0.0; 9];
    cols.copy_from_slice(&v[4..13]);
    PivotBody {
        mass_properties: MassProperties {
            mass: v[0],
            center_of_mass: vec3(1),
            inertia: DMat3::from_cols_array(&cols),
        },
        pivot_body: vec3(13),
        gravity_world: vec3(16),
    }
}

/// The problem as plain numbers (exact: every one is an `f64` of it);
/// `None` for a spin on the ground (its body holds contact shapes and
/// laws, not written as numbers yet).
fn to_numbers(problem: &SteadyProblem) -> Option<Vec<f64>> {
    let numbers = match problem {
        SteadyProblem::FreeRotation {
            moments,
            axis,
            spin,
        } => {
            let mut v = vec![FREE];
            v.extend(moments.to_array());
            v.extend([*axis as f64, *spin]);
            v
        }
        SteadyProblem::SleepingTop { top, spin, hanging } => {
            let mut v = vec![SLEEPING];
            v.extend(top_numbers(top));
            v.extend([*spin, f64::from(u8::from(*hanging))]);
            v
        }
        SteadyProblem::Precession {
            top,
            tilt,
            spin,
            which,
        } => {
            let mut v = vec![PRECESSION];
            v.extend(top_numbers(top));
            let fast = matches!(which, Precession::Fast);
            v.extend([*tilt, *spin, f64::from(u8::from(fast))]);
            v
        }
        SteadyProblem::GroundSpin { .. } => return None,
    };
    Some(numbers)
}

/// The problem of [`to_numbers`]; `None` for numbers it never writes.
fn from_numbers(v: &[f64]) -> Option<SteadyProblem> {
    let (&tag, rest) = v.split_first()?;
    let flag = |x: f64| (x == 0.0 || x == 1.0).then_some(x == 1.0);
    if tag == FREE && rest.len() == 5 {
        let axis = rest[3];
        let axis = [0.0, 1.0, 2.0].iter().position(|&a| a == axis)?;
        return Some(SteadyProblem::FreeRotation {
            moments: DVec3::new(rest[0], rest[1], rest[2]),
            axis,
            spin: rest[4],
        });
    }
    if tag == SLEEPING && rest.len() == TOP_NUMBERS + 2 {
        return Some(SteadyProblem::SleepingTop {
            top: top_from(rest),
            spin: rest[TOP_NUMBERS],
            hanging: flag(rest[TOP_NUMBERS + 1])?,
        });
    }
    if tag == PRECESSION && rest.len() == TOP_NUMBERS + 3 {
        let fast = flag(rest[TOP_NUMBERS + 2])?;
        return Some(SteadyProblem::Precession {
            top: top_from(rest),
            tilt: rest[TOP_NUMBERS],
            spin: rest[TOP_NUMBERS + 1],
            which: if fast {
                Precession::Fast
            } else {
                Precession::Slow
            },
        });
    }
    None
}

#[pymethods]
impl PySteadyProblem {
    /// The problem of ``numbers`` (what ``__reduce__`` gives).
    #[new]
    fn new(numbers: Vec<f64>) -> PyResult<Self> {
        let problem = from_numbers(&numbers).ok_or_else(|| {
            error("numbers: not the state of a steady motion (kreisel._native._SteadyProblem)")
        })?;
        Ok(Self { problem })
    }

    /// What it is, in words (``"sleeping top"``).
    #[getter]
    fn kind(&self) -> &'static str {
        self.problem.kind()
    }

    /// The parameters it can be swept in, with their values.
    #[getter]
    fn parameters<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        parameters(py, &self.problem)
    }

    /// Pickling: the class and its numbers.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let numbers = to_numbers(&slf.get().problem).ok_or_else(|| {
            error(
                "a spin on the ground cannot be sent to an executor yet (its contact shapes \
                 are not written as numbers): map it without one (threads)",
            )
        })?;
        let args = PyTuple::new(py, [numbers])?;
        PyTuple::new(py, [slf.get_type().into_any(), args.into_any()])
    }

    fn __repr__(&self) -> String {
        let parameters: Vec<String> = self
            .problem
            .parameters()
            .iter()
            .map(|(p, v)| format!("{p}={v}"))
            .collect();
        format!(
            "<steady motion: {} ({})>",
            self.problem.kind(),
            parameters.join(", ")
        )
    }
}

/// The dict name → value of the problem's parameters.
fn parameters<'py>(py: Python<'py>, problem: &SteadyProblem) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for (p, v) in problem.parameters() {
        dict.set_item(p.name(), v)?;
    }
    Ok(dict)
}

/// The steady motion nearest body ``body``'s state in ``world``.
pub fn near(world: &PyWorld, body: &Bound<'_, PyAny>) -> PyResult<SteadyProblem> {
    let (found, gravity) = world.body_and_gravity(body)?;
    SteadyProblem::near(found, gravity).map_err(analysis_error)
}

/// The steady motion nearest body ``body``'s state in ``world``, picklable
/// (``kreisel.stability_map`` ships it to an executor's workers).
#[pyfunction]
fn _steady_problem(
    world: PyRef<'_, PyWorld>,
    body: &Bound<'_, PyAny>,
) -> PyResult<PySteadyProblem> {
    guard(|| {
        Ok(PySteadyProblem {
            problem: near(&world, body)?,
        })
    })
}

/// Is this motion stable? The steady motion nearest the state of body
/// ``body`` of ``world`` (free, or on a pivot under the world's gravity),
/// linearised with exact derivatives, every zero eigenvalue named.
///
/// A dict: ``kind`` (``"sleeping top"``, ``"free rotation about a
/// principal axis"``, ``"slow steady precession"``, ...), ``parameters``
/// (name -> value: ``spin`` rad/s, ``tilt`` rad, ``com_offset`` m,
/// ``gravity`` m/s^2), ``state`` (the steady motion in the reduced
/// coordinates) and ``state_names``, ``frame`` (``"body"`` or
/// ``"space"``: the coordinates' frame, in which ``eigenvalues`` are seen),
/// ``eigenvalues`` (complex, 1/s: a perturbation along mode k goes like
/// ``Re(modes[k] e^{eigenvalues[k] t})``, by real part then imaginary
/// part, descending), ``modes`` (complex, one row per eigenvalue, one
/// column per state component, unit length), ``space_frequencies``
/// (rad/s as seen in space where the mode is circular, NaN where not),
/// ``zero_modes`` (the zero eigenvalues taken out, ``(kind, name)``:
/// ``("Casimir", "|γ|²")``, ...), ``dependent`` and ``reduced_by``,
/// ``residual``, ``verdict`` (``"stable"``, ``"unstable"``,
/// ``"neutral"``) with ``growth_rate`` (unstable: the largest Re λ, 1/s),
/// ``asymptotic`` (stable) or ``reason`` (neutral).
///
/// The sleeping top (``J₁`` about the pivot, spin ``ω₃``, ``M g l``):
/// stable iff ``I₃² ω₃² > 4 J₁ M g l``; growth rate ``√(4 J₁ M g l −
/// I₃² ω₃²)/(2 J₁)`` below; precession frequencies in space ``(I₃ ω₃ ±
/// √(I₃² ω₃² − 4 J₁ M g l))/(2 J₁)`` above. A free body spinning at ``ω``
/// about its intermediate axis grows at ``ω √((I₂ − I₁)(I₃ − I₂)/(I₁ I₃))``.
///
/// >>> import kreisel
/// >>> w = kreisel.World(dt=0.01)
/// >>> b = w.add_body(1.0, moments=(1.0, 2.0, 3.0), omega_body=(0.0, 2.0, 0.0))
/// >>> s = kreisel.stability(w, b)
/// >>> s["verdict"], round(s["growth_rate"], 12)   # 2 √((2−1)(3−2)/(1·3))
/// ('unstable', 1.154700538379)
///
/// Raises KreiselError (a ValueError) with the library's one line when
/// there is no steady motion near the state, or for a body on the table.
#[pyfunction]
fn stability<'py>(
    py: Python<'py>,
    world: PyRef<'py, PyWorld>,
    body: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let problem = near(&world, body)?;
        let lin = py.detach(|| problem.linearise()).map_err(analysis_error)?;
        linearisation_dict(py, &problem, &lin)
    })
}

/// The dict of [`stability`].
fn linearisation_dict<'py>(
    py: Python<'py>,
    problem: &SteadyProblem,
    lin: &Linearisation,
) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    dict.set_item("kind", problem.kind())?;
    dict.set_item("parameters", parameters(py, problem)?)?;
    dict.set_item("state", PyArray1::from_slice(py, &lin.state))?;
    dict.set_item("state_names", lin.state_names.clone())?;
    dict.set_item(
        "frame",
        match lin.frame {
            Frame::Body => "body",
            Frame::Space => "space",
        },
    )?;
    let complex = |e: kreisel_analysis::Eigenvalue| Complex64::new(e.re, e.im);
    let eigenvalues: Vec<Complex64> = lin.modes.iter().map(|m| complex(m.eigenvalue)).collect();
    dict.set_item("eigenvalues", PyArray1::from_vec(py, eigenvalues))?;
    let rows: Vec<Vec<Complex64>> = lin
        .modes
        .iter()
        .map(|m| m.shape.iter().copied().map(complex).collect())
        .collect();
    let modes = if rows.is_empty() {
        PyArray2::zeros(py, [0, lin.state.len()], false)
    } else {
        PyArray2::from_vec2(py, &rows).map_err(|e| error(format!("internal error: {e}")))?
    };
    dict.set_item("modes", modes)?;
    let space: Vec<f64> = lin
        .modes
        .iter()
        .map(|m| m.space_frequency.unwrap_or(f64::NAN))
        .collect();
    dict.set_item("space_frequencies", PyArray1::from_vec(py, space))?;
    let named = |modes: &[kreisel_analysis::ZeroMode]| -> Vec<(String, String)> {
        modes
            .iter()
            .map(|z| (z.kind.to_string(), z.name.clone()))
            .collect()
    };
    dict.set_item("zero_modes", named(&lin.zero_modes))?;
    dict.set_item("dependent", named(&lin.dependent))?;
    dict.set_item("reduced_by", lin.reduced_by.clone())?;
    dict.set_item("residual", lin.residual)?;
    dict.set_item("max_real_part", lin.max_real_part())?;
    dict.set_item("verdict", lin.verdict.name())?;
    match &lin.verdict {
        Verdict::Stable { asymptotic } => dict.set_item("asymptotic", *asymptotic)?,
        Verdict::Unstable { growth_rate } => dict.set_item("growth_rate", *growth_rate)?,
        Verdict::Neutral { reason } => dict.set_item("reason", reason.as_str())?,
    }
    Ok(dict)
}

/// The parameter of a sweep's key, or the library's `Sweep` error.
pub fn parameter(name: &str) -> Result<Parameter, AnalysisError> {
    name.parse().map_err(|why| AnalysisError::Sweep {
        name: name.to_owned(),
        why,
    })
}

/// Adds the functions and the class to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PySteadyProblem>()?;
    m.add_function(wrap_pyfunction!(stability, m)?)?;
    m.add_function(wrap_pyfunction!(_steady_problem, m)?)
}
