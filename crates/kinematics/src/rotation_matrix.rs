//! Rotation matrices ⇄ quaternions, with a checked conversion for matrices
//! read from files.

use glam::{DMat3, DQuat};

use crate::KinematicsError;

/// Default tolerance of [`try_quat_from_rotation_matrix`] on `max |MᵀM − I|`.
///
/// `1e-6` accepts matrices printed with seven or more significant digits
/// (typical of IMU logs and CAD exports) and rejects anything that is not
/// meant to be a rotation (a scale, a shear, a typo).
pub const ORTHONORMALITY_TOLERANCE: f64 = 1e-6;

/// The rotation matrix (`world_from_body`: `v_world = M v_body`) of a unit quaternion.
///
/// ```text
/// M = [1−2(y²+z²)   2(xy−wz)    2(xz+wy)
///      2(xy+wz)    1−2(x²+z²)   2(yz−wx)
///      2(xz−wy)     2(yz+wx)   1−2(x²+y²)]
/// ```
///
/// ```
/// use glam::{DMat3, DQuat, DVec3};
/// use kreisel_kinematics::rotation_matrix_from_quat;
/// let m = rotation_matrix_from_quat(DQuat::from_rotation_z(core::f64::consts::FRAC_PI_2));
/// assert!((m * DVec3::X - DVec3::Y).length() < 1e-15);
/// ```
pub fn rotation_matrix_from_quat(world_from_body: DQuat) -> DMat3 {
    DMat3::from_quat(world_from_body)
}

/// The largest element of `|MᵀM − I|`: how far `m` is from orthonormal.
///
/// ```text
/// d = max_ij |(MᵀM − I)_ij|
/// ```
///
/// ```
/// use glam::DMat3;
/// use kreisel_kinematics::orthonormality_error;
/// assert_eq!(orthonormality_error(DMat3::IDENTITY), 0.0);
/// assert_eq!(orthonormality_error(DMat3::IDENTITY * 2.0), 3.0);
/// ```
pub fn orthonormality_error(m: DMat3) -> f64 {
    let g = m.transpose() * m - DMat3::IDENTITY;
    g.to_cols_array()
        .iter()
        .fold(0.0_f64, |acc, v| acc.max(v.abs()))
}

/// The unit quaternion of a rotation matrix, without checks (Shepperd's method).
///
/// Shepperd, "Quaternion from rotation matrix", J. Guidance and Control
/// 1(3):223 (1978): of `4w² = 1 + tr M`, `4x² = 1 + 2M₀₀ − tr M`, … take
/// the largest, so the square root and the divisions are well conditioned.
///
/// ```text
/// w-case: r = √(1 + M₀₀ + M₁₁ + M₂₂),  w = r/2,  x = (M₂₁ − M₁₂)/(2r), …
/// ```
///
/// The result is normalised. For a matrix that is slightly off orthonormal
/// (rounded digits) the result is a nearby rotation; use
/// [`try_quat_from_rotation_matrix`] on untrusted input.
///
/// # Panics
/// If `m` has a non-finite element or `det M ≤ 0` (the zero matrix, a
/// reflection such as `−I`): no rotation is near such a matrix, and
/// returning one (the identity for the zero matrix, a half turn for `−I`)
/// would be a silently wrong answer. [`try_quat_from_rotation_matrix`]
/// returns a typed error instead.
///
/// ```
/// use glam::{DMat3, DQuat};
/// use kreisel_kinematics::{quat_from_rotation_matrix, rotation_angle_between};
/// let q = DQuat::from_rotation_x(3.0);
/// let back = quat_from_rotation_matrix(DMat3::from_quat(q));
/// assert!(rotation_angle_between(q, back) < 1e-15);
/// ```
pub fn quat_from_rotation_matrix(m: DMat3) -> DQuat {
    let determinant = m.determinant();
    // `>` is false for NaN, so a non-finite matrix lands here too.
    if !(determinant > 0.0 && m.is_finite()) {
        panic!(
            "quat_from_rotation_matrix: not a rotation (determinant {determinant}); use try_quat_from_rotation_matrix"
        );
    }
    // m.col(c)[r] = M_rc
    let e = |r: usize, c: usize| m.col(c)[r];
    let (m00, m11, m22) = (e(0, 0), e(1, 1), e(2, 2));
    let trace = m00 + m11 + m22;
    let q = if trace >= m00 && trace >= m11 && trace >= m22 {
        let r = (1.0 + trace).sqrt();
        let f = 0.5 / r;
        DQuat::from_xyzw(
            (e(2, 1) - e(1, 2)) * f,
            (e(0, 2) - e(2, 0)) * f,
            (e(1, 0) - e(0, 1)) * f,
            0.5 * r,
        )
    } else if m00 >= m11 && m00 >= m22 {
        let r = (1.0 + m00 - m11 - m22).sqrt();
        let f = 0.5 / r;
        DQuat::from_xyzw(
            0.5 * r,
            (e(0, 1) + e(1, 0)) * f,
            (e(0, 2) + e(2, 0)) * f,
            (e(2, 1) - e(1, 2)) * f,
        )
    } else if m11 >= m22 {
        let r = (1.0 - m00 + m11 - m22).sqrt();
        let f = 0.5 / r;
        DQuat::from_xyzw(
            (e(0, 1) + e(1, 0)) * f,
            0.5 * r,
            (e(1, 2) + e(2, 1)) * f,
            (e(0, 2) - e(2, 0)) * f,
        )
    } else {
        let r = (1.0 - m00 - m11 + m22).sqrt();
        let f = 0.5 / r;
        DQuat::from_xyzw(
            (e(0, 2) + e(2, 0)) * f,
            (e(1, 2) + e(2, 1)) * f,
            0.5 * r,
            (e(1, 0) - e(0, 1)) * f,
        )
    };
    q.normalize()
}

