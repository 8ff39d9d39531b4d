//! A free rigid body under gravity and applied inputs: its parameters, the
//! loads it feels, its mechanical energy and the power of the inputs.

use glam::DVec3;

use super::state::check_finite;
use super::{ForcedState, Inputs};
use crate::heavy_top::FreeFlow;
use crate::{DynamicsError, RigidBody};

/// A free rigid body (no pivot) under uniform gravity and applied
/// [`Inputs`], as the forced splittings advance it.
///
/// ```text
/// L̇_world = τ(t, s),   q̇ = ½ q ⊗ (0, ω),   ω = I⁻¹ L
/// ẋ = v,   m v̇ = F(t, s) + m g
/// ```
/// Gravity acts at the centre of mass: it moves it and exerts no torque
/// about it.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{ForcedBody, ForcedState, Inputs, RigidBody};
/// let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0))?;
/// let inputs = Inputs::default().with_torque_world(DVec3::Z).with_angular_damping(0.5);
/// let forced = ForcedBody::try_new(body, 2.0, DVec3::new(0.0, 0.0, -9.81), inputs)?;
/// let s = ForcedState::try_new(&body, DQuat::IDENTITY, DVec3::Z, DVec3::ZERO, DVec3::X)?;
/// // ω = e_z: power τ·ω − c|ω|² = 1 − 0.5; energy 3/2 + ½ 2 · 1.
/// assert!((forced.power(0.0, &s) - 0.5).abs() < 1e-15);
/// assert!((forced.mechanical_energy(&s) - 2.5).abs() < 1e-15);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone)]
pub struct ForcedBody {
    body: RigidBody,
    mass: f64,
    gravity_world: DVec3,
    inputs: Inputs,
    /// `τ_body` in principal axes.
    torque_principal: DVec3,
    /// The point forces: point in principal axes, force in world axes.
    points_principal: Vec<(DVec3, DVec3)>,
    /// `F_w + Σ Fₖ`, N.
    force_world: DVec3,
    /// `k = c / I` per principal axis, 1/s.
    decay: DVec3,
    pub(super) free: FreeFlow,
}

