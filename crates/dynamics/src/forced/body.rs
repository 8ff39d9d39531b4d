//! A free rigid body under gravity and applied inputs: its parameters, the
//! loads it feels, its mechanical energy and the power of the inputs.

use glam::DVec3;

use kreisel_inertia::MassProperties;

use super::state::check_finite;
use super::{ForcedState, Inputs};
use crate::heavy_top::FreeFlow;
use crate::{DynamicsError, HeavyTop, HeavyTopAuto, PrincipalState, RigidBody};

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
    /// The fixed pivot of a body on one (`None`: a free body).
    anchor: Option<Box<Anchor>>,
}

/// A body's fixed pivot: the heavy top it makes (inertia about the pivot,
/// centre of mass from it, weight) and where the pivot is.
#[derive(Debug, Clone)]
struct Anchor {
    top: HeavyTop,
    pivot_world: DVec3,
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
            anchor: None,
        };
        forced.set_inputs(inputs)?;
        Ok(forced)
    }

    /// A body turning about a fixed pivot under gravity and `inputs` (a
    /// heavy top with applied loads): `pivot_body` is the pivot in body
    /// coordinates (those of `mass_properties`), `pivot_world` where it is
    /// held. The state's angular momentum is about the pivot; its position
    /// and velocity are the centre of mass's, which follow the attitude
    /// ([`ForcedBody::state_on_pivot`]).
    ///
    /// ```text
    /// dL/dt = L × J⁻¹L + τ + c × Rᵀ(F + m g)     (principal axes of J about the pivot)
    /// x = p + R c,   v = ω × R c
    /// ```
    ///
    /// A force at the centre of mass or at a body point turns the body
    /// about the pivot; the pivot takes up the rest. Gravity is kicked
    /// exactly with the other loads, so without inputs this is the
    /// kick–free–kick splitting of [`crate::HeavyTopSplitting`].
    ///
    /// # Errors
    /// The errors of [`HeavyTop::try_new`];
    /// [`DynamicsError::InvalidBodyParameter`] for a non-finite
    /// `pivot_world`; [`DynamicsError::InvalidInput`] as
    /// [`Inputs::validate`].
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{ForcedBody, Inputs, PrincipalState};
    /// use kreisel_inertia::MassProperties;
    /// let top = MassProperties::new(0.5, DVec3::ZERO, glam::DMat3::from_diagonal(DVec3::new(0.02, 0.02, 0.035)));
    /// let motor = Inputs::default().with_torque_body(DVec3::new(0.0, 0.0, 0.002));
    /// let forced = ForcedBody::try_on_pivot(&top, DVec3::new(0.0, 0.0, -0.05), DVec3::ZERO, DVec3::new(0.0, 0.0, -9.81), motor)?;
    /// let s = forced.state_on_pivot(PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 0.0, 0.7) });
    /// // Upright: the centre of mass 5 cm above the pivot, at rest.
    /// assert!((s.position_world - DVec3::new(0.0, 0.0, 0.05)).length() < 1e-15);
    /// assert_eq!(s.velocity_world, DVec3::ZERO);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_on_pivot(
        mass_properties: &MassProperties,
        pivot_body: DVec3,
        pivot_world: DVec3,
        gravity_world: DVec3,
        inputs: Inputs,
    ) -> Result<Self, DynamicsError> {
        check_finite("pivot_world", pivot_world)?;
        let top = HeavyTop::try_new(mass_properties, pivot_body, gravity_world)?;
        let mut forced = Self::try_new(*top.body(), mass_properties.mass, gravity_world, inputs)?;
        forced.anchor = Some(Box::new(Anchor { top, pivot_world }));
        Ok(forced)
    }

    /// The heavy top a body on a pivot makes (`None` for a free body).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{ForcedBody, Inputs, RigidBody};
    /// let body = RigidBody::try_from_principal_moments(DVec3::ONE)?;
    /// assert!(ForcedBody::try_new(body, 1.0, DVec3::ZERO, Inputs::default())?.heavy_top().is_none());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn heavy_top(&self) -> Option<&HeavyTop> {
        self.anchor.as_ref().map(|a| &a.top)
    }

    /// The full state of a body on a pivot in rotational state `rotation`:
    /// the centre of mass where the attitude puts it and its velocity
    /// (a free body's: at the origin, at rest).
    ///
    /// ```text
    /// x = p + R c,   v = (R J⁻¹L) × R c
    /// ```
    ///
    /// (Example: [`ForcedBody::try_on_pivot`].)
    pub fn state_on_pivot(&self, rotation: PrincipalState) -> ForcedState {
        let mut state = ForcedState::at_origin(rotation);
        self.follow_pivot(&mut state);
        state
    }

    /// On a pivot: puts the centre of mass where the attitude says.
    #[inline]
    pub(super) fn follow_pivot(&self, state: &mut ForcedState) {
        if let Some(anchor) = &self.anchor {
            let q = state.rotation.world_from_principal.normalize();
            let arm = q * anchor.top.com_principal();
            let omega_world = q * (state.rotation.l_principal / self.body.principal_moments());
            state.position_world = anchor.pivot_world + arm;
            state.velocity_world = omega_world.cross(arm);
        }
    }

    /// The sub-steps a step of `h` needs to stay stable: those of
    /// [`HeavyTopAuto`] on a pivot, 1 for a free body.
    ///
    /// # Errors
    /// [`DynamicsError::TooManySubsteps`] as [`HeavyTopAuto::try_substeps`].
    pub(crate) fn stable_substeps(
        &self,
        state: &ForcedState,
        h: f64,
    ) -> Result<u32, DynamicsError> {
        match &self.anchor {
            None => Ok(1),
            Some(anchor) => {
                let n = HeavyTopAuto.try_substeps(&anchor.top, &state.rotation, h)?;
                Ok(u32::try_from(n).unwrap_or(u32::MAX))
            }
        }
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
        let mut force = self.force_world;
        if let Some(load) = self.inputs.load.as_ref().filter(|l| !l.reads_velocity()) {
            let (tau, f) = load.eval(t, state);
            world += tau;
            force += f;
        }
        let mut tau = principal_from_world * world + self.torque_principal;
        for (r, f) in &self.points_principal {
            tau += r.cross(principal_from_world * *f);
        }
        if let Some(anchor) = &self.anchor {
            // About the pivot: every force, gravity too, acts at the
            // centre of mass's arm c (a point force's own arm r is above).
            let weight = force + anchor.top.weight_world();
            tau += anchor
                .top
                .com_principal()
                .cross(principal_from_world * weight);
        }
        tau
    }

    /// On a pivot: the torque about the pivot, principal axes, of a force
    /// through the centre of mass (zero for a free body).
    #[inline]
    pub(super) fn pivot_torque_principal(&self, principal_force: DVec3) -> DVec3 {
        self.anchor.as_ref().map_or(DVec3::ZERO, |a| {
            a.top.com_principal().cross(principal_force)
        })
    }

    /// Whether the body turns about a fixed pivot.
    #[inline]
    pub(super) fn is_anchored(&self) -> bool {
        self.anchor.is_some()
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
        // About a pivot, ½ L·J⁻¹L holds the centre of mass's motion too.
        let translation = if self.anchor.is_some() {
            0.0
        } else {
            0.5 * self.mass * state.velocity_world.length_squared()
        };
        state.rotation.energy(&self.body) + translation
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
