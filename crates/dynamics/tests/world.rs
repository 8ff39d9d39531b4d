//! The World against the pieces it is built from, used directly: the exact
//! solution, the exact propagator, `integrate_heavy_top`, and the closed
//! form of ballistic flight (with energy conservation as an independent
//! check).

use glam::{DQuat, DVec3};
use kreisel_dynamics::{
    Body, BodyState, DynamicsError, ExactSolution, FreeBodyMethod, HeavyTop, HeavyTopMethod, Plan,
    PrincipalState, World, integrate_heavy_top,
};
use kreisel_inertia::MassProperties;
use kreisel_kinematics::rotation_angle_between;

mod common;
use common::initial;

const MOMENTS: DVec3 = DVec3::new(1.0, 2.0, 3.0);

/// An asymmetric body near the separatrix (the Dzhanibekov flip).
fn asymmetric() -> Body {
    Body::from_principal_moments(1.5, MOMENTS)
        .world_from_body(DQuat::from_xyzw(0.1, 0.2, 0.3, 0.9))
        .omega_body(DVec3::new(0.01, 1.0, 0.2))
        .try_build()
        .unwrap()
}

/// The angle between the world's attitude and the principal-frame state's.
fn angle(state: &BodyState, body: &Body, other: &PrincipalState) -> f64 {
    rotation_angle_between(
        state.world_from_body,
        other.world_from_body(body.rigid_body()),
    )
}

#[test]
fn advance_to_is_the_exact_solution_at_t() {
    let body = asymmetric();
    let exact = ExactSolution::try_new(MOMENTS, initial(&body)).unwrap();
    let mut world = World::try_new(DVec3::ZERO, 0.01).unwrap();
    let id = world.add(body.clone()).unwrap();
    assert_eq!(world.plan(id), Some(&Plan::Asymmetric));
    let mut worst: f64 = 0.0;
    for t in [0.37, 1.0, 2.5, 13.123, 100.0, 1234.5678] {
        world.advance_to(t).unwrap();
        let s = world.state(id).unwrap();
        assert_eq!(s.time, t);
        let e = exact.state_at(t);
        // The world evaluates at the sum of its grid steps in double-double,
        // t to within half an ulp: |ω| ulp(t) ≲ 2e-13 rad at t = 1234.
        let bound = 4.0 * f64::EPSILON * (1.0 + t);
        let a = angle(&s, &body, &e);
        worst = worst.max(a / bound);
        assert!(a <= bound, "t = {t}: {a:e} rad");
        assert!((s.l_world - e.l_world()).length() <= bound * 2.0, "t = {t}");
    }
    println!("advance_to vs state_at: worst {worst:.2} of the rounding bound");
}

#[test]
fn game_steps_equal_the_propagator_bit_for_bit() {
    let body = asymmetric();
    let h = 1.0 / 60.0;
    let exact = FreeBodyMethod::Exact.integrator();
    let mut propagator = exact.propagator(MOMENTS, initial(&body));
    // A world whose dt is the frame, and one whose dt is not (then every
    // step re-anchors its grid): both accumulate the time exactly as the
    // propagator does.
    for dt in [h, 0.01] {
        let mut world = World::try_new(DVec3::ZERO, dt).unwrap();
        let id = world.add(body.clone()).unwrap();
        let mut reference = exact.propagator(MOMENTS, initial(&body));
        for _ in 0..600 {
            world.step(h).unwrap();
            reference.advance(h);
            let s = world.state(id).unwrap();
            let r = reference.state();
            assert_eq!(
                s.world_from_body,
                r.world_from_body(body.rigid_body()),
                "dt = {dt}"
            );
            assert_eq!(s.l_world, r.l_world(), "dt = {dt}");
        }
    }
    // And advance_steps(600) lands on the same state as 600 single steps.
    let mut world = World::try_new(DVec3::ZERO, h).unwrap();
    let id = world.add(body.clone()).unwrap();
    world.advance_steps(600).unwrap();
    for _ in 0..600 {
        propagator.advance(h);
    }
    let s = world.state(id).unwrap();
    assert_eq!(
        s.world_from_body,
        propagator.state().world_from_body(body.rigid_body())
    );
}

