//! Rotations for Python: `from_euler`, `as_euler` and `convert`, vectorised
//! over numpy arrays of any leading shape.
//!
//! Every function runs the CLI's own conversion (`kreisel convert`,
//! [`kreisel_scene::representation::Representation`]) row by row, so Python
//! gets the CLI's numbers bit for bit, its normalisation rules, ranges and
//! error messages; a bad row is named by its index (`angles[2, 1]: …`)
//! where the CLI names a line. The GIL is released while the rows are
//! converted. Euler rates and angular velocity live in `rotations_rates.rs`.

use glam::DQuat;
use kreisel_kinematics::EulerSequence;
use kreisel_scene::line_problem::LineProblem;
use kreisel_scene::representation::Representation;
use kreisel_scene::rotation_lines::{euler_angles_of_quat, euler_angles_of_quats};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::errors::{error, guard};
use crate::rotations_arrays::{Floats, non_finite, numbers, row_name, to_numpy};

/// The 24 sequence names, for error messages.
fn sequence_names() -> String {
    let names: Vec<String> = EulerSequence::all().iter().map(|s| s.to_string()).collect();
    names.join(" ")
}

/// Parses a sequence name (`"ZXZ"`, `"xyz"`, …).
///
/// # Errors
/// A `KreiselError` with the library's reason and the valid names.
pub fn parse_sequence(seq: &str) -> PyResult<EulerSequence> {
    seq.parse().map_err(|e| {
        error(format!(
            "seq: {e}; valid sequences: {} (uppercase intrinsic, lowercase extrinsic)",
            sequence_names()
        ))
    })
}

/// Parses a representation name as `kreisel convert --from/--to` does.
fn parse_representation(argument: &str, text: &str) -> PyResult<Representation> {
    text.parse()
        .map_err(|e: String| error(format!("{argument} `{text}`: {e}")))
}

/// The trailing shape of an array of one representation: `(3, 3)` for a
/// matrix, `(count,)` otherwise.
fn trailing_shape(representation: Representation) -> Vec<usize> {
    match representation {
        Representation::Matrix => vec![3, 3],
        other => vec![other.count()],
    }
}

/// Converts rows of `m` numbers in `input` into rows of `n` numbers in
/// `output`, stopping at the first bad row (its index in `input`).
fn convert_rows(
    input: &[f64],
    output: &mut [f64],
    from: Representation,
    to: Representation,
    degrees: bool,
) -> Result<(), (usize, LineProblem)> {
    if let (Representation::Quat | Representation::QuatXyzw, Representation::Euler(sequence)) =
        (from, to)
    {
        return quat_rows_to_euler(input, output, from, sequence, degrees);
    }
    let rows = input.chunks_exact(from.count());
    for (i, (row, slot)) in rows.zip(output.chunks_exact_mut(to.count())).enumerate() {
        if let Some(problem) = non_finite(row) {
            return Err((i, problem));
        }
        let q = from
            .quat_from_numbers(&numbers(row), degrees)
            .map_err(|problem| (i, problem))?;
        slot.copy_from_slice(to.numbers_from_quat(q, degrees).as_slice());
    }
    Ok(())
}

/// Quaternion rows (`(w, x, y, z)`, or `(x, y, z, w)` for `quat-xyzw`) →
/// Euler angles: the CLI's own [`euler_angles_of_quat`] (what
/// `Representation::convert_numbers` calls for `quat → euler:SEQ`), four
/// rows at a time in SIMD registers ([`euler_angles_of_quats`]: the same
/// bits), without the CLI's generic row of numbers. A function of its own
/// (never inlined into [`convert_rows`]), so that the generic loop's code
/// cannot change how this one is compiled: the SIMD lanes proved sensitive
/// to inlining (a const-generic variant ran at 93 instead of 42 ns a row).
#[inline(never)]
fn quat_rows_to_euler(
    input: &[f64],
    output: &mut [f64],
    from: Representation,
    sequence: EulerSequence,
    degrees: bool,
) -> Result<(), (usize, LineProblem)> {
    /// Rows converted side by side (four measured fastest on x86-64: two
    /// SSE2 registers a number; `quats` below lists them).
    const LANES: usize = 4;
    let xyzw = from == Representation::QuatXyzw;
    let quat = |r: &[f64]| {
        if xyzw {
            DQuat::from_xyzw(r[0], r[1], r[2], r[3])
        } else {
            DQuat::from_xyzw(r[1], r[2], r[3], r[0])
        }
    };
    let mut blocks_in = input.chunks_exact(4 * LANES);
    let mut blocks_out = output.chunks_exact_mut(3 * LANES);
    for (k, (rows, slots)) in (&mut blocks_in).zip(&mut blocks_out).enumerate() {
        // (not array::from_fn: its closure was left out of line, `perf`)
        let quats = [
            quat(&rows[..4]),
            quat(&rows[4..8]),
            quat(&rows[8..12]),
            quat(&rows[12..]),
        ];
        match euler_angles_of_quats::<LANES>(sequence, quats, degrees) {
            Ok(angles) => slots.copy_from_slice(angles.as_flattened()),
            Err((j, e)) => {
                // The rows before j are rotations; j is not, and the CLI
                // names a number that is not finite first.
                let problem = non_finite(&rows[4 * j..4 * j + 4]).unwrap_or(LineProblem::from(e));
                return Err((k * LANES + j, problem));
            }
        }
    }
    let done = input.len() / 4 / LANES * LANES;
    let rest = blocks_in.remainder().chunks_exact(4);
    for (j, (row, slot)) in rest
        .zip(blocks_out.into_remainder().chunks_exact_mut(3))
        .enumerate()
    {
        let angles = euler_angles_of_quat(sequence, quat(row), degrees)
            .map_err(|e| (done + j, non_finite(row).unwrap_or(LineProblem::from(e))))?;
        slot.copy_from_slice(&angles);
    }
    Ok(())
}

