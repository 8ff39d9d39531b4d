//! Quaternion → Euler angles for all 24 conventions, accurate at and next to
//! gimbal lock (Bernardes & Viollet 2022), one rotation at a time or
//! several side by side (SIMD lanes, the same numbers).

use core::f64::consts::{PI, TAU};

use glam::{DQuat, DVec3};

use crate::KinematicsError;
use crate::atan2::atan2_lanes;
use crate::euler_angles::EulerDecomposition;
use crate::euler_sequence::{EulerSequence, Frame, gather};
use crate::quaternion::try_scale_quats;

/// `[f(0), …, f(N − 1)]`: one lane a quaternion.
#[inline(always)]
fn lanes<const N: usize>(f: impl FnMut(usize) -> f64) -> [f64; N] {
    crate::lanes::lanes(0.0, f)
}

/// Wraps an angle from `[−π, π]` into `(−π, π]` (maps `−π` to `π`).
#[inline]
fn half_open(angle: f64) -> f64 {
    if angle <= -PI { angle + TAU } else { angle }
}

impl EulerSequence {
    /// Euler angles of a rotation given as any non-zero finite quaternion,
    /// of any magnitude: [`EulerSequence::from_quat`] after an exact scaling
    /// by a power of two (its formulas are scale-invariant).
    ///
    /// ```text
    /// angles(q) = from_quat(2^k q),  max |2^k q_i| ∈ [1, 2)
    /// ```
    ///
    /// Faster than normalising first, and one rounding more accurate: the
    /// angles are those of `q` itself, not of `q / |q|` rounded.
    ///
    /// # Errors
    /// [`KinematicsError::NonFinite`] if a component is NaN or infinite,
    /// [`KinematicsError::ZeroQuaternion`] if all components are zero.
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_kinematics::EulerSequence;
    /// let zyx: EulerSequence = "ZYX".parse()?;
    /// let q = zyx.to_quat(DVec3::new(0.5, -0.25, 1.0));
    /// let found = zyx.try_from_quat(q * 1e-200)?;
    /// assert!((found.angles - DVec3::new(0.5, -0.25, 1.0)).abs().max_element() < 1e-15);
    /// assert!(zyx.try_from_quat(DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)).is_err());
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    #[inline]
    pub fn try_from_quat(self, q: DQuat) -> Result<EulerDecomposition, KinematicsError> {
        let [found] = self.try_from_quats([q]).map_err(|(_, e)| e)?;
        Ok(found)
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
        let [found] = self.from_quats([world_from_body]);
        found
    }

