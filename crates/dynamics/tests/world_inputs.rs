//! Bodies with applied inputs in a [`World`]: the world moves them exactly
//! as [`ForcedPropagator`] does, a sphere spun up about its axis follows
//! the closed form, the energy column's change is the work done, and the
//! plans follow the inputs.
//!
//! `cargo test -p kreisel-dynamics --test world_inputs -- --nocapture`
//! prints the measured errors.

use glam::{DQuat, DVec3};
use kreisel_dynamics::{
    Body, DynamicsError, ForcedBody, ForcedPropagator, ForcedSplitting, ForcedState,
    FreeBodyMethod, Inputs, Plan, PrincipalState, World,
};
use kreisel_kinematics::rotation_angle_between;

const GRAVITY: DVec3 = DVec3::new(0.0, 0.0, -9.81);

fn asymmetric(inputs: Inputs) -> Body {
    Body::from_principal_moments(2.0, DVec3::new(1.0, 2.0, 3.0))
        .world_from_body(DQuat::from_rotation_x(0.3) * DQuat::from_rotation_z(0.2))
        .omega_body(DVec3::new(0.4, 1.0, -0.2))
        .free(DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.5, 0.0, 4.0))
        .try_build()
        .unwrap()
        .with_inputs(inputs)
        .unwrap()
}

#[test]
fn the_world_steps_a_forced_body_as_its_propagator_bit_for_bit() {
    let inputs = Inputs::default()
        .with_torque_world(DVec3::new(0.1, -0.2, 0.3))
        .with_force_world(DVec3::new(0.0, 1.0, 0.0));
    let body = asymmetric(inputs.clone());
    let dt = 1.0 / 60.0;
    for (method, splitting) in [
        (FreeBodyMethod::Auto, ForcedSplitting::DEFAULT),
        (FreeBodyMethod::Strang, ForcedSplitting::STRANG),
        (FreeBodyMethod::Splitting8, ForcedSplitting::ORDER_8),
    ] {
        let mut world = World::try_new(GRAVITY, dt).unwrap();
        world.set_free_body_method(method).unwrap();
        let id = world.add(body.clone()).unwrap();
        assert_eq!(world.plan(id), Some(&Plan::Forced { method: splitting }));

        let rigid = *body.rigid_body();
        let forced = ForcedBody::try_new(rigid, body.mass(), GRAVITY, inputs.clone()).unwrap();
        let start = ForcedState::try_new(
            &rigid,
            body.world_from_body(),
            body.omega_body(),
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(0.5, 0.0, 4.0),
        )
        .unwrap();
        let mut direct = ForcedPropagator::try_new(splitting, &forced, 0.0, start).unwrap();
        // A game loop (step), then whole steps (advance_steps).
        for _ in 0..120 {
            world.step(dt).unwrap();
            direct.try_advance(dt).unwrap();
        }
        world.advance_steps(480).unwrap();
        for _ in 0..480 {
            direct.try_advance(dt).unwrap();
        }
        let s = world.state(id).unwrap();
        let d = direct.forced_state();
        assert_eq!(s.world_from_body, d.rotation.world_from_body(&rigid));
        assert_eq!(s.l_world, d.rotation.l_world());
        assert_eq!(s.omega_body, d.rotation.omega_body(&rigid));
        assert_eq!(
            (s.position, s.velocity),
            (d.position_world, d.velocity_world)
        );
        assert_eq!(s.energy, forced.mechanical_energy(&d));
    }
}

