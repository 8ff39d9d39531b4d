//! Unit-quaternion helpers: checked normalisation, the canonical sign, and the
//! angle between two rotations.

use glam::{DQuat, DVec3};

use crate::KinematicsError;
use crate::lanes::lanes;

/// Euclidean norm of a vector of any magnitude, without overflow or underflow.
///
/// ```text
/// |v| = m · |v / m|,  m = max |v_i|   (only when |v|² would leave the normal range)
/// ```
pub(crate) fn norm_of(components: &[f64]) -> f64 {
    let m = components.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    if !(1e-150..=1e150).contains(&m) {
        if m == 0.0 || !m.is_finite() {
            return m;
        }
        let s: f64 = components.iter().map(|c| (c / m) * (c / m)).sum();
        return m * s.sqrt();
    }
    components.iter().map(|c| c * c).sum::<f64>().sqrt()
}

/// Euclidean norm of a 3-vector, without overflow or underflow.
#[inline]
pub(crate) fn norm3(v: DVec3) -> f64 {
    norm_of(&[v.x, v.y, v.z])
}

/// The unit vector along `v`, or `None` for the zero vector; exact in
/// direction for any finite magnitude (subnormal components included).
pub(crate) fn normalized3(v: DVec3) -> Option<DVec3> {
    let m = v.abs().max_element();
    if m == 0.0 {
        return None;
    }
    let scaled = v / m;
    Some(scaled / scaled.length())
}

/// Normalises a quaternion into a unit quaternion, refusing zero and
/// non-finite input.
///
/// ```text
/// q̂ = q / |q|
/// ```
///
/// Works for any finite magnitude (`1e-300` or `1e300` components alike).
///
/// # Errors
/// [`KinematicsError::NonFinite`] if a component is NaN or infinite,
/// [`KinematicsError::ZeroQuaternion`] if all components are zero.
///
/// ```
/// use glam::DQuat;
/// use kreisel_kinematics::try_normalize_quat;
/// let q = try_normalize_quat(DQuat::from_xyzw(0.0, 0.0, 0.0, 2.0))?;
/// assert_eq!(q, DQuat::IDENTITY);
/// assert!(try_normalize_quat(DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0)).is_err());
/// # Ok::<(), kreisel_kinematics::KinematicsError>(())
/// ```
pub fn try_normalize_quat(q: DQuat) -> Result<DQuat, KinematicsError> {
    let c = [q.w, q.x, q.y, q.z];
    if c.iter().any(|v| !v.is_finite()) {
        return Err(KinematicsError::NonFinite { what: "quaternion" });
    }
    let m = c.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    if m == 0.0 {
        return Err(KinematicsError::ZeroQuaternion);
    }
    // Scale by the largest component first: |q / m| ∈ [1, 2], so neither the
    // squares nor the division can overflow or underflow.
    let [w, x, y, z] = c.map(|v| v / m);
    let n = (w * w + x * x + y * y + z * z).sqrt();
    Ok(DQuat::from_xyzw(x / n, y / n, z / n, w / n))
}

/// Each `q` times the power of two that puts its largest component in
/// `[1, 2)`, refusing zero and non-finite input (as [`try_normalize_quat`]);
/// lane by lane, without data-dependent branches, for SIMD.
///
/// ```text
/// q' = 2^k q,  max |q'_i| ∈ [1, 2)
/// ```
///
/// Exact (a scaling by a power of two rounds nothing), except for
/// components more than 2¹⁰²² times smaller than the largest, which become
/// subnormal: for a scale-invariant formula, `q'` is `q` without the risk
/// of overflow or underflow, at the cost of one multiplication a component
/// (instead of `try_normalize_quat`'s square root and divisions).
///
/// # Errors
/// The first quaternion that is not a rotation, by its index:
/// [`KinematicsError::NonFinite`] if a component is NaN or infinite,
/// [`KinematicsError::ZeroQuaternion`] if all components are zero.
#[inline(always)]
pub(crate) fn try_scale_quats<const N: usize>(
    q: [DQuat; N],
) -> Result<[DQuat; N], (usize, KinematicsError)> {
    /// 2⁶⁴.
    const TWO_64: f64 = 18_446_744_073_709_551_616.0;
    let m: [f64; N] = lanes(0.0, |i| {
        let c = [q[i].w, q[i].x, q[i].y, q[i].z].map(f64::abs);
        c.into_iter().fold(0.0, |m, v| if v > m { v } else { m })
    });
    if let Some(i) = (0..N).find(|&i| !q[i].is_finite() || m[i] == 0.0) {
        let e = if q[i].is_finite() {
            KinematicsError::ZeroQuaternion
        } else {
            KinematicsError::NonFinite { what: "quaternion" }
        };
        return Err((i, e));
    }
    Ok(lanes(DQuat::IDENTITY, |i| {
        // 2^(1023 − e) for m's biased exponent e is a normal number for
        // e ∈ [1, 2045]; subnormal m (e = 0) and m ≥ 2¹⁰²³ (e = 2046) are
        // brought into that range first.
        let first = if m[i] < f64::MIN_POSITIVE {
            TWO_64
        } else if m[i] >= f64::MAX / 2.0 {
            1.0 / TWO_64
        } else {
            1.0
        };
        let e = (m[i] * first).to_bits() >> 52;
        q[i] * first * f64::from_bits((2046 - e) << 52)
    }))
}