impl ForcedBody {
    /// A body with rotational inertia `body`, mass `mass` (kg), gravity
    /// `gravity_world` (m/s²) and applied `inputs`.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidBodyParameter`] for a mass that is not
    /// positive and finite or a non-finite gravity;
    /// [`DynamicsError::InvalidInput`] as [`Inputs::validate`].
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{ForcedBody, Inputs, RigidBody};
    /// let body = RigidBody::try_from_principal_moments(DVec3::ONE)?;
    /// assert!(ForcedBody::try_new(body, 0.0, DVec3::ZERO, Inputs::default()).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_new(
        body: RigidBody,
        mass: f64,
        gravity_world: DVec3,
        inputs: Inputs,
    ) -> Result<Self, DynamicsError> {
        if !(mass.is_finite() && mass > 0.0) {
            return Err(DynamicsError::InvalidBodyParameter {
                parameter: "mass",
                value: mass,
                reason: "must be positive and finite",
            });
        }
        check_finite("gravity_world", gravity_world)?;
        let mut forced = Self {
            body,
            mass,
            gravity_world,
            inputs: Inputs::default(),
            torque_principal: DVec3::ZERO,
            points_principal: Vec::new(),
            force_world: DVec3::ZERO,
            decay: DVec3::ZERO,
            free: FreeFlow::for_moments(body.principal_moments()),
        };
        forced.set_inputs(inputs)?;
        Ok(forced)
    }

    /// Replaces the applied inputs (between steps: a controller's new
    /// command), keeping the body's prepared free flow.
    ///
    /// # Errors
    /// As [`Inputs::validate`]; the inputs are then unchanged.
    pub fn set_inputs(&mut self, inputs: Inputs) -> Result<(), DynamicsError> {
        inputs.validate()?;
        let principal_from_body = self.body.body_from_principal().conjugate();
        self.torque_principal = principal_from_body * inputs.torque_body;
        self.points_principal = inputs
            .point_forces
            .iter()
            .map(|p| (principal_from_body * p.point_body, p.force_world))
            .collect();
        self.force_world = inputs.force_world
            + inputs
                .point_forces
                .iter()
                .map(|p| p.force_world)
                .sum::<DVec3>();
        self.decay = inputs.angular_damping / self.body.principal_moments();
        self.inputs = inputs;
        Ok(())
    }

    /// The rotational inertia about the centre of mass.
    pub fn body(&self) -> &RigidBody {
        &self.body
    }

    /// The mass, kg.
    pub fn mass(&self) -> f64 {
        self.mass
    }

    /// Gravity, world axes, m/s².
    pub fn gravity_world(&self) -> DVec3 {
        self.gravity_world
    }

    /// The applied inputs.
    pub fn inputs(&self) -> &Inputs {
        &self.inputs
    }

    /// Whether the free flow is exact (two equal moments) rather than PDMV10.
    pub fn free_flow_is_exact(&self) -> bool {
        matches!(self.free, FreeFlow::Symmetric { .. })
    }

    /// The torque about the centre of mass in principal axes from the
    /// constant inputs and a law that reads no velocity, at attitude
    /// `state.rotation` (damping excluded).
    ///
    /// ```text
    /// τ_p = Rᵀ(τ_w + τ_law) + τ_bp + Σ r_pk × (Rᵀ Fₖ)
    /// ```
    pub(super) fn configuration_torque_principal(&self, t: f64, state: &ForcedState) -> DVec3 {
        let principal_from_world = state.rotation.world_from_principal.normalize().conjugate();
        let mut world = self.inputs.torque_world;
        if let Some(load) = self.inputs.load.as_ref().filter(|l| !l.reads_velocity()) {
            world += load.eval(t, state).0;
        }
        let mut tau = principal_from_world * world + self.torque_principal;
        for (r, f) in &self.points_principal {
            tau += r.cross(principal_from_world * *f);
        }
        tau
    }

    /// The constant force through the centre of mass (point forces
    /// included) plus a law's force when it reads no velocity, N.
    pub(super) fn configuration_force_world(&self, t: f64, state: &ForcedState) -> DVec3 {
        match self.inputs.load.as_ref().filter(|l| !l.reads_velocity()) {
            Some(load) => self.force_world + load.eval(t, state).1,
            None => self.force_world,
        }
    }

    /// `c / I` per principal axis.
    pub(super) fn decay(&self) -> DVec3 {
        self.decay
    }

    /// Every applied torque and force at `(t, state)`, world axes: the
    /// constant inputs, the point forces, damping and the law (gravity
    /// excluded: it is in the potential energy).
    ///
    /// ```text
    /// τ = τ_w + R τ_b + Σ (R rₖ) × Fₖ − c ω_w + τ_law,   F = F_w + Σ Fₖ + F_law
    /// ```
    pub fn applied_world(&self, t: f64, state: &ForcedState) -> (DVec3, DVec3) {
        let q = state.rotation.world_from_principal.normalize();
        let mut torque = self.inputs.torque_world + q * self.torque_principal;
        for (r, f) in &self.points_principal {
            torque += (q * *r).cross(*f);
        }
        torque -= self.inputs.angular_damping * state.omega_world(self.body.principal_moments());
        let mut force = self.force_world;
        if let Some(load) = &self.inputs.load {
            let (tau, f) = load.eval(t, state);
            torque += tau;
            force += f;
        }
        (torque, force)
    }

    /// The power of the applied inputs (damping included, gravity not):
    /// the rate of change of the mechanical energy.
    ///
    /// ```text
    /// P = τ·ω_w + F·v = dE/dt
    /// ```
    pub fn power(&self, t: f64, state: &ForcedState) -> f64 {
        let (torque, force) = self.applied_world(t, state);
        torque.dot(state.omega_world(self.body.principal_moments()))
            + force.dot(state.velocity_world)
    }

    /// The mechanical energy: rotation, translation and gravity's potential
    /// (zero at the world origin). Its change is the work of the inputs, a
    /// diagnostic of a run, not a conserved quantity.
    ///
    /// ```text
    /// E = ½ Σ Lₖ²/Iₖ + ½ m |v|² − m g·x
    /// ```
    pub fn mechanical_energy(&self, state: &ForcedState) -> f64 {
        state.rotation.energy(&self.body) + 0.5 * self.mass * state.velocity_world.length_squared()
            - self.mass * self.gravity_world.dot(state.position_world)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Bodies can be stepped on threads: the body, its inputs (laws
    /// included) and its state are `Send + Sync`.
    #[test]
    fn bodies_cross_threads() {
        fn send_sync<T: Send + Sync>() {}
        send_sync::<ForcedBody>();
        send_sync::<Inputs>();
        send_sync::<ForcedState>();
    }

    #[test]
    fn bad_parameters_are_refused() {
        let body = RigidBody::try_from_principal_moments(DVec3::ONE).unwrap();
        let e = ForcedBody::try_new(body, f64::NAN, DVec3::ZERO, Inputs::default()).unwrap_err();
        assert!(matches!(
            e,
            DynamicsError::InvalidBodyParameter {
                parameter: "mass",
                ..
            }
        ));
        let e = ForcedBody::try_new(
            body,
            1.0,
            DVec3::new(0.0, f64::INFINITY, 0.0),
            Inputs::default(),
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "free body: gravity_world = inf: must be finite"
        );
        let mut forced = ForcedBody::try_new(body, 1.0, DVec3::ZERO, Inputs::default()).unwrap();
        assert!(
            forced
                .set_inputs(Inputs::default().with_angular_damping(-0.1))
                .is_err()
        );
        assert!(forced.inputs().is_none());
    }
}
