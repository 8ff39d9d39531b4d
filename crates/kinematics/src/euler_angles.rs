//! Euler angles → quaternion for all 24 conventions, and the decomposition
//! type of the way back (`euler_from_quat.rs`).

use glam::{DQuat, DVec3};

use crate::euler_sequence::{EulerSequence, Frame, scatter};

/// Euler angles recovered from a rotation, with a flag for gimbal lock.
///
/// `angles` holds the three angles in the order of the sequence, in radians:
/// first and third in `(−π, π]`, middle in `[0, π]` (proper Euler) or
/// `[−π/2, π/2]` (Tait–Bryan).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EulerDecomposition {
    /// The angles `(first, middle, third)`, radians.
    pub angles: DVec3,
    /// `true` when the middle angle is exactly at gimbal lock: then only the
    /// sum (or difference) of the first and third angles is defined, and the
    /// third angle is returned as `0` by convention.
    pub gimbal_lock: bool,
}

impl EulerSequence {
    /// The rotation (`world_from_body`) described by Euler angles in this convention.
    ///
    /// ```text
    /// intrinsic ABC:  q = q_A(α) ⊗ q_B(β) ⊗ q_C(γ)
    /// extrinsic abc:  q = q_c(γ) ⊗ q_b(β) ⊗ q_a(α)
    /// q_n(t) = (cos t/2, sin t/2 · e_n)
    /// ```
    ///
    /// `angles` = `(α, β, γ)` in radians, in the order of the sequence. Any
    /// finite values are accepted (no range is required).
    ///
    /// ```
    /// use glam::DQuat;
    /// use kreisel_kinematics::EulerSequence;
    /// let zxz: EulerSequence = "ZXZ".parse()?;
    /// let (phi, theta, psi) = (0.1, 0.2, 0.3);
    /// let q = zxz.to_quat(glam::DVec3::new(phi, theta, psi));
    /// let expect = DQuat::from_rotation_z(phi) * DQuat::from_rotation_x(theta) * DQuat::from_rotation_z(psi);
    /// assert!(q.abs_diff_eq(expect, 1e-15));
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    #[inline]
    pub fn to_quat(self, angles: DVec3) -> DQuat {
        let [a, b, c] = self.intrinsic_axes();
        let t = match self.frame() {
            Frame::Intrinsic => angles,
            Frame::Extrinsic => DVec3::new(angles.z, angles.y, angles.x),
        };
        let (sa, ca) = (0.5 * t.x).sin_cos();
        let (sb, cb) = (0.5 * t.y).sin_cos();
        let (sg, cg) = (0.5 * t.z).sin_cos();
        // q_A(α) ⊗ q_B(β) ⊗ q_C(γ) multiplied out, written along (A, B, T)
        // with T the third axis and ε = ε_{ABT}; for Tait–Bryan C = T.
        let eps = a.parity(b);
        let (w, u) = if a == c {
            (
                cb * (ca * cg - sa * sg),
                DVec3::new(
                    cb * (ca * sg + sa * cg),
                    sb * (ca * cg + sa * sg),
                    eps * sb * (sa * cg - ca * sg),
                ),
            )
        } else {
            let (cc, cs, sc, ss) = (ca * cg, ca * sg, sa * cg, sa * sg);
            (
                cb * cc - eps * sb * ss,
                DVec3::new(
                    cb * sc + eps * sb * cs,
                    sb * cc - eps * cb * ss,
                    eps * sb * sc + cb * cs,
                ),
            )
        };
        let v = scatter(a, b, u);
        DQuat::from_xyzw(v.x, v.y, v.z, w)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation_angle_between;

    fn seqs() -> [EulerSequence; 24] {
        EulerSequence::all()
    }

    #[test]
    fn intrinsic_is_product_of_body_axis_rotations() {
        let angles = DVec3::new(0.7, -0.4, 2.9);
        let xyz: EulerSequence = "XYZ".parse().unwrap();
        let expect = DQuat::from_rotation_x(0.7)
            * DQuat::from_rotation_y(-0.4)
            * DQuat::from_rotation_z(2.9);
        assert!(rotation_angle_between(xyz.to_quat(angles), expect) < 1e-15);
        let ext: EulerSequence = "xyz".parse().unwrap();
        let expect = DQuat::from_rotation_z(2.9)
            * DQuat::from_rotation_y(-0.4)
            * DQuat::from_rotation_x(0.7);
        assert!(rotation_angle_between(ext.to_quat(angles), expect) < 1e-15);
    }

    #[test]
    fn round_trip_generic_angles_recovers_angles() {
        for seq in seqs() {
            let middle = if seq.is_proper() { 1.1 } else { -0.6 };
            let angles = DVec3::new(-2.5, middle, 0.4);
            let d = seq.from_quat(seq.to_quat(angles));
            assert!(!d.gimbal_lock);
            assert!(
                (d.angles - angles).abs().max_element() < 1e-14,
                "{seq}: {d:?}"
            );
            // q and −q give the same angles
            let d2 = seq.from_quat(-seq.to_quat(angles));
            assert!(
                (d2.angles - angles).abs().max_element() < 1e-14,
                "{seq}: {d2:?}"
            );
        }
    }
}