#[test]
fn a_sphere_spun_up_about_its_axis_follows_the_closed_form() {
    // I = 0.5, ω₀ = 1 about n, τ = 0.3 n (world axes):
    // L(t) = (I ω₀ + τ t) n,  q(t) = exp(θ(t) n) q₀,  θ = ω₀ t + τ t²/(2I).
    let (inertia, omega0, tau) = (0.5, 1.0, 0.3);
    let n = DVec3::new(1.0, 2.0, 2.0) / 3.0;
    let q0 = DQuat::from_rotation_y(0.7);
    let body = Body::from_principal_moments(1.5, DVec3::splat(inertia))
        .world_from_body(q0)
        .omega_body(q0.conjugate() * (omega0 * n))
        .try_build()
        .unwrap()
        .with_inputs(Inputs::default().with_torque_world(tau * n))
        .unwrap();
    let mut world = World::try_new(GRAVITY, 0.01).unwrap();
    let id = world.add(body).unwrap();
    let mut worst: (f64, f64) = (0.0, 0.0);
    for t in [0.5, 1.0, 2.5, 5.0, 7.5, 10.0] {
        world.advance_to(t).unwrap();
        let s = world.state(id).unwrap();
        let theta = omega0 * t + tau * t * t / (2.0 * inertia);
        let q = DQuat::from_axis_angle(n, theta) * q0;
        let l = (inertia * omega0 + tau * t) * n;
        let angle = rotation_angle_between(s.world_from_body, q);
        let l_error = (s.l_world - l).length() / l.length();
        worst = (worst.0.max(angle), worst.1.max(l_error));
        // Gravity alone moves the centre of mass (no force applied).
        let x = GRAVITY * (0.5 * t * t);
        assert!((s.position - x).length() <= 1e-12 * x.length(), "t = {t}");
    }
    println!(
        "sphere, torque ∥ L, 10 s at dt = 0.01 (θ = 40 rad): attitude {:.1e} rad, |ΔL|/|L| {:.1e}",
        worst.0, worst.1
    );
    assert!(worst.0 < 1e-12, "attitude error {:.2e} rad", worst.0);
    assert!(worst.1 < 1e-12, "L error {:.2e}", worst.1);
}

#[test]
fn the_energy_column_changes_by_the_work_done() {
    // Torques in world and body axes, damping and a force: the mechanical
    // energy's change is ∫ (τ·ω + F·v) dt, measured from the run's states
    // (composite Simpson over steps of dt). No gravity: under g the
    // centre of mass falls 490 m in 10 s and the rounding of ½m|v|² − m g·x
    // (≈ 10⁴ J each) alone is ~1e-8 J.
    let (tau_w, tau_b, c, f) = (
        DVec3::new(0.2, -0.1, 0.3),
        DVec3::new(0.0, 0.05, 0.1),
        0.02,
        DVec3::new(0.5, 0.0, 0.0),
    );
    let inputs = Inputs::default()
        .with_torque_world(tau_w)
        .with_torque_body(tau_b)
        .with_angular_damping(c)
        .with_force_world(f);
    let body = asymmetric(inputs);
    let dt = 1e-3;
    let mut world = World::try_new(DVec3::ZERO, dt).unwrap();
    let id = world.add(body).unwrap();
    let power = |world: &World| {
        let s = world.state(id).unwrap();
        let omega_world = s.world_from_body * s.omega_body;
        let torque = tau_w + s.world_from_body * tau_b - c * omega_world;
        (torque.dot(omega_world) + f.dot(s.velocity), s.energy)
    };
    let (p0, e0) = power(&world);
    let (mut work, mut previous) = (0.0, p0);
    let panels = 5000; // 10 s
    for _ in 0..panels {
        world.step(dt).unwrap();
        let (mid, _) = power(&world);
        world.step(dt).unwrap();
        let (end, _) = power(&world);
        work += (previous + 4.0 * mid + end) * dt / 3.0;
        previous = end;
    }
    let (_, e1) = power(&world);
    let mismatch = ((e1 - e0) - work).abs();
    println!(
        "ΔE = {:.12} J, work = {:.12} J, |ΔE − W| = {mismatch:.1e} J",
        e1 - e0,
        work
    );
    assert!(work.abs() > 1.0, "the inputs do work: {work}");
    assert!(mismatch < 1e-10 * work.abs(), "|ΔE − W| = {mismatch:.2e} J");
}

