//! # kreisel for Python
//!
//! The native module `kreisel._native` (PyO3, abi3: one wheel for every
//! CPython ≥ 3.9); the package `kreisel` (`python/kreisel/__init__.py`)
//! re-exports it. No physics here: bindings and error messages over the
//! library crates (and the CLI's parsers and writers, so that Python gets
//! exactly the CLI's numbers and messages).
#![deny(missing_docs)]
#![forbid(unsafe_code)]

use pyo3::prelude::*;

mod arguments;
mod errors;
mod mass;
mod rotations;
mod rotations_arrays;
mod rotations_rates;
mod simulation;
mod stability;
mod stability_map;
mod top;

/// The native module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    errors::register(m)?;
    rotations::register(m)?;
    rotations_rates::register(m)?;
    mass::register(m)?;
    simulation::register(m)?;
    top::register(m)?;
    stability::register(m)?;
    stability_map::register(m)?;
    Ok(())
}
