//! Rotation vectors (axis × angle): the exponential and logarithm maps of
//! unit quaternions, accurate for tiny angles and for angles near π.

use glam::{DQuat, DVec3};

use crate::canonical_quat;
use crate::quaternion::norm3;

/// The unit quaternion of a rotation vector (the exponential map).
///
/// ```text
/// θ = |v|,  q = (cos θ/2, sin(θ/2)/θ · v),   q = (1, 0) for v = 0
/// ```
///
/// `|v|` is computed without underflow, so a rotation vector of `1e-300` rad
/// keeps all its digits; any finite length is accepted (angles beyond π wrap
/// around).
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_kinematics::quat_from_rotation_vector;
/// let q = quat_from_rotation_vector(DVec3::new(0.0, 0.0, 0.5));
/// assert!(q.abs_diff_eq(DQuat::from_rotation_z(0.5), 1e-16));
/// let tiny = quat_from_rotation_vector(DVec3::new(1e-300, 0.0, 0.0));
/// assert_eq!(tiny.x, 0.5e-300);
/// ```
pub fn quat_from_rotation_vector(rotation_vector: DVec3) -> DQuat {
    let theta = norm3(rotation_vector);
    if theta == 0.0 {
        return DQuat::IDENTITY;
    }
    let (s, c) = (0.5 * theta).sin_cos();
    // sin(θ/2)/θ: both factors are accurate to an ulp, for θ down to the
    // smallest subnormal, so no series is needed.
    let v = rotation_vector * (s / theta);
    DQuat::from_xyzw(v.x, v.y, v.z, c)
}

/// The rotation vector of a unit quaternion (the logarithm map), with angle
/// in `[0, π]`.
///
/// ```text
/// (w, v) ← canonical_quat(w, v)   (w ≥ 0; at w = 0 the first non-zero of x, y, z > 0)
///   θ = 2 atan2(|v|, w);   r = θ/|v| · v,   r = 0 for v = 0
/// ```
///
/// The atan2 form keeps full relative precision for tiny angles (no
/// `acos(w)`) and near π (no division by `sin θ/2 → 0`: `|v| → 1` there). At
/// exactly π, where `r` and `−r` are the same rotation, the first non-zero
/// component of `r` is positive (as in scipy), so `q` and `−q` give the same `r`.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_kinematics::rotation_vector_from_quat;
/// let r = rotation_vector_from_quat(DQuat::from_rotation_y(3.0));
/// assert!((r - DVec3::new(0.0, 3.0, 0.0)).length() < 1e-15);
/// // q and −q are the same rotation:
/// let r2 = rotation_vector_from_quat(-DQuat::from_rotation_y(3.0));
/// assert!((r2 - r).length() < 1e-15);
/// ```
pub fn rotation_vector_from_quat(world_from_body: DQuat) -> DVec3 {
    let q = canonical_quat(world_from_body);
    let v = DVec3::new(q.x, q.y, q.z);
    let s = norm3(v);
    if s == 0.0 {
        return DVec3::ZERO;
    }
    v * (2.0 * s.atan2(q.w) / s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;

    #[test]
    fn exp_log_round_trip_over_all_scales() {
        let axis = DVec3::new(0.36, -0.48, 0.8);
        for angle in [1e-300, 1e-200, 1e-20, 1e-8, 0.3, 2.0, PI - 1e-8, PI - 1e-15] {
            let r = axis * angle;
            let back = rotation_vector_from_quat(quat_from_rotation_vector(r));
            let rel = (back - r).length() / angle;
            assert!(rel < 4e-16, "angle {angle}: relative error {rel}");
        }
    }

    #[test]
    fn log_of_pi_rotation() {
        let r = rotation_vector_from_quat(DQuat::from_xyzw(0.0, 0.0, 1.0, 0.0));
        assert_eq!(r, DVec3::new(0.0, 0.0, PI));
        let r = rotation_vector_from_quat(DQuat::from_xyzw(0.0, -0.6, 0.8, 0.0));
        assert_eq!(r, DVec3::new(0.0, 0.6, -0.8) * PI);
    }

    #[test]
    fn identity_maps_to_zero() {
        assert_eq!(rotation_vector_from_quat(DQuat::IDENTITY), DVec3::ZERO);
        assert_eq!(quat_from_rotation_vector(DVec3::ZERO), DQuat::IDENTITY);
    }
}