/// The unit quaternion of a rotation matrix, after checking that it is one.
///
/// ```text
/// accept M iff  all M_ij finite,  max |MᵀM − I| ≤ tolerance,  det M > 0
/// ```
///
/// # Errors
/// [`KinematicsError::NonFinite`], [`KinematicsError::NotOrthonormal`]
/// (the deviation and the tolerance), [`KinematicsError::Reflection`] (an
/// orthonormal matrix with determinant −1).
///
/// ```
/// use glam::{DMat3, DQuat};
/// use kreisel_kinematics::{try_quat_from_rotation_matrix, ORTHONORMALITY_TOLERANCE};
/// let q = try_quat_from_rotation_matrix(DMat3::from_rotation_y(0.3), ORTHONORMALITY_TOLERANCE)?;
/// assert!(q.abs_diff_eq(DQuat::from_rotation_y(0.3), 1e-15));
/// let mirror = DMat3::from_diagonal(glam::DVec3::new(1.0, 1.0, -1.0));
/// assert!(try_quat_from_rotation_matrix(mirror, ORTHONORMALITY_TOLERANCE).is_err());
/// # Ok::<(), kreisel_kinematics::KinematicsError>(())
/// ```
pub fn try_quat_from_rotation_matrix(m: DMat3, tolerance: f64) -> Result<DQuat, KinematicsError> {
    if !m.is_finite() {
        return Err(KinematicsError::NonFinite { what: "matrix" });
    }
    let deviation = orthonormality_error(m);
    if deviation.is_nan() || deviation > tolerance {
        return Err(KinematicsError::NotOrthonormal {
            deviation,
            tolerance,
        });
    }
    let determinant = m.determinant();
    if determinant <= 0.0 {
        return Err(KinematicsError::Reflection { determinant });
    }
    Ok(quat_from_rotation_matrix(m))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation_angle_between;
    use glam::DVec3;

    #[test]
    fn every_shepperd_branch_round_trips() {
        let axes = [
            DVec3::X,
            DVec3::Y,
            DVec3::Z,
            DVec3::new(1.0, 1.0, 1.0).normalize(),
        ];
        for axis in axes {
            for angle in [0.0, 0.4, 2.0, 3.1, core::f64::consts::PI] {
                let q = DQuat::from_axis_angle(axis, angle);
                let back = quat_from_rotation_matrix(rotation_matrix_from_quat(q));
                let err = rotation_angle_between(q, back);
                assert!(err < 1e-15, "{axis} {angle} {err}");
            }
        }
    }

    #[test]
    fn zero_matrix_and_point_reflection_are_rejected() {
        // Regression: the zero matrix gave the identity, −I a half turn.
        let tol = ORTHONORMALITY_TOLERANCE;
        assert!(matches!(
            try_quat_from_rotation_matrix(DMat3::ZERO, tol),
            Err(KinematicsError::NotOrthonormal { .. })
        ));
        assert!(matches!(
            try_quat_from_rotation_matrix(-DMat3::IDENTITY, tol),
            Err(KinematicsError::Reflection { .. })
        ));
        for m in [
            DMat3::ZERO,
            -DMat3::IDENTITY,
            DMat3::from_diagonal(DVec3::NAN),
        ] {
            let unchecked = std::panic::catch_unwind(|| quat_from_rotation_matrix(m));
            assert!(unchecked.is_err(), "{m}");
        }
    }

    #[test]
    fn checks_reject_scale_shear_reflection_nan() {
        let tol = ORTHONORMALITY_TOLERANCE;
        let scaled = DMat3::IDENTITY * (1.0 + 1e-5);
        assert!(matches!(
            try_quat_from_rotation_matrix(scaled, tol),
            Err(KinematicsError::NotOrthonormal { .. })
        ));
        let reflection = DMat3::from_diagonal(DVec3::new(-1.0, 1.0, 1.0));
        assert!(matches!(
            try_quat_from_rotation_matrix(reflection, tol),
            Err(KinematicsError::Reflection { .. })
        ));
        let mut nan = DMat3::IDENTITY;
        nan.y_axis.x = f64::NAN;
        assert_eq!(
            try_quat_from_rotation_matrix(nan, tol),
            Err(KinematicsError::NonFinite { what: "matrix" })
        );
        // Seven significant digits are accepted.
        let m = DMat3::from_rotation_x(0.3);
        let rounded = DMat3::from_cols_array(&m.to_cols_array().map(|v| (v * 1e7).round() / 1e7));
        let q = try_quat_from_rotation_matrix(rounded, tol).unwrap();
        assert!(rotation_angle_between(q, DQuat::from_rotation_x(0.3)) < 1e-7);
    }
}
