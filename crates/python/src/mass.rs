//! `kreisel.mass_properties` (a mesh file) and
//! `kreisel.mass_properties_from_arrays` (vertex and face arrays, e.g. from
//! trimesh): the report of `kreisel inertia --format json` as a dict.
//!
//! No physics here: the options become the CLI's [`Setup`], the CLI's
//! [`compute`] loads, checks, repairs and integrates, and the dict is built
//! from its [`Report`] field by field in the JSON's order, so the numbers,
//! warnings and error messages are the CLI's (numbers as `float`, vectors
//! and matrices as numpy arrays; a non-finite number, `null` in JSON, stays
//! a float here).

use std::path::PathBuf;

use glam::{DMat3, DVec3};
use kreisel_inertia::io::{Body, LoadWarning};
use kreisel_inertia::{MassModel, TriMesh};
use kreisel_scene::error::{BodyProblem, SceneError};
use kreisel_scene::inertia_request::{
    DensityChoice, FRAME, Report, Setup, Summary, compute, compute_scaled,
};
use kreisel_scene::mesh_options::{Units, WeldChoice};
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::arguments::{number, path};
use crate::errors::{error, guard, scene_error};

/// Wall thickness of the shell model without `thickness`, m (the CLI's).
const DEFAULT_THICKNESS: f64 = kreisel_scene::mesh_options::DEFAULT_THICKNESS;

/// The name of the file in the report of `mass_properties_from_arrays`.
const ARRAYS_FILE: &str = "<arrays>";

/// An optional number argument (`name` names it in messages).
fn optional(name: &str, value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<f64>> {
    value.map(|v| number(name, v)).transpose()
}

/// A positive finite number, or the CLI's message for `quantity`.
fn positive(value: f64, quantity: &str) -> PyResult<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(error(format!(
            "{quantity} must be a positive finite number, got {value}"
        )))
    }
}

/// The options of both functions, checked as the CLI checks its own.
#[allow(clippy::too_many_arguments)] // the Python keywords, one each
fn setup(
    file: PathBuf,
    density: Option<&Bound<'_, PyAny>>,
    mass: Option<&Bound<'_, PyAny>>,
    units: &str,
    model: &str,
    thickness: Option<&Bound<'_, PyAny>>,
    weld: Option<&Bound<'_, PyAny>>,
    merge: bool,
    scale: Option<&Bound<'_, PyAny>>,
) -> PyResult<Setup> {
    let density = optional("density", density)?;
    let mass = optional("mass", mass)?;
    let thickness = optional("thickness", thickness)?;
    let scale = optional("scale", scale)?;
    let units = match units {
        "mm" => Units::Mm,
        "cm" => Units::Cm,
        "m" => Units::M,
        "in" => Units::In,
        other => {
            return Err(error(format!(
                "units must be one of \"mm\", \"cm\", \"m\", \"in\", got {other:?}"
            )));
        }
    };
    let thickness = thickness
        .map(|t| positive(t, "thickness (m)"))
        .transpose()?;
    let model = match (model, thickness) {
        ("solid", None) => MassModel::Solid,
        ("hull", None) => MassModel::ConvexHull,
        ("shell", t) => MassModel::Shell {
            thickness: t.unwrap_or(DEFAULT_THICKNESS),
        },
        ("solid" | "hull", Some(_)) => {
            return Err(error(
                "thickness is the wall of model=\"shell\": give model=\"shell\" or no thickness",
            ));
        }
        (other, _) => {
            return Err(error(format!(
                "model must be one of \"solid\", \"shell\", \"hull\", got {other:?}"
            )));
        }
    };
    let density = match (density, mass) {
        (Some(_), Some(_)) => {
            return Err(error(
                "density and mass exclude each other: mass sets the density from the total volume",
            ));
        }
        (Some(d), None) => DensityChoice::Given(positive(d, "density (kg/m^3)")?),
        (None, Some(m)) => DensityChoice::TotalMass(positive(m, "mass (kg)")?),
        (None, None) => DensityChoice::Default,
    };
    let weld = match weld {
        None => WeldChoice::Default,
        Some(w)
            if w.extract::<String>()
                .is_ok_and(|s| s.eq_ignore_ascii_case("off")) =>
        {
            WeldChoice::Off
        }
        Some(w) => match w.extract::<f64>() {
            Ok(t) if t.is_finite() && t >= 0.0 => WeldChoice::Metres(t),
            _ => {
                return Err(error(
                    "weld must be \"off\" or a non-negative finite number of metres",
                ));
            }
        },
    };
    let (units, scale) = match scale {
        None => (Some(units), units.scale()),
        Some(_) if units != Units::M => {
            return Err(error(
                "scale and units exclude each other: scale is metres per mesh unit",
            ));
        }
        Some(s) => (None, positive(s, "scale (metres per mesh unit)")?),
    };
    Ok(Setup {
        file,
        units,
        scale,
        model,
        density,
        weld,
        merge,
    })
}

