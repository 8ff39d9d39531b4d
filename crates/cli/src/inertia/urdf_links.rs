//! From a link's geometry to its mass properties: each mesh (loaded by
//! kreisel-inertia, scaled per axis) or box, cylinder and sphere primitive
//! integrated at unit density, placed by its `<origin>`, and summed as one
//! rigid solid in the link frame.
//!
//! ```text
//! part k:  c ↦ R_k c + t_k,   I ↦ R_k I R_kᵀ           (R = Rz(y) Ry(p) Rx(r))
//! link:    m = Σ m_k,  c = Σ m_k c_k / m,  I = Σ_k [I_k + m_k (|d_k|² E − d_k d_kᵀ)]
//! ```
//!
//! At unit density the mass is the volume; the caller scales the result to
//! the link's mass or to `--density`.

use std::path::Path;

use glam::DVec3;
use kreisel_inertia::io::{Body, LoadOptions, SolidOptions};
use kreisel_inertia::{MassModel, MassProperties, Material, TriMesh};

use super::WeldChoice;
use super::urdf_args::GeometrySource;
use super::urdf_document::{Geometry, Link, Shape};
use super::urdf_notes::tidy;
use super::urdf_paths::MeshPaths;
use super::urdf_table::sig;
use crate::error::CliError;
use kreisel_scene::error::one_line;

/// A link's geometry integrated at unit density (1 kg/m³).
#[derive(Debug, Clone, PartialEq)]
pub struct LinkSolid {
    /// Mass properties in the link frame; `mass` is the volume, m³.
    pub unit: MassProperties,
    /// What was integrated: mesh file names and primitive names.
    pub parts: Vec<String>,
    /// Repairs made to the meshes.
    pub warnings: Vec<String>,
    /// Points whose convex hull holds the geometry (mesh vertices, primitive
    /// bounding-box corners), link frame.
    pub hull_points: Vec<DVec3>,
}

/// Smallest and largest plausible size of a link's geometry, m: outside,
/// a mesh's scale was likely left out (a mesh in mm read as m) or doubled.
const PLAUSIBLE_SIZE: (f64, f64) = (1e-3, 10.0);

impl LinkSolid {
    /// The diagonal of the geometry's bounding box, m.
    pub fn size(&self) -> f64 {
        let (lo, hi) = self
            .hull_points
            .iter()
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &p| {
                (lo.min(p), hi.max(p))
            });
        (hi - lo).length()
    }

    /// A warning when the geometry is implausibly large or small for a link.
    pub fn size_warning(&self) -> Option<String> {
        let size = self.size();
        let (small, large) = PLAUSIBLE_SIZE;
        (!(small..=large).contains(&size)).then(|| {
            format!(
                "the geometry is {} m across, implausible for a link: is each mesh's scale right?",
                sig(size)
            )
        })
    }
}

/// What became of a link's geometry.
#[derive(Debug, Clone, PartialEq)]
pub enum LinkOutcome {
    /// The link has no geometry of the chosen kind.
    NoGeometry,
    /// Integrated.
    Solid(LinkSolid),
    /// A mesh or primitive that cannot be integrated, and why (one line).
    Failed(String),
}

/// One part's unit-density properties in its own frame, its hull points,
/// its name and warnings; `Err` with a reason when it cannot be integrated.
type Part = Result<(MassProperties, Vec<DVec3>, String, Vec<String>), String>;

/// The eight corners of the box `[-h, h]`.
fn corners(h: DVec3) -> Vec<DVec3> {
    (0..8)
        .map(|i| {
            DVec3::new(
                if i & 1 == 0 { -h.x } else { h.x },
                if i & 2 == 0 { -h.y } else { h.y },
                if i & 4 == 0 { -h.z } else { h.z },
            )
        })
        .collect()
}

/// A primitive at unit density (a mesh or an unknown element: the reason it is not one).
fn primitive(shape: &Shape) -> Part {
    let (props, half, name) = match *shape {
        Shape::Box { size } => (
            MassProperties::solid_box(1.0, size),
            size / 2.0,
            "box".to_owned(),
        ),
        Shape::Cylinder { radius, length } => (
            MassProperties::solid_cylinder(1.0, radius, length),
            DVec3::new(radius, radius, length / 2.0),
            "cylinder".to_owned(),
        ),
        Shape::Sphere { radius } => (
            MassProperties::solid_sphere(1.0, radius),
            DVec3::splat(radius),
            "sphere".to_owned(),
        ),
        Shape::Capsule { radius, length } => (
            MassProperties::solid_capsule(1.0, radius, length),
            DVec3::new(radius, radius, length / 2.0 + radius),
            "capsule".to_owned(),
        ),
        Shape::Other { ref element } => {
            return Err(format!(
                "<{element}> geometry cannot be integrated (kreisel knows box, cylinder, sphere, capsule and mesh)"
            ));
        }
        Shape::Mesh { .. } => return Err("a mesh is not a primitive".to_owned()),
    };
    let props = props.map_err(|e| format!("{name}: {}", one_line(&e.to_string())))?;
    Ok((props, corners(half), name, Vec::new()))
}

/// How meshes are loaded and modelled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshModel {
    /// Vertex welding (`--weld`).
    pub weld: WeldChoice,
    /// Solid, or the solid convex hull (`--hull`).
    pub model: MassModel,
}

