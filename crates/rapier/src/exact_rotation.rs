//! [`ExactRotation`]: the adapter that carries managed rapier bodies'
//! torque-free rotation with kreisel's exact flow, in `f64`, around
//! rapier's own step (the splitting is described in the crate docs).

use std::collections::HashMap;

use glam::{DQuat, DVec3};
use kreisel_dynamics::{Body, BodyId, DynamicsError, World};
use kreisel_kinematics::glam033_interop::{dquat_from_quat, dvec3_from_vec3};
use rapier3d::prelude::{ColliderSet, RigidBody, RigidBodyHandle, RigidBodySet, RigidBodyType};

use crate::RapierAdapterError;

/// One managed body: its kreisel twin and what the adapter last saw and
/// wrote on the rapier side.
#[derive(Debug, Clone)]
pub(crate) struct Managed {
    /// The rapier body.
    pub(crate) handle: RigidBodyHandle,
    /// The body's twin in the adapter's [`World`] (body axes = the rapier
    /// body's principal axes of inertia).
    pub(crate) id: BodyId,
    /// Principal axes → rapier's local axes (`principal_inertia_local_frame`).
    pub(crate) local_from_principal: DQuat,
    /// Principal moments, kg·m² (rapier's, in `f64`).
    pub(crate) moments: DVec3,
    /// The rapier mass properties the twin was made from (to notice changes).
    pub(crate) signature: [f32; 8],
    /// The rotation and angular velocity the adapter last wrote (or read),
    /// bit for bit: a different value before a step means someone else set
    /// it. While kreisel carries the body, `written.1` is the angular
    /// velocity rapier's step starts from (world axes).
    pub(crate) written: (rapier3d::math::Rotation, rapier3d::math::Vector),
    /// Who carries the rotation now.
    pub(crate) carrier: Carrier,
    /// The body's own `allow_fast_rotation`, in force while rapier carries
    /// it; while kreisel does, rapier's cap on |ω| dt (which its own
    /// linearised rotation needs and the exact flow does not) is lifted,
    /// so that it does not cut a fast spin.
    pub(crate) fast_rotation: bool,
    /// The second half of the last step's kick (world axes, N·m·s): part of
    /// the body's angular momentum, applied to the twin with the next
    /// step's first half.
    pub(crate) pending: DVec3,
}

/// Who carries a managed body's rotation over the next step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Carrier {
    /// kreisel: the exact torque-free flow, kicked by what rapier's step
    /// did to the angular velocity (torques, damping); rapier's
    /// gyroscopic term is off.
    Kreisel,
    /// rapier alone, gyroscopic term on, while the body touches something
    /// (active contacts or a joint) or sleeps; the `f64` state is
    /// re-synchronised from rapier's when the body is free again.
    Rapier,
}

/// Exact free rotation for a set of rapier bodies: call
/// [`ExactRotation::step_world`] instead of `PhysicsWorld::step` (or
/// [`ExactRotation::before_step`] and [`ExactRotation::after_step`] on
/// either side of `PhysicsPipeline::step`).
///
/// For each managed body the adapter keeps the attitude and the angular
/// momentum in `f64` in a kreisel [`World`] (no gravity: rapier moves the
/// centre of mass). While the body is free (no active contact, no joint,
/// awake) kreisel carries its rotation ([`Carrier::Kreisel`]): rapier's
/// gyroscopic term is off, and after each step of rapier's
///
/// ```text
/// J = R I Rᵀ (ω_after − ω_before)  (what rapier's step did: torques, damping)
/// L ← L + J/2,  (R, L) ← exact torque-free flow over dt,  L ← L + J/2
/// rapier ← R (about rapier's new centre of mass),  ω = R I⁻¹ Rᵀ L   (rounded to f32)
/// ```
///
/// A body on which nothing acted has `Δω = 0` bit for bit and moves along
/// the exact solution, set up once (a few µs to ~50 µs) and evaluated each
/// step. While it touches something rapier carries it alone
/// ([`Carrier::Rapier`], gyroscopic term on); when it is free again the
/// `f64` state is re-synchronised from rapier's. So is it when its
/// rotation or angular velocity was set by someone else between steps.
///
/// ```
/// use kreisel_rapier::ExactRotation;
/// use rapier3d::prelude::*;
/// let mut world = PhysicsWorld::new();
/// world.gravity = Vector::ZERO;
/// // rapier's Dzhanibekov T-handle: I = (1, 2, 3), ω₀ = (0.01, 1, 0).
/// let props = MassProperties::new(Vector::ZERO, 1.0, Vector::new(1.0, 2.0, 3.0));
/// let handle = world.insert_body(
///     RigidBodyBuilder::dynamic().additional_mass_properties(props).angvel(Vector::new(0.01, 1.0, 0.0)),
/// );
/// let mut exact = ExactRotation::new();
/// exact.manage(&mut world.bodies, &world.colliders, handle)?;
/// let start = exact.rotation(handle).unwrap();
/// for _ in 0..600 {
///     exact.step_world(&mut world)?; // or before_step, pipeline.step(…), after_step
/// }
/// // 10 s later L_world and the energy are those of the start, in f64, to rounding.
/// let now = exact.rotation(handle).unwrap();
/// assert!((now.l_world - start.l_world).length() < 1e-13);
/// assert!((now.energy - start.energy).abs() < 1e-13);
/// # Ok::<(), kreisel_rapier::RapierAdapterError>(())
/// ```
#[derive(Debug)]
pub struct ExactRotation {
    pub(crate) world: World,
    /// The managed bodies (released ones swapped out).
    pub(crate) managed: Vec<Managed>,
    /// Where each handle is in `managed`.
    pub(crate) index: HashMap<RigidBodyHandle, usize>,
}