#[test]
fn set_inputs_remakes_the_plan() {
    let mut world = World::try_new(GRAVITY, 0.01).unwrap();
    let id = world.add(asymmetric(Inputs::default())).unwrap();
    assert_eq!(world.plan(id), Some(&Plan::Asymmetric));
    world.advance_to(1.0).unwrap();
    let before = world.state(id).unwrap();

    let torque = Inputs::default().with_torque_body(DVec3::Z);
    world.set_inputs(id, torque.clone()).unwrap();
    let forced = Plan::Forced {
        method: ForcedSplitting::DEFAULT,
    };
    assert_eq!(world.plan(id), Some(&forced));
    assert!(
        world
            .plan(id)
            .unwrap()
            .to_string()
            .contains("splitting6 (order 6)")
    );
    // Re-planning keeps the state: position, velocity and attitude go on.
    let now = world.state(id).unwrap();
    assert_eq!(
        (now.position, now.velocity, now.l_world),
        (before.position, before.velocity, before.l_world)
    );
    world.advance_to(2.0).unwrap();
    assert_eq!(world.body(id).unwrap().inputs().torque_body, DVec3::Z);

    // Methods without a torque kick are refused, and nothing changes.
    let e = world
        .set_free_body_method(FreeBodyMethod::Pdmv6)
        .unwrap_err();
    assert!(matches!(
        e,
        DynamicsError::MethodTakesNoInputs {
            method: "pdmv6",
            ..
        }
    ));
    assert_eq!(world.free_body_method(), FreeBodyMethod::Auto);
    assert_eq!(world.plan(id), Some(&forced));
    world
        .set_free_body_method(FreeBodyMethod::Splitting4)
        .unwrap();
    assert_eq!(
        world.plan(id),
        Some(&Plan::Forced {
            method: ForcedSplitting::ORDER_4
        })
    );

    // Inputs switched off: the exact plan again, from the state reached.
    world.set_free_body_method(FreeBodyMethod::Auto).unwrap();
    world.set_inputs(id, Inputs::default()).unwrap();
    assert_eq!(world.plan(id), Some(&Plan::Asymmetric));
    let off = world.state(id).unwrap();
    world.advance_to(3.0).unwrap();
    let later = world.state(id).unwrap();
    assert!((later.l_world - off.l_world).length() < 1e-14 * off.l_world.length());
    // Ballistic again: x = x₀ + v₀ t + g t²/2 from the state at t = 2.
    let x = off.position + off.velocity + 0.5 * GRAVITY;
    assert!((later.position - x).length() < 1e-13 * x.length());

    // A world on RK4 refuses inputs; bad inputs are refused.
    let mut rk4 = World::try_new(GRAVITY, 0.01).unwrap();
    rk4.set_free_body_method(FreeBodyMethod::Rk4).unwrap();
    let id = rk4.add(asymmetric(Inputs::default())).unwrap();
    let e = rk4.set_inputs(id, torque.clone()).unwrap_err();
    assert!(e.to_string().contains("`rk4`"), "{e}");
    assert_eq!(rk4.plan(id), Some(&Plan::Stepping(FreeBodyMethod::Rk4)));
    assert!(rk4.body(id).unwrap().inputs().is_none());
    assert!(rk4.add(asymmetric(torque)).is_err());
    let e = world
        .set_inputs(id, Inputs::default().with_angular_damping(-1.0))
        .unwrap_err();
    assert!(matches!(e, DynamicsError::InvalidInput { .. }), "{e}");
}

