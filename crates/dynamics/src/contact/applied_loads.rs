//! Torques and forces applied to a body on the ground besides gravity and
//! the contact: the crate's [`Inputs`] (constant torques and forces, forces
//! at body points, angular damping, a user law of time and state), read
//! on a [`GroundTopState`].

use std::sync::Arc;

use glam::{DQuat, DVec3};

use super::{GroundTop, GroundTopState};
use crate::{DynamicsError, ForcedBody, ForcedState, Inputs, PrincipalState, RigidBody};

/// The inputs of a ground top with what evaluating them needs: the
/// principal frame (the user law reads a [`ForcedState`]).
#[derive(Debug, Clone)]
pub(crate) struct AppliedLoads {
    forced: Arc<ForcedBody>,
    body_from_principal: DQuat,
}

impl PartialEq for AppliedLoads {
    /// The same loads object (a user law cannot be compared).
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.forced, &other.forced)
    }
}

impl AppliedLoads {
    /// The loads of `inputs` on a body of `mass` kg with inertia
    /// `inertia_body` (about its centre of mass, body axes) under gravity
    /// `g` along −z; `None` for no inputs.
    ///
    /// # Errors
    /// [`Inputs::validate`]'s, [`RigidBody::try_from_inertia_tensor`]'s
    /// and [`ForcedBody::try_new`]'s.
    pub(crate) fn try_new(
        inertia_body: glam::DMat3,
        mass: f64,
        gravity: f64,
        inputs: Inputs,
    ) -> Result<Option<Self>, DynamicsError> {
        inputs.validate()?;
        if inputs.is_none() {
            return Ok(None);
        }
        let body = RigidBody::try_from_inertia_tensor(inertia_body)?;
        let forced = ForcedBody::try_new(body, mass, DVec3::new(0.0, 0.0, -gravity), inputs)?;
        Ok(Some(Self {
            forced: Arc::new(forced),
            body_from_principal: body.body_from_principal(),
        }))
    }

    /// The inputs these loads come from.
    pub(crate) fn inputs(&self) -> &Inputs {
        self.forced.inputs()
    }

    /// Torque about the centre of mass and force through it, world axes,
    /// at `(t, state)`.
    pub(crate) fn at(&self, t: f64, state: &GroundTopState) -> (DVec3, DVec3) {
        let world_from_principal = state.world_from_body.normalize() * self.body_from_principal;
        let forced_state = ForcedState {
            rotation: PrincipalState {
                world_from_principal,
                l_principal: world_from_principal.conjugate() * state.l_world,
            },
            position_world: state.com_world,
            velocity_world: state.velocity_world,
        };
        self.forced.applied_world(t, &forced_state)
    }
}

impl GroundTop {
    /// The same body with `inputs` applied besides gravity and the contact
    /// force: torques and forces in world or body axes, forces at body
    /// points, angular damping `−c ω`, a user law `(t, state) ↦ (τ, F)`
    /// (it reads the state as a [`ForcedState`]: principal frame, `L` about
    /// the centre of mass). They enter the equations as
    ///
    /// ```text
    /// m v̇_G = N e + F − m g ẑ,   L̇ = ρ × N e + τ
    /// N = [g − F_z/m − ((I_w⁻¹ (L × ω + τ)) × ρ)_z − (ω × ρ̇)_z] / κ
    /// rolling:  b = g ẑ − F/m + ρ × (I_w⁻¹ (L × ω + τ)) − ω × ρ̇
    /// ```
    ///
    /// (module docs, [`crate::contact`]): the contact force is solved with
    /// the loads included, so a load that lifts the body is a lift-off
    /// like any other. The energy [`GroundTop::energy`] then changes by
    /// the inputs' power as well ([`GroundTop::input_power`]), and a torque
    /// breaks Jellett's integral. `Inputs::default()` (nothing applied)
    /// removes them.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidInput`] as [`Inputs::validate`].
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec2, DVec3};
    /// use kreisel_dynamics::{Friction, GroundTop, Inputs, SphereContact};
    /// // A ball pushed sideways through its centre, no friction: it slides
    /// // at F/m while the normal force still carries its weight.
    /// let ball = SphereContact::try_new(0.1, DVec3::ZERO)?;
    /// let i = DMat3::from_diagonal(DVec3::splat(0.004));
    /// let push = Inputs::default().with_force_world(DVec3::new(2.0, 0.0, 0.0));
    /// let top = GroundTop::try_new(1.0, i, ball, Friction::None, 9.81)?.try_with_inputs(push)?;
    /// let mut s = top.try_state_on_ground(DQuat::IDENTITY, DVec3::ZERO, DVec2::ZERO)?;
    /// top.try_advance(&mut s, 0.0, 0.01, 100, |_, _| {})?;
    /// assert!((s.com_world.x - 0.5 * 2.0 * 1.0).abs() < 1e-12);
    /// assert!((top.normal_force(&s)? - 9.81).abs() < 1e-12);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_with_inputs(self, inputs: Inputs) -> Result<Self, DynamicsError> {
        let mut top = self;
        top.loads = AppliedLoads::try_new(top.inertia_body(), top.mass(), top.gravity(), inputs)?;
        Ok(top)
    }

    /// The applied inputs (`None`: nothing but gravity and the contact).
    pub fn inputs(&self) -> Option<&Inputs> {
        self.loads.as_ref().map(AppliedLoads::inputs)
    }

    /// The applied torque about the centre of mass and force through it at
    /// `(t, state)`, world axes (zero without inputs):
    ///
    /// ```text
    /// τ = τ_w + A τ_b + Σ (A rₖ) × Fₖ − c ω + τ_law,   F = F_w + Σ Fₖ + F_law
    /// ```
    pub fn applied_world(&self, t: f64, state: &GroundTopState) -> (DVec3, DVec3) {
        match &self.loads {
            Some(loads) => loads.at(t, state),
            None => (DVec3::ZERO, DVec3::ZERO),
        }
    }

    /// The power of the applied inputs, `P = τ·ω + F·v_G`, W: with the
    /// contact force's power (`N f·v_P`, zero when rolling or frictionless)
    /// the rate of change of [`GroundTop::energy`].
    pub fn input_power(&self, t: f64, state: &GroundTopState) -> f64 {
        let (torque, force) = self.applied_world(t, state);
        torque.dot(self.omega_world(state)) + force.dot(state.velocity_world)
    }
}
