//! A world moved on 1, 2 and 5 threads: the states are bit-identical (each
//! body's arithmetic does not depend on the thread that runs it), and a
//! failed run reports the same first failure (earliest step, then lowest
//! index) and leaves the same states.

use std::num::NonZeroUsize;

use glam::{DQuat, DVec3};
use kreisel_dynamics::{Body, BodyState, DynamicsError, FreeBodyMethod, Inputs, Plan, World};

const GRAVITY: DVec3 = DVec3::new(0.0, 0.0, -9.81);
const DT: f64 = 1e-3;

/// A heavy top, varied by `i`.
fn top(i: usize) -> Body {
    let f = i as f64;
    Body::from_principal_moments(1.0, DVec3::new(0.02, 0.02 + 2e-4 * f, 0.015))
        .world_from_body(DQuat::from_rotation_x(0.1 + 0.01 * f))
        .omega_body(DVec3::new(0.3, 0.1 * f, 40.0 + f))
        .pivot(DVec3::new(0.0, 0.0, -0.1), DVec3::ZERO)
        .try_build()
        .unwrap()
}

/// An asymmetric free body in flight, varied by `i`.
fn free(i: usize) -> Body {
    let f = i as f64;
    Body::from_principal_moments(1.5, DVec3::new(1.0, 2.0 + 0.02 * f, 3.0))
        .world_from_body(DQuat::from_xyzw(0.1, 0.2, 0.3, 0.9).normalize())
        .omega_body(DVec3::new(0.01, 1.0 + 0.1 * f, 0.2))
        .free(DVec3::new(f, 0.0, 0.0), DVec3::new(0.0, 1.0, 5.0))
        .try_build()
        .unwrap()
}

/// A free body under a torque law of time and attitude, `NaN` from time
/// `fails_at` on (never when `fails_at` is infinite).
fn forced(i: usize, fails_at: f64) -> Body {
    let law = move |t: f64, s: &kreisel_dynamics::ForcedState| {
        if t >= fails_at {
            (DVec3::splat(f64::NAN), DVec3::splat(f64::NAN))
        } else {
            let tilt = s.rotation.world_from_principal.x;
            (
                DVec3::new(0.0, 0.0, 0.5),
                DVec3::new(0.1 * t.sin(), tilt, 0.2),
            )
        }
    };
    free(i)
        .with_inputs(Inputs::default().with_torque_body(DVec3::X).with_load(law))
        .unwrap()
}

/// Every bit of a state.
fn bits(s: &BodyState) -> Vec<u64> {
    let q = s.world_from_body;
    [s.time, q.w, q.x, q.y, q.z, s.energy]
        .into_iter()
        .chain(s.omega_body.to_array())
        .chain(s.l_world.to_array())
        .chain(s.position.to_array())
        .chain(s.velocity.to_array())
        .map(f64::to_bits)
        .collect()
}

/// One call that moves a world.
type Call = dyn Fn(&mut World) -> Result<(), DynamicsError>;

/// The world of `bodies` under `method` on `threads` threads, moved by a
/// game loop's steps, whole steps and an `advance_to` off the grid; every
/// state (bits) after each call, or the first error.
fn run(
    bodies: &[Body],
    method: FreeBodyMethod,
    threads: usize,
) -> (Vec<Vec<u64>>, Option<DynamicsError>) {
    let mut world = World::try_new(GRAVITY, DT).unwrap();
    world.set_free_body_method(method).unwrap();
    world.set_threads(NonZeroUsize::new(threads).unwrap());
    let ids: Vec<_> = bodies
        .iter()
        .map(|b| world.add(b.clone()).unwrap())
        .collect();
    let mut states = Vec::new();
    let mut error = None;
    let calls: [&Call; 4] = [
        &|w| w.step(DT),
        &|w| w.step(0.7 * DT),
        &|w| w.advance_steps(120),
        &|w| w.advance_to(0.2537),
    ];
    for call in calls {
        let result = call(&mut world);
        states.extend(ids.iter().map(|&id| bits(&world.state(id).unwrap())));
        if let Err(e) = result {
            error = Some(e);
            break;
        }
    }
    (states, error)
}

/// Heavy tops, asymmetric free bodies and (when the method can move them)
/// forced bodies, interleaved.
fn mixed(with_forced: bool) -> Vec<Body> {
    let mut bodies = Vec::new();
    for i in 0..12 {
        bodies.push(top(i));
        bodies.push(free(i));
        if with_forced {
            bodies.push(forced(i, f64::INFINITY));
        }
    }
    bodies
}

#[test]
fn states_are_bit_identical_on_1_2_and_5_threads() {
    for (method, with_forced) in [(FreeBodyMethod::Auto, true), (FreeBodyMethod::Rk4, false)] {
        let bodies = mixed(with_forced);
        let (one, error) = run(&bodies, method, 1);
        assert!(error.is_none(), "{method}: {error:?}");
        assert_eq!(one.len(), 4 * bodies.len());
        for threads in [2, 5] {
            let (many, error) = run(&bodies, method, threads);
            assert!(error.is_none(), "{method}, {threads} threads: {error:?}");
            assert!(one == many, "{method}: {threads} threads differ from 1");
        }
    }
}