/// The representative of `±q` with a non-negative scalar part (and, when
/// `w = 0`, a positive first non-zero vector component), as scipy's
/// `canonical=True`.
///
/// ```text
/// q ≡ −q;  canonical(q) = sign · q,  sign chosen so that (w, x, y, z) is lexicographically ≥ 0
/// ```
///
/// ```
/// use glam::DQuat;
/// use kreisel_kinematics::canonical_quat;
/// let q = DQuat::from_xyzw(0.0, -1.0, 0.0, 0.0);
/// assert_eq!(canonical_quat(q), DQuat::from_xyzw(0.0, 1.0, 0.0, 0.0));
/// ```
pub fn canonical_quat(q: DQuat) -> DQuat {
    let first_nonzero = [q.w, q.x, q.y, q.z]
        .into_iter()
        .find(|&c| c != 0.0)
        .unwrap_or(0.0);
    if first_nonzero < 0.0 { -q } else { q }
}

/// The angle of the rotation that takes `a` to `b`, in `[0, π]`, accurate for
/// tiny angles and for angles near π.
///
/// ```text
/// d = a⁻¹ ⊗ b,   angle = 2 · atan2(|vec d|, |w_d|)
/// ```
///
/// Treats `q` and `−q` as the same rotation. Both inputs should be unit
/// quaternions (the formula is scale-invariant, so any non-zero ones work).
///
/// ```
/// use glam::DQuat;
/// use kreisel_kinematics::rotation_angle_between;
/// let a = DQuat::from_rotation_z(0.25);
/// let b = DQuat::from_rotation_z(0.75);
/// assert!((rotation_angle_between(a, b) - 0.5).abs() < 1e-15);
/// assert_eq!(rotation_angle_between(a, -a), 0.0);
/// ```
pub fn rotation_angle_between(a: DQuat, b: DQuat) -> f64 {
    let d = a.conjugate() * b;
    2.0 * norm3(DVec3::new(d.x, d.y, d.z)).atan2(d.w.abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalise_extreme_magnitudes() {
        for scale in [1e-310, 1e-200, 1.0, 1e200, 1e308] {
            let q = try_normalize_quat(DQuat::from_xyzw(scale, -scale, 0.0, scale)).unwrap();
            let expect = 1.0 / 3.0_f64.sqrt();
            assert!((q.x - expect).abs() < 4e-16, "{scale}: {q:?}");
            assert!((q.length() - 1.0).abs() < 4e-16);
        }
    }

    #[test]
    fn scale_is_exact_and_lands_in_one_to_two() {
        let q = DQuat::from_xyzw(0.3, -0.7, 0.1, 0.2);
        for k in [-1020, -600, -1, 0, 1, 500, 1000, 1021] {
            let input = q * 2.0_f64.powi(k);
            let scaled = try_scale_quats([input]).unwrap()[0];
            // The same power of two for every component (an exact scaling),
            // putting the largest, |y| = 0.7 · 2^k, at 1.4.
            let factor = scaled.y / input.y;
            assert_eq!(factor, 2.0_f64.powi(1 - k), "{k}");
            assert_eq!(scaled, input * factor, "{k}");
            assert_eq!(scaled.y, -1.4, "{k}");
        }
        let huge = DQuat::from_xyzw(f64::MAX, -f64::MAX, 1.0, 0.0);
        let scaled = try_scale_quats([huge]).unwrap()[0];
        assert_eq!(scaled.x, 2.0 - f64::EPSILON);
        assert_eq!(scaled.y, -(2.0 - f64::EPSILON));
        let tiny = DQuat::from_xyzw(0.0, 5e-324, 0.0, -1e-323);
        assert_eq!(
            try_scale_quats([tiny]).unwrap()[0],
            DQuat::from_xyzw(0.0, 0.5, 0.0, -1.0)
        );
        assert_eq!(
            try_scale_quats([DQuat::IDENTITY, DQuat::from_xyzw(0.0, 0.0, f64::NAN, 1.0)]),
            Err((1, KinematicsError::NonFinite { what: "quaternion" }))
        );
        assert_eq!(
            try_scale_quats([
                DQuat::from_xyzw(-0.0, 0.0, 0.0, 0.0),
                DQuat::from_xyzw(0.0, 0.0, f64::NAN, 1.0)
            ]),
            Err((0, KinematicsError::ZeroQuaternion))
        );
    }

    #[test]
    fn normalise_rejects_nan_inf_zero() {
        let bad = [
            DQuat::from_xyzw(f64::NAN, 0.0, 0.0, 1.0),
            DQuat::from_xyzw(0.0, f64::INFINITY, 0.0, 1.0),
        ];
        for q in bad {
            assert_eq!(
                try_normalize_quat(q),
                Err(KinematicsError::NonFinite { what: "quaternion" })
            );
        }
        assert_eq!(
            try_normalize_quat(DQuat::from_xyzw(0.0, 0.0, 0.0, -0.0)),
            Err(KinematicsError::ZeroQuaternion)
        );
    }

    #[test]
    fn angle_between_tiny_and_near_pi() {
        let tiny = 1e-300;
        let a = DQuat::IDENTITY;
        let b = DQuat::from_xyzw((tiny / 2.0_f64).sin(), 0.0, 0.0, (tiny / 2.0_f64).cos());
        assert_eq!(rotation_angle_between(a, b), tiny);
        let eps = 1e-12;
        let c = DQuat::from_axis_angle(DVec3::Y, core::f64::consts::PI - eps);
        let err = (rotation_angle_between(a, c) - (core::f64::consts::PI - eps)).abs();
        assert!(err < 1e-15, "{err}");
    }
}