    /// [`EulerSequence::from_quat`] of `N` rotations at once: the same
    /// numbers, bit for bit, computed lane by lane without data-dependent
    /// branches, so that the compiler can use SIMD registers (x86-64 with
    /// SSE2, random quaternions, one interleaved run: four at a time 34 ns a
    /// quaternion, one at a time 72 ns, normalising first with glibc's
    /// `atan2`, as before, 135 ns).
    ///
    /// ```
    /// use glam::DQuat;
    /// use kreisel_kinematics::EulerSequence;
    /// let zxz: EulerSequence = "ZXZ".parse()?;
    /// let q = [DQuat::from_rotation_x(0.5), DQuat::from_rotation_z(1.0)];
    /// let [a, b] = zxz.from_quats(q);
    /// assert_eq!([a, b], [zxz.from_quat(q[0]), zxz.from_quat(q[1])]);
    /// assert!(b.gimbal_lock && !a.gimbal_lock);
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    #[inline(always)]
    pub fn from_quats<const N: usize>(
        self,
        world_from_body: [DQuat; N],
    ) -> [EulerDecomposition; N] {
        let q = world_from_body;
        let [a, b, c] = self.intrinsic_axes();
        let proper = a == c;
        // Components along (A, B, T), T the third axis, ε = ε_{ABT}; for
        // Tait–Bryan C = T.
        let u = |i: usize| {
            let (u, eps) = gather(a, b, DVec3::new(q[i].x, q[i].y, q[i].z));
            (u.x, u.y, eps * u.z)
        };
        let eps = a.parity(b);
        let (x0, x1, y0, y1) = if proper {
            (
                lanes::<N>(|i| q[i].w),
                lanes::<N>(|i| u(i).0),
                lanes::<N>(|i| u(i).1),
                lanes::<N>(|i| u(i).2),
            )
        } else {
            (
                lanes::<N>(|i| q[i].w - u(i).1),
                lanes::<N>(|i| u(i).0 - u(i).2),
                lanes::<N>(|i| q[i].w + u(i).1),
                lanes::<N>(|i| u(i).0 + u(i).2),
            )
        };
        let sign = if proper { 1.0 } else { -eps };
        // β = 2 atan2(|y|, |x|) = atan2(2|x||y|, |x|² − |y|²): one square
        // root instead of two, and as accurate (absolute error ~1e-16 rad
        // for every β). For Tait–Bryan, β − π/2 = atan2(|y|² − |x|², 2|x||y|)
        // lands in [−π/2, π/2] directly, without rounding in a subtraction.
        // q is unit (or of moderate size): the squares cannot overflow, and
        // they underflow only ~1e-162 from the lock, where treating the
        // rotation as locked costs < 1e-160 rad.
        let nx2 = lanes::<N>(|i| x0[i] * x0[i] + x1[i] * x1[i]);
        let ny2 = lanes::<N>(|i| y0[i] * y0[i] + y1[i] * y1[i]);
        let sin_m = lanes::<N>(|i| 2.0 * (nx2[i] * ny2[i]).sqrt());
        let cos_m = lanes::<N>(|i| nx2[i] - ny2[i]);
        let middle = if proper {
            atan2_lanes(sin_m, cos_m)
        } else {
            atan2_lanes(lanes::<N>(|i| -cos_m[i]), sin_m)
        };

        // Away from the lock: α = atan2(x₁y₀ + x₀y₁, x₀y₀ − x₁y₁), γ from
        // the other pair. Exactly at the lock (|y| = 0 or |x| = 0) only
        // α + sγ = 2X (|y| = 0) or α − sγ = 2Y (|x| = 0) is defined: the
        // "first" atan2 takes that double angle (p = x or y), and the
        // sequence's third angle is set to 0.
        let locked: [bool; N] = crate::lanes::lanes(false, |i| ny2[i] == 0.0 || nx2[i] == 0.0);
        let p0 = lanes::<N>(|i| if ny2[i] == 0.0 { x0[i] } else { y0[i] });
        let p1 = lanes::<N>(|i| if ny2[i] == 0.0 { x1[i] } else { y1[i] });
        let first = atan2_lanes(
            lanes::<N>(|i| {
                let away = x1[i] * y0[i] + x0[i] * y1[i];
                if locked[i] { 2.0 * p0[i] * p1[i] } else { away }
            }),
            lanes::<N>(|i| {
                let away = x0[i] * y0[i] - x1[i] * y1[i];
                if locked[i] {
                    p0[i] * p0[i] - p1[i] * p1[i]
                } else {
                    away
                }
            }),
        );
        let second = atan2_lanes(
            lanes::<N>(|i| x1[i] * y0[i] - x0[i] * y1[i]),
            lanes::<N>(|i| x0[i] * y0[i] + x1[i] * y1[i]),
        );
        // Which intrinsic angle is the sequence's *third* one (set to 0 at the lock).
        let zero_first = self.frame() == Frame::Extrinsic;
        let unset = EulerDecomposition {
            angles: DVec3::ZERO,
            gimbal_lock: false,
        };
        crate::lanes::lanes(unset, |i| {
            let (alpha, gamma) = if !locked[i] {
                (half_open(first[i]), half_open(sign * second[i]))
            } else if zero_first {
                let s = if ny2[i] == 0.0 { sign } else { -sign };
                (0.0, half_open(s * first[i]))
            } else {
                (half_open(first[i]), 0.0)
            };
            let angles = match self.frame() {
                Frame::Intrinsic => DVec3::new(alpha, middle[i], gamma),
                Frame::Extrinsic => DVec3::new(gamma, middle[i], alpha),
            };
            EulerDecomposition {
                angles,
                gimbal_lock: locked[i],
            }
        })
    }