#[test]
fn the_plans_of_the_mixed_world() {
    // The test above covers every kind of motion it claims to.
    let mut world = World::try_new(GRAVITY, DT).unwrap();
    for b in mixed(true) {
        world.add(b).unwrap();
    }
    let plans: Vec<_> = world.plans().map(|(_, p)| *p).collect();
    assert!(plans.iter().any(|p| matches!(p, Plan::HeavyTop(_))));
    assert!(plans.iter().any(|p| matches!(p, Plan::Asymmetric)));
    assert!(plans.iter().any(|p| matches!(p, Plan::Forced { .. })));
}

#[test]
fn the_first_failure_is_the_same_on_any_number_of_threads() {
    // Forced bodies failing at various steps among heavy tops (on 5 threads
    // 9 and 27 are in different chunks): bodies 9 and 27 fail at the same,
    // earliest step; 3, a lower index, one step later; 21 later still. The
    // earliest step wins, then the lowest index: body 9.
    let fails_at = |i: usize| match i {
        3 => 0.0505,
        9 | 27 => 0.0495,
        21 => 0.1,
        _ => f64::INFINITY,
    };
    let bodies: Vec<Body> = (0..36)
        .map(|i| {
            if i % 3 == 0 {
                forced(i, fails_at(i))
            } else {
                top(i)
            }
        })
        .collect();
    let (one, error) = run(&bodies, FreeBodyMethod::Auto, 1);
    let error = error.expect("the NaN loads must stop the world");
    let DynamicsError::BodyFailed { body, time, .. } = &error else {
        panic!("{error}");
    };
    assert_eq!(*body, 9, "{error}");
    // The step that starts at the first grid time ≥ 0.0495 s lands 1 ms later.
    assert!((0.0495..0.0495 + 2.0 * DT).contains(time), "{error}");
    for threads in [2, 5] {
        let (many, other) = run(&bodies, FreeBodyMethod::Auto, threads);
        assert_eq!(
            other.map(|e| e.to_string()),
            Some(error.to_string()),
            "{threads} threads"
        );
        assert!(
            one == many,
            "{threads} threads: states after the failure differ"
        );
    }
}

/// A symmetric free body spinning at ~10²⁰⁰ rad/s about its odd axis,
/// valid, whose closed form overflows (and turns NaN) past t ≈ 1.8e108 s.
fn overflowing_symmetric() -> Body {
    Body::from_principal_moments(1.0, DVec3::new(1e-100, 1.0, 1.0))
        .omega_body(DVec3::new(1e200, 1.0, 0.0))
        .try_build()
        .unwrap()
}

#[test]
fn exact_solutions_are_evaluated_on_the_threads_bit_identically() {
    // 200 exact bodies: 134 asymmetric and symmetric ones evaluated as
    // jobs, enough for 2 threads (134 / 64), and 66 spheres in their batch.
    let exact_bodies = |failing: &[usize]| -> Vec<Body> {
        (0..200)
            .map(|i| {
                if failing.contains(&i) {
                    return overflowing_symmetric();
                }
                let f = i as f64;
                let moments = match i % 3 {
                    0 => DVec3::new(1.0, 2.0 + 0.01 * f, 3.0),
                    1 => DVec3::new(1.0, 1.0, 1.5),
                    _ => DVec3::splat(2.0),
                };
                Body::from_principal_moments(1.0, moments)
                    .world_from_body(DQuat::from_rotation_z(0.01 * f))
                    .omega_body(DVec3::new(0.3, 1.0 + 0.01 * f, 0.2))
                    .try_build()
                    .unwrap()
            })
            .collect()
    };
    let run_to = |bodies: &[Body], threads: usize, times: &[f64]| {
        let mut world = World::try_new(DVec3::ZERO, 1e95).unwrap();
        world.set_threads(NonZeroUsize::new(threads).unwrap());
        let ids: Vec<_> = bodies
            .iter()
            .map(|b| world.add(b.clone()).unwrap())
            .collect();
        let mut states = Vec::new();
        let mut error = None;
        for &t in times {
            let result = world.advance_to(t);
            states.extend(ids.iter().map(|&id| bits(&world.state(id).unwrap())));
            if let Err(e) = result {
                error = Some(e.to_string());
                break;
            }
        }
        (states, error)
    };
    let times = [0.37, 12.5, 1e3, 1e110];
    let calm = exact_bodies(&[]);
    let (one, error) = run_to(&calm, 1, &times[..3]);
    assert!(error.is_none());
    // Bodies 61 and 190 overflow at the last time; on 2 threads they are
    // in different chunks, and the lower index is reported.
    let failing = exact_bodies(&[61, 190]);
    let (one_failing, failure) = run_to(&failing, 1, &times);
    let failure = failure.expect("the overflow must stop the world");
    assert!(failure.starts_with("body 61:"), "{failure}");
    for threads in [2, 5] {
        assert!(
            one == run_to(&calm, threads, &times[..3]).0,
            "{threads} threads"
        );
        let (many, other) = run_to(&failing, threads, &times);
        assert_eq!(other.as_ref(), Some(&failure), "{threads} threads");
        assert!(one_failing == many, "{threads} threads: states differ");
    }
}
