//! Axis–angle pairs: a unit axis and an angle about it.

use glam::{DQuat, DVec3};

use crate::quaternion::{norm3, normalized3};
use crate::{KinematicsError, canonical_quat};

/// A rotation by `angle` radians about the unit vector `axis` (right-hand rule).
///
/// ```text
/// q = (cos angle/2, sin(angle/2) · axis)
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisAngle {
    /// Unit rotation axis.
    pub axis: DVec3,
    /// Rotation angle, radians.
    pub angle: f64,
}

impl AxisAngle {
    /// The identity: angle 0 about the x axis.
    pub const IDENTITY: Self = Self {
        axis: DVec3::X,
        angle: 0.0,
    };

    /// Builds an axis–angle pair, normalising the axis.
    ///
    /// A zero axis is accepted only with a zero angle (the identity; the
    /// axis is then taken as x).
    ///
    /// # Errors
    /// [`KinematicsError::NonFinite`] for NaN or infinite input,
    /// [`KinematicsError::ZeroAxis`] for a zero axis with a non-zero angle.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::AxisAngle;
    /// let aa = AxisAngle::try_new(DVec3::new(0.0, 0.0, 2.0), 0.5)?;
    /// assert_eq!(aa.axis, DVec3::Z);
    /// assert!(AxisAngle::try_new(DVec3::ZERO, 0.5).is_err());
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub fn try_new(axis: DVec3, angle: f64) -> Result<Self, KinematicsError> {
        if !axis.is_finite() || !angle.is_finite() {
            return Err(KinematicsError::NonFinite { what: "axis-angle" });
        }
        match normalized3(axis) {
            Some(axis) => Ok(Self { axis, angle }),
            None if angle == 0.0 => Ok(Self::IDENTITY),
            None => Err(KinematicsError::ZeroAxis { angle }),
        }
    }

    /// Builds an axis–angle pair from a valid axis.
    ///
    /// # Panics
    /// On input that [`AxisAngle::try_new`] rejects.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::AxisAngle;
    /// assert_eq!(AxisAngle::new(DVec3::new(3.0, 0.0, 0.0), 1.0).axis, DVec3::X);
    /// ```
    pub fn new(axis: DVec3, angle: f64) -> Self {
        match Self::try_new(axis, angle) {
            Ok(a) => a,
            Err(e) => panic!("{e}"),
        }
    }

    /// The rotation as a unit quaternion.
    ///
    /// ```text
    /// q = (cos angle/2, sin(angle/2) · axis)
    /// ```
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_kinematics::AxisAngle;
    /// let q = AxisAngle::new(DVec3::Y, 0.25).to_quat();
    /// assert!(q.abs_diff_eq(DQuat::from_rotation_y(0.25), 1e-16));
    /// ```
    pub fn to_quat(self) -> DQuat {
        let (s, c) = (0.5 * self.angle).sin_cos();
        let v = self.axis * s;
        DQuat::from_xyzw(v.x, v.y, v.z, c)
    }

    /// The axis–angle pair of a unit quaternion, with angle in `[0, π]`.
    ///
    /// ```text
    /// q ← canonical_quat(q),  angle = 2 atan2(|v|, w),  axis = v / |v|   (axis = x for the identity)
    /// ```
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_kinematics::AxisAngle;
    /// let aa = AxisAngle::from_quat(DQuat::from_rotation_z(-0.5));
    /// assert!((aa.axis - DVec3::NEG_Z).length() < 1e-15);
    /// assert!((aa.angle - 0.5).abs() < 1e-15);
    /// ```
    pub fn from_quat(world_from_body: DQuat) -> Self {
        let q = canonical_quat(world_from_body);
        let v = DVec3::new(q.x, q.y, q.z);
        match normalized3(v) {
            // 2 atan2(|v|, w) ∈ [0, π] exactly, as w ≥ 0.
            Some(axis) => Self {
                axis,
                angle: 2.0 * norm3(v).atan2(q.w),
            },
            None => Self::IDENTITY,
        }
    }

    /// The rotation vector `axis · angle`.
    ///
    /// ```text
    /// r = angle · axis
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::AxisAngle;
    /// assert_eq!(AxisAngle::new(DVec3::Z, 2.0).to_rotation_vector(), DVec3::new(0.0, 0.0, 2.0));
    /// ```
    pub fn to_rotation_vector(self) -> DVec3 {
        self.axis * self.angle
    }

    /// The axis–angle pair of a rotation vector (angle = its length, any size).
    ///
    /// ```text
    /// angle = |r|,  axis = r / |r|   (axis = x for r = 0)
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::AxisAngle;
    /// let aa = AxisAngle::from_rotation_vector(DVec3::new(0.0, -4.0, 0.0));
    /// assert_eq!((aa.axis, aa.angle), (DVec3::NEG_Y, 4.0));
    /// ```
    pub fn from_rotation_vector(rotation_vector: DVec3) -> Self {
        match normalized3(rotation_vector) {
            Some(axis) => Self {
                axis,
                angle: norm3(rotation_vector),
            },
            None => Self::IDENTITY,
        }
    }
}

impl From<AxisAngle> for DQuat {
    fn from(a: AxisAngle) -> Self {
        a.to_quat()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{quat_from_rotation_vector, rotation_angle_between};

    #[test]
    fn quat_round_trip_including_tiny_and_near_pi() {
        let axis = DVec3::new(2.0, -1.0, 2.0) / 3.0;
        for angle in [1e-250, 1e-9, 1.0, 3.0, core::f64::consts::PI - 1e-13] {
            let q = AxisAngle::new(axis, angle).to_quat();
            let back = AxisAngle::from_quat(q);
            assert!((back.axis - axis).length() < 4e-16, "{angle}");
            assert!((back.angle - angle).abs() <= 4e-16 * angle, "{angle}");
            assert!(rotation_angle_between(q, back.to_quat()) < 1e-300_f64.max(4e-16 * angle));
            assert!(
                rotation_angle_between(q, quat_from_rotation_vector(back.to_rotation_vector()))
                    <= 4e-16 * angle.max(1.0)
            );
        }
    }

    #[test]
    fn rejects_non_finite() {
        assert!(AxisAngle::try_new(DVec3::new(f64::NAN, 0.0, 1.0), 1.0).is_err());
        assert!(AxisAngle::try_new(DVec3::Z, f64::INFINITY).is_err());
    }
}