#[test]
fn resting_bodies_and_spheres_need_no_elliptic_set_up() {
    let mut world = World::try_new(DVec3::new(0.0, 0.0, -9.81), 0.01).unwrap();
    let rest = world
        .add(
            Body::from_principal_moments(1.0, MOMENTS)
                .try_build()
                .unwrap(),
        )
        .unwrap();
    let sphere = Body::from_mass_properties(MassProperties::solid_sphere(1000.0, 0.1).unwrap())
        .omega_body(DVec3::new(1.0, -2.0, 3.0))
        .try_build()
        .unwrap();
    let sphere = world.add(sphere).unwrap();
    let spin = Body::from_principal_moments(1.0, MOMENTS)
        .omega_body(DVec3::new(0.0, 0.0, 7.0))
        .try_build()
        .unwrap();
    let spin = world.add(spin).unwrap();
    let symmetric = Body::from_principal_moments(1.0, DVec3::new(1.0, 1.0, 1.5))
        .omega_body(DVec3::new(0.3, 0.0, 1.0))
        .try_build()
        .unwrap();
    let symmetric = world.add(symmetric).unwrap();
    assert_eq!(world.plan(rest), Some(&Plan::Resting));
    assert_eq!(world.plan(sphere), Some(&Plan::Sphere));
    assert_eq!(world.plan(spin), Some(&Plan::PrincipalSpin { axis: 2 }));
    assert_eq!(world.plan(symmetric), Some(&Plan::Symmetric { axis: 2 }));
    world.advance_to(10.0).unwrap();
    // The resting body has not turned; the sphere turned uniformly.
    let s = world.state(rest).unwrap();
    assert_eq!(
        (s.world_from_body, s.omega_body),
        (DQuat::IDENTITY, DVec3::ZERO)
    );
    let s = world.state(sphere).unwrap();
    let expected = DQuat::from_scaled_axis(DVec3::new(1.0, -2.0, 3.0) * 10.0);
    assert!(rotation_angle_between(s.world_from_body, expected) < 1e-13);
    let s = world.state(spin).unwrap();
    assert!(rotation_angle_between(s.world_from_body, DQuat::from_rotation_z(70.0)) < 1e-13);
}

#[test]
fn setters_restart_the_exact_solution_from_the_new_state() {
    let body = asymmetric();
    let mut world = World::try_new(DVec3::ZERO, 0.01).unwrap();
    let id = world.add(body.clone()).unwrap();
    world.advance_to(2.0).unwrap();
    let kicks: [&dyn Fn(&mut World); 3] = [
        &|w| {
            w.apply_angular_impulse(id, DVec3::new(0.5, -0.2, 1.0))
                .unwrap()
        },
        &|w| w.set_omega_body(id, DVec3::new(1.0, 0.1, -0.3)).unwrap(),
        &|w| w.set_attitude(id, DQuat::from_rotation_x(0.7)).unwrap(),
    ];
    let mut t = 2.0;
    for kick in kicks {
        let before = world.state(id).unwrap();
        kick(&mut world);
        let after = world.state(id).unwrap();
        assert_ne!(before, after);
        let restart = PrincipalState::try_from_omega_body(
            body.rigid_body(),
            after.world_from_body,
            after.omega_body,
        )
        .unwrap();
        let exact = ExactSolution::try_new(MOMENTS, restart).unwrap();
        t += 3.0;
        world.advance_to(t).unwrap();
        let s = world.state(id).unwrap();
        let a = angle(&s, &body, &exact.state_at(3.0));
        assert!(a < 1e-13, "{a:e}");
    }
    // The impulse adds to L_world.
    let before = world.state(id).unwrap().l_world;
    world.apply_angular_impulse(id, DVec3::Z).unwrap();
    let after = world.state(id).unwrap().l_world;
    assert!((after - before - DVec3::Z).length() < 1e-15);
}

