//! Euler angles for `f32` engines (bevy, avian, rapier's glam types): `f32`
//! quaternions and angles in and out, the conversion computed in `f64`
//! inside, so the only error is the final rounding to `f32`.
//!
//! ```text
//! to_quat_f32(a)   = round_f32(to_quat(a as f64))
//! from_quat_f32(q) = round_f32(from_quat(q as f64))
//! ```
//!
//! Measured over the 24 conventions, far from and next to gimbal lock
//! (`tests/euler_f32.rs`): `to_quat_f32` within 0.72 `f32` ε of the exact
//! rotation, `from_quat_f32`'s angles turning back into the input within
//! 2 ε, and the middle angle within 6e-8 rad of the `f64` decomposition
//! 1e-3 … 1e-5 rad from the lock (glam 0.34's own `f32` `Quat::to_euler`:
//! 2.6e-7 rad there).

use glam::{Quat, Vec3};

use crate::EulerSequence;

/// [`crate::EulerDecomposition`] in `f32`: the angles `(first, middle,
/// third)` in radians and whether the middle angle is exactly at gimbal
/// lock (then the third angle is 0 by convention).
///
/// ```
/// use glam::Vec3;
/// use kreisel_kinematics::EulerSequence;
/// let seq: EulerSequence = "ZYX".parse()?;
/// let q = seq.to_quat_f32(Vec3::new(0.3, core::f32::consts::FRAC_PI_2, -0.2));
/// let found = seq.from_quat_f32(q);
/// assert!((found.angles.y - core::f32::consts::FRAC_PI_2).abs() < 1e-6);
/// # Ok::<(), kreisel_kinematics::KinematicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EulerDecompositionF32 {
    /// The angles `(first, middle, third)`, radians.
    pub angles: Vec3,
    /// `true` when the `f64` decomposition of the input is exactly at the lock.
    pub gimbal_lock: bool,
}

impl EulerSequence {
    /// The `f32` rotation (`world_from_body`) of `f32` Euler angles in this
    /// convention, computed in `f64` ([`EulerSequence::to_quat`]) and
    /// rounded once.
    ///
    /// ```text
    /// q = round_f32(to_quat(angles as f64))
    /// ```
    ///
    /// ```
    /// use glam::Vec3;
    /// use kreisel_kinematics::EulerSequence;
    /// let seq: EulerSequence = "zxz".parse()?;
    /// let angles = Vec3::new(0.1, 0.2, 0.3);
    /// let q = seq.to_quat_f32(angles);
    /// assert_eq!(q, seq.to_quat(angles.as_dvec3()).as_quat());
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub fn to_quat_f32(self, angles: Vec3) -> Quat {
        self.to_quat(angles.as_dvec3()).as_quat()
    }

    /// The `f32` Euler angles of an `f32` rotation (`world_from_body`, unit
    /// to `f32` rounding) in this convention, computed in `f64`
    /// ([`EulerSequence::from_quat`], with its ranges and gimbal-lock
    /// convention) and rounded once.
    ///
    /// ```text
    /// angles = round_f32(from_quat(q as f64).angles)
    /// ```
    ///
    /// ```
    /// use glam::Vec3;
    /// use kreisel_kinematics::{EulerSequence, rotation_angle_between};
    /// let seq: EulerSequence = "ZYX".parse()?;
    /// // 1e-7 rad from gimbal lock.
    /// let q = seq.to_quat_f32(Vec3::new(0.4, core::f32::consts::FRAC_PI_2 - 1e-7, 0.3));
    /// let ours = seq.from_quat_f32(q).angles;
    /// let back = seq.to_quat(ours.as_dvec3());
    /// assert!(rotation_angle_between(back, q.as_dquat()) < 5e-7);
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub fn from_quat_f32(self, world_from_body: Quat) -> EulerDecompositionF32 {
        let found = self.from_quat(world_from_body.as_dquat());
        EulerDecompositionF32 {
            angles: found.angles.as_vec3(),
            gimbal_lock: found.gimbal_lock,
        }
    }
}
