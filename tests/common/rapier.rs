//! rapier3d-f64 (a dev-dependency) as a second free-body integrator: a world
//! of torque-free bodies with given principal moments, set up from the same
//! (attitude, body-frame angular momentum) states as kreisel's reference
//! trajectories, stepped with rapier's full `PhysicsWorld::step` pipeline on
//! one thread, and read back as glam `DQuat`/`DVec3`.
//!
//! Used by `tests/rapier_cross_check.rs` (`cargo test --test
//! rapier_cross_check -- --nocapture`), `benches/free_body.rs`,
//! `benches/world.rs` and `examples/free_body_work_precision.rs`, which include it with
//! `#[path = "…/common/rapier.rs"] mod rapier;`.
//!
//! What rapier 0.36 does per step of size `dt` (read from its source:
//! `staged_island_solver/worker.rs`, `RigidBodyVelocity::integrate_linearized`,
//! `gyroscopic_corrected_angvel`), with `num_solver_iterations = 4` substeps
//! of `h = dt/4`, for a body without contacts:
//!
//! ```text
//! per substep:  w = R⁻¹ ω_world,  L = I w                         (R = world_from_principal)
//!               L' = (L − h w × L) · |L| / |L − h w × L|           (explicit Euler, |L| kept)
//!               ω_world = R I⁻¹ L'
//!               q ← normalize((1, h ω_world / 2) ⊗ q)               (rotation by 2 atan(|ω|h/2), not |ω|h)
//! ```
//!
//! a first-order method. Set here: unit mass, principal frame = body frame
//! (`MassProperties::with_principal_inertia_frame(…, IDENTITY)` as the only
//! mass, no colliders, so rapier keeps the moments exactly), no gravity, no
//! damping, no sleeping, no CCD (`max_ccd_substeps = 0`), gyroscopic terms on
//! (the default). rapier is built without its `parallel` feature, so the
//! pipeline runs on the calling thread. rapier clamps |ω| to
//! `π/4 / dt` unless fast rotation is allowed; [`RapierBodies::new`] asserts
//! the scenario stays below that, so the clamp never acts.
#![allow(dead_code)]

use kreisel::kinematics::glam::{DQuat, DVec3};
use rapier3d_f64::prelude::{
    MassProperties, PhysicsWorld, Pose, RigidBodyBuilder, RigidBodyHandle, Rotation, Vector,
};

/// Free bodies in one rapier world.
pub struct RapierBodies {
    world: PhysicsWorld,
    handles: Vec<RigidBodyHandle>,
    /// Principal moments of each body.
    moments: Vec<DVec3>,
}

fn to_rapier_vec(v: DVec3) -> Vector {
    Vector::new(v.x, v.y, v.z)
}

fn from_rapier_vec(v: Vector) -> DVec3 {
    DVec3::new(v.x, v.y, v.z)
}

/// glam's quaternions (kreisel's glam and rapier's glamx re-export of an
/// older glam) both store `x, y, z, w` (scalar last): convert component
/// by component, never through a scalar-first array.
fn to_rapier_rot(q: DQuat) -> Rotation {
    Rotation::from_xyzw(q.x, q.y, q.z, q.w)
}

fn from_rapier_rot(q: Rotation) -> DQuat {
    DQuat::from_xyzw(q.x, q.y, q.z, q.w)
}

impl RapierBodies {
    /// A world of `n` bodies with principal moments `moments` (unit mass),
    /// each at attitude `world_from_principal` with body-frame angular
    /// momentum `l_principal`, stepped with `dt`.
    ///
    /// # Panics
    /// If `|ω| dt ≥ π/4` (rapier would clamp ω) or `n = 0`.
    pub fn new(
        moments: DVec3,
        world_from_principal: DQuat,
        l_principal: DVec3,
        dt: f64,
        n: usize,
    ) -> Self {
        assert!(n > 0, "at least one body");
        Self::from_states(&vec![(moments, world_from_principal, l_principal); n], dt)
    }

