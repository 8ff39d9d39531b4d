//! Conversions between the glam types of this crate and nalgebra's
//! (feature `nalgebra`).
//!
//! glam and nalgebra are both foreign crates, so these are free functions
//! rather than `From` impls.
//!
//! ```
//! use glam::DQuat;
//! use kreisel_kinematics::nalgebra_interop::{dquat_from_unit_quaternion, unit_quaternion_from_dquat};
//! let q = DQuat::from_rotation_x(0.5);
//! let n = unit_quaternion_from_dquat(q);
//! assert_eq!(n.w, q.w);
//! assert_eq!(dquat_from_unit_quaternion(&n), q);
//! ```

use glam::{DMat3, DQuat, DVec3};
use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector3};

/// glam `DVec3` → nalgebra `Vector3<f64>`.
///
/// ```text
/// (x, y, z) ↦ (x, y, z)
/// ```
pub fn vector3_from_dvec3(v: DVec3) -> Vector3<f64> {
    Vector3::new(v.x, v.y, v.z)
}

/// nalgebra `Vector3<f64>` → glam `DVec3`.
///
/// ```text
/// (x, y, z) ↦ (x, y, z)
/// ```
pub fn dvec3_from_vector3(v: &Vector3<f64>) -> DVec3 {
    DVec3::new(v.x, v.y, v.z)
}

/// glam `DQuat` → nalgebra `UnitQuaternion<f64>`, component for component
/// (no renormalisation: the caller's quaternion must be unit).
///
/// ```text
/// (w, x, y, z) ↦ (w, x, y, z)
/// ```
pub fn unit_quaternion_from_dquat(q: DQuat) -> UnitQuaternion<f64> {
    UnitQuaternion::new_unchecked(Quaternion::new(q.w, q.x, q.y, q.z))
}

/// nalgebra `UnitQuaternion<f64>` → glam `DQuat`, component for component.
///
/// ```text
/// (w, x, y, z) ↦ (w, x, y, z)
/// ```
pub fn dquat_from_unit_quaternion(q: &UnitQuaternion<f64>) -> DQuat {
    DQuat::from_xyzw(q.i, q.j, q.k, q.w)
}

/// glam `DMat3` → nalgebra `Matrix3<f64>` (same element at the same row and column).
///
/// ```text
/// M_rc ↦ M_rc
/// ```
pub fn matrix3_from_dmat3(m: DMat3) -> Matrix3<f64> {
    Matrix3::from_column_slice(&m.to_cols_array())
}

/// nalgebra `Matrix3<f64>` → glam `DMat3`.
///
/// ```text
/// M_rc ↦ M_rc
/// ```
pub fn dmat3_from_matrix3(m: &Matrix3<f64>) -> DMat3 {
    DMat3::from_cols_slice(m.as_slice())
}

/// glam rotation `DMat3` → nalgebra `Rotation3<f64>` (unchecked: the matrix
/// must be a rotation).
///
/// ```text
/// M_rc ↦ R_rc
/// ```
pub fn rotation3_from_dmat3(m: DMat3) -> Rotation3<f64> {
    Rotation3::from_matrix_unchecked(matrix3_from_dmat3(m))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotations_act_the_same_in_both_libraries() {
        let q = DQuat::from_rotation_y(0.4) * DQuat::from_rotation_z(-1.2);
        let v = DVec3::new(0.3, -0.7, 2.0);
        let nq = unit_quaternion_from_dquat(q);
        let nv = nq * vector3_from_dvec3(v);
        assert!((dvec3_from_vector3(&nv) - q * v).length() < 1e-15);
        let m = DMat3::from_quat(q);
        let nr = rotation3_from_dmat3(m);
        assert!((dvec3_from_vector3(&(nr * vector3_from_dvec3(v))) - m * v).length() < 1e-15);
        assert_eq!(dmat3_from_matrix3(&matrix3_from_dmat3(m)), m);
    }
}
