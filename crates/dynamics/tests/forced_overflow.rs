//! A forced body whose state stays finite while a quantity its rows report
//! overflows stops with [`Divergence::Overflow`] at the step that made it,
//! never with a row of `inf` (regression: `force = [1e200, 0, 0]` wrote
//! `energy = inf` rows and the run went on).

use glam::DVec3;
use kreisel_dynamics::{Body, Divergence, DynamicsError, Inputs, World};

/// A free body under `inputs`, stepped by `dt` for `steps` steps (or to the
/// first failure): the failure, and the last state's energy and velocity.
fn run(inputs: Inputs, steps: u64) -> (Option<DynamicsError>, f64, f64) {
    let mut world = World::try_new(DVec3::ZERO, 0.1).unwrap();
    let body = Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0))
        .omega_body(DVec3::new(0.1, 1.0, 0.0))
        .try_build()
        .unwrap()
        .with_inputs(inputs)
        .unwrap();
    let id = world.add(body).unwrap();
    let error = world.advance_steps(steps).err();
    let s = world.state(id).unwrap();
    (error, s.energy, s.velocity.length())
}

/// The body index, time and reason of a `BodyFailed`.
fn failure(error: &DynamicsError) -> (usize, f64, Divergence) {
    match error {
        DynamicsError::BodyFailed { body, time, source } => match **source {
            DynamicsError::Diverged { reason, .. } => (*body, *time, reason),
            ref other => panic!("{other}"),
        },
        other => panic!("{other}"),
    }
}

#[test]
fn a_force_whose_kinetic_energy_overflows_stops_the_run() {
    // v = 1e200 t m/s: finite, but ½ m v² = inf from the first step.
    let (error, energy, speed) = run(
        Inputs::default().with_force_world(DVec3::new(1e200, 0.0, 0.0)),
        10,
    );
    let error = error.expect("the run must stop");
    let (body, time, reason) = failure(&error);
    assert_eq!((body, time), (0, 0.1));
    assert_eq!(reason, Divergence::Overflow { quantity: "energy" });
    assert!(
        error.to_string().contains("its energy is no longer finite"),
        "{error}"
    );
    // The body keeps the last state whose rows are finite: the start.
    assert!(energy.is_finite() && speed == 0.0, "{energy} {speed}");
}

#[test]
fn a_torque_whose_rotational_energy_overflows_stops_the_run() {
    // The torque_body = [0, 0, 1e160] and torque = [1e300, 0, 0]:
    // L = 1e159 after one step, ½ L²/I = inf. (The free flow squares L
    // too: its state may go first.)
    for inputs in [
        Inputs::default().with_torque_body(DVec3::new(0.0, 0.0, 1e160)),
        Inputs::default().with_torque_world(DVec3::new(1e300, 0.0, 0.0)),
    ] {
        let (error, energy, _) = run(inputs, 10);
        let (_, time, reason) = failure(&error.expect("the run must stop"));
        assert!(
            matches!(reason, Divergence::Overflow { .. } | Divergence::NonFinite),
            "{reason:?}"
        );
        assert_eq!(time, 0.1);
        assert!(energy.is_finite(), "{energy}");
    }
    // A moderate torque runs on (10 s, |ω| up to 1.3 rad/s).
    let (error, energy, _) = run(
        Inputs::default().with_torque_body(DVec3::new(0.0, 0.0, 0.3)),
        100,
    );
    assert!(error.is_none() && energy.is_finite(), "{error:?}");
}
