//! [`ExactRotation`]'s step: who carries each managed body's rotation
//! over rapier's step, the kick and the exact flow, and what is written
//! back.

use glam::DVec3;
use kreisel_dynamics::DynamicsError;
use kreisel_kinematics::glam033_interop::{
    dquat_from_quat, dvec3_from_vec3, quat_from_dquat, vec3_from_dvec3,
};
use rapier3d::math::Pose;
use rapier3d::prelude::{
    ImpulseJointSet, MultibodyJointSet, NarrowPhase, PhysicsWorld, RigidBody, RigidBodyHandle,
    RigidBodySet,
};

use crate::exact_rotation::{Carrier, Managed, signature};
use crate::{ExactRotation, RapierAdapterError};

/// What a managed body touches after rapier's step: its colliders' active
/// contacts (rapier's narrow phase) and the joints attached to it.
#[derive(Clone, Copy)]
pub struct Touching<'a> {
    /// rapier's narrow phase, after its step.
    pub narrow_phase: &'a NarrowPhase,
    /// The impulse joints.
    pub impulse_joints: &'a ImpulseJointSet,
    /// The multibody joints.
    pub multibody_joints: &'a MultibodyJointSet,
}

impl Touching<'_> {
    /// Whether body `handle` has an active contact or a joint.
    fn touches(&self, handle: RigidBodyHandle, rb: &RigidBody) -> bool {
        let contact = rb.colliders().iter().any(|&c| {
            (self.narrow_phase.contact_pairs_with(c)).any(|pair| pair.has_any_active_contact())
        });
        contact
            || self.impulse_joints.attached_joints(handle).next().is_some()
            || self.multibody_joints.rigid_body_link(handle).is_some()
    }
}

impl ExactRotation {
    /// One step of a rapier `PhysicsWorld` (its `step()`, with its
    /// integration parameters' `dt`) between [`ExactRotation::before_step`]
    /// and [`ExactRotation::after_step`].
    ///
    /// # Errors
    /// As [`ExactRotation::before_step`] (then rapier's step is not taken)
    /// and [`ExactRotation::after_step`].
    pub fn step_world(&mut self, world: &mut PhysicsWorld) -> Result<(), RapierAdapterError> {
        let dt = world.integration_parameters.dt;
        // Refused before rapier steps: rapier quarantines bodies on a
        // non-finite dt.
        if !(dt.is_finite() && dt > 0.0) {
            return Err(RapierAdapterError::InvalidStep { dt });
        }
        self.before_step(&mut world.bodies)?;
        world.step();
        let touching = Touching {
            narrow_phase: &world.narrow_phase,
            impulse_joints: &world.impulse_joints,
            multibody_joints: &world.multibody_joints,
        };
        self.after_step(&mut world.bodies, touching, dt)
    }

    /// Before rapier's step: notes each managed body's angular velocity,
    /// and re-synchronises the `f64` state of any body kreisel carries
    /// whose rotation or angular velocity was set since the adapter last
    /// wrote them (a teleport, a velocity set by game code). Bodies no
    /// longer in the set are released.
    ///
    /// # Errors
    /// [`RapierAdapterError::MassPropertiesChanged`] for a body whose mass
    /// properties changed (release and manage it again);
    /// [`RapierAdapterError::Dynamics`] for a non-finite state set by
    /// someone else.
    pub fn before_step(&mut self, bodies: &mut RigidBodySet) -> Result<(), RapierAdapterError> {
        let gone: Vec<RigidBodyHandle> = (self.managed.iter())
            .filter(|m| bodies.get(m.handle).is_none())
            .map(|m| m.handle)
            .collect();
        for handle in gone {
            self.release(bodies, handle);
        }
        for m in &mut self.managed {
            let Some(rb) = bodies.get(m.handle) else {
                continue;
            };
            if signature(rb) != m.signature {
                return Err(RapierAdapterError::MassPropertiesChanged { handle: m.handle });
            }
            let now = (*rb.rotation(), rb.angvel());
            if m.carrier == Carrier::Kreisel && now != m.written {
                take_rapiers(&mut self.world, m, rb, true)?;
                m.pending = DVec3::ZERO;
                m.written = now;
            }
        }
        Ok(())
    }

