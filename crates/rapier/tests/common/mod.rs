//! Helpers shared by kreisel-rapier's integration tests: rapier scenes
//! without gravity, and the independent reference — kreisel_dynamics'
//! `ExactSolution` (checked against 60-digit mpmath data in
//! kreisel-dynamics) started from a rapier body's `f32` state.

#![allow(dead_code)]

use glam::{DQuat, DVec3};
use kreisel_dynamics::{ExactSolution, PrincipalState};
use kreisel_kinematics::glam033_interop::{dquat_from_quat, dvec3_from_vec3};
use kreisel_rapier::ExactRotation;
use rapier3d::prelude::*;

/// A rapier world without gravity.
pub fn free_world() -> PhysicsWorld {
    let mut world = PhysicsWorld::new();
    world.gravity = Vector::ZERO;
    world
}

/// A dynamic body without colliders whose mass properties are given:
/// unit mass, principal `moments` along the axes `frame` (principal →
/// rapier's local axes), centre of mass `com` (local axes). It never
/// sleeps: rapier puts a collider-less body turning slower than 0.5 rad/s
/// to sleep after 0.5 s, and these bodies are for free flight.
pub fn body_with_moments(
    world: &mut PhysicsWorld,
    moments: Vector,
    frame: Rotation,
    com: Vector,
    rotation: Rotation,
    angvel: Vector,
) -> RigidBodyHandle {
    let props = MassProperties::with_principal_inertia_frame(com, 1.0, moments, frame);
    world.insert_body(
        RigidBodyBuilder::dynamic()
            .additional_mass_properties(props)
            .can_sleep(false)
            .rotation(rotation.to_scaled_axis())
            .angvel(angvel),
    )
}

/// The exact torque-free motion from rapier body `rb`'s current `f32`
/// state (converted to `f64` exactly), and the body's principal frame
/// (principal → rapier's local axes).
pub fn exact_from(rb: &RigidBody) -> (ExactSolution, DQuat) {
    let props = &rb.mass_properties().local_mprops;
    let moments = dvec3_from_vec3(props.principal_inertia());
    let local_from_principal = dquat_from_quat(props.principal_inertia_local_frame).normalize();
    let world_from_principal =
        (dquat_from_quat(*rb.rotation()).normalize() * local_from_principal).normalize();
    let omega_principal = world_from_principal.conjugate() * dvec3_from_vec3(rb.angvel());
    let state = PrincipalState {
        world_from_principal,
        l_principal: moments * omega_principal,
    };
    let exact = ExactSolution::try_new(moments, state).expect("a physical body");
    (exact, local_from_principal)
}

/// The attitude (rapier's body axes → world) of the exact motion at `t`.
pub fn exact_attitude(exact: &ExactSolution, local_from_principal: DQuat, t: f64) -> DQuat {
    exact.state_at(t).world_from_principal * local_from_principal.conjugate()
}

/// Angle of the rotation between two attitudes, rad.
pub fn angle(a: DQuat, b: DQuat) -> f64 {
    kreisel_kinematics::rotation_angle_between(a.normalize(), b.normalize())
}

/// A rapier body's attitude in `f64` (exact conversion, normalised).
pub fn attitude(rb: &RigidBody) -> DQuat {
    dquat_from_quat(*rb.rotation()).normalize()
}

/// A rapier vector in `f64`, exactly.
pub fn d(v: Vector) -> DVec3 {
    dvec3_from_vec3(v)
}

/// The angular momentum of rapier body `rb` about its centre of mass,
/// world axes, from its `f32` state in `f64`.
pub fn l_world(rb: &RigidBody) -> DVec3 {
    let props = &rb.mass_properties().local_mprops;
    let q = (attitude(rb) * dquat_from_quat(props.principal_inertia_local_frame)).normalize();
    let moments = dvec3_from_vec3(props.principal_inertia());
    q * (moments * (q.conjugate() * d(rb.angvel())))
}

/// The exact torque-free motion from the adapter's own `f64` state `now`
/// of rapier body `rb` (whose mass properties give the moments and the
/// principal frame).
pub fn exact_from_managed(
    rb: &RigidBody,
    now: &kreisel_rapier::ManagedRotation,
) -> (ExactSolution, DQuat) {
    let props = &rb.mass_properties().local_mprops;
    let moments = dvec3_from_vec3(props.principal_inertia());
    let local_from_principal = dquat_from_quat(props.principal_inertia_local_frame).normalize();
    let world_from_principal = (now.world_from_body * local_from_principal).normalize();
    let state = PrincipalState {
        world_from_principal,
        l_principal: world_from_principal.conjugate() * now.l_world,
    };
    let exact = ExactSolution::try_new(moments, state).expect("a physical body");
    (exact, local_from_principal)
}

/// An asymmetric body, principal axes tilted against rapier's local axes,
/// centre of mass off the origin, tumbling.
pub fn tumbling_body(world: &mut PhysicsWorld) -> RigidBodyHandle {
    body_with_moments(
        world,
        Vector::new(0.2, 0.45, 0.6),
        Rotation::from_scaled_axis(Vector::new(0.3, -0.2, 0.5)),
        Vector::new(0.1, -0.05, 0.2),
        Rotation::from_scaled_axis(Vector::new(-0.4, 1.1, 0.2)),
        Vector::new(0.4, 2.5, -0.3),
    )
}

/// An adapter managing body `handle` of `world`.
pub fn managed(world: &mut PhysicsWorld, handle: RigidBodyHandle) -> ExactRotation {
    let mut exact = ExactRotation::new();
    exact
        .manage(&mut world.bodies, &world.colliders, handle)
        .unwrap();
    exact
}
