//! The package's one exception, `kreisel.KreiselError` (a `ValueError`),
//! carrying the same one-line message as the CLI (with the Python
//! argument where the CLI names its option: `i3`, not `--i3`), and the
//! guard that keeps a Rust panic from ever crossing into Python.

use kreisel_inertia::InertiaError;
use kreisel_scene::error::{BodyProblem, SceneError, one_line};
use kreisel_scene::numbers::Shortest;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

pyo3::create_exception!(
    kreisel,
    KreiselError,
    PyValueError,
    "Bad input to kreisel: the message is the CLI's one line (what is wrong and where); for a bad argument it begins with the argument's name."
);

/// A `KreiselError` with `message` (made one line, as the CLI prints it).
pub fn error(message: impl std::fmt::Display) -> PyErr {
    KreiselError::new_err(one_line(&message.to_string()))
}

/// The Python keyword of a command-line option: `--theta-dot0` is
/// `theta_dot0` (the functions take the options as keywords of those names).
fn keyword(option: &str) -> String {
    option.trim_start_matches('-').replace('-', "_")
}

/// A `KreiselError` for an error of the CLI's code: its one line, but
/// where it names a command-line option (a typed field, or a hint of the
/// CLI's own wording) the Python argument instead.
pub fn scene_error(e: SceneError) -> PyErr {
    match e {
        SceneError::Argument { argument, message } => {
            error(format!("{}: {message}", keyword(&argument)))
        }
        SceneError::Method { problem } => error(format!("method: {problem}")),
        SceneError::DerivedDensity { path, mass, volume } => error(format!(
            "mass: {}: total volume {} m^3 gives no finite positive density for mass {} kg",
            path.display(),
            Shortest(volume),
            Shortest(mass)
        )),
        SceneError::Body {
            path,
            body,
            problem,
        } => error(format!(
            "{}: body '{}': {}",
            path.display(),
            one_line(&body),
            body_problem(&problem)
        )),
        other => error(other),
    }
}

/// [`BodyProblem`]'s message with the advice in keywords (`model="shell"`,
/// `weld=…`, `merge=True`) where the CLI's names its options.
fn body_problem(problem: &BodyProblem) -> String {
    let text = |source: &InertiaError| one_line(&source.to_string());
    match problem {
        BodyProblem::Inertia { source } => format!("{}{}", text(source), solid_hint(source)),
        BodyProblem::Cracks { source, weld } => format!(
            "{}; rerun with weld={} to close them",
            text(source),
            Shortest(*weld)
        ),
        BodyProblem::ClosedOnlyMerged { source } => format!(
            "{}; the file's bodies together form a closed surface: rerun with merge=True to treat them as one solid",
            text(source)
        ),
        other => other.to_string(),
    }
}

/// What gives the right answer for a surface that encloses no volume (the
/// CLI's advice, in keywords).
fn solid_hint(error: &InertiaError) -> &'static str {
    match error {
        InertiaError::OpenMesh { .. } | InertiaError::NonManifold { .. } => {
            "; if the surface is open on purpose, model=\"shell\" models a thin-walled part (see thickness) and model=\"hull\" a convex one"
        }
        InertiaError::MeshOutOfRange { .. } => " (set with units or scale, metres per mesh unit)",
        InertiaError::NonOrientable { .. } => {
            "; it bounds no volume, but model=\"shell\" models it as a thin wall (see thickness)"
        }
        _ => "",
    }
}

/// Runs `f`, turning a Rust panic into a `KreiselError` ("internal error:
/// …") instead of pyo3's `PanicException`: no input may raise anything but
/// a `ValueError` (or a `TypeError` from argument conversion).
pub fn guard<T>(f: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(result) => result,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown".to_owned());
            Err(error(format!("internal error (please report): {what}")))
        }
    }
}

/// Adds the exception to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("KreiselError", m.py().get_type::<KreiselError>())
}
