//! The package's one exception, `kreisel.KreiselError` (a `ValueError`),
//! carrying the same one-line message as the CLI, and the guard that keeps
//! a Rust panic from ever crossing into Python.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

pyo3::create_exception!(
    kreisel,
    KreiselError,
    PyValueError,
    "Bad input to kreisel: the message is the CLI's one line (what is wrong and where)."
);

/// A `KreiselError` with `message` (made one line, as the CLI prints it).
pub fn error(message: impl std::fmt::Display) -> PyErr {
    KreiselError::new_err(kreisel_cli::error::one_line(&message.to_string()))
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
