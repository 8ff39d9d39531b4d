//! Quaternion kinematics: the attitude derivative, angular velocity from two
//! attitudes, constant-rate rotation and slerp.

use glam::{DQuat, DVec3};

use crate::{quat_from_rotation_vector, rotation_vector_from_quat};

/// The time derivative of the attitude for a body-frame angular velocity.
///
/// ```text
/// q̇ = ½ q ⊗ (0, ω_body)
/// ```
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_kinematics::quat_derivative;
/// let dq = quat_derivative(DQuat::IDENTITY, DVec3::new(0.0, 0.0, 2.0));
/// assert_eq!(dq, DQuat::from_xyzw(0.0, 0.0, 1.0, 0.0));
/// ```
pub fn quat_derivative(world_from_body: DQuat, omega_body: DVec3) -> DQuat {
    world_from_body * DQuat::from_xyzw(omega_body.x, omega_body.y, omega_body.z, 0.0) * 0.5
}

/// The time derivative of the attitude for a world-frame angular velocity.
///
/// ```text
/// q̇ = ½ (0, ω_world) ⊗ q
/// ```
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_kinematics::{quat_derivative, quat_derivative_world};
/// let q = DQuat::from_rotation_x(0.7);
/// let omega_body = DVec3::new(0.1, 0.2, 0.3);
/// let a = quat_derivative(q, omega_body);
/// let b = quat_derivative_world(q, q * omega_body);
/// assert!(a.abs_diff_eq(b, 1e-16));
/// ```
pub fn quat_derivative_world(world_from_body: DQuat, omega_world: DVec3) -> DQuat {
    DQuat::from_xyzw(omega_world.x, omega_world.y, omega_world.z, 0.0) * world_from_body * 0.5
}

/// The attitude after rotating for `dt` at a constant body-frame angular velocity.
///
/// ```text
/// q(t + dt) = q(t) ⊗ exp(ω_body dt)
/// ```
///
/// This is the exact solution of `q̇ = ½ q ⊗ (0, ω_body)` for constant ω.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_kinematics::{rotate_by_omega_body, rotation_angle_between};
/// let q = rotate_by_omega_body(DQuat::IDENTITY, DVec3::new(0.0, 0.0, 2.0), 0.25);
/// assert!(rotation_angle_between(q, DQuat::from_rotation_z(0.5)) < 1e-16);
/// ```
pub fn rotate_by_omega_body(world_from_body: DQuat, omega_body: DVec3, dt: f64) -> DQuat {
    world_from_body * quat_from_rotation_vector(omega_body * dt)
}

/// The constant body-frame angular velocity that takes attitude `q0` to `q1`
/// in time `dt` along the shortest path.
///
/// ```text
/// ω_body = log(q0⁻¹ ⊗ q1) / dt
/// ```
///
/// Inverse of [`rotate_by_omega_body`] for rotations up to π.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_kinematics::{omega_body_from_attitudes, rotate_by_omega_body};
/// let q0 = DQuat::from_rotation_y(1.0);
/// let omega = DVec3::new(0.3, -0.2, 0.5);
/// let q1 = rotate_by_omega_body(q0, omega, 0.1);
/// assert!((omega_body_from_attitudes(q0, q1, 0.1) - omega).length() < 1e-14);
/// ```
pub fn omega_body_from_attitudes(q0: DQuat, q1: DQuat, dt: f64) -> DVec3 {
    rotation_vector_from_quat(q0.conjugate() * q1) / dt
}

/// The constant world-frame angular velocity that takes attitude `q0` to
/// `q1` in time `dt` along the shortest path.
///
/// ```text
/// ω_world = log(q1 ⊗ q0⁻¹) / dt
/// ```
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_kinematics::omega_world_from_attitudes;
/// let q1 = DQuat::from_rotation_z(0.2) * DQuat::from_rotation_x(1.0);
/// let w = omega_world_from_attitudes(DQuat::from_rotation_x(1.0), q1, 0.1);
/// assert!((w - DVec3::new(0.0, 0.0, 2.0)).length() < 1e-14);
/// ```
pub fn omega_world_from_attitudes(q0: DQuat, q1: DQuat, dt: f64) -> DVec3 {
    rotation_vector_from_quat(q1 * q0.conjugate()) / dt
}

/// Spherical linear interpolation between two attitudes along the shortest
/// arc, at constant angular speed.
///
/// ```text
/// slerp(q0, q1, t) = q0 ⊗ exp(t · log(q0⁻¹ ⊗ q1)),   t ∈ [0, 1]
/// ```
///
/// Shoemake, "Animating rotation with quaternion curves", SIGGRAPH 1985.
/// The log/exp form is accurate for nearly equal attitudes, where the
/// textbook `sin((1−t)Ω)/sin Ω` form divides by a vanishing `sin Ω`.
///
/// ```
/// use glam::DQuat;
/// use kreisel_kinematics::{rotation_angle_between, slerp};
/// let q = slerp(DQuat::IDENTITY, DQuat::from_rotation_z(1.0), 0.25);
/// assert!(rotation_angle_between(q, DQuat::from_rotation_z(0.25)) < 1e-15);
/// ```
pub fn slerp(q0: DQuat, q1: DQuat, t: f64) -> DQuat {
    q0 * quat_from_rotation_vector(rotation_vector_from_quat(q0.conjugate() * q1) * t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation_angle_between;

    #[test]
    fn derivative_matches_finite_difference_of_exact_rotation() {
        let q = DQuat::from_rotation_y(0.4) * DQuat::from_rotation_x(-1.3);
        let omega = DVec3::new(0.7, -0.1, 1.9);
        let h = 1e-6;
        let fd =
            (rotate_by_omega_body(q, omega, h) - rotate_by_omega_body(q, omega, -h)) * (0.5 / h);
        let exact = quat_derivative(q, omega);
        assert!((fd - exact).length() < 1e-9, "{fd:?} vs {exact:?}");
    }

    #[test]
    fn slerp_has_constant_angular_speed_and_takes_short_way() {
        let q0 = DQuat::from_rotation_x(0.3);
        // −q1 is the same attitude: slerp must still take the short arc.
        let q1 = -(DQuat::from_rotation_z(0.9) * q0);
        let total = rotation_angle_between(q0, q1);
        for t in [0.0, 0.1, 0.5, 0.9, 1.0] {
            let q = slerp(q0, q1, t);
            assert!((rotation_angle_between(q0, q) - t * total).abs() < 1e-15);
            assert!((rotation_angle_between(q, q1) - (1.0 - t) * total).abs() < 1e-15);
        }
    }

    #[test]
    fn world_and_body_rates_are_related_by_the_attitude() {
        let q0 = DQuat::from_rotation_y(0.8);
        let omega_body = DVec3::new(0.2, 0.5, -0.4);
        let q1 = rotate_by_omega_body(q0, omega_body, 0.5);
        let w_world = omega_world_from_attitudes(q0, q1, 0.5);
        // constant ω_body and ω_world = q ω_body (q changes only about ω, which it leaves fixed)
        assert!((w_world - q0 * omega_body).length() < 1e-15);
    }
}
