//! Euler-angle rates ⇄ angular velocity, in the body and the world frame,
//! for all 24 conventions (Shuster 1993).

use glam::{DMat3, DVec3};

use crate::KinematicsError;
use crate::euler_sequence::{Axis, EulerSequence, Frame};

/// `|det|` of the rate matrix below which the inverse is refused.
///
/// The determinant is `sin θ` (proper Euler) or `cos θ` (Tait–Bryan) up to
/// sign, so this is the distance in radians from gimbal lock; there the
/// rates exceed `10⁹ |ω|` and lose about nine of their sixteen digits.
pub const RATE_SINGULARITY_TOLERANCE: f64 = 1e-9;

/// Rotates `v` by `angle` about a coordinate axis (active, right-hand rule).
#[inline]
fn rotate_about(axis: Axis, angle: f64, v: DVec3) -> DVec3 {
    let (s, c) = angle.sin_cos();
    let i = axis.index();
    let (j, k) = ((i + 1) % 3, (i + 2) % 3);
    let mut out = v;
    out[j] = c * v[j] - s * v[k];
    out[k] = s * v[j] + c * v[k];
    out
}

/// In which frame an angular velocity is written.
#[derive(Clone, Copy)]
enum In {
    Body,
    World,
}

impl EulerSequence {
    /// The angles in the intrinsic order of [`EulerSequence::intrinsic_axes`].
    #[inline]
    fn intrinsic_angles(self, angles: DVec3) -> DVec3 {
        match self.frame() {
            Frame::Intrinsic => angles,
            Frame::Extrinsic => DVec3::new(angles.z, angles.y, angles.x),
        }
    }

    /// The columns of the rate matrix, in the order of the sequence's angles.
    fn rate_columns(self, angles: DVec3, frame: In) -> [DVec3; 3] {
        let [a, b, c] = self.intrinsic_axes();
        let t = self.intrinsic_angles(angles);
        let (ea, eb, ec) = (a.unit(), b.unit(), c.unit());
        let cols = match frame {
            // ω_world = α̇ e_A + β̇ R_A(α) e_B + γ̇ R_A(α) R_B(β) e_C
            In::World => [
                ea,
                rotate_about(a, t.x, eb),
                rotate_about(a, t.x, rotate_about(b, t.y, ec)),
            ],
            // ω_body = α̇ R_C(γ)ᵀ R_B(β)ᵀ e_A + β̇ R_C(γ)ᵀ e_B + γ̇ e_C
            In::Body => [
                rotate_about(c, -t.z, rotate_about(b, -t.y, ea)),
                rotate_about(c, -t.z, eb),
                ec,
            ],
        };
        match self.frame() {
            Frame::Intrinsic => cols,
            Frame::Extrinsic => [cols[2], cols[1], cols[0]],
        }
    }

    /// The determinant of the rate matrices (body and world alike).
    ///
    /// ```text
    /// intrinsic ABC:  det = −sin β (proper),   ε_ABC cos β (Tait–Bryan)
    /// extrinsic abc:  det = +sin β (proper),  −ε_CBA cos β = ε_abc cos β (Tait–Bryan)
    /// ```
    ///
    /// It vanishes exactly at gimbal lock.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::EulerSequence;
    /// let zxz: EulerSequence = "ZXZ".parse()?;
    /// let angles = DVec3::new(0.3, 0.5, -1.0);
    /// assert_eq!(zxz.rate_matrix_determinant(angles), -(0.5f64).sin());
    /// assert!((zxz.rate_matrix_body(angles).determinant() + (0.5f64).sin()).abs() < 1e-15);
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub fn rate_matrix_determinant(self, angles: DVec3) -> f64 {
        let [a, b, _] = self.intrinsic_axes();
        let intrinsic = if self.is_proper() {
            -angles.y.sin()
        } else {
            a.parity(b) * angles.y.cos()
        };
        match self.frame() {
            Frame::Intrinsic => intrinsic,
            Frame::Extrinsic => -intrinsic,
        }
    }

