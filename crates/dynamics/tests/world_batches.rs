//! How the World moves its bodies in batches: uniform rotations (spheres,
//! principal spins) evaluated together in one structure of arrays, resting
//! bodies left out of the per-step loop, reads from a compact table. Every
//! state must be bit for bit what the exact propagator gives the body on
//! its own, however the batch is reshuffled by setters, and the checks and
//! refusals must be those of the exact solution.

use glam::{DQuat, DVec3};
use kreisel_dynamics::{
    Body, BodyId, Divergence, DynamicsError, ExactSolution, FreeBodyMethod, Plan, PrincipalState,
    Propagator, World,
};
use kreisel_kinematics::rotation_angle_between;

mod common;
use common::initial;

const H: f64 = 1.0 / 60.0;

fn body(moments: DVec3, attitude: DQuat, omega_body: DVec3) -> Body {
    Body::from_principal_moments(2.0, moments)
        .world_from_body(attitude)
        .omega_body(omega_body)
        .free(DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.5, 0.0, 4.0))
        .try_build()
        .unwrap()
}

/// Spheres, principal spins, a symmetric, an asymmetric and a resting body,
/// interleaved.
fn mixed() -> Vec<(Body, Plan)> {
    let tilt = |k: f64| DQuat::from_axis_angle(DVec3::new(1.0, k, 0.5).normalize(), 0.3 * k);
    let asym = DVec3::new(1.0, 2.0, 3.0);
    vec![
        (
            body(DVec3::splat(2.0), tilt(1.0), DVec3::new(0.3, 1.0, -0.2)),
            Plan::Sphere,
        ),
        (
            body(asym, tilt(2.0), DVec3::new(0.0, 0.0, 4.0)),
            Plan::PrincipalSpin { axis: 2 },
        ),
        (body(asym, tilt(3.0), DVec3::ZERO), Plan::Resting),
        (
            body(DVec3::splat(0.5), tilt(4.0), DVec3::new(10.0, 0.0, 0.0)),
            Plan::Sphere,
        ),
        (
            body(asym, tilt(5.0), DVec3::new(0.01, 1.0, 0.0)),
            Plan::Asymmetric,
        ),
        (
            body(
                DVec3::new(1.0, 1.0, 1.5),
                tilt(6.0),
                DVec3::new(0.3, 0.0, 1.0),
            ),
            Plan::Symmetric { axis: 2 },
        ),
        (
            body(DVec3::splat(3.0), tilt(7.0), DVec3::new(-1.0, 0.5, 2.0)),
            Plan::Sphere,
        ),
    ]
}

/// The world's reading of body `id` equals the propagator's state, bit for bit.
fn assert_same(world: &World, id: BodyId, body: &Body, r: &PrincipalState, frame: usize) {
    let s = world.state(id).unwrap();
    let rigid = body.rigid_body();
    assert_eq!(
        (s.world_from_body, s.omega_body, s.l_world),
        (r.world_from_body(rigid), r.omega_body(rigid), r.l_world()),
        "body {} frame {frame}",
        id.index()
    );
}