/// A heavy asymmetric top: 2 kg, its centre of mass off every principal axis.
fn heavy_top_body() -> (MassProperties, Body) {
    let props = MassProperties::try_new(
        2.0,
        DVec3::new(0.01, 0.02, 0.1),
        glam::DMat3::from_diagonal(DVec3::new(0.02, 0.025, 0.012)),
    )
    .unwrap();
    let body = Body::from_mass_properties(props)
        .world_from_body(DQuat::from_rotation_x(0.3))
        .omega_body(DVec3::new(0.5, -1.0, 40.0))
        .pivot(DVec3::ZERO, DVec3::new(0.0, 0.0, 1.0))
        .try_build()
        .unwrap();
    (props, body)
}

#[test]
fn heavy_tops_move_as_integrate_heavy_top_moves_them() {
    let g = DVec3::new(0.0, 0.0, -9.81);
    let (props, body) = heavy_top_body();
    let top = HeavyTop::try_new(&props, DVec3::ZERO, g).unwrap();
    for method in [
        HeavyTopMethod::Auto,
        HeavyTopMethod::Rk4,
        HeavyTopMethod::Splitting6,
    ] {
        let mut world = World::try_new(g, 2e-3).unwrap();
        world.set_heavy_top_method(method).unwrap();
        let id = world.add(body.clone()).unwrap();
        assert_eq!(world.plan(id), Some(&Plan::HeavyTop(method)));
        world.advance_steps(500).unwrap();
        let mut s = PrincipalState::try_from_omega_body(
            top.body(),
            body.world_from_body(),
            body.omega_body(),
        )
        .unwrap();
        integrate_heavy_top(method.integrator(), &top, &mut s, 2e-3, 500).unwrap();
        let w = world.state(id).unwrap();
        assert_eq!(w.world_from_body, s.world_from_body(top.body()), "{method}");
        assert_eq!(w.l_world, s.l_world(), "{method}");
        // Energy about the pivot, the pivot 1 m up.
        let e = top.energy(&s) + 2.0 * 9.81 * 1.0;
        assert_eq!(w.energy, e, "{method}");
        // The centre of mass hangs from the pivot at |c|.
        let arm = w.position - DVec3::new(0.0, 0.0, 1.0);
        let off = (arm.length() - props.center_of_mass.length()).abs();
        assert!(off < 4.0 * f64::EPSILON, "{method}: {off:e}");
    }
}

#[test]
fn the_centre_of_mass_flies_in_closed_form() {
    let g = DVec3::new(0.0, -1.62, 0.0);
    let (x0, v0) = (DVec3::new(1.0, 20.0, -3.0), DVec3::new(2.0, 5.0, 0.5));
    let body = Body::from_principal_moments(3.0, MOMENTS)
        .omega_body(DVec3::new(0.2, 0.1, 1.0))
        .free(x0, v0)
        .try_build()
        .unwrap();
    let mut world = World::try_new(g, 0.01).unwrap();
    let id = world.add(body).unwrap();
    let e0 = world.state(id).unwrap().energy;
    for t in [0.5, 1.0, 7.25, 30.0] {
        world.advance_to(t).unwrap();
        let s = world.state(id).unwrap();
        let x = DVec3::new(1.0 + 2.0 * t, 20.0 + 5.0 * t - 0.81 * t * t, -3.0 + 0.5 * t);
        let v = DVec3::new(2.0, 5.0 - 1.62 * t, 0.5);
        assert!((s.position - x).length() <= 1e-13 * x.length(), "t = {t}");
        assert!(
            (s.velocity - v).length() <= 1e-14 * v.length().max(1.0),
            "t = {t}"
        );
        // Rotational + translational + potential energy is conserved.
        assert!(
            (s.energy - e0).abs() <= 1e-12 * e0.abs(),
            "t = {t}: {} vs {e0}",
            s.energy
        );
    }
}