    /// A world of one body per entry `(moments, world_from_principal,
    /// l_principal)` (unit mass), stepped with `dt`.
    ///
    /// # Panics
    /// If `|ω| dt ≥ π/4` for a body (rapier would clamp ω).
    pub fn from_states(bodies: &[(DVec3, DQuat, DVec3)], dt: f64) -> Self {
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::ZERO;
        world.integration_parameters.dt = dt;
        world.integration_parameters.max_ccd_substeps = 0;
        let handles = bodies
            .iter()
            .enumerate()
            .map(|(i, &(moments, world_from_principal, l_principal))| {
                let omega_principal = l_principal / moments;
                // rapier's per-step clamp (`MAX_ROTATION = π/4` per full step):
                // |ω|² = Σ Lₖ²/Iₖ² ≤ (Σ Lₖ²/Iₖ)/I_min = 2E/I_min all along the motion.
                let omega_max =
                    ((l_principal * omega_principal).element_sum() / moments.min_element()).sqrt();
                assert!(
                    omega_max * dt < std::f64::consts::FRAC_PI_4,
                    "rapier would clamp |ω| at dt = {dt}"
                );
                let mprops = MassProperties::with_principal_inertia_frame(
                    Vector::ZERO,
                    1.0,
                    to_rapier_vec(moments),
                    Rotation::IDENTITY,
                );
                // Spread the bodies out (no colliders, so nothing interacts).
                let translation = Vector::new(3.0 * i as f64, 0.0, 0.0);
                world.insert_body(
                    RigidBodyBuilder::dynamic()
                        .pose(Pose::from_parts(
                            translation,
                            to_rapier_rot(world_from_principal),
                        ))
                        .angvel(to_rapier_vec(world_from_principal * omega_principal))
                        .additional_mass_properties(mprops)
                        .gravity_scale(0.0)
                        .linear_damping(0.0)
                        .angular_damping(0.0)
                        .can_sleep(false)
                        .ccd_enabled(false),
                )
            })
            .collect::<Vec<_>>();
        RapierBodies {
            world,
            handles,
            moments: bodies.iter().map(|b| b.0).collect(),
        }
    }

    /// One body (see [`RapierBodies::new`]).
    pub fn single(
        moments: DVec3,
        world_from_principal: DQuat,
        l_principal: DVec3,
        dt: f64,
    ) -> Self {
        Self::new(moments, world_from_principal, l_principal, dt, 1)
    }

    /// Advances every body by one step of `dt` (the full pipeline).
    pub fn step(&mut self) {
        self.world.step();
    }

    /// Advances every body by `steps` steps.
    pub fn steps(&mut self, steps: usize) {
        for _ in 0..steps {
            self.world.step();
        }
    }

    /// The number of bodies.
    pub fn len(&self) -> usize {
        self.handles.len()
    }

    /// Attitude (`world_from_principal`) of body `i`.
    pub fn attitude(&self, i: usize) -> DQuat {
        from_rapier_rot(*self.world.bodies[self.handles[i]].rotation())
    }

    /// World-frame angular velocity of body `i` (what rapier stores).
    pub fn omega_world(&self, i: usize) -> DVec3 {
        from_rapier_vec(self.world.bodies[self.handles[i]].angvel())
    }

    /// Body-frame (principal-frame) angular velocity of body `i`.
    pub fn omega_principal(&self, i: usize) -> DVec3 {
        self.attitude(i).inverse() * self.omega_world(i)
    }

    /// Body-frame angular momentum `L = I ω` of body `i`.
    pub fn l_principal(&self, i: usize) -> DVec3 {
        self.moments[i] * self.omega_principal(i)
    }

    /// (attitude, body-frame L) of body `i`.
    pub fn state(&self, i: usize) -> (DQuat, DVec3) {
        (self.attitude(i), self.l_principal(i))
    }

    /// The principal moments and principal frame rapier uses for body `i`
    /// (after the first step they come from its mass-property update).
    pub fn rapier_inertia(&self, i: usize) -> (DVec3, DQuat) {
        let m = &self.world.bodies[self.handles[i]]
            .mass_properties()
            .local_mprops;
        (
            from_rapier_vec(m.principal_inertia()),
            from_rapier_rot(m.principal_inertia_local_frame),
        )
    }
}