#[test]
fn every_body_equals_its_exact_propagator_bit_for_bit_while_the_batch_is_reshuffled() {
    let bodies = mixed();
    let g = DVec3::new(0.0, 0.0, -9.81);
    let mut world = World::try_new(g, 0.01).unwrap();
    let exact = FreeBodyMethod::Exact.integrator();
    let mut references: Vec<Option<Box<dyn Propagator>>> = Vec::new();
    let mut ids = Vec::new();
    for (b, plan) in &bodies {
        let id = world.add(b.clone()).unwrap();
        assert_eq!(world.plan(id), Some(plan));
        ids.push(id);
        let moments = b.rigid_body().principal_moments();
        references.push(Some(exact.propagator(moments, initial(b))));
    }
    // Body 0 (the first sphere, slot 0 of the batch) comes to rest at
    // frame 40, so the last sphere moves into its slot; body 1 (a spin) is
    // knocked off its axis at frame 60 and leaves the batch; body 0 spins
    // again at frame 80 and re-enters it last. The others must not notice.
    let mut restarts: Vec<(usize, usize, ExactSolution)> = Vec::new();
    for frame in 1..=120 {
        world.step(H).unwrap();
        for (k, r) in references.iter_mut().enumerate() {
            if let Some(r) = r {
                r.advance(H);
                assert_same(&world, ids[k], &bodies[k].0, &r.state(), frame);
            }
        }
        for &(k, since, ref solution) in &restarts {
            let s = world.state(ids[k]).unwrap();
            let e = solution.state_at((frame - since) as f64 * H);
            let a = rotation_angle_between(
                s.world_from_body,
                e.world_from_body(bodies[k].0.rigid_body()),
            );
            assert!(a < 1e-14, "body {k} frame {frame}: {a:e}");
        }
        let mut restart = |world: &mut World, k: usize, restarts: &mut Vec<_>| {
            references[k] = None;
            restarts.retain(|r: &(usize, usize, ExactSolution)| r.0 != k);
            let s = world.state(ids[k]).unwrap();
            let state = PrincipalState::try_from_omega_body(
                bodies[k].0.rigid_body(),
                s.world_from_body,
                s.omega_body,
            )
            .unwrap();
            let moments = bodies[k].0.rigid_body().principal_moments();
            restarts.push((k, frame, ExactSolution::try_new(moments, state).unwrap()));
        };
        match frame {
            40 => {
                world.set_omega_body(ids[0], DVec3::ZERO).unwrap();
                assert_eq!(world.plan(ids[0]), Some(&Plan::Resting));
                restart(&mut world, 0, &mut restarts);
            }
            60 => {
                world
                    .apply_angular_impulse(ids[1], DVec3::new(0.5, 0.0, 0.0))
                    .unwrap();
                assert_eq!(world.plan(ids[1]), Some(&Plan::Asymmetric));
                restart(&mut world, 1, &mut restarts);
            }
            80 => {
                world
                    .set_omega_body(ids[0], DVec3::new(0.0, 2.0, 1.0))
                    .unwrap();
                assert_eq!(world.plan(ids[0]), Some(&Plan::Sphere));
                restart(&mut world, 0, &mut restarts);
            }
            _ => {}
        }
        // Batch reads give what `state` gives.
        let attitudes: Vec<DQuat> = world.attitudes().collect();
        for (id, s) in world.states() {
            assert_eq!(Some(s), world.state(id));
            assert_eq!(attitudes[id.index()], s.world_from_body);
        }
    }
    // The centre of mass flew in closed form all along, and the energy
    // read is the rotational energy plus the translational one.
    let t = world.time();
    for (k, (b, _)) in bodies.iter().enumerate() {
        let s = world.state(ids[k]).unwrap();
        let x = DVec3::new(1.0, 2.0, 3.0) + DVec3::new(0.5, 0.0, 4.0) * t + 0.5 * g * t * t;
        assert!((s.position - x).length() < 1e-13, "body {k}");
        let rotational = 0.5
            * s.omega_body
                .dot(b.rigid_body().principal_moments() * s.omega_body);
        let expected = rotational + 0.5 * 2.0 * s.velocity.length_squared() - 2.0 * g.dot(x);
        assert!((s.energy - expected).abs() < 1e-12, "body {k}");
    }
}

#[test]
fn a_resting_body_reports_its_given_state_until_the_world_moves() {
    let attitude = DQuat::from_xyzw(0.1, 0.2, 0.3, 0.9);
    let b = body(DVec3::new(1.0, 2.0, 3.0), attitude, DVec3::ZERO);
    let given = initial(&b);
    let settled = ExactSolution::try_new(DVec3::new(1.0, 2.0, 3.0), given)
        .unwrap()
        .state_at(0.0);
    let rigid = *b.rigid_body();
    let mut world = World::try_new(DVec3::ZERO, 0.1).unwrap();
    let id = world.add(b).unwrap();
    assert_eq!(world.plan(id), Some(&Plan::Resting));
    let q = |w: &World| w.state(id).unwrap().world_from_body;
    assert_eq!(q(&world), given.world_from_body(&rigid));
    world.step(0.1).unwrap();
    assert_eq!(q(&world), settled.world_from_body(&rigid));
    world.advance_to(1e6).unwrap();
    assert_eq!(q(&world), settled.world_from_body(&rigid));
    // A new attitude is reported as given, then as the exact solution's.
    let turned = DQuat::from_rotation_y(0.7);
    world.set_attitude(id, turned).unwrap();
    let given = PrincipalState::try_from_omega_body(&rigid, turned, DVec3::ZERO).unwrap();
    let settled = ExactSolution::try_new(DVec3::new(1.0, 2.0, 3.0), given)
        .unwrap()
        .state_at(0.0);
    assert_eq!(q(&world), given.world_from_body(&rigid));
    world.step(0.1).unwrap();
    assert_eq!(q(&world), settled.world_from_body(&rigid));
}

/// A spin about principal axis 1 at 10²⁰⁰ rad/s: a valid state (|L|² and
/// the energy are finite), whose rotation angle ω t overflows past t ≈ 1.8e108 s.
fn fast_spin() -> Body {
    Body::from_principal_moments(1.0, DVec3::new(1e-100, 1.0, 1.0))
        .omega_body(DVec3::new(1e200, 0.0, 0.0))
        .try_build()
        .unwrap()
}