    /// The matrix that maps Euler-angle rates to the body-frame angular velocity.
    ///
    /// Shuster, "A survey of attitude representations", J. Astronaut. Sci.
    /// 41:439 (1993), §5.
    ///
    /// ```text
    /// ω_body = M_body(angles) · (α̇, β̇, γ̇)
    /// intrinsic ABC:  M_body = [R_C(γ)ᵀR_B(β)ᵀ e_A | R_C(γ)ᵀ e_B | e_C]
    /// ZXZ (φ, θ, ψ):  ω₁ = φ̇ sin θ sin ψ + θ̇ cos ψ
    ///                 ω₂ = φ̇ sin θ cos ψ − θ̇ sin ψ
    ///                 ω₃ = φ̇ cos θ + ψ̇
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::EulerSequence;
    /// let zxz: EulerSequence = "ZXZ".parse()?;
    /// let (th, ps) = (0.4_f64, 1.1_f64);
    /// let w = zxz.rate_matrix_body(DVec3::new(0.2, th, ps)) * DVec3::new(1.0, 0.0, 0.0);
    /// assert!((w - DVec3::new(th.sin() * ps.sin(), th.sin() * ps.cos(), th.cos())).length() < 1e-15);
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub fn rate_matrix_body(self, angles: DVec3) -> DMat3 {
        let [c0, c1, c2] = self.rate_columns(angles, In::Body);
        DMat3::from_cols(c0, c1, c2)
    }

    /// The matrix that maps Euler-angle rates to the world-frame angular velocity.
    ///
    /// ```text
    /// ω_world = M_world(angles) · (α̇, β̇, γ̇) = R(angles) · M_body(angles) · (α̇, β̇, γ̇)
    /// intrinsic ABC:  M_world = [e_A | R_A(α) e_B | R_A(α) R_B(β) e_C]
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::EulerSequence;
    /// let seq: EulerSequence = "yxz".parse()?;
    /// let angles = DVec3::new(0.3, -0.2, 0.9);
    /// let q = seq.to_quat(angles);
    /// let rates = DVec3::new(1.0, 2.0, 3.0);
    /// let world = seq.rate_matrix_world(angles) * rates;
    /// let body = seq.rate_matrix_body(angles) * rates;
    /// assert!((world - q * body).length() < 1e-14);
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub fn rate_matrix_world(self, angles: DVec3) -> DMat3 {
        let [c0, c1, c2] = self.rate_columns(angles, In::World);
        DMat3::from_cols(c0, c1, c2)
    }

    fn inverse_rate_matrix(self, angles: DVec3, frame: In) -> Result<DMat3, KinematicsError> {
        let determinant = self.rate_matrix_determinant(angles);
        if determinant.is_nan() || determinant.abs() < RATE_SINGULARITY_TOLERANCE {
            return Err(KinematicsError::RateSingularity {
                sequence: self,
                middle_angle: angles.y,
                determinant,
                tolerance: RATE_SINGULARITY_TOLERANCE,
            });
        }
        // Rows of the inverse are cross products of the columns over det.
        let [c0, c1, c2] = self.rate_columns(angles, frame);
        Ok(DMat3::from_cols(c1.cross(c2), c2.cross(c0), c0.cross(c1)).transpose() / determinant)
    }