impl Default for ExactRotation {
    fn default() -> Self {
        Self::new()
    }
}

/// The rapier mass properties that define a twin (local centre of mass,
/// inverse mass, inverse principal moments, principal frame).
pub(crate) fn signature(rb: &RigidBody) -> [f32; 8] {
    let m = &rb.mass_properties().local_mprops;
    let (i, f) = (m.inv_principal_inertia, m.principal_inertia_local_frame);
    [m.inv_mass, i.x, i.y, i.z, f.w, f.x, f.y, f.z]
}

/// rapier's name for a body type.
fn kind_name(kind: RigidBodyType) -> &'static str {
    match kind {
        RigidBodyType::Dynamic => "dynamic",
        RigidBodyType::Fixed => "fixed",
        RigidBodyType::KinematicPositionBased => "kinematic (position-based)",
        RigidBodyType::KinematicVelocityBased => "kinematic (velocity-based)",
        _ => "of another kind",
    }
}

impl ExactRotation {
    /// An adapter managing no body yet.
    ///
    /// ```
    /// let exact = kreisel_rapier::ExactRotation::new();
    /// assert_eq!(exact.len(), 0);
    /// ```
    pub fn new() -> Self {
        Self {
            // A world without gravity whose dt is only a default: every
            // step is taken with rapier's dt.
            world: World::try_new(DVec3::ZERO, 1.0 / 60.0)
                .unwrap_or_else(|_| unreachable!("zero gravity and dt = 1/60 are valid")),
            managed: Vec::new(),
            index: HashMap::new(),
        }
    }

    /// Moves the managed bodies' exact solutions on up to `n` threads
    /// ([`World::set_threads`]; default one).
    pub fn set_threads(&mut self, n: std::num::NonZeroUsize) {
        self.world.set_threads(n);
    }

    /// The number of bodies managed.
    pub fn len(&self) -> usize {
        self.managed.len()
    }

    /// `true` when no body is managed.
    pub fn is_empty(&self) -> bool {
        self.managed.is_empty()
    }

    /// Whether `handle` is managed.
    pub fn is_managed(&self, handle: RigidBodyHandle) -> bool {
        self.index.contains_key(&handle)
    }

    /// The kreisel [`World`] holding the managed bodies' rotations (body
    /// axes there are each body's principal axes; its gravity is zero).
    pub fn world(&self) -> &World {
        &self.world
    }