    /// [`EulerSequence::try_from_quat`] of `N` quaternions at once, lane by
    /// lane as [`EulerSequence::from_quats`]: the same numbers, bit for bit.
    ///
    /// # Errors
    /// The first quaternion that is not a rotation: its index, and its
    /// error as [`EulerSequence::try_from_quat`].
    ///
    /// ```
    /// use glam::DQuat;
    /// use kreisel_kinematics::{EulerSequence, KinematicsError};
    /// let xyz: EulerSequence = "xyz".parse()?;
    /// let q = [DQuat::from_rotation_y(0.5) * 3.0, DQuat::from_rotation_x(-1.0)];
    /// let [a, b] = xyz.try_from_quats(q).unwrap();
    /// assert_eq!([a, b], [xyz.try_from_quat(q[0])?, xyz.try_from_quat(q[1])?]);
    /// let zero = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    /// assert_eq!(xyz.try_from_quats([q[0], zero]), Err((1, KinematicsError::ZeroQuaternion)));
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    #[inline(always)]
    pub fn try_from_quats<const N: usize>(
        self,
        quats: [DQuat; N],
    ) -> Result<[EulerDecomposition; N], (usize, KinematicsError)> {
        Ok(self.from_quats(try_scale_quats(quats)?))
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

    /// Quaternions of every kind: generic, next to and exactly at the lock,
    /// unnormalised (tiny, huge, subnormal), and not rotations at all.
    fn mixed_quats(seq: EulerSequence) -> Vec<DQuat> {
        let mut all = Vec::new();
        for (k, lock) in seq.gimbal_lock_angles().into_iter().enumerate() {
            for delta in [0.0, 1e-300, 1e-12, 1e-3, 0.7] {
                let middle = if lock > 0.0 {
                    lock - delta
                } else {
                    lock + delta
                };
                let q = seq.to_quat(DVec3::new(0.3 - k as f64, middle, -2.9));
                all.extend([q, -q, q * 3.0, q * 1e-300, q * 1e300, q * 5e-324]);
            }
        }
        all.extend([
            DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0),
            DQuat::from_xyzw(0.0, f64::NAN, 0.0, 1.0),
            DQuat::from_xyzw(f64::MAX, f64::MAX, -f64::MAX, 1.0),
            DQuat::from_xyzw(f64::INFINITY, 0.0, 0.0, 1.0),
        ]);
        all
    }

    #[test]
    fn side_by_side_gives_the_same_bits() {
        for seq in seqs() {
            let quats: Vec<DQuat> = mixed_quats(seq)
                .into_iter()
                .filter(|&q| seq.try_from_quat(q).is_ok())
                .collect();
            for block in quats.chunks_exact(4) {
                let q: [DQuat; 4] = core::array::from_fn(|i| block[i]);
                let four = seq.try_from_quats(q).unwrap();
                let two = [
                    seq.try_from_quats([q[0], q[1]]).unwrap(),
                    seq.try_from_quats([q[2], q[3]]).unwrap(),
                ];
                let bits =
                    |d: EulerDecomposition| (d.angles.to_array().map(f64::to_bits), d.gimbal_lock);
                for i in 0..4 {
                    let one = seq.try_from_quat(q[i]).unwrap();
                    assert_eq!(bits(four[i]), bits(one), "{seq} {:?}", q[i]);
                    assert_eq!(bits(two[i / 2][i % 2]), bits(one), "{seq} {:?}", q[i]);
                    // Scaling by a power of two changes no bit.
                    if q[i].length().is_finite() && q[i].length() > 1e-300 {
                        assert_eq!(one, seq.from_quat(q[i]), "{seq} {:?}", q[i]);
                    }
                }
            }
        }
    }

    #[test]
    fn side_by_side_reports_the_first_bad_quaternion() {
        let zyx: EulerSequence = "ZYX".parse().unwrap();
        let good = DQuat::from_rotation_y(0.3);
        let zero = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
        let nan = DQuat::from_xyzw(0.0, f64::NAN, 0.0, 1.0);
        assert_eq!(
            zyx.try_from_quats([good, good, nan, zero]),
            Err((2, KinematicsError::NonFinite { what: "quaternion" }))
        );
        assert_eq!(
            zyx.try_from_quats([good, zero, nan, good]),
            Err((1, KinematicsError::ZeroQuaternion))
        );
    }

    #[test]
    fn any_magnitude_gives_the_rotation() {
        for seq in seqs() {
            let angles = DVec3::new(2.0, if seq.is_proper() { 0.4 } else { -0.4 }, -1.0);
            let q = seq.to_quat(angles);
            for scale in [1e-310, 1e-200, 1.0, 1e200, 1e308] {
                let d = seq.try_from_quat(q * scale).unwrap();
                // Subnormal components keep ~40 of their 53 bits.
                let tolerance = if scale < 1e-300 { 1e-10 } else { 1e-15 };
                assert!(
                    (d.angles - angles).abs().max_element() < tolerance,
                    "{seq} {scale}: {d:?}"
                );
            }
        }
        let zyx: EulerSequence = "ZYX".parse().unwrap();
        assert_eq!(
            zyx.try_from_quat(DQuat::from_xyzw(0.0, 0.0, 0.0, -0.0)),
            Err(KinematicsError::ZeroQuaternion)
        );
        assert_eq!(
            zyx.try_from_quat(DQuat::from_xyzw(0.0, 0.0, f64::NEG_INFINITY, 1.0)),
            Err(KinematicsError::NonFinite { what: "quaternion" })
        );
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
