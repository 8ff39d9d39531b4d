//! The state of a free body under applied inputs: rotation about the centre
//! of mass and the motion of the centre of mass.

use glam::{DQuat, DVec3};

use crate::{DynamicsError, PrincipalState, RigidBody};

/// Attitude and angular momentum about the centre of mass (principal frame)
/// with the position and velocity of the centre of mass (world axes).
///
/// ```text
/// q = world_from_principal,   L = l_principal,   ω = I⁻¹ L,   x, v  (world)
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForcedState {
    /// Attitude and angular momentum about the centre of mass.
    pub rotation: PrincipalState,
    /// Position of the centre of mass, world axes, m.
    pub position_world: DVec3,
    /// Velocity of the centre of mass, world axes, m/s.
    pub velocity_world: DVec3,
}

impl ForcedState {
    /// A state from the attitude, the body-axes angular velocity and the
    /// centre of mass's position and velocity.
    ///
    /// ```text
    /// q_wp = q_wb ⊗ q_bp,   L_p = I ω_p
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::InvalidState`] as
    /// [`PrincipalState::try_from_omega_body`];
    /// [`DynamicsError::InvalidBodyParameter`] for a non-finite position or
    /// velocity.
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{ForcedState, RigidBody};
    /// let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0))?;
    /// let s = ForcedState::try_new(&body, DQuat::IDENTITY, DVec3::Y, DVec3::ZERO, DVec3::X)?;
    /// assert_eq!(s.rotation.l_principal, DVec3::new(0.0, 2.0, 0.0));
    /// assert!(ForcedState::try_new(&body, DQuat::IDENTITY, DVec3::Y, DVec3::NAN, DVec3::X).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_new(
        body: &RigidBody,
        world_from_body: DQuat,
        omega_body: DVec3,
        position_world: DVec3,
        velocity_world: DVec3,
    ) -> Result<Self, DynamicsError> {
        let rotation = PrincipalState::try_from_omega_body(body, world_from_body, omega_body)?;
        check_finite("position_world", position_world)?;
        check_finite("velocity_world", velocity_world)?;
        Ok(Self {
            rotation,
            position_world,
            velocity_world,
        })
    }

    /// A body at the origin, at rest, with this rotational state.
    pub fn at_origin(rotation: PrincipalState) -> Self {
        Self {
            rotation,
            position_world: DVec3::ZERO,
            velocity_world: DVec3::ZERO,
        }
    }

    /// Angular velocity in world axes.
    ///
    /// ```text
    /// ω_w = q̂ (I⁻¹ L_p)
    /// ```
    pub fn omega_world(&self, moments: DVec3) -> DVec3 {
        self.rotation.world_from_principal.normalize() * (self.rotation.l_principal / moments)
    }

    /// Whether every number is finite.
    pub fn is_finite(&self) -> bool {
        self.rotation.world_from_principal.is_finite()
            && self.rotation.l_principal.is_finite()
            && self.position_world.is_finite()
            && self.velocity_world.is_finite()
    }
}

/// A typed error unless every component of `v` is finite.
pub(crate) fn check_finite(parameter: &'static str, v: DVec3) -> Result<(), DynamicsError> {
    match v.to_array().into_iter().find(|x| !x.is_finite()) {
        Some(value) => Err(DynamicsError::InvalidBodyParameter {
            parameter,
            value,
            reason: "must be finite",
        }),
        None => Ok(()),
    }
}