#[test]
fn a_diverging_body_stops_the_world_with_its_name_and_time() {
    let mut world = World::try_new(DVec3::ZERO, 0.1).unwrap();
    world.set_free_body_method(FreeBodyMethod::Rk4).unwrap();
    let calm = Body::from_principal_moments(1.0, MOMENTS).omega_body(DVec3::Y);
    world.add(calm.clone().try_build().unwrap()).unwrap();
    let wild = calm.omega_body(DVec3::new(100.0, 3.0, 0.0));
    world.add(wild.try_build().unwrap()).unwrap();
    let e = world.advance_to(5.0).unwrap_err();
    match &e {
        DynamicsError::BodyFailed {
            body: 1,
            time,
            source,
        } => {
            assert_eq!(*time, 0.1);
            assert!(matches!(
                **source,
                DynamicsError::Diverged { method: "rk4", .. }
            ));
        }
        other => panic!("{other}"),
    }
    // The world refuses to go on; going back is refused too.
    assert_eq!(world.step(0.1).unwrap_err(), e);
    let mut fresh = World::try_new(DVec3::ZERO, 0.1).unwrap();
    fresh.advance_to(1.0).unwrap();
    assert!(matches!(
        fresh.advance_to(0.5),
        Err(DynamicsError::InvalidTime { .. })
    ));
}

/// `kreisel simulate`'s grid, written out: steps of `dt` ending at `k·dt`,
/// the last one `duration − (N − 1)·dt` (N = 10 here, the last step
/// 0.09999999999999998 s, not 0.1).
fn simulate_grid(duration: f64, dt: f64, n: u64) -> Vec<f64> {
    (1..=n)
        .map(|k| {
            if k < n {
                dt
            } else {
                duration - (n - 1) as f64 * dt
            }
        })
        .collect()
}

#[test]
fn rows_on_the_simulate_grid_equal_a_propagator_stepped_on_it() {
    let (duration, dt, every) = (1.0, 0.1, 3);
    let steps = simulate_grid(duration, dt, 10);
    assert_ne!(steps[9], dt);
    let body = asymmetric();
    for method in [
        FreeBodyMethod::Auto,
        FreeBodyMethod::Rk4,
        FreeBodyMethod::Pdmv6,
    ] {
        let mut world = World::try_new(DVec3::ZERO, dt).unwrap();
        world.set_free_body_method(method).unwrap();
        let id = world.add(body.clone()).unwrap();
        let integrator = method.integrator();
        let mut reference = integrator.propagator(MOMENTS, initial(&body));
        let mut done = 0;
        for (k, h) in steps.iter().enumerate() {
            reference.advance(*h);
            let k = k as u64 + 1;
            let last = k == steps.len() as u64;
            if k.is_multiple_of(every) && !last {
                world.advance_steps(k - done).unwrap();
                done = k;
            } else if last {
                world.advance_to(duration).unwrap();
            } else {
                continue;
            }
            let (s, r) = (world.state(id).unwrap(), reference.state());
            assert_eq!(
                s.world_from_body,
                r.world_from_body(body.rigid_body()),
                "{method} k = {k}"
            );
            assert_eq!(s.l_world, r.l_world(), "{method} k = {k}");
            assert_eq!(s.time, if last { duration } else { k as f64 * dt });
        }
    }
}

#[test]
fn exact_bodies_take_no_steps_on_the_way() {
    // 10¹⁵ steps of dt: a world that stepped its exact bodies would not
    // finish; one that evaluates them at t answers at once.
    let body = asymmetric();
    let mut world = World::try_new(DVec3::ZERO, 1e-9).unwrap();
    let id = world.add(body.clone()).unwrap();
    let t = 1e6;
    world.advance_to(t).unwrap();
    let exact = ExactSolution::try_new(MOMENTS, initial(&body)).unwrap();
    let s = world.state(id).unwrap();
    // Both are evaluations at t (to half an ulp of t): |ω| ulp(t) ≈ 1e-10 rad.
    let a = angle(&s, &body, &exact.state_at(t));
    assert!(a < 4.0 * f64::EPSILON * t, "{a:e}");
}