    /// The matrix that maps the body-frame angular velocity to Euler-angle rates.
    ///
    /// ```text
    /// (α̇, β̇, γ̇) = M_body⁻¹ ω_body,   M⁻¹ = [c₁×c₂ ; c₂×c₀ ; c₀×c₁] / det   (rows)
    /// ```
    ///
    /// # Errors
    /// [`KinematicsError::RateSingularity`] when `|det|` (= `|sin θ|` or
    /// `|cos θ|`) is below [`RATE_SINGULARITY_TOLERANCE`].
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_kinematics::EulerSequence;
    /// let seq: EulerSequence = "ZYX".parse()?;
    /// let angles = DVec3::new(0.3, 1.2, -0.4);
    /// let product = seq.inverse_rate_matrix_body(angles)? * seq.rate_matrix_body(angles);
    /// assert!(product.abs_diff_eq(DMat3::IDENTITY, 1e-15));
    /// assert!(seq.inverse_rate_matrix_body(DVec3::new(0.3, core::f64::consts::FRAC_PI_2, 0.0)).is_err());
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub fn inverse_rate_matrix_body(self, angles: DVec3) -> Result<DMat3, KinematicsError> {
        self.inverse_rate_matrix(angles, In::Body)
    }

    /// The matrix that maps the world-frame angular velocity to Euler-angle rates.
    ///
    /// ```text
    /// (α̇, β̇, γ̇) = M_world⁻¹ ω_world
    /// ```
    ///
    /// # Errors
    /// [`KinematicsError::RateSingularity`] near gimbal lock, as
    /// [`EulerSequence::inverse_rate_matrix_body`].
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_kinematics::EulerSequence;
    /// let seq: EulerSequence = "zxz".parse()?;
    /// let angles = DVec3::new(0.3, 1.2, -0.4);
    /// let product = seq.inverse_rate_matrix_world(angles)? * seq.rate_matrix_world(angles);
    /// assert!(product.abs_diff_eq(DMat3::IDENTITY, 1e-15));
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub fn inverse_rate_matrix_world(self, angles: DVec3) -> Result<DMat3, KinematicsError> {
        self.inverse_rate_matrix(angles, In::World)
    }

    /// Euler-angle rates for a body-frame angular velocity.
    ///
    /// ```text
    /// (α̇, β̇, γ̇) = M_body(angles)⁻¹ · ω_body
    /// ```
    ///
    /// # Errors
    /// [`KinematicsError::RateSingularity`] near gimbal lock.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::EulerSequence;
    /// let zxz: EulerSequence = "ZXZ".parse()?;
    /// // Spin about the body z axis: only ψ̇ changes.
    /// let rates = zxz.rates_from_omega_body(DVec3::new(0.1, 0.5, 0.2), DVec3::new(0.0, 0.0, 3.0))?;
    /// assert!((rates - DVec3::new(0.0, 0.0, 3.0)).length() < 1e-15);
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub fn rates_from_omega_body(
        self,
        angles: DVec3,
        omega_body: DVec3,
    ) -> Result<DVec3, KinematicsError> {
        Ok(self.inverse_rate_matrix_body(angles)? * omega_body)
    }

