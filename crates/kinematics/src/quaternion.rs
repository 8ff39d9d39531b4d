//! Unit-quaternion helpers: checked normalisation, the canonical sign, and the
//! angle between two rotations.

use glam::{DQuat, DVec3};

use crate::KinematicsError;

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
