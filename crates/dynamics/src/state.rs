//! The state of a free rigid body and its conserved quantities.

use glam::{DQuat, DVec3};

use crate::{DynamicsError, RigidBody};

/// The state of a rigid body in its principal frame: what integrators advance.
///
/// ```text
/// q = world_from_principal,   L = angular momentum in principal axes,   ω = I⁻¹ L
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrincipalState {
    /// Attitude: maps principal-frame coordinates to world coordinates.
    pub world_from_principal: DQuat,
    /// Angular momentum in principal axes, kg·m²/s.
    pub l_principal: DVec3,
}

impl PrincipalState {
    /// A state from an attitude and a body-frame angular velocity.
    ///
    /// ```text
    /// q_wp = q_wb ⊗ q_bp,   L_p = I ω_p,   ω_p = q_bp⁻¹ ω_b
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::InvalidState`] for a zero or non-finite quaternion,
    /// a non-finite angular velocity, or one whose angular momentum or
    /// energy overflows `f64` ([`PrincipalState::validate`]). The
    /// quaternion is normalised.
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{PrincipalState, RigidBody};
    /// let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0))?;
    /// let s = PrincipalState::try_from_omega_body(&body, DQuat::IDENTITY, DVec3::new(0.01, 1.0, 0.0))?;
    /// assert_eq!(s.l_principal, DVec3::new(0.01, 2.0, 0.0));
    /// // I ω² overflows: refused rather than holding inf.
    /// assert!(PrincipalState::try_from_omega_body(&body, DQuat::IDENTITY, DVec3::splat(1e308)).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_from_omega_body(
        body: &RigidBody,
        world_from_body: DQuat,
        omega_body: DVec3,
    ) -> Result<Self, DynamicsError> {
        let q = kreisel_kinematics::try_normalize_quat(world_from_body).map_err(|_| {
            DynamicsError::InvalidState {
                reason: "attitude quaternion is zero or not finite",
            }
        })?;
        if !omega_body.is_finite() {
            return Err(DynamicsError::InvalidState {
                reason: "angular velocity is not finite",
            });
        }
        let q_bp = body.body_from_principal();
        let omega_p = q_bp.conjugate() * omega_body;
        let state = Self {
            world_from_principal: q * q_bp,
            l_principal: omega_p * body.principal_moments(),
        };
        state.validate(body.principal_moments())?;
        Ok(state)
    }

    /// Checks that the state can be advanced for principal moments
    /// `moments`: a finite, non-zero attitude, and an angular momentum whose
    /// square in the body's unit of inertia and whose energy are finite.
    ///
    /// ```text
    /// q finite, |q| > 0;   |L̂|² < ∞, L̂ = L / 2ᵏ (2ᵏ ≈ max Iₖ);   E = ½ Σ Lₖ²/Iₖ < ∞
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::InvalidState`] naming what is wrong.
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::PrincipalState;
    /// let s = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 1e300, 0.0) };
    /// assert!(s.validate(DVec3::splat(1e300)).is_ok()); // ω = 1 rad/s
    /// assert!(s.validate(DVec3::splat(1.0)).is_err()); // E = 5e599 J
    /// ```
    pub fn validate(&self, moments: DVec3) -> Result<(), DynamicsError> {
        let bad = |reason| Err(DynamicsError::InvalidState { reason });
        let q = self.world_from_principal;
        if !q.is_finite() || q.length_squared() == 0.0 {
            return bad("attitude quaternion is zero or not finite");
        }
        if !self.l_principal.is_finite() {
            return bad("angular momentum is not finite (I ω overflows)");
        }
        let unit = crate::rigid_body::moment_scale(moments);
        let l = self.l_principal / unit;
        if !(l.length_squared().is_finite()
            && kinetic_energy(moments, self.l_principal).is_finite())
        {
            return bad("angular momentum too large: |L|^2 or the energy I w^2/2 overflows");
        }
        Ok(())
    }

    /// The body-frame attitude: maps body coordinates to world coordinates.
    ///
    /// ```text
    /// q_wb = q_wp ⊗ q_bp⁻¹
    /// ```
    pub fn world_from_body(&self, body: &RigidBody) -> DQuat {
        self.world_from_principal * body.body_from_principal().conjugate()
    }

    /// Angular velocity in body axes.
    ///
    /// ```text
    /// ω_b = q_bp (I⁻¹ L_p)
    /// ```
    pub fn omega_body(&self, body: &RigidBody) -> DVec3 {
        body.body_from_principal() * (self.l_principal / body.principal_moments())
    }

    /// Rotational kinetic energy, evaluated in the body's unit of inertia
    /// (an exact power-of-two rescaling), so `Lₖ²` cannot overflow while the
    /// energy itself is finite (moments of 1e200 kg m² at 1 rad/s).
    ///
    /// ```text
    /// E = ½ Σ Lₖ² / Iₖ = 2ᵏ · ½ Σ L̂ₖ² / Îₖ,   L̂ = L/2ᵏ, Î = I/2ᵏ
    /// ```
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{PrincipalState, RigidBody};
    /// let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0))?;
    /// let s = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 2.0, 0.0) };
    /// assert_eq!(s.energy(&body), 1.0);
    /// let big = RigidBody::try_from_principal_moments(DVec3::new(1e200, 2e200, 3e200))?;
    /// let s = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 2e200, 0.0) };
    /// assert!((s.energy(&big) / 1e200 - 1.0).abs() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn energy(&self, body: &RigidBody) -> f64 {
        kinetic_energy(body.principal_moments(), self.l_principal)
    }

    /// Angular momentum in world axes (constant for a free body).
    ///
    /// ```text
    /// L_w = q̂ L_p q̂⁻¹,   q̂ = q_wp / |q_wp|
    /// ```
    ///
    /// The attitude is normalised for the evaluation only (the state is not
    /// changed): after 10⁷ exact rotations `|q|` has wandered from 1 by
    /// rounding, and a unit-quaternion formula would report that as a drift
    /// of `L_w`.
    pub fn l_world(&self) -> DVec3 {
        self.world_from_principal.normalize() * self.l_principal
    }
}

/// `½ Σ Lₖ²/Iₖ` in the unit of inertia of `moments` (see
/// `rigid_body::moment_scale`): bit for bit the plain formula wherever that
/// does not overflow.
#[inline]
pub(crate) fn kinetic_energy(moments: DVec3, l: DVec3) -> f64 {
    let unit = crate::rigid_body::moment_scale(moments);
    let l = l / unit;
    0.5 * (l * l / (moments / unit)).element_sum() * unit
}
