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
    /// [`DynamicsError::InvalidState`] for a zero or non-finite quaternion
    /// or a non-finite angular velocity. The quaternion is normalised.
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{PrincipalState, RigidBody};
    /// let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0))?;
    /// let s = PrincipalState::try_from_omega_body(&body, DQuat::IDENTITY, DVec3::new(0.01, 1.0, 0.0))?;
    /// assert_eq!(s.l_principal, DVec3::new(0.01, 2.0, 0.0));
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
        Ok(Self {
            world_from_principal: q * q_bp,
            l_principal: omega_p * body.principal_moments(),
        })
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

    /// Rotational kinetic energy.
    ///
    /// ```text
    /// E = ½ Σ Lₖ² / Iₖ
    /// ```
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{PrincipalState, RigidBody};
    /// let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0))?;
    /// let s = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 2.0, 0.0) };
    /// assert_eq!(s.energy(&body), 1.0);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn energy(&self, body: &RigidBody) -> f64 {
        0.5 * (self.l_principal * self.l_principal / body.principal_moments()).element_sum()
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
