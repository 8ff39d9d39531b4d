//! Euler angles ⇄ quaternion for all 24 conventions, accurate at and next to
//! gimbal lock (Bernardes & Viollet 2022).

use core::f64::consts::{PI, TAU};

use glam::{DQuat, DVec3};

use crate::euler_sequence::{EulerSequence, Frame, gather, scatter};

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

/// Wraps an angle from `[−π, π]` into `(−π, π]` (maps `−π` to `π`).
#[inline]
fn half_open(angle: f64) -> f64 {
    if angle <= -PI { angle + TAU } else { angle }
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

    /// Euler angles of a rotation (`world_from_body`) in this convention.
    ///
    /// The direct method of Bernardes & Viollet, "Quaternion to Euler angles
    /// conversion: a direct, general and computationally efficient method",
    /// PLoS ONE 17:e0276302 (2022), in its atan2/hypot form and rewritten for
    /// intrinsic sequences `ABC` (an extrinsic `abc` is the intrinsic `CBA`
    /// with the angles reversed). With `l` the axis that is neither A nor B
    /// and `ε = ε_{ABl}` (Levi-Civita):
    ///
    /// ```text
    /// proper (C = A):      x = (w, q_A),              y = (q_B, ε q_l)
    /// Tait–Bryan (C = l):  x = (w − q_B, q_A − ε q_C),  y = (w + q_B, q_A + ε q_C)
    /// middle β = 2 atan2(|y|, |x|) = atan2(2|x||y|, |x|² − |y|²)   (proper)
    ///        β = atan2(|y|² − |x|², 2|x||y|)                     (Tait–Bryan: the above − π/2)
    /// first  α = atan2(x₁y₀ + x₀y₁, x₀y₀ − x₁y₁)          = X + Y
    /// third  γ = s · atan2(x₁y₀ − x₀y₁, x₀y₀ + x₁y₁)      = s (X − Y),  s = 1 proper, −ε Tait–Bryan
    /// where x = |x| (cos X, sin X), y = |y| (cos Y, sin Y)
    /// ```
    ///
    /// No acos/asin is used, so the middle angle keeps full precision next to
    /// the lock, and the first and third angles come from the products of
    /// `x` and `y`, which stay well-defined however small `|y|` or `|x|` get.
    /// Only exactly at the lock (`|y| = 0` or `|x| = 0`) is the
    /// decomposition not unique; then the third angle is set to 0, the first
    /// carries the whole rotation, and `gimbal_lock` is `true`.
    ///
    /// The quaternion need not be normalised (the formulas are
    /// scale-invariant), but must be non-zero and finite.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::{EulerSequence, rotation_angle_between};
    /// let seq: EulerSequence = "xyz".parse()?;
    /// // 1e-12 rad from gimbal lock (middle angle π/2 − 1e-12):
    /// let angles = DVec3::new(0.3, core::f64::consts::FRAC_PI_2 - 1e-12, -1.2);
    /// let q = seq.to_quat(angles);
    /// let found = seq.from_quat(q);
    /// assert!(!found.gimbal_lock);
    /// assert!(rotation_angle_between(q, seq.to_quat(found.angles)) < 1e-15);
    /// assert!((found.angles.y - angles.y).abs() < 1e-15);
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    #[inline]
    pub fn from_quat(self, world_from_body: DQuat) -> EulerDecomposition {
        let q = world_from_body;
        let [a, b, c] = self.intrinsic_axes();
        // Components along (A, B, T), T the third axis; for Tait–Bryan C = T.
        let (u, eps) = gather(a, b, DVec3::new(q.x, q.y, q.z));
        let proper = a == c;
        let (x0, x1, y0, y1, sign) = if proper {
            (q.w, u.x, u.y, eps * u.z, 1.0)
        } else {
            let (qa, qb, qc) = (u.x, u.y, eps * u.z);
            (q.w - qb, qa - qc, q.w + qb, qa + qc, -eps)
        };
        // β = 2 atan2(|y|, |x|) = atan2(2|x||y|, |x|² − |y|²): one square
        // root instead of two, and as accurate (absolute error ~1e-16 rad
        // for every β). For Tait–Bryan, β − π/2 = atan2(|y|² − |x|², 2|x||y|)
        // lands in [−π/2, π/2] directly, without rounding in a subtraction.
        // q is unit (or of moderate size): the squares cannot overflow, and
        // they underflow only ~1e-162 from the lock, where treating the
        // rotation as locked costs < 1e-160 rad.
        let (nx2, ny2) = (x0 * x0 + x1 * x1, y0 * y0 + y1 * y1);
        let (sin_m, cos_m) = (2.0 * (nx2 * ny2).sqrt(), nx2 - ny2);
        let middle = if proper {
            sin_m.atan2(cos_m)
        } else {
            (-cos_m).atan2(sin_m)
        };

        // Which intrinsic angle is the sequence's *third* one (set to 0 at the lock).
        let zero_first = self.frame() == Frame::Extrinsic;
        let (first, third, gimbal_lock) = if ny2 == 0.0 || nx2 == 0.0 {
            // α + sγ = 2X when |y| = 0;  α − sγ = 2Y when |x| = 0.
            let (p0, p1, s) = if ny2 == 0.0 {
                (x0, x1, sign)
            } else {
                (y0, y1, -sign)
            };
            let double = (2.0 * p0 * p1).atan2(p0 * p0 - p1 * p1);
            if zero_first {
                (0.0, half_open(s * double), true)
            } else {
                (half_open(double), 0.0, true)
            }
        } else {
            let alpha = (x1 * y0 + x0 * y1).atan2(x0 * y0 - x1 * y1);
            let gamma = sign * (x1 * y0 - x0 * y1).atan2(x0 * y0 + x1 * y1);
            (half_open(alpha), half_open(gamma), false)
        };
        let angles = match self.frame() {
            Frame::Intrinsic => DVec3::new(first, middle, third),
            Frame::Extrinsic => DVec3::new(third, middle, first),
        };
        EulerDecomposition {
            angles,
            gimbal_lock,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation_angle_between;
    use core::f64::consts::FRAC_PI_2;

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

    #[test]
    fn exact_lock_sets_third_angle_zero_and_flags_it() {
        for seq in seqs() {
            for lock in seq.gimbal_lock_angles() {
                let angles = DVec3::new(0.3, lock, -0.9);
                let q = seq.to_quat(angles);
                let d = seq.from_quat(q);
                // The lock is flagged when the quaternion lands exactly on it.
                if d.gimbal_lock {
                    assert_eq!(d.angles.z, 0.0, "{seq}");
                    assert_eq!(d.angles.y, lock, "{seq}");
                }
                let err = rotation_angle_between(q, seq.to_quat(d.angles));
                assert!(err < 1e-15, "{seq} at {lock}: {err}");
            }
        }
    }

    #[test]
    fn axis_quaternion_at_lock_is_flagged() {
        // A pure rotation about the first axis has middle angle 0 for proper sequences.
        let zxz: EulerSequence = "ZXZ".parse().unwrap();
        let d = zxz.from_quat(DQuat::from_rotation_z(1.0));
        assert!(d.gimbal_lock);
        assert_eq!(d.angles, DVec3::new(1.0, 0.0, 0.0));
        let zxz_ext: EulerSequence = "zxz".parse().unwrap();
        let d = zxz_ext.from_quat(DQuat::from_rotation_z(1.0));
        assert!(d.gimbal_lock);
        assert!((d.angles - DVec3::new(1.0, 0.0, 0.0)).abs().max_element() < 1e-15);
        // Half a turn about y for XYZ Tait–Bryan lock: y = π/2 exactly.
        let xyz: EulerSequence = "XYZ".parse().unwrap();
        let q = DQuat::from_xyzw(0.0, 0.5f64.sqrt(), 0.0, 0.5f64.sqrt());
        let d = xyz.from_quat(q);
        assert!(d.gimbal_lock);
        assert_eq!(d.angles.y, FRAC_PI_2);
    }

    #[test]
    fn ranges_are_half_open() {
        for seq in seqs() {
            let d = seq.from_quat(seq.to_quat(DVec3::new(
                PI,
                if seq.is_proper() { 1.0 } else { 0.5 },
                PI,
            )));
            assert!(d.angles.x > -PI && d.angles.x <= PI, "{seq} {d:?}");
            assert!(d.angles.z > -PI && d.angles.z <= PI, "{seq} {d:?}");
        }
    }
}
