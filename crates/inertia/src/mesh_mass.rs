//! From a mesh to a body: the model (solid, thin shell, convex hull), the
//! material (density or total mass), checks and repairs, and the result with
//! everything a report needs to state.

use core::fmt;

use crate::mass_properties::check_positive;
use crate::{
    CheckedMesh, InertiaError, MassProperties, MeshMoments, MeshWarning, TriMesh, convex_hull,
    prepare_shell, prepare_solid,
};

/// How a mesh becomes a body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MassModel {
    /// The volume enclosed by a closed surface (the default).
    Solid,
    /// The surface as a thin shell of uniform `thickness` (m); open meshes
    /// are allowed. Thin-shell approximation: exact as `thickness → 0`, with
    /// a relative error of order `thickness / size` otherwise.
    Shell {
        /// Wall thickness, m.
        thickness: f64,
    },
    /// The solid convex hull of the vertices (open or broken meshes too).
    ConvexHull,
}

impl fmt::Display for MassModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MassModel::Solid => f.write_str("solid"),
            MassModel::Shell { thickness } => write!(f, "shell (thickness {thickness} m)"),
            MassModel::ConvexHull => f.write_str("convex hull (solid)"),
        }
    }
}

/// The amount of material: a uniform density or the total mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Material {
    /// Uniform density, kg/m³.
    Density(f64),
    /// Total mass, kg; the density follows from the volume.
    TotalMass(f64),
}

/// Mass properties of a mesh with what was assumed and found on the way.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshMassReport {
    /// Mass, centre of mass and inertia about it, in mesh axes.
    pub properties: MassProperties,
    /// The model used.
    pub model: MassModel,
    /// The density used, kg/m³ (given, or derived from a total mass).
    pub density: f64,
    /// Volume of material, m³ (for a shell: area × thickness).
    pub volume: f64,
    /// Surface area of the (repaired) mesh or hull, m².
    pub area: f64,
    /// Number of triangles integrated.
    pub triangles: usize,
    /// What was repaired in the mesh.
    pub warnings: Vec<MeshWarning>,
}

/// Mass properties of a mesh under a model and a material.
///
/// ```text
/// solid / hull:  m = ρ V,  I from the volume moments
/// shell:         m = ρ t A, I from the surface moments scaled by ρ t
/// TotalMass(M):  ρ = M / V   (V = t A for a shell)
/// ```
///
/// The mesh is checked and repaired first ([`prepare_solid`] or
/// [`prepare_shell`]); the repairs are listed in the report's warnings.
///
/// # Errors
/// [`InertiaError::NonPositive`] for a density, mass or thickness that is
/// not positive and finite; the errors of [`prepare_solid`] (an open mesh:
/// use [`MassModel::Shell`] or [`MassModel::ConvexHull`]),
/// [`convex_hull`] and [`MeshMoments::mass_properties`].
///
/// ```
/// use glam::DVec3;
/// use kreisel_inertia::{mesh_mass_properties, MassModel, Material, TriMesh};
/// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
/// let tet = TriMesh::new(v, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]);
/// let report = mesh_mass_properties(tet, MassModel::Solid, Material::TotalMass(2.0))?;
/// assert!((report.density - 12.0).abs() < 1e-13);
/// assert!((report.properties.mass - 2.0).abs() < 1e-15);
/// # Ok::<(), kreisel_inertia::InertiaError>(())
/// ```
pub fn mesh_mass_properties(
    mesh: TriMesh,
    model: MassModel,
    material: Material,
) -> Result<MeshMassReport, InertiaError> {
    match material {
        Material::Density(d) => check_positive("density", d)?,
        Material::TotalMass(m) => check_positive("mass", m)?,
    };
    let (checked, thickness) = match model {
        MassModel::Solid => (prepare_solid(mesh)?, None),
        MassModel::Shell { thickness } => (
            prepare_shell(mesh)?,
            Some(check_positive("thickness", thickness)?),
        ),
        MassModel::ConvexHull => (
            CheckedMesh {
                mesh: convex_hull(&mesh)?,
                warnings: Vec::new(),
            },
            None,
        ),
    };
    let surface = MeshMoments::shell(&checked.mesh);
    let area = surface.zeroth;
    let (moments, volume, scale) = match thickness {
        // A shell's material per unit area is ρ t.
        Some(t) => (surface, area * t, t),
        None => {
            let solid = MeshMoments::solid(&checked.mesh);
            (solid, solid.zeroth, 1.0)
        }
    };
    // `>` is false for NaN too.
    if volume.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) {
        return Err(InertiaError::ZeroVolume);
    }
    let density = match material {
        Material::Density(d) => d,
        Material::TotalMass(m) => m / volume,
    };
    let properties = moments.mass_properties(density * scale)?;
    Ok(MeshMassReport {
        properties,
        model,
        density,
        volume,
        area,
        triangles: checked.mesh.triangles().len(),
        warnings: checked.warnings,
    })
}