/// A mesh file's bodies, scaled per axis, at unit density; `written` is
/// its filename as the URDF writes it (named in messages).
fn mesh(path: &Path, written: &str, scale: DVec3, how: MeshModel) -> Part {
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    // The library's messages name the file: as the URDF writes it.
    let fail = |e: &dyn std::fmt::Display| tidy(&one_line(&e.to_string()), path, written);
    if !(scale.is_finite() && scale.x * scale.y * scale.z != 0.0) {
        return Err(format!(
            "{name}: scale {scale} has a zero or non-finite component"
        ));
    }
    let load = LoadOptions {
        weld: how.weld.weld(scale.abs().max_element()),
        merge: false,
    };
    let bodies = load.load(path).map_err(|e| fail(&e))?;
    let mirrored = scale.x * scale.y * scale.z < 0.0;
    let mut points = Vec::new();
    let bodies = bodies
        .into_iter()
        .map(|body| {
            let (vertices, mut triangles) = body.mesh.into_parts();
            let vertices: Vec<DVec3> = vertices.into_iter().map(|v| v * scale).collect();
            if mirrored {
                // A mirror turns the surface inside out: keep it outward.
                triangles.iter_mut().for_each(|t| t.swap(1, 2));
            }
            points.extend_from_slice(&vertices);
            let mesh = TriMesh::try_new(vertices, triangles).map_err(|e| fail(&e))?;
            Ok(Body { mesh, ..body })
        })
        .collect::<Result<Vec<_>, String>>()?;
    let options = SolidOptions {
        load,
        scale: 1.0,
        model: how.model,
        material: Material::Density(1.0),
    };
    let solid = options.solid(path, bodies).map_err(|e| {
        let hint = if how.model == MassModel::Solid {
            " (--hull models each mesh as its solid convex hull)"
        } else {
            ""
        };
        format!("{}{hint}", fail(&e))
    })?;
    let warnings = solid
        .warnings()
        .map(|(body, w)| {
            let warning = format!(
                "{name} body '{}': {}",
                one_line(body),
                one_line(&w.to_string())
            );
            tidy(&warning, path, written)
        })
        .collect();
    Ok((solid.properties, points, name, warnings))
}

/// Integrates one geometry element, placed in the link frame.
fn part(
    urdf: &Path,
    geometry: &Geometry,
    paths: &MeshPaths,
    how: MeshModel,
) -> Result<Part, CliError> {
    let local = match &geometry.shape {
        Shape::Mesh { filename, scale } => {
            let file = paths.resolve(filename).map_err(|message| CliError::Urdf {
                path: urdf.to_path_buf(),
                line: Some(geometry.line),
                message,
            })?;
            mesh(&file, filename, *scale, how)
        }
        shape => primitive(shape),
    };
    let (q, t) = (geometry.origin.rotation(), geometry.origin.xyz);
    Ok(local.map(|(props, points, name, warnings)| {
        let points = points.into_iter().map(|p| q * p + t).collect();
        (props.placed(q, t), points, name, warnings)
    }))
}

/// The link's geometry of the chosen kind at unit density.
///
/// # Errors
/// [`CliError::Urdf`] for a mesh that does not exist or a package that
/// cannot be found (naming the line). A mesh that exists but cannot be
/// integrated (open, unknown format, …) is [`LinkOutcome::Failed`].
pub fn integrate(
    urdf: &Path,
    link: &Link,
    source: GeometrySource,
    paths: &MeshPaths,
    how: MeshModel,
) -> Result<LinkOutcome, CliError> {
    let geometries = match source {
        GeometrySource::Collision => &link.collision,
        GeometrySource::Visual => &link.visual,
    };
    if geometries.is_empty() {
        return Ok(LinkOutcome::NoGeometry);
    }
    let mut solid = LinkSolid {
        unit: MassProperties::point(0.0, DVec3::ZERO),
        parts: Vec::new(),
        warnings: Vec::new(),
        hull_points: Vec::new(),
    };
    let mut placed = Vec::with_capacity(geometries.len());
    let mut failures = Vec::new();
    for geometry in geometries {
        match part(urdf, geometry, paths, how)? {
            Ok((props, points, name, warnings)) => {
                placed.push(props);
                solid.hull_points.extend(points);
                solid.parts.push(name);
                solid.warnings.extend(warnings);
            }
            Err(reason) => failures.push(reason),
        }
    }
    if !failures.is_empty() {
        return Ok(LinkOutcome::Failed(failures.join("; ")));
    }
    solid.unit = placed.into_iter().sum();
    solid.warnings.extend(solid.size_warning());
    Ok(LinkOutcome::Solid(solid))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn implausible_sizes_are_named() {
        let solid = |h: f64| LinkSolid {
            unit: MassProperties::point(1.0, DVec3::ZERO),
            parts: Vec::new(),
            warnings: Vec::new(),
            hull_points: corners(DVec3::splat(h)),
        };
        assert_eq!(solid(0.5).size(), 3f64.sqrt());
        assert_eq!(solid(0.5).size_warning(), None);
        // A 100 mm part read as metres.
        let w = solid(50.0).size_warning().unwrap();
        assert!(w.starts_with("the geometry is 173.205 m across"), "{w}");
        assert!(solid(1e-4).size_warning().is_some());
    }
}
