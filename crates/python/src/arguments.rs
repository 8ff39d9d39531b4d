//! Python arguments in: numbers, sequences of numbers, integers in a range
//! and paths, each converted under its Python name, so that a bad one
//! raises a `KreiselError` (a bad value) or a `TypeError` (a wrong type)
//! whose message begins with that name (`moments: expected a sequence of 3
//! numbers, got 2 items`, `threads: -1 is out of range …`), never pyo3's
//! anonymous `ValueError` or an `OverflowError`.

use std::fmt::Display;
use std::path::PathBuf;

use pyo3::exceptions::{PyOverflowError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PySequence, PyString};

use crate::errors::error;

/// A `TypeError`: `name` must be `what`, and the type it got.
fn wrong_type(name: &str, what: &str, value: &Bound<'_, PyAny>) -> PyErr {
    let got = value
        .get_type()
        .name()
        .map_or_else(|_| "?".to_owned(), |n| n.to_string());
    PyTypeError::new_err(format!("{name} must be {what}, got {got}"))
}

/// The argument's text as Python prints it (`str(value)`).
fn text(value: &Bound<'_, PyAny>) -> String {
    value
        .str()
        .map_or_else(|_| "?".to_owned(), |s| s.to_string())
}

/// `f` applied to the argument's name and the error: a function for
/// `map_err` that names the argument of a library error (`dt: step size
/// must be positive and finite, got 0`).
pub fn named<E: Display>(name: &str) -> impl Fn(E) -> PyErr + '_ {
    move |e| error(format!("{name}: {e}"))
}

/// A real number (`float`, `int`, numpy scalars; not necessarily finite).
///
/// # Errors
/// `TypeError` for something that is not a number, `KreiselError` for an
/// integer too large for a float.
pub fn number(name: &str, value: &Bound<'_, PyAny>) -> PyResult<f64> {
    value.extract::<f64>().map_err(|e| {
        if e.is_instance_of::<PyOverflowError>(value.py()) {
            error(format!(
                "{name}: {} is too large for a float (at most about 1.8e308)",
                text(value)
            ))
        } else {
            wrong_type(name, "a number", value)
        }
    })
}

/// A sequence (list, tuple, numpy array; not a string) of exactly `n`
/// items, each converted by `item` under the name `name[i]`.
///
/// # Errors
/// `TypeError` for something that is not a sequence, `KreiselError` for
/// another length; as `item` for an item.
pub fn sequence<T>(
    name: &str,
    value: &Bound<'_, PyAny>,
    n: usize,
    what: &str,
    item: impl Fn(&str, &Bound<'_, PyAny>) -> PyResult<T>,
) -> PyResult<Vec<T>> {
    let expected = format!("a sequence of {n} {what}");
    // Lists, tuples and numpy arrays (not a collections.abc.Sequence); not
    // a string, whose characters are no numbers.
    let is_sequence = value.cast::<PySequence>().is_ok() || value.hasattr("__array__")?;
    if !is_sequence || value.is_instance_of::<PyString>() || value.is_instance_of::<PyBytes>() {
        return Err(wrong_type(name, &expected, value));
    }
    // (a 0-dimensional array has no length)
    let len = value
        .len()
        .map_err(|_| wrong_type(name, &expected, value))?;
    if len != n {
        return Err(error(format!(
            "{name}: expected {expected}, got {len} items"
        )));
    }
    (0..n)
        .map(|i| item(&format!("{name}[{i}]"), &value.get_item(i)?))
        .collect()
}

/// A finite real number.
///
/// # Errors
/// As [`number`]; `KreiselError` for NaN or an infinity.
pub fn finite(name: &str, value: &Bound<'_, PyAny>) -> PyResult<f64> {
    let x = number(name, value)?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(error(format!("{name}: {x} is not a finite number")))
    }
}

/// `N` finite numbers (a vector, a quaternion w, x, y, z).
///
/// # Errors
/// As [`sequence`] and [`finite`]: the message names the argument, and the
/// item (`omega_body[1]`) for a bad number.
pub fn numbers<const N: usize>(name: &str, value: &Bound<'_, PyAny>) -> PyResult<[f64; N]> {
    let items = sequence(name, value, N, "numbers", finite)?;
    Ok(std::array::from_fn(|i| items[i]))
}

/// A 3 × 3 matrix of finite numbers, as 3 rows.
///
/// # Errors
/// As [`numbers`], for the matrix and each row (`inertia[2]`).
pub fn matrix3(name: &str, value: &Bound<'_, PyAny>) -> PyResult<[[f64; 3]; 3]> {
    let rows = sequence(name, value, 3, "rows of 3 numbers", numbers::<3>)?;
    Ok([rows[0], rows[1], rows[2]])
}

/// Any Python integer (`int`, numpy integers; not `bool`) that fits 128 bits.
///
/// # Errors
/// `TypeError` for something that is not an integer, `KreiselError` for one
/// beyond ±2^127.
pub fn int(name: &str, value: &Bound<'_, PyAny>) -> PyResult<i128> {
    if value.is_instance_of::<PyBool>() {
        return Err(wrong_type(name, "an integer", value));
    }
    value.extract::<i128>().map_err(|e| {
        if e.is_instance_of::<PyOverflowError>(value.py()) {
            error(format!("{name}: {} is out of range", text(value)))
        } else {
            wrong_type(name, "an integer", value)
        }
    })
}

/// An integer from `lo` to `hi` (inclusive).
///
/// # Errors
/// As [`int`]; `KreiselError` naming the range for one outside it.
pub fn integer<T>(name: &str, value: &Bound<'_, PyAny>, lo: T, hi: T) -> PyResult<T>
where
    T: Copy + Display + TryFrom<i128> + Into<i128>,
{
    let out_of_range = || {
        error(format!(
            "{name}: {} is out of range (an integer from {lo} to {hi})",
            text(value)
        ))
    };
    let n = int(name, value).map_err(|e| {
        if e.is_instance_of::<PyTypeError>(value.py()) {
            e
        } else {
            out_of_range()
        }
    })?;
    if n < lo.into() || n > hi.into() {
        return Err(out_of_range());
    }
    T::try_from(n).map_err(|_| out_of_range())
}

/// A file path (`str` or `os.PathLike`), not empty.
///
/// # Errors
/// `TypeError` for anything else, `KreiselError` for an empty path.
pub fn path(name: &str, value: &Bound<'_, PyAny>) -> PyResult<PathBuf> {
    let path: PathBuf = value
        .extract()
        .map_err(|_| wrong_type(name, "a path (str or os.PathLike)", value))?;
    if path.as_os_str().is_empty() {
        return Err(error(format!("{name}: path is empty")));
    }
    Ok(path)
}