#[test]
fn a_pivot_takes_inputs_as_a_driven_top() {
    let top = Body::from_principal_moments(1.0, DVec3::new(0.02, 0.02, 0.01))
        .omega_body(DVec3::new(0.0, 0.0, 50.0))
        .pivot(DVec3::new(0.0, 0.0, -0.1), DVec3::ZERO);
    let motor = Inputs::default().with_torque_body(DVec3::new(0.0, 0.0, 0.01));
    let driven = top.try_build().unwrap().with_inputs(motor.clone()).unwrap();
    let mut world = World::try_new(GRAVITY, 1e-3).unwrap();
    let id = world.add(driven).unwrap();
    assert_eq!(
        world.plan(id),
        Some(&Plan::DrivenTop {
            method: ForcedSplitting::ORDER_8
        })
    );
    // RK4 has no kick for the loads: refused, nothing changes.
    let e = world
        .set_heavy_top_method(kreisel_dynamics::HeavyTopMethod::Rk4)
        .unwrap_err();
    assert!(
        matches!(e, DynamicsError::MethodTakesNoInputs { .. }),
        "{e}"
    );
    assert_eq!(
        world.heavy_top_method(),
        kreisel_dynamics::HeavyTopMethod::Auto
    );
    // Inputs off: the top's own plan again (a Lagrange top: its closed form).
    world.set_inputs(id, Inputs::default()).unwrap();
    assert_eq!(world.plan(id), Some(&Plan::LagrangeTop));
    world.set_inputs(id, motor).unwrap();
    assert!(matches!(world.plan(id), Some(Plan::DrivenTop { .. })));
}

#[test]
fn zero_inputs_keep_the_exact_plan_bit_for_bit() {
    let zero = Inputs::default()
        .with_torque_world(DVec3::ZERO)
        .with_torque_body(DVec3::ZERO)
        .with_angular_damping(0.0);
    let mut world = World::try_new(GRAVITY, 0.01).unwrap();
    let plain = world.add(asymmetric(Inputs::default())).unwrap();
    let zeroed = world.add(asymmetric(zero)).unwrap();
    assert_eq!(world.plan(zeroed), Some(&Plan::Asymmetric));
    world.advance_to(7.3).unwrap();
    assert_eq!(world.state(plain), world.state(zeroed));
    let s = world.state(zeroed).unwrap();
    let body = asymmetric(Inputs::default());
    let start = PrincipalState::try_from_omega_body(
        body.rigid_body(),
        body.world_from_body(),
        body.omega_body(),
    )
    .unwrap();
    // Torque-free: L_world is conserved.
    assert!((s.l_world - start.l_world()).length() < 1e-14 * s.l_world.length());
}

#[test]
fn setters_move_a_forced_body_and_keep_it_forced() {
    // m = 2, F = (1, 0, 0) N: a = g + F/m; the centre of mass restarts from
    // what is set, the spin from the impulse, the plan stays forced.
    let force = DVec3::new(1.0, 0.0, 0.0);
    let inputs = Inputs::default().with_force_world(force);
    let mut world = World::try_new(GRAVITY, 0.01).unwrap();
    let id = world.add(asymmetric(inputs)).unwrap();
    world.advance_to(1.0).unwrap();
    let (x0, v0) = (DVec3::new(0.0, 0.0, 10.0), DVec3::new(0.0, 2.0, 0.0));
    world.set_centre_of_mass(id, x0, v0).unwrap();
    let l_before = world.state(id).unwrap().l_world;
    world.apply_angular_impulse(id, DVec3::Z).unwrap();
    let forced = Some(&Plan::Forced {
        method: ForcedSplitting::DEFAULT,
    });
    assert_eq!(world.plan(id), forced);
    world.advance_to(3.0).unwrap();
    let s = world.state(id).unwrap();
    let a = GRAVITY + force / 2.0;
    let x = x0 + v0 * 2.0 + a * 2.0;
    assert!(
        (s.position - x).length() < 1e-12 * x.length(),
        "{:?}",
        s.position
    );
    assert!((s.velocity - (v0 + a * 2.0)).length() < 1e-12 * v0.length());
    // A force through the centre of mass turns nothing: L = L + J.
    assert!((s.l_world - (l_before + DVec3::Z)).length() < 1e-13);
}