    /// Takes over the free rotation of the dynamic body `handle` from now
    /// on, from its current rotation and angular velocity and its mass
    /// properties (recomputed from `colliders` now), and turns its
    /// gyroscopic term in rapier off (rapier would otherwise apply it a
    /// second time). Managing a managed body again re-synchronises it.
    ///
    /// # Errors
    /// [`RapierAdapterError::UnknownBody`], [`RapierAdapterError::NotDynamic`],
    /// [`RapierAdapterError::RotationLocked`],
    /// [`RapierAdapterError::InvalidMassProperties`] (no mass or inertia, or
    /// moments that violate the triangle inequality),
    /// [`RapierAdapterError::Dynamics`] for a non-finite state. On an error
    /// nothing changes.
    pub fn manage(
        &mut self,
        bodies: &mut RigidBodySet,
        colliders: &ColliderSet,
        handle: RigidBodyHandle,
    ) -> Result<(), RapierAdapterError> {
        let rb = bodies
            .get_mut(handle)
            .ok_or(RapierAdapterError::UnknownBody { handle })?;
        // rapier brings mass properties up to date at the start of its
        // next step; the twin needs them now.
        rb.recompute_mass_properties_from_colliders(colliders);
        let rb = &*rb;
        if rb.body_type() != RigidBodyType::Dynamic {
            return Err(RapierAdapterError::NotDynamic {
                handle,
                kind: kind_name(rb.body_type()),
            });
        }
        if rb.is_rotation_locked().iter().any(|&locked| locked) {
            return Err(RapierAdapterError::RotationLocked { handle });
        }
        let props = &rb.mass_properties().local_mprops;
        let (mass, moments) = (props.mass(), props.principal_inertia());
        let invalid = |reason: String| RapierAdapterError::InvalidMassProperties {
            handle,
            mass,
            moments: moments.to_array(),
            reason,
        };
        if !(mass > 0.0 && mass.is_finite()) || moments.min_element() <= 0.0 {
            return Err(invalid(
                "a managed body needs a positive mass and inertia".into(),
            ));
        }
        let moments = dvec3_from_vec3(moments);
        // rapier's f32 quaternions are unit only to f32 rounding: rotating
        // by one unnormalised would scale ω by |q|².
        let local_from_principal = dquat_from_quat(props.principal_inertia_local_frame).normalize();
        let world_from_principal =
            dquat_from_quat(*rb.rotation()).normalize() * local_from_principal;
        let omega_principal = world_from_principal.conjugate() * dvec3_from_vec3(rb.angvel());
        let body = Body::from_principal_moments(f64::from(mass), moments)
            .world_from_body(world_from_principal)
            .omega_body(omega_principal)
            .try_build()
            .map_err(|e| match e {
                DynamicsError::InvalidBody { .. }
                | DynamicsError::UnphysicalInertia { .. }
                | DynamicsError::InertiaTensor { .. } => invalid(e.to_string()),
                source => RapierAdapterError::Dynamics { handle, source },
            })?;
        let slot = self.index.get(&handle).copied();
        let twin = match slot.map(|k| &self.managed[k]) {
            Some(old) => {
                let (q, w) = (body.world_from_body(), body.omega_body());
                // The same body again: the twin takes the new state.
                self.world
                    .set_rotation(old.id, q, w)
                    .map_err(RapierAdapterError::dynamics(handle))?;
                old.id
            }
            None => self
                .world
                .add(body)
                .map_err(RapierAdapterError::dynamics(handle))?,
        };
        let written = (*rb.rotation(), rb.angvel());
        let managed = Managed {
            handle,
            id: twin,
            local_from_principal,
            moments,
            signature: signature(rb),
            written,
            carrier: Carrier::Kreisel,
            pending: DVec3::ZERO,
            fast_rotation: slot.map_or(rb.is_fast_rotation_allowed(), |k| {
                self.managed[k].fast_rotation
            }),
        };
        match slot {
            Some(k) => self.managed[k] = managed,
            None => {
                self.index.insert(handle, self.managed.len());
                self.managed.push(managed);
            }
        }
        if let Some(rb) = bodies.get_mut(handle) {
            rb.enable_gyroscopic_forces(false);
            rb.set_allow_fast_rotation(true);
        }
        Ok(())
    }

    /// Hands body `handle` back to rapier (its gyroscopic term on again);
    /// `false` if it was not managed. A body removed from the set is
    /// released by the next step.
    pub fn release(&mut self, bodies: &mut RigidBodySet, handle: RigidBodyHandle) -> bool {
        let Some(k) = self.index.remove(&handle) else {
            return false;
        };
        let managed = self.managed.swap_remove(k);
        if let Some(moved) = self.managed.get(k) {
            self.index.insert(moved.handle, k);
        }
        // The twin rests (costs nothing) from now on.
        let _ = self
            .world
            .set_rotation(managed.id, DQuat::IDENTITY, DVec3::ZERO);
        if let Some(rb) = bodies.get_mut(handle) {
            rb.enable_gyroscopic_forces(true);
            rb.set_allow_fast_rotation(managed.fast_rotation);
        }
        true
    }

    /// Who carries body `handle`'s rotation over the next step (`None` if
    /// it is not managed).
    pub fn carrier(&self, handle: RigidBodyHandle) -> Option<Carrier> {
        Some(self.managed[*self.index.get(&handle)?].carrier)
    }

    /// The `f64` rotational state kreisel carries for `handle`: attitude
    /// (rapier's body axes → world), angular velocity and momentum in world
    /// axes, rotational energy; `None` if it is not managed or while rapier
    /// carries it ([`Carrier::Rapier`]: read rapier's body then).
    ///
    /// ```text
    /// L_world = R I Rᵀ ω_world,   E = ½ ω · L
    /// ```
    pub fn rotation(&self, handle: RigidBodyHandle) -> Option<ManagedRotation> {
        let m = &self.managed[*self.index.get(&handle)?];
        if m.carrier != Carrier::Kreisel {
            return None;
        }
        let s = self.world.state(m.id)?;
        let q = s.world_from_body;
        let l_world = s.l_world + m.pending;
        let omega_world = q * ((q.conjugate() * l_world) / m.moments);
        Some(ManagedRotation {
            world_from_body: q * m.local_from_principal.conjugate(),
            omega_world,
            l_world,
            energy: 0.5 * omega_world.dot(l_world),
        })
    }
}

/// The `f64` rotation the adapter keeps for one rapier body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ManagedRotation {
    /// Attitude, rapier's body axes → world.
    pub world_from_body: DQuat,
    /// Angular velocity, world axes, rad/s.
    pub omega_world: DVec3,
    /// Angular momentum about the centre of mass, world axes, kg·m²/s.
    pub l_world: DVec3,
    /// Rotational kinetic energy, J.
    pub energy: f64,
}
