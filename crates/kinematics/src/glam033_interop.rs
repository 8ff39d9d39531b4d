//! Conversions between glam 0.33's `f32` types — the ones bevy_math 0.20
//! and rapier 0.36 use — and this crate's glam `f64` types (feature
//! `glam033`, so that no glam version is forced on anyone).
//!
//! Two versions of glam are foreign to each other, so these are free
//! functions rather than `From` impls. `f32 → f64` is exact; `f64 → f32`
//! rounds each component once.
//!
//! ```text
//! (w, x, y, z) ↦ (w, x, y, z)      (x, y, z) ↦ (x, y, z)
//! ```
//!
//! ```
//! use kreisel_kinematics::glam033_interop::{dquat_from_quat, quat_from_dquat};
//! let engine = glam033::Quat::from_rotation_z(0.5); // a rotation from bevy or rapier
//! let q = dquat_from_quat(engine);                  // exact
//! assert_eq!(quat_from_dquat(q), engine);           // and back, bit for bit
//! ```

use glam::{DQuat, DVec3};

/// glam 0.33 `Quat` (`f32`) → `DQuat`, exactly.
///
/// ```
/// use kreisel_kinematics::glam033_interop::dquat_from_quat;
/// let q = dquat_from_quat(glam033::Quat::from_xyzw(0.0, 0.0, 0.6, 0.8));
/// assert_eq!((q.w, q.z), (f64::from(0.8f32), f64::from(0.6f32)));
/// ```
pub fn dquat_from_quat(q: glam033::Quat) -> DQuat {
    DQuat::from_xyzw(q.x.into(), q.y.into(), q.z.into(), q.w.into())
}

/// `DQuat` → glam 0.33 `Quat` (`f32`), each component rounded once.
///
/// ```
/// use kreisel_kinematics::glam033_interop::quat_from_dquat;
/// let q = quat_from_dquat(glam::DQuat::IDENTITY);
/// assert_eq!(q, glam033::Quat::IDENTITY);
/// ```
pub fn quat_from_dquat(q: glam::DQuat) -> glam033::Quat {
    glam033::Quat::from_xyzw(q.x as f32, q.y as f32, q.z as f32, q.w as f32)
}

/// glam 0.33 `Vec3` (`f32`) → `DVec3`, exactly.
///
/// ```
/// use kreisel_kinematics::glam033_interop::dvec3_from_vec3;
/// assert_eq!(dvec3_from_vec3(glam033::Vec3::new(1.0, 2.0, 3.0)), glam::DVec3::new(1.0, 2.0, 3.0));
/// ```
pub fn dvec3_from_vec3(v: glam033::Vec3) -> DVec3 {
    DVec3::new(v.x.into(), v.y.into(), v.z.into())
}

/// `DVec3` → glam 0.33 `Vec3` (`f32`), each component rounded once.
///
/// ```
/// use kreisel_kinematics::glam033_interop::vec3_from_dvec3;
/// assert_eq!(vec3_from_dvec3(glam::DVec3::new(0.5, -1.0, 2.0)), glam033::Vec3::new(0.5, -1.0, 2.0));
/// ```
pub fn vec3_from_dvec3(v: DVec3) -> glam033::Vec3 {
    glam033::Vec3::new(v.x as f32, v.y as f32, v.z as f32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::EulerSequence;

    #[test]
    fn round_trips_are_exact_and_rotations_agree() {
        for k in 0..100 {
            let t = k as f32 * 0.37;
            let engine = glam033::Quat::from_euler(glam033::EulerRot::ZYX, t, 0.5 * t, -t);
            assert_eq!(quat_from_dquat(dquat_from_quat(engine)), engine);
            let v = glam033::Vec3::new(t, -2.0 * t, 1.0 / (1.0 + t));
            assert_eq!(vec3_from_dvec3(dvec3_from_vec3(v)), v);
            // The same rotation of the same vector, in both glam versions.
            let ours = dquat_from_quat(engine) * dvec3_from_vec3(v);
            let theirs = dvec3_from_vec3(engine * v);
            assert!(
                (ours - theirs).length() <= 4.0 * f64::from(f32::EPSILON) * ours.length().max(1.0)
            );
        }
        // An engine's attitude to Euler angles, through this crate.
        let seq: EulerSequence = "ZYX".parse().unwrap();
        let engine = glam033::Quat::from_euler(glam033::EulerRot::ZYX, 0.3, 0.2, 0.1);
        let angles = seq.from_quat(dquat_from_quat(engine)).angles;
        assert!((angles - glam::DVec3::new(0.3, 0.2, 0.1)).length() < 1e-6);
    }
}
