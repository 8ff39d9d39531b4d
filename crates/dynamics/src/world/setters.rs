//! Changing a body's state between steps: its plan is remade from the new
//! state (the exact solution set up again, the checks' reference reset).

use glam::{DQuat, DVec3};

use super::motion::Motion;
use super::{BodyId, Entry, World};
use crate::{DynamicsError, Inputs, PrincipalState};

impl World {
    /// The entry of `id`, or [`DynamicsError::UnknownBody`].
    fn entry(&self, id: BodyId) -> Result<&Entry, DynamicsError> {
        self.entries
            .get(id.0)
            .ok_or(DynamicsError::UnknownBody { index: id.0 })
    }

    /// Sets body `id`'s angular velocity (body axes, rad/s) now, keeping
    /// its attitude; its plan is remade from the new state.
    ///
    /// # Errors
    /// [`DynamicsError::UnknownBody`]; [`DynamicsError::InvalidState`] for
    /// a non-finite or overflowing ω; the plan's set-up errors (for a body
    /// on the table, whose run starts again from the new state: a shape
    /// turned into the table, [`DynamicsError::BodyInsideTable`]; then
    /// nothing changes).
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, Plan, World};
    /// use glam::DVec3;
    /// let mut world = World::try_new(DVec3::ZERO, 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).try_build()?)?;
    /// assert_eq!(world.plan(id), Some(&Plan::Resting));
    /// world.set_omega_body(id, DVec3::new(0.1, 1.0, 0.0))?;
    /// assert_eq!(world.plan(id), Some(&Plan::Asymmetric));
    /// assert!((world.state(id).unwrap().omega_body - DVec3::new(0.1, 1.0, 0.0)).length() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_omega_body(&mut self, id: BodyId, omega_body: DVec3) -> Result<(), DynamicsError> {
        let entry = self.entry(id)?;
        let world_from_body = self.rotation(id.0).world_from_body(&entry.rigid);
        self.set_rotation(id, world_from_body, omega_body)
    }

    /// Sets body `id`'s attitude (body → world; normalised) and angular
    /// velocity (body axes, rad/s) now, together: one new plan (what an
    /// engine adapter does when the engine's state was changed).
    ///
    /// ```text
    /// L_world = R (I ω_body),   R = world_from_body
    /// ```
    ///
    /// # Errors
    /// As [`World::set_omega_body`], and for a zero or non-finite quaternion.
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// use glam::{DQuat, DVec3};
    /// let mut world = World::try_new(DVec3::ZERO, 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).try_build()?)?;
    /// world.set_rotation(id, DQuat::from_rotation_z(1.0), DVec3::Y)?;
    /// let s = world.state(id).unwrap();
    /// assert!((s.l_world - DVec3::new(-2.0 * 1f64.sin(), 2.0 * 1f64.cos(), 0.0)).length() < 1e-15);
    /// assert!(world.set_rotation(id, DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0), DVec3::Y).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_rotation(
        &mut self,
        id: BodyId,
        world_from_body: DQuat,
        omega_body: DVec3,
    ) -> Result<(), DynamicsError> {
        let entry = self.entry(id)?;
        let next = PrincipalState::try_from_omega_body(&entry.rigid, world_from_body, omega_body)?;
        self.replan(id.0, next)
    }

    /// Applies an angular impulse `j_world` (N·m·s, world axes; about the
    /// centre of mass, or about the pivot) to body `id` now: `L_world += J`.
    ///
    /// # Errors
    /// As [`World::set_omega_body`].
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// use glam::DVec3;
    /// let mut world = World::try_new(DVec3::ZERO, 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::Y).try_build()?)?;
    /// world.apply_angular_impulse(id, DVec3::new(0.0, 0.0, 3.0))?;
    /// assert!((world.state(id).unwrap().l_world - DVec3::new(0.0, 2.0, 3.0)).length() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn apply_angular_impulse(
        &mut self,
        id: BodyId,
        j_world: DVec3,
    ) -> Result<(), DynamicsError> {
        if !j_world.is_finite() {
            return Err(DynamicsError::InvalidState {
                reason: "angular impulse is not finite",
            });
        }
        self.entry(id)?;
        let state = self.rotation(id.0);
        let q = state.world_from_principal.normalize();
        let next = PrincipalState {
            world_from_principal: q,
            l_principal: state.l_principal + q.conjugate() * j_world,
        };
        self.replan(id.0, next)
    }

    /// Sets body `id`'s attitude (body → world; normalised) now, keeping
    /// its angular velocity in body axes.
    ///
    /// # Errors
    /// As [`World::set_omega_body`], and for a zero or non-finite quaternion.
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// use glam::{DQuat, DVec3};
    /// let mut world = World::try_new(DVec3::ZERO, 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::Y).try_build()?)?;
    /// world.set_attitude(id, DQuat::from_rotation_z(1.0))?;
    /// assert!((world.state(id).unwrap().l_world - DVec3::new(-2.0 * 1f64.sin(), 2.0 * 1f64.cos(), 0.0)).length() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_attitude(
        &mut self,
        id: BodyId,
        world_from_body: DQuat,
    ) -> Result<(), DynamicsError> {
        let entry = self.entry(id)?;
        let omega_body = self.rotation(id.0).omega_body(&entry.rigid);
        self.set_rotation(id, world_from_body, omega_body)
    }

    /// Sets a free body's centre of mass (m) and its velocity (m/s), world
    /// axes, now: its flight restarts from them. A body on the table
    /// ([`crate::Support::Table`]) starts its run again from them (above
    /// the table or touching it).
    ///
    /// ```text
    /// x(t) = x + v (t − now) + ½ g (t − now)²
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::UnknownBody`]; [`DynamicsError::InvalidBody`] for
    /// a non-finite vector, a body on a pivot (which does not fly) or on
    /// the ground (whose height follows from its attitude);
    /// [`DynamicsError::BodyInsideTable`] for a body on the table put
    /// into it, and the errors of its run's start
    /// ([`crate::TableMotion::try_new`]; then nothing changes).
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// use glam::DVec3;
    /// let mut world = World::try_new(DVec3::new(0.0, 0.0, -10.0), 0.1)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::ONE).try_build()?)?;
    /// world.advance_to(1.0)?;
    /// world.set_centre_of_mass(id, DVec3::ZERO, DVec3::new(0.0, 0.0, 10.0))?; // a blow
    /// world.advance_to(2.0)?;
    /// let s = world.state(id).unwrap();
    /// assert!((s.position - DVec3::new(0.0, 0.0, 5.0)).length() < 1e-14);
    /// assert!(s.velocity.length() < 1e-14);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_centre_of_mass(
        &mut self,
        id: BodyId,
        position: DVec3,
        velocity: DVec3,
    ) -> Result<(), DynamicsError> {
        let entry = self.entry(id)?;
        if matches!(entry.motion, Motion::Table(_)) {
            if !(position.is_finite() && velocity.is_finite()) {
                let field = if position.is_finite() {
                    "velocity"
                } else {
                    "position"
                };
                let reason = "must be finite";
                return Err(DynamicsError::InvalidBody { field, reason });
            }
            return self.move_on_table(id.0, position, velocity);
        }
        let field = if entry.top.is_some() {
            Some((
                "position",
                "cannot be set for a body on a pivot: it does not fly",
            ))
        } else if matches!(entry.motion, Motion::Ground(_)) {
            Some((
                "position",
                "cannot be set for a body on the ground: its height and vertical velocity \
                 follow from its attitude and spin",
            ))
        } else if !position.is_finite() {
            Some(("position", "must be finite"))
        } else if !velocity.is_finite() {
            Some(("velocity", "must be finite"))
        } else {
            None
        };
        if let Some((field, reason)) = field {
            return Err(DynamicsError::InvalidBody { field, reason });
        }
        let now = self.time();
        self.reads[id.0].ballistic = (position, velocity, now);
        if let Motion::Forced(forced) = &mut self.entries[id.0].motion {
            let state = &mut forced.state;
            (state.position_world, state.velocity_world) = (position, velocity);
        }
        Ok(())
    }

    /// Replaces what is applied to body `id` from now on (a controller's
    /// new command, a motor switched on or off); its plan is remade from
    /// its current state: nonzero inputs give [`crate::Plan::Forced`] (on a
    /// pivot [`crate::Plan::DrivenTop`]), inputs all zero the torque-free
    /// plan (on a pivot the heavy top's).
    ///
    /// # Errors
    /// [`DynamicsError::UnknownBody`]; [`DynamicsError::InvalidInput`] as
    /// [`Inputs::validate`]; [`DynamicsError::MethodTakesNoInputs`] when
    /// the world's free-body method (heavy-top method, on a pivot) cannot
    /// move a body with inputs; [`DynamicsError::InvalidBody`] (`"inputs"`)
    /// for inputs not all zero on a body on the table (loads are not
    /// modelled there). On an error nothing changes.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, ForcedSplitting, Inputs, Plan, World};
    /// let mut world = World::try_new(DVec3::ZERO, 0.01)?;
    /// let id = world.add(Body::from_principal_moments(1.0, DVec3::ONE).omega_body(DVec3::Z).try_build()?)?;
    /// assert_eq!(world.plan(id), Some(&Plan::Sphere));
    /// world.set_inputs(id, Inputs::default().with_torque_world(DVec3::Z))?; // a motor on
    /// assert_eq!(world.plan(id), Some(&Plan::Forced { method: ForcedSplitting::DEFAULT }));
    /// world.advance_to(1.0)?;
    /// // L = L₀ + τ t, to the rounding of 900 kicks (2e-14 measured).
    /// let error = (world.state(id).unwrap().l_world - 2.0 * DVec3::Z).length();
    /// assert!(error < 1e-13, "{error:e}");
    /// world.set_inputs(id, Inputs::default())?; // and off
    /// assert_eq!(world.plan(id), Some(&Plan::Sphere));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn set_inputs(&mut self, id: BodyId, inputs: Inputs) -> Result<(), DynamicsError> {
        let entry = self.entry(id)?;
        inputs.validate()?;
        super::body::check_table_inputs(entry.body.support(), &inputs)?;
        if matches!(entry.motion, Motion::Table(_)) {
            // Inputs all zero: nothing changes in the motion.
            self.entries[id.0].body.set_inputs(inputs);
            return Ok(());
        }
        if let Some(super::Entry {
            motion: super::motion::Motion::Ground(ground),
            body,
            ..
        }) = self.entries.get_mut(id.0)
        {
            // The contact model takes the inputs as they are (its RK4 has
            // no splitting to choose); its state stays.
            ground.top = ground.top.clone().try_with_inputs(inputs.clone())?;
            ground.restart_check();
            body.set_inputs(inputs);
            return Ok(());
        }
        let entry = self.entry(id)?;
        if !inputs.is_none() {
            if entry.top.is_some() {
                super::Plan::driven_top_splitting(self.heavy_top_method())?;
            } else {
                super::Plan::forced_splitting(self.free_body_method())?;
            }
        }
        let state = self.rotation(id.0);
        let previous = entry.body.inputs().clone();
        self.entries[id.0].body.set_inputs(inputs);
        let replanned = self.replan(id.0, state);
        if replanned.is_err() {
            self.entries[id.0].body.set_inputs(previous);
        }
        replanned
    }
}