#[test]
fn a_uniform_rotation_whose_angle_overflows_fails_as_the_exact_solution_does() {
    let spin = fast_spin();
    // The closed form itself: finite at 1e100 s, not at 1e110 s.
    let exact = ExactSolution::try_new(DVec3::new(1e-100, 1.0, 1.0), initial(&spin)).unwrap();
    assert!(exact.state_at(1e100).world_from_principal.is_finite());
    assert!(!exact.state_at(1e110).world_from_principal.is_finite());
    // Bodies 1 and 2 overflow; body 0 comes to rest, so body 2 takes its
    // slot and is evaluated before body 1: the lower index is reported.
    let mut world = World::try_new(DVec3::ZERO, 1e95).unwrap();
    let calm = body(DVec3::ONE, DQuat::IDENTITY, DVec3::Z);
    let ids: Vec<BodyId> = [calm, spin.clone(), spin]
        .into_iter()
        .map(|b| world.add(b).unwrap())
        .collect();
    assert_eq!(world.plan(ids[1]), Some(&Plan::PrincipalSpin { axis: 0 }));
    world.set_omega_body(ids[0], DVec3::ZERO).unwrap();
    world.advance_to(1e100).unwrap();
    assert!(world.state(ids[1]).unwrap().world_from_body.is_finite());
    let e = world.advance_to(1e110).unwrap_err();
    match &e {
        DynamicsError::BodyFailed { body, time, source } => {
            assert_eq!((*body, *time), (1, 1e110));
            assert!(
                matches!(
                    **source,
                    DynamicsError::Diverged {
                        reason: Divergence::NonFinite,
                        ..
                    }
                ),
                "{source}"
            );
        }
        other => panic!("{other}"),
    }
    assert_eq!(world.step(1.0).unwrap_err(), e);
}

#[test]
fn non_finite_input_is_refused_when_the_plan_is_made() {
    let sphere = || Body::from_principal_moments(1.0, DVec3::ONE);
    assert!(sphere().omega_body(DVec3::NAN).try_build().is_err());
    assert!(
        sphere()
            .world_from_body(DQuat::from_xyzw(f64::INFINITY, 0.0, 0.0, 1.0))
            .try_build()
            .is_err()
    );
    let mut world = World::try_new(DVec3::ZERO, 0.1).unwrap();
    let id = world
        .add(sphere().omega_body(DVec3::Z).try_build().unwrap())
        .unwrap();
    world.step(0.1).unwrap();
    let before = world.state(id).unwrap();
    assert!(
        world
            .set_omega_body(id, DVec3::new(f64::NAN, 0.0, 0.0))
            .is_err()
    );
    assert!(world.set_omega_body(id, DVec3::splat(1e300)).is_err());
    assert!(world.apply_angular_impulse(id, DVec3::INFINITY).is_err());
    assert!(world.set_attitude(id, DQuat::NAN).is_err());
    // Nothing changed: the sphere turns on from where it was.
    assert_eq!(world.state(id).unwrap(), before);
    assert_eq!(world.plan(id), Some(&Plan::Sphere));
    world.step(0.1).unwrap();
    let q = world.state(id).unwrap().world_from_body;
    assert!(rotation_angle_between(q, DQuat::from_rotation_z(0.2)) < 1e-15);
}

#[test]
fn bodies_moved_between_the_batch_the_list_and_rest_are_moved_once_per_step() {
    use kreisel_dynamics::Inputs;
    let mut bodies: Vec<Body> = mixed().into_iter().map(|(b, _)| b).collect();
    bodies.push(
        body(DVec3::new(1.0, 2.0, 3.0), DQuat::IDENTITY, DVec3::Y)
            .with_inputs(Inputs::default().with_torque_world(DVec3::new(0.0, 0.0, 0.1)))
            .unwrap(),
    );
    let mut world = World::try_new(DVec3::ZERO, H).unwrap();
    let ids: Vec<BodyId> = bodies
        .iter()
        .map(|b| world.add(b.clone()).unwrap())
        .collect();
    world.advance_steps(30).unwrap();
    // Every body to a stepping method (the forced one to the Strang
    // splitting), then back to the exact plans, each time against
    // propagators started from the states read at the switch.
    for method in [FreeBodyMethod::Strang, FreeBodyMethod::Auto] {
        world.set_free_body_method(method).unwrap();
        let free = if method == FreeBodyMethod::Auto {
            FreeBodyMethod::Exact
        } else {
            method
        };
        let integrator = free.integrator();
        let mut references: Vec<Option<Box<dyn Propagator>>> = ids
            .iter()
            .zip(&bodies)
            .map(|(&id, b)| {
                let s = world.state(id).unwrap();
                let state = PrincipalState::try_from_omega_body(
                    b.rigid_body(),
                    s.world_from_body,
                    s.omega_body,
                )
                .unwrap();
                let moments = b.rigid_body().principal_moments();
                // The forced body's reference is its own torque law: below.
                b.inputs()
                    .is_none()
                    .then(|| integrator.propagator(moments, state))
            })
            .collect();
        let l0 = world.state(ids[7]).unwrap().l_world;
        for frame in 1..=60 {
            world.step(H).unwrap();
            for (k, r) in references.iter_mut().enumerate() {
                let Some(r) = r else { continue };
                r.advance(H);
                let s = world.state(ids[k]).unwrap();
                let rigid = bodies[k].rigid_body();
                let a = rotation_angle_between(s.world_from_body, r.state().world_from_body(rigid));
                assert!(a < 1e-12, "{method}: body {k} frame {frame}: {a:e}");
            }
            // The torque about z adds 0.1 N m · t to L_world, once per step.
            let l = world.state(ids[7]).unwrap().l_world;
            let expected = l0 + DVec3::new(0.0, 0.0, 0.1 * frame as f64 * H);
            assert!((l - expected).length() < 1e-12, "{method}: frame {frame}");
        }
    }
}