    /// Euler-angle rates for a world-frame angular velocity.
    ///
    /// ```text
    /// (α̇, β̇, γ̇) = M_world(angles)⁻¹ · ω_world
    /// ```
    ///
    /// # Errors
    /// [`KinematicsError::RateSingularity`] near gimbal lock.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::EulerSequence;
    /// let zxz: EulerSequence = "ZXZ".parse()?;
    /// // Spin about the world z axis: only φ̇ changes.
    /// let rates = zxz.rates_from_omega_world(DVec3::new(0.1, 0.5, 0.2), DVec3::new(0.0, 0.0, 3.0))?;
    /// assert!((rates - DVec3::new(3.0, 0.0, 0.0)).length() < 1e-15);
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub fn rates_from_omega_world(
        self,
        angles: DVec3,
        omega_world: DVec3,
    ) -> Result<DVec3, KinematicsError> {
        Ok(self.inverse_rate_matrix_world(angles)? * omega_world)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::omega_body_from_attitudes;

    /// Angles away from lock for any sequence.
    fn generic_angles(seq: EulerSequence) -> DVec3 {
        DVec3::new(0.7, if seq.is_proper() { 1.1 } else { -0.5 }, -2.3)
    }

    #[test]
    fn zxz_matches_the_notes_corrected_formula() {
        // Notes §3.9 with ERRATA: ω₁ = φ̇ sinθ sinψ + θ̇ cosψ, ω₂ = φ̇ sinθ cosψ − θ̇ sinψ, ω₃ = ψ̇ + φ̇ cosθ.
        let zxz: EulerSequence = "ZXZ".parse().unwrap();
        let (ph, th, ps) = (0.3_f64, 0.8_f64, -1.4_f64);
        let (dph, dth, dps) = (0.5, -1.2, 2.0);
        let w = zxz.rate_matrix_body(DVec3::new(ph, th, ps)) * DVec3::new(dph, dth, dps);
        let expect = DVec3::new(
            dph * th.sin() * ps.sin() + dth * ps.cos(),
            dph * th.sin() * ps.cos() - dth * ps.sin(),
            dps + dph * th.cos(),
        );
        assert!((w - expect).length() < 1e-15, "{w} vs {expect}");
    }

    #[test]
    fn all_24_match_finite_differences_of_the_rotation() {
        let rates = DVec3::new(0.9, -0.4, 1.3);
        let h = 1e-5;
        for seq in EulerSequence::all() {
            let angles = generic_angles(seq);
            let q_minus = seq.to_quat(angles - rates * h);
            let q_plus = seq.to_quat(angles + rates * h);
            // Central difference: O(h²) ≈ 1e-10.
            let fd_body = omega_body_from_attitudes(q_minus, q_plus, 2.0 * h);
            let body = seq.rate_matrix_body(angles) * rates;
            assert!(
                (fd_body - body).length() < 1e-9,
                "{seq}: {fd_body} vs {body}"
            );
            let world = seq.rate_matrix_world(angles) * rates;
            let fd_world = seq.to_quat(angles) * fd_body;
            assert!(
                (fd_world - world).length() < 1e-9,
                "{seq}: {fd_world} vs {world}"
            );
        }
    }

    #[test]
    fn inverse_round_trips_and_determinant_is_analytic() {
        for seq in EulerSequence::all() {
            let angles = generic_angles(seq);
            let m = seq.rate_matrix_body(angles);
            assert!(
                (m.determinant() - seq.rate_matrix_determinant(angles)).abs() < 1e-15,
                "{seq}"
            );
            let mw = seq.rate_matrix_world(angles);
            assert!(
                (mw.determinant() - seq.rate_matrix_determinant(angles)).abs() < 1e-15,
                "{seq}"
            );
            let omega = DVec3::new(-0.3, 0.8, 0.25);
            let rates = seq.rates_from_omega_body(angles, omega).unwrap();
            assert!((m * rates - omega).length() < 1e-15, "{seq}");
            let rates = seq.rates_from_omega_world(angles, omega).unwrap();
            assert!((mw * rates - omega).length() < 1e-15, "{seq}");
        }
    }

    #[test]
    fn typed_error_at_and_near_lock_only() {
        for seq in EulerSequence::all() {
            for lock in seq.gimbal_lock_angles() {
                for offset in [0.0, 1e-12, -1e-10] {
                    let angles = DVec3::new(0.2, lock + offset, 0.4);
                    let r = seq.rates_from_omega_body(angles, DVec3::X);
                    assert!(
                        matches!(r, Err(KinematicsError::RateSingularity { .. })),
                        "{seq} {lock}"
                    );
                }
                // 1e-6 rad from the lock is fine, and still accurate.
                let step = if lock > 0.0 { -1e-6 } else { 1e-6 };
                let angles = DVec3::new(0.2, lock + step, 0.4);
                let omega = DVec3::new(0.1, 0.2, 0.3);
                let rates = seq.rates_from_omega_body(angles, omega).unwrap();
                let back = seq.rate_matrix_body(angles) * rates;
                assert!((back - omega).length() < 1e-9, "{seq}");
            }
        }
    }
}