/// The fewest rows worth a second thread (a spawn costs ~20 µs, a row
/// ~0.1–0.2 µs).
const ROWS_PER_THREAD: usize = 1 << 15;

/// [`convert_rows`] on up to `available_parallelism` scoped threads, each
/// on a contiguous block of rows; the error reported is the first bad row,
/// as on one thread. The numbers are the same: each row is converted alone.
fn convert_rows_parallel(
    input: &[f64],
    output: &mut [f64],
    from: Representation,
    to: Representation,
    degrees: bool,
) -> Result<(), (usize, LineProblem)> {
    let (m, n) = (from.count(), to.count());
    let rows = input.len() / m;
    let threads = std::thread::available_parallelism()
        .map_or(1, usize::from)
        .min(rows / ROWS_PER_THREAD)
        .max(1);
    if threads == 1 {
        return convert_rows(input, output, from, to, degrees);
    }
    let per = rows.div_ceil(threads);
    let results: Vec<Result<(), (usize, LineProblem)>> = std::thread::scope(|scope| {
        let jobs: Vec<_> = (input.chunks(per * m))
            .zip(output.chunks_mut(per * n))
            .enumerate()
            .map(|(k, (rows_in, rows_out))| {
                scope.spawn(move || {
                    convert_rows(rows_in, rows_out, from, to, degrees)
                        .map_err(|(i, problem)| (k * per + i, problem))
                })
            })
            .collect();
        jobs.into_iter()
            .map(|job| {
                job.join()
                    .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
            })
            .collect()
    });
    results.into_iter().collect()
}

/// Converts every row of `values` from `from` to `to` (the GIL released).
///
/// ```text
/// row (numbers in `from`) → unit quaternion → numbers in `to`
/// ```
///
/// # Errors
/// A `KreiselError` for a wrong shape, or naming the first bad row with the
/// CLI's message for it.
fn convert_array<'py>(
    py: Python<'py>,
    values: &Floats<'py>,
    from: Representation,
    to: Representation,
    degrees: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let leading = values.leading_shape(
        &trailing_shape(from),
        &format!("{} numbers for {from}", from.count()),
    )?;
    let data = values.values();
    let data: &[f64] = &data;
    let (m, n) = (from.count(), to.count());
    let result = py.detach(|| {
        let mut out = vec![0.0; data.len() / m * n];
        convert_rows_parallel(data, &mut out, from, to, degrees).map(|()| out)
    });
    match result {
        Ok(out) => {
            let mut shape = leading;
            shape.extend(trailing_shape(to));
            to_numpy(py, shape, out)
        }
        Err((row, problem)) => Err(error(format!(
            "{}: {problem}",
            row_name(values.name(), &leading, row)
        ))),
    }
}

/// Quaternions of Euler angles: `(..., 3)` angles → `(..., 4)` unit
/// quaternions `(w, x, y, z)`, canonical (`w ≥ 0`).
///
/// `seq` names the convention as scipy does: uppercase is intrinsic
/// (`"ZXZ"`: about the moving body axes), lowercase extrinsic (`"zxz"`:
/// about the fixed axes); all 24 (`XYZ XZY YXZ YZX ZXY ZYX XYX XZX YXY YZY
/// ZXZ ZYZ` and their lowercase forms). Angles in radians, or degrees with
/// `degrees=True`. The numbers are those of `kreisel convert --from
/// euler:SEQ --to quat`, bit for bit.
///
/// Intrinsic `ABC`: `q = q_A(a0) ⊗ q_B(a1) ⊗ q_C(a2)`; extrinsic `abc`:
/// `q = q_c(a2) ⊗ q_b(a1) ⊗ q_a(a0)`, `q_n(t) = (cos t/2, sin t/2 e_n)`.
///
/// Raises `KreiselError` (a `ValueError`) for an unknown sequence, a last
/// axis that is not 3 long, or a non-finite angle (naming its index).
///
/// >>> import kreisel
/// >>> kreisel.from_euler("ZXZ", [90.0, 0.0, 0.0], degrees=True).round(12).tolist()
/// [0.707106781187, 0.0, 0.0, 0.707106781187]
/// >>> kreisel.from_euler("xyz", [[0.0, 0.0, 0.0], [3.141592653589793, 0.0, 0.0]]).round(12).tolist()
/// [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]
#[pyfunction]
#[pyo3(signature = (seq, angles, degrees = false))]
fn from_euler<'py>(
    py: Python<'py>,
    seq: &str,
    angles: &Bound<'py, PyAny>,
    degrees: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    guard(|| {
        let sequence = parse_sequence(seq)?;
        let angles = Floats::read("angles", angles)?;
        convert_array(
            py,
            &angles,
            Representation::Euler(sequence),
            Representation::Quat,
            degrees,
        )
    })
}