/// A numpy vector.
pub(crate) fn vector<'py>(py: Python<'py>, v: &[f64]) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_slice(py, v)
}

/// A 3 × 3 numpy matrix, rows of `m`.
fn matrix_rows<'py>(py: Python<'py>, m: DMat3) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let rows: Vec<f64> = (0..3).flat_map(|r| m.row(r).to_array()).collect();
    PyArray1::from_vec(py, rows).reshape([3, 3])
}

/// The fields of one body or of the assembly, in the JSON's order.
fn fields(dict: &Bound<'_, PyDict>, setup: &Setup, s: &Summary) -> PyResult<()> {
    let py = dict.py();
    dict.set_item("file", setup.file.display().to_string())?;
    dict.set_item("units", setup.units_name())?;
    dict.set_item("scale", setup.scale)?;
    dict.set_item("model", setup.model_name())?;
    if let Some(t) = setup.thickness() {
        dict.set_item("thickness", t)?;
    }
    dict.set_item("density", s.density)?;
    dict.set_item("density_source", setup.density_source())?;
    dict.set_item("frame", FRAME)?;
    dict.set_item("mass", s.properties.mass)?;
    dict.set_item("volume", s.volume)?;
    dict.set_item("area", s.area)?;
    dict.set_item("triangles", s.triangles)?;
    let c: DVec3 = s.properties.center_of_mass;
    dict.set_item("center_of_mass", vector(py, &c.to_array()))?;
    dict.set_item("inertia", matrix_rows(py, s.properties.inertia)?)?;
    dict.set_item(
        "principal_moments",
        vector(py, &s.principal.moments.to_array()),
    )?;
    // Rows = columns of the rotation matrix = the axes (as the JSON).
    dict.set_item(
        "principal_axes",
        matrix_rows(py, s.principal.axes.transpose())?,
    )?;
    let q = s.principal.orientation;
    dict.set_item("principal_orientation", vector(py, &[q.w, q.x, q.y, q.z]))?;
    dict.set_item("warnings", PyList::new(py, &s.warnings)?)?;
    Ok(())
}

/// The report as the dict of `kreisel inertia --format json`.
fn report_dict<'py>(py: Python<'py>, report: &Report) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    fields(&dict, &report.setup, &report.assembly)?;
    let bodies = PyList::empty(py);
    for body in &report.bodies {
        let b = PyDict::new(py);
        b.set_item("name", &body.name)?;
        fields(&b, &report.setup, body)?;
        bodies.append(b)?;
    }
    dict.set_item("bodies", bodies)?;
    Ok(dict)
}

