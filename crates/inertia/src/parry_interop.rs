//! The bridge to parry3d: mass properties for cross-checks, and conversions to and from parry's
//! types (parry 0.31 uses glam 0.33 vectors; kreisel uses glam 0.34).

use glam::{DMat3, DVec3};
use parry3d_f64::mass_properties::MassProperties as ParryMassProperties;
use parry3d_f64::math::Vector as ParryVector;

use crate::{MassProperties, TriMesh};

/// A kreisel vector as a parry vector.
#[inline]
pub fn to_parry(v: DVec3) -> ParryVector {
    ParryVector::new(v.x, v.y, v.z)
}

/// A parry vector as a kreisel vector.
#[inline]
pub fn from_parry(v: ParryVector) -> DVec3 {
    DVec3::new(v.x, v.y, v.z)
}

/// parry's mass properties of a closed mesh, converted to kreisel's type
/// (for cross-checks; parry returns no error for open or mis-wound meshes).
///
/// ```text
/// I = R diag(principal) Rᵀ,   R = parry's principal_inertia_local_frame
/// ```
///
/// ```
/// use glam::DVec3;
/// use kreisel_inertia::{parry_mass_properties, TriMesh};
/// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
/// let tet = TriMesh::new(v, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]);
/// let p = parry_mass_properties(&tet, 6.0);
/// assert!((p.mass - 1.0).abs() < 1e-14);
/// ```
pub fn parry_mass_properties(mesh: &TriMesh, density: f64) -> MassProperties {
    let points: Vec<ParryVector> = mesh.vertices().iter().map(|&p| to_parry(p)).collect();
    let parry = ParryMassProperties::from_trimesh(density, &points, mesh.triangles());
    from_parry_mass_properties(&parry)
}

/// Converts parry's mass properties (principal form) to kreisel's.
pub fn from_parry_mass_properties(parry: &ParryMassProperties) -> MassProperties {
    let r = parry.principal_inertia_local_frame;
    let to_dvec = |v: parry3d_f64::math::Vector| DVec3::new(v.x, v.y, v.z);
    let cols = [
        to_dvec(r * ParryVector::X),
        to_dvec(r * ParryVector::Y),
        to_dvec(r * ParryVector::Z),
    ];
    let rot = DMat3::from_cols(cols[0], cols[1], cols[2]);
    let principal = from_parry(parry.principal_inertia());
    MassProperties {
        mass: parry.mass(),
        center_of_mass: from_parry(parry.local_com),
        inertia: rot * DMat3::from_diagonal(principal) * rot.transpose(),
    }
}
