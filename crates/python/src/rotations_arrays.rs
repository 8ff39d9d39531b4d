//! numpy arrays in and out of the rotation functions: any array-like of
//! numbers becomes a C-ordered run of `f64` with its shape, results go back
//! as new `float64` arrays, and a bad row is named by its index
//! (`angles[2, 1]: …`) the way the CLI names a line (`line 3: …`).

use std::borrow::Cow;

use kreisel_scene::line_problem::LineProblem;
use kreisel_scene::numbers::Numbers;
use numpy::ndarray::{Array, IxDyn};
use numpy::{AllowTypeChange, IntoPyArray, PyArrayDyn, PyArrayLike, PyUntypedArrayMethods};
use pyo3::prelude::*;

use crate::errors::error;

/// A numeric input array (read as `float64`), named for error messages.
pub struct Floats<'py> {
    name: &'static str,
    array: PyArrayLike<'py, f64, IxDyn, AllowTypeChange>,
}

impl<'py> Floats<'py> {
    /// Reads `value` as an array of `float64` (lists, ints, float32 … are
    /// converted by `numpy.asarray`).
    ///
    /// # Errors
    /// A `KreiselError` naming the argument when numpy cannot convert it.
    pub fn read(name: &'static str, value: &Bound<'py, PyAny>) -> PyResult<Self> {
        let py = value.py();
        let cannot = |e: PyErr| {
            error(format!(
                "{name}: cannot read as an array of float64 numbers: {}",
                e.value(py)
            ))
        };
        let raw = numpy::get_array_module(py)?
            .getattr("asarray")?
            .call1((value,))
            .map_err(cannot)?;
        let dtype = raw.getattr("dtype")?;
        let kind: String = dtype.getattr("kind")?.extract()?;
        // Integers, floats and objects holding numbers convert exactly
        // enough; complex numbers, booleans, strings and dates would
        // convert silently (or with a mere warning) into wrong angles.
        if !matches!(kind.as_str(), "i" | "u" | "f" | "O") {
            return Err(error(format!(
                "{name}: cannot read as an array of float64 numbers: dtype {} is not real numbers",
                dtype.str()?
            )));
        }
        let array = raw.extract().map_err(cannot)?;
        Ok(Self { name, array })
    }

    /// The argument's name.
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// The array's shape.
    pub fn shape(&self) -> Vec<usize> {
        self.array.shape().to_vec()
    }

    /// The values in C order (borrowed when the array is C-contiguous).
    pub fn values(&self) -> Cow<'_, [f64]> {
        match self.array.as_slice() {
            Ok(slice) => Cow::Borrowed(slice),
            Err(_) => Cow::Owned(self.array.as_array().iter().copied().collect()),
        }
    }

    /// The leading shape when the trailing axes are `trailing`.
    ///
    /// # Errors
    /// A `KreiselError` saying which shape was expected: `what` names the
    /// content (e.g. `"3 numbers for euler:ZXZ"`).
    pub fn leading_shape(&self, trailing: &[usize], what: &str) -> PyResult<Vec<usize>> {
        let shape = self.shape();
        let k = trailing.len();
        if shape.len() < k || shape[shape.len() - k..] != *trailing {
            let expected: Vec<String> = trailing.iter().map(usize::to_string).collect();
            return Err(error(format!(
                "{}: expected shape (..., {}) ({what}), found {}",
                self.name,
                expected.join(", "),
                shape_text(&shape)
            )));
        }
        Ok(shape[..shape.len() - k].to_vec())
    }
}

/// A shape as numpy prints it: `(3,)`, `(2, 4)`, `()`.
pub fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => {
            let parts: Vec<String> = shape.iter().map(usize::to_string).collect();
            format!("({})", parts.join(", "))
        }
    }
}

/// `name[i, j]` for the row with flat index `row` of an array whose leading
/// shape is `leading` (`name` alone for a single row).
pub fn row_name(name: &str, leading: &[usize], row: usize) -> String {
    if leading.is_empty() {
        return name.to_owned();
    }
    let mut index = vec![0; leading.len()];
    let mut rest = row;
    for (slot, &n) in index.iter_mut().zip(leading).rev() {
        *slot = rest % n.max(1);
        rest /= n.max(1);
    }
    let parts: Vec<String> = index.iter().map(usize::to_string).collect();
    format!("{name}[{}]", parts.join(", "))
}

/// The CLI's complaint about the first non-finite number of a row, if any.
pub fn non_finite(row: &[f64]) -> Option<LineProblem> {
    row.iter()
        .find(|v| !v.is_finite())
        .map(|v| LineProblem::NonFinite {
            token: v.to_string(),
        })
}

/// A row of 3, 4 or 9 numbers as the CLI's [`Numbers`] (the counts of the
/// representations; any other length is an internal error).
pub fn numbers(row: &[f64]) -> Numbers {
    match *row {
        [a, b, c] => Numbers::from_array([a, b, c]),
        [a, b, c, d] => Numbers::from_array([a, b, c, d]),
        [a, b, c, d, e, f, g, h, i] => Numbers::from_array([a, b, c, d, e, f, g, h, i]),
        // Every caller cuts rows with `chunks_exact(Representation::count())`,
        // which is 3, 4 or 9.
        _ => unreachable!("rows have 3, 4 or 9 numbers, not {}", row.len()),
    }
}

/// A new `float64` array of `shape` holding `data` (C order).
///
/// # Errors
/// An internal `KreiselError` if the length does not match the shape.
pub fn to_numpy<'py>(
    py: Python<'py>,
    shape: Vec<usize>,
    data: Vec<f64>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let array = Array::from_shape_vec(IxDyn(&shape), data)
        .map_err(|e| error(format!("internal error (please report): {e}")))?;
    Ok(array.into_pyarray(py))
}