/// Mass, centre of mass, inertia tensor and principal axes of the bodies in
/// a mesh file (STL, OBJ, PLY, glTF/GLB): the report of
/// `kreisel inertia FILE --format json` as a dict.
///
/// Keys (the assembly; SI units after scaling): ``file``, ``units``,
/// ``scale``, ``model``, ``thickness`` (shell only), ``density``,
/// ``density_source``, ``frame``, ``mass``, ``volume``, ``area``,
/// ``triangles``, ``center_of_mass`` (3,), ``inertia`` (3, 3) about the
/// centre of mass in mesh axes (off-diagonal elements carry the minus
/// sign), ``principal_moments`` (3,) ascending, ``principal_axes`` (3, 3)
/// one axis per row, ``principal_orientation`` (4,) w, x, y, z,
/// ``warnings`` (list of str, the repairs made), and ``bodies``: one dict
/// per body of the file with its ``name`` and the same keys.
///
/// density (kg/m^3, default 1000) or mass (kg, of the whole file); units
/// "mm", "cm", "m" or "in"; model "solid" (a closed surface), "shell" (a
/// thin wall of ``thickness`` m, default 0.001) or "hull" (the solid
/// convex hull). weld: "off" or a tolerance in metres (default 1e-6 x the
/// bounding-box diagonal); merge=True treats all bodies as one; scale:
/// metres per mesh unit instead of units (as ``--scale``).
///
/// Raises KreiselError (a ValueError) with the CLI's one-line message: a
/// missing or unreadable file, an open mesh for the solid model, bad options.
///
/// >>> import kreisel
/// >>> p = kreisel.mass_properties("assets/t_handle.obj", density=2700.0)
/// >>> sorted(p)[:4]
/// ['area', 'bodies', 'center_of_mass', 'density']
/// >>> p["inertia"].shape, p["model"]
/// ((3, 3), 'solid')
#[pyfunction]
#[pyo3(signature = (path, density=None, mass=None, units="m", model="solid", thickness=None, *, weld=None, merge=false, scale=None))]
#[allow(clippy::too_many_arguments)] // the Python keywords, one each
fn mass_properties<'py>(
    py: Python<'py>,
    path: &Bound<'py, PyAny>,
    density: Option<&Bound<'py, PyAny>>,
    mass: Option<&Bound<'py, PyAny>>,
    units: &str,
    model: &str,
    thickness: Option<&Bound<'py, PyAny>>,
    weld: Option<&Bound<'py, PyAny>>,
    merge: bool,
    scale: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let file = self::path("path", path)?;
        let setup = setup(
            file, density, mass, units, model, thickness, weld, merge, scale,
        )?;
        let report = py.detach(|| compute(setup)).map_err(scene_error)?;
        report_dict(py, &report)
    })
}

/// `array` (already of element type `T`) as an (N, 3) array's rows, or
/// `bad` naming what is wrong.
fn rows_of_three<T: numpy::Element + Copy>(
    array: &Bound<'_, PyAny>,
    bad: impl Fn(String) -> PyErr,
) -> PyResult<Vec<[T; 3]>> {
    let array = array
        .cast::<PyArray2<T>>()
        .map_err(|_| bad(format!("got {} dimensions", ndim(array))))?;
    let view = array.readonly();
    let rows = view.as_array();
    if rows.ncols() != 3 {
        return Err(bad(format!("got shape {:?}", rows.shape())));
    }
    Ok(rows
        .rows()
        .into_iter()
        .map(|r| [r[0], r[1], r[2]])
        .collect())
}

/// The vertices as an (N, 3) float64 array's rows.
fn vertices_of(vertices: &Bound<'_, PyAny>) -> PyResult<Vec<DVec3>> {
    let np = vertices.py().import("numpy")?;
    let bad = |what: String| {
        error(format!(
            "vertices must be an (N, 3) array of numbers: {what}"
        ))
    };
    let array = np
        .call_method1("asarray", (vertices, "float64"))
        .map_err(|e| bad(e.to_string()))?;
    Ok(rows_of_three::<f64>(&array, bad)?
        .into_iter()
        .map(DVec3::from_array)
        .collect())
}

/// `array.ndim` (0 when unknown).
fn ndim(array: &Bound<'_, PyAny>) -> usize {
    array.getattr("ndim").and_then(|n| n.extract()).unwrap_or(0)
}

/// The faces as (M, 3) integer vertex indices below `vertex_count`.
fn faces_of(faces: &Bound<'_, PyAny>, vertex_count: usize) -> PyResult<Vec<[u32; 3]>> {
    let np = faces.py().import("numpy")?;
    let bad = |what: String| {
        error(format!(
            "faces must be an (M, 3) array of integer vertex indices: {what}"
        ))
    };
    let array = np
        .call_method1("asarray", (faces,))
        .map_err(|e| bad(e.to_string()))?;
    let kind: String = array.getattr("dtype")?.getattr("kind")?.extract()?;
    if !(kind == "i" || kind == "u") {
        let dtype = array.getattr("dtype")?.str()?.to_string();
        return Err(bad(format!("got dtype {dtype}")));
    }
    // Signed and unsigned read apart: a uint64 beyond i64 keeps its value.
    if kind == "u" {
        let array = array.call_method1("astype", ("uint64",))?;
        indices(&rows_of_three::<u64>(&array, &bad)?, vertex_count, bad)
    } else {
        let array = array.call_method1("astype", ("int64",))?;
        indices(&rows_of_three::<i64>(&array, &bad)?, vertex_count, bad)
    }
}

