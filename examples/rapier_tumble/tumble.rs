//! rapier's Dzhanibekov scenario in rapier3d (`f32`), with and without
//! kreisel's exact rotation, observed the same way: the body-frame angular
//! velocity, |L| and the rotational energy after every step, read from
//! rapier's own (`f32`) state — what a game sees.

use kreisel::kinematics::glam::{DQuat, DVec3};
use kreisel_rapier::{ExactRotation, RapierAdapterError};
use rapier3d::prelude::{MassProperties, PhysicsWorld, RigidBodyBuilder, RigidBodyHandle, Vector};

/// Principal moments of the scenario, kg·m².
pub const MOMENTS: [f32; 3] = [1.0, 2.0, 3.0];
/// Initial angular velocity (body = world axes at t = 0), rad/s.
pub const OMEGA0: [f32; 3] = [0.01, 1.0, 0.0];

/// Who carries the rotation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Engine {
    /// rapier alone (its gyroscopic term on, the default).
    Rapier,
    /// rapier with [`ExactRotation`] managing the body.
    RapierKreisel,
}

/// What one run observed.
#[derive(Debug, Clone)]
pub struct Run {
    /// The times ω₂ (body axes) changed sign, s (linearly interpolated).
    pub sign_changes: Vec<f64>,
    /// |L| and the energy at t = 0.
    pub start: (f64, f64),
    /// The largest relative departure of |L| and of the energy from their
    /// start values over the run (signed: the value of largest magnitude).
    pub worst: (f64, f64),
    /// The relative change of |L| and of the energy at the end.
    pub end: (f64, f64),
}

impl Run {
    /// The period of ω: two flips, i.e. two sign changes of ω₂, averaged
    /// over all the sign changes seen; `None` with fewer than three.
    pub fn period(&self) -> Option<f64> {
        let n = self.sign_changes.len();
        (n >= 3).then(|| 2.0 * (self.sign_changes[n - 1] - self.sign_changes[0]) / (n - 1) as f64)
    }
}

/// The body's state read from rapier: ω in body axes, |L|, energy.
fn observe(world: &PhysicsWorld, handle: RigidBodyHandle) -> (DVec3, f64, f64) {
    let rb = &world.bodies[handle];
    let r = *rb.rotation();
    let q = DQuat::from_xyzw(r.x.into(), r.y.into(), r.z.into(), r.w.into()).normalize();
    let w = rb.angvel();
    let omega_body = q.conjugate() * DVec3::new(w.x.into(), w.y.into(), w.z.into());
    let moments = DVec3::from_array(MOMENTS.map(f64::from));
    let l_body = moments * omega_body;
    (omega_body, l_body.length(), 0.5 * omega_body.dot(l_body))
}

/// Runs the scenario for `duration` seconds in steps of `dt`.
///
/// # Errors
/// What the adapter reports (nothing, for this scenario).
pub fn run(engine: Engine, dt: f32, duration: f64) -> Result<Run, RapierAdapterError> {
    let mut world = PhysicsWorld::new();
    world.gravity = Vector::ZERO;
    world.integration_parameters.dt = dt;
    let props = MassProperties::new(Vector::ZERO, 1.0, Vector::from_array(MOMENTS));
    let body = RigidBodyBuilder::dynamic()
        .additional_mass_properties(props)
        .angvel(Vector::from_array(OMEGA0))
        .can_sleep(false);
    let handle = world.insert_body(body);
    let mut exact = ExactRotation::new();
    if engine == Engine::RapierKreisel {
        exact.manage(&mut world.bodies, &world.colliders, handle)?;
    }
    let (omega0, l0, e0) = observe(&world, handle);
    let mut run = Run {
        sign_changes: Vec::new(),
        start: (l0, e0),
        worst: (0.0, 0.0),
        end: (0.0, 0.0),
    };
    let steps = (duration / f64::from(dt)).round() as u64;
    let mut previous = omega0.y;
    for k in 1..=steps {
        match engine {
            Engine::Rapier => world.step(),
            Engine::RapierKreisel => exact.step_world(&mut world)?,
        }
        let (omega, l, e) = observe(&world, handle);
        if omega.y.signum() != previous.signum() {
            let t1 = k as f64 * f64::from(dt);
            run.sign_changes
                .push(t1 - f64::from(dt) * omega.y / (omega.y - previous));
        }
        previous = omega.y;
        let now = ((l - l0) / l0, (e - e0) / e0);
        if now.0.abs() > run.worst.0.abs() {
            run.worst.0 = now.0;
        }
        if now.1.abs() > run.worst.1.abs() {
            run.worst.1 = now.1;
        }
        run.end = now;
    }
    Ok(run)
}