/// Euler angles of quaternions: `(..., 4)` quaternions `(w, x, y, z)` (any
/// non-zero length; normalised) → `(..., 3)` angles.
///
/// Ranges: first and third angle in `(-π, π]`, middle in `[0, π]` (proper
/// Euler, e.g. `ZXZ`) or `[-π/2, π/2]` (Tait–Bryan, e.g. `XYZ`); exactly at
/// gimbal lock the third angle is 0 and the first carries the rotation. The
/// method (Bernardes & Viollet 2022, atan2 only) keeps ~1e-16 rad next to
/// the lock. Radians, or degrees with `degrees=True`. The numbers are
/// those of `kreisel convert --from quat --to euler:SEQ`, bit for bit.
///
/// Raises `KreiselError` for an unknown sequence, a last axis that is not 4
/// long, a non-finite number or a zero quaternion (naming its index).
///
/// >>> import kreisel
/// >>> q = kreisel.from_euler("ZXZ", [10.0, 20.0, 30.0], degrees=True)
/// >>> kreisel.as_euler("ZXZ", q, degrees=True).round(9).tolist()
/// [10.0, 20.0, 30.0]
/// >>> kreisel.as_euler("ZXZ", [1.0, 0.0, 0.0, 0.0]).tolist()
/// [0.0, 0.0, 0.0]
#[pyfunction]
#[pyo3(signature = (seq, quats, degrees = false))]
fn as_euler<'py>(
    py: Python<'py>,
    seq: &str,
    quats: &Bound<'py, PyAny>,
    degrees: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    guard(|| {
        let sequence = parse_sequence(seq)?;
        let quats = Floats::read("quats", quats)?;
        convert_array(
            py,
            &quats,
            Representation::Quat,
            Representation::Euler(sequence),
            degrees,
        )
    })
}

/// Converts rotations between the representations of `kreisel convert`.
///
/// `src` and `dst` are `"quat"` (`w, x, y, z`, last axis 4; any non-zero
/// length on input, canonical `w ≥ 0` on output), `"quat-xyzw"` (scipy's
/// and ROS's order), `"matrix"` (active, `v_world = M v_body`, last axes
/// `(3, 3)`; orthonormal within 1e-6 and `det > 0` on input), `"rotvec"`
/// (axis · angle, always radians), `"axis-angle"` (`x, y, z, angle`; output
/// unit axis and angle in `[0, π]`) or `"euler:SEQ"` (e.g. `"euler:ZXZ"`).
/// With `degrees=True`, Euler angles and the axis–angle angle are in
/// degrees. The leading shape is kept: `(..., 3, 3)` matrices become
/// `(..., 4)` quaternions. The numbers are the CLI's, bit for bit.
///
/// Raises `KreiselError` with the CLI's message for an unknown
/// representation, a wrong shape, and the first row that is not a rotation
/// (naming its index: `values[2]: matrix is a reflection, …`).
///
/// >>> import kreisel
/// >>> kreisel.convert([0.0, 0.0, 1.5707963267948966], "rotvec", "axis-angle", degrees=True).round(12).tolist()
/// [0.0, 0.0, 1.0, 90.0]
/// >>> kreisel.convert([[1, 0, 0], [0, 0, -1], [0, 1, 0]], "matrix", "quat-xyzw").round(12).tolist()
/// [0.707106781187, 0.0, 0.0, 0.707106781187]
#[pyfunction]
#[pyo3(signature = (values, src, dst, degrees = false))]
fn convert<'py>(
    py: Python<'py>,
    values: &Bound<'py, PyAny>,
    src: &str,
    dst: &str,
    degrees: bool,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    guard(|| {
        let from = parse_representation("src", src)?;
        let to = parse_representation("dst", dst)?;
        let values = Floats::read("values", values)?;
        convert_array(py, &values, from, to, degrees)
    })
}

/// Adds this part's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(from_euler, m)?)?;
    m.add_function(wrap_pyfunction!(as_euler, m)?)?;
    m.add_function(wrap_pyfunction!(convert, m)?)?;
    Ok(())
}