/// Rows of integers as vertex indices below `vertex_count`, or `bad`
/// naming the first that is not one (with its value).
fn indices<T: Copy + std::fmt::Display + TryInto<u32>>(
    rows: &[[T; 3]],
    vertex_count: usize,
    bad: impl Fn(String) -> PyErr,
) -> PyResult<Vec<[u32; 3]>> {
    let mut out = Vec::with_capacity(rows.len());
    for (i, row) in rows.iter().enumerate() {
        let mut tri = [0u32; 3];
        for (j, (&k, slot)) in row.iter().zip(&mut tri).enumerate() {
            *slot = k
                .try_into()
                .ok()
                .filter(|&k| (k as usize) < vertex_count)
                .ok_or_else(|| {
                    bad(format!(
                        "faces[{i}, {j}] = {k} is not a vertex index (0 <= index < {vertex_count})"
                    ))
                })?;
        }
        out.push(tri);
    }
    Ok(out)
}

/// One body from arrays, as the loader makes one from a file: checked,
/// welded in the arrays' units (saying so), scaled to metres.
fn body_of(
    setup: &Setup,
    name: &str,
    vertices: Vec<DVec3>,
    faces: Vec<[u32; 3]>,
) -> Result<Body, SceneError> {
    let body_error = |problem: BodyProblem| SceneError::Body {
        path: setup.file.clone(),
        body: name.to_owned(),
        problem,
    };
    let inertia_error = |e| body_error(BodyProblem::from(e));
    let mesh = TriMesh::try_new(vertices, faces).map_err(inertia_error)?;
    let (mesh, welded) = mesh
        .welded(setup.weld.weld(setup.scale))
        .map_err(inertia_error)?;
    let warnings = if welded.merged > 0 {
        vec![LoadWarning::Welded {
            vertices: welded.merged,
            tolerance: welded.tolerance,
            max_move: welded.max_move,
        }]
    } else {
        Vec::new()
    };
    let mesh = if setup.scale == 1.0 {
        mesh
    } else {
        mesh.try_scaled(setup.scale)
            .map_err(|_| body_error(BodyProblem::ScaleOverflow { scale: setup.scale }))?
    };
    Ok(Body {
        name: name.to_owned(),
        mesh,
        warnings,
    })
}

/// `mass_properties` for a mesh given as arrays: ``vertices`` (N, 3)
/// floats and ``faces`` (M, 3) integer vertex indices, e.g. a trimesh's
/// ``mesh.vertices`` and ``mesh.faces``. The dict is that of
/// `mass_properties` with ``file`` "<arrays>" and one body named ``name``.
/// The arrays are welded, checked and repaired as a file would be.
///
/// >>> import numpy as np, kreisel
/// >>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
/// >>> f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
/// >>> p = kreisel.mass_properties_from_arrays(v, f, density=6.0)
/// >>> float(p["mass"])   # 6 kg/m^3 x 1/6 m^3
/// 1.0
#[pyfunction]
#[pyo3(signature = (vertices, faces, density=None, mass=None, units="m", model="solid", thickness=None, *, weld=None, name="mesh", scale=None))]
#[allow(clippy::too_many_arguments)] // the Python keywords, one each
fn mass_properties_from_arrays<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    density: Option<&Bound<'py, PyAny>>,
    mass: Option<&Bound<'py, PyAny>>,
    units: &str,
    model: &str,
    thickness: Option<&Bound<'py, PyAny>>,
    weld: Option<&Bound<'py, PyAny>>,
    name: &str,
    scale: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    guard(|| {
        let setup = setup(
            PathBuf::from(ARRAYS_FILE),
            density,
            mass,
            units,
            model,
            thickness,
            weld,
            false,
            scale,
        )?;
        let vertices = vertices_of(vertices)?;
        let faces = faces_of(faces, vertices.len())?;
        let report = py
            .detach(|| {
                let body = body_of(&setup, name, vertices, faces)?;
                compute_scaled(setup, vec![body])
            })
            .map_err(scene_error)?;
        report_dict(py, &report)
    })
}

/// Adds this part's functions to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(mass_properties, m)?)?;
    m.add_function(wrap_pyfunction!(mass_properties_from_arrays, m)?)?;
    Ok(())
}