    /// After rapier's step of `dt` seconds, for each managed body:
    /// - free before and after the step (no active contact, no joint,
    ///   awake, enabled and dynamic): kreisel carries it. Its angular
    ///   momentum is kicked by what rapier's step did to its angular
    ///   velocity (torques, damping: `Δω = 0` bit for bit when nothing
    ///   acted), half before and half after the exact torque-free flow over
    ///   `dt`, and its attitude (about the centre of mass rapier moved to)
    ///   and angular velocity are written back, rounded to `f32`;
    /// - touching something (or asleep, disabled, made kinematic or fixed)
    ///   after the step: rapier carries it,
    ///   its gyroscopic term on, and nothing is written;
    /// - free again after rapier carried it: the `f64` state is
    ///   re-synchronised from rapier's and kreisel carries it from the
    ///   next step on.
    ///
    /// ```text
    /// kreisel:  J = R I Rᵀ (ω_after − ω_before),  L ← L + J/2,  (R, L) ← Φ_dt(R, L),  L ← L + J/2,  ω = R I⁻¹ Rᵀ L
    /// ```
    ///
    /// # Errors
    /// [`RapierAdapterError::InvalidStep`] for a `dt` that is not positive
    /// and finite; [`RapierAdapterError::Dynamics`] for a non-finite
    /// velocity from rapier, or a body whose flow failed.
    pub fn after_step(
        &mut self,
        bodies: &mut RigidBodySet,
        touching: Touching<'_>,
        dt: f32,
    ) -> Result<(), RapierAdapterError> {
        if !(dt.is_finite() && dt > 0.0) {
            return Err(RapierAdapterError::InvalidStep { dt });
        }
        // Who carries each body next; kicks for the bodies kreisel carried
        // through a free step.
        let mut next = Vec::with_capacity(self.managed.len());
        // The second halves of this step's kicks: (body, impulse).
        let mut pending = Vec::new();
        for m in &self.managed {
            let Some(rb) = bodies.get(m.handle) else {
                next.push(m.carrier);
                continue;
            };
            // Disabled, kinematic or fixed bodies are rapier's (or the
            // user's) to move.
            let free = rb.is_enabled()
                && rb.is_dynamic()
                && !rb.is_sleeping()
                && !touching.touches(m.handle, rb);
            next.push(if free {
                Carrier::Kreisel
            } else {
                Carrier::Rapier
            });
            if free && m.carrier == Carrier::Kreisel {
                // Strang: half of this step's kick before the flow (with the
                // half left over from the step before), half after it.
                let mut j_world = m.pending;
                if rb.angvel() != m.written.1 {
                    let d_omega_world = dvec3_from_vec3(rb.angvel()) - dvec3_from_vec3(m.written.1);
                    let Some(s) = self.world.state(m.id) else {
                        continue;
                    };
                    let q = s.world_from_body;
                    let half = 0.5 * (q * (m.moments * (q.conjugate() * d_omega_world)));
                    j_world += half;
                    pending.push((next.len() - 1, half));
                }
                if j_world != DVec3::ZERO {
                    (self.world)
                        .apply_angular_impulse(m.id, j_world)
                        .map_err(RapierAdapterError::dynamics(m.handle))?;
                }
            }
        }
        self.world
            .step(f64::from(dt))
            .map_err(|e| self.failure(e))?;
        for m in &mut self.managed {
            m.pending = DVec3::ZERO;
        }
        for (k, half) in pending {
            self.managed[k].pending = half;
        }
        for (m, next) in self.managed.iter_mut().zip(next) {
            let Some(rb) = bodies.get_mut(m.handle) else {
                continue;
            };
            match (m.carrier, next) {
                (Carrier::Kreisel, Carrier::Kreisel) => write_back(&self.world, m, rb),
                (Carrier::Kreisel, Carrier::Rapier) => {
                    // rapier moved it through this step's contact; the twin
                    // rests (costs nothing) until the body is free again.
                    take_rapiers(&mut self.world, m, rb, false)?;
                    rb.enable_gyroscopic_forces(true);
                    rb.set_allow_fast_rotation(m.fast_rotation);
                }
                (Carrier::Rapier, Carrier::Kreisel) => {
                    rb.enable_gyroscopic_forces(false);
                    rb.set_allow_fast_rotation(true);
                    take_rapiers(&mut self.world, m, rb, true)?;
                }
                (Carrier::Rapier, Carrier::Rapier) => {}
            }
            m.carrier = next;
            m.written = (*rb.rotation(), rb.angvel());
        }
        Ok(())
    }

    /// A failed World step as the adapter's error, naming the rapier body.
    fn failure(&self, error: DynamicsError) -> RapierAdapterError {
        let body = match &error {
            DynamicsError::BodyFailed { body, .. } => Some(*body),
            _ => None,
        };
        let handle = (self.managed.iter())
            .find(|m| Some(m.id.index()) == body)
            .map_or(RigidBodyHandle::invalid(), |m| m.handle);
        RapierAdapterError::Dynamics {
            handle,
            source: error,
        }
    }
}

/// The twin takes rapier's rotation and, if `moving`, its angular
/// velocity (exact: `f32` → `f64`); else it rests there (a plan that costs
/// nothing).
fn take_rapiers(
    world: &mut kreisel_dynamics::World,
    m: &Managed,
    rb: &RigidBody,
    moving: bool,
) -> Result<(), RapierAdapterError> {
    let world_from_principal = dquat_from_quat(*rb.rotation()).normalize() * m.local_from_principal;
    let omega_principal = match moving {
        true => world_from_principal.conjugate() * dvec3_from_vec3(rb.angvel()),
        false => DVec3::ZERO,
    };
    (world.set_rotation(m.id, world_from_principal, omega_principal))
        .map_err(RapierAdapterError::dynamics(m.handle))
}

/// Writes the twin's attitude (turned about the centre of mass rapier moved
/// the body to) and angular velocity into rapier, rounded to `f32`.
fn write_back(world: &kreisel_dynamics::World, m: &Managed, rb: &mut RigidBody) {
    let Some(s) = world.state(m.id) else {
        return;
    };
    let rotation = quat_from_dquat(s.world_from_body * m.local_from_principal.conjugate());
    if rotation != *rb.rotation() {
        let local_com = dvec3_from_vec3(rb.mass_properties().local_mprops.local_com);
        let com_world = dvec3_from_vec3(rb.center_of_mass());
        let translation = com_world - dquat_from_quat(rotation) * local_com;
        rb.set_position(
            Pose::from_parts(vec3_from_dvec3(translation), rotation),
            false,
        );
    }
    // ω from L_world and the half kick still to come.
    let q = s.world_from_body;
    let l_principal = q.conjugate() * (s.l_world + m.pending);
    rb.set_angvel(vec3_from_dvec3(q * (l_principal / m.moments)), false);
}
