//! The forced splittings against the references of `tests/data/forced/`
//! (`python3 tests/data/gen/forced.py`: Euler's equations in body axes with
//! the quaternion, written from the physics, integrated at 32 digits by
//! mpmath Gragg–Bulirsch–Stoer and checked against scipy DOP853 at 1e-13),
//! against closed forms, and against the heavy top's free flow.
//!
//! `cargo test -p kreisel-dynamics --release --test forced_reference -- --nocapture --test-threads 1`
//! prints the measured errors and orders.

use glam::{DQuat, DVec3};
use kreisel_dynamics::{
    ForcedBody, ForcedPropagator, ForcedSplitting, ForcedState, HeavyTop, HeavyTopIntegrator,
    HeavyTopSplitting, Inputs, PrincipalState, RigidBody,
};
use kreisel_kinematics::rotation_angle_between;

mod common;
use common::forced_refs::{NAMES, Reference, load, vec3};

/// Runs `method` with `substeps` steps per sample interval; the largest
/// attitude error over the samples and the final state.
fn run(r: &Reference, method: ForcedSplitting, substeps: usize) -> (f64, ForcedState) {
    r.run(method, substeps)
}

/// The Done-when: the default method reaches ≤ 1e-10 rad at every
/// sample over 10 s at dt = 0.01 on every reference; the angular and
/// linear velocities follow too.
#[test]
fn default_method_at_dt_001_on_every_reference() {
    for name in NAMES {
        let r = load(name);
        let (err, s) = run(&r, ForcedSplitting::DEFAULT, 10);
        let last = r.samples.last().unwrap();
        let omega_err = (s.rotation.omega_body(r.body.body()) - vec3(&last[5..8])).length();
        let x_err = (s.position_world - vec3(&last[8..11])).length();
        let v_err = (s.velocity_world - vec3(&last[11..14])).length();
        println!(
            "{name:>24}: {err:.1e} rad  |Δω(10 s)| {omega_err:.1e}  |Δx| {x_err:.1e}  |Δv| {v_err:.1e}"
        );
        assert!(err <= 1e-10, "{name}: {err:e} rad");
        assert!(omega_err <= 1e-10, "{name}: {omega_err:e} rad/s");
        assert!(
            x_err <= 1e-10 && v_err <= 1e-10,
            "{name}: {x_err:e} m, {v_err:e} m/s"
        );
    }
}

/// The attitude error at the last sample (10 s) after `n` equal steps.
fn final_error(r: &Reference, method: ForcedSplitting, n: usize) -> f64 {
    let t_end = r.samples.last().unwrap()[0];
    let h = t_end / n as f64;
    let mut p = ForcedPropagator::try_new(method, &r.body, 0.0, r.start).unwrap();
    for _ in 0..n {
        p.try_advance(h).unwrap();
    }
    r.attitude_error(&p.forced_state(), r.samples.len() - 1)
}

/// Step counts (over 10 s) of the convergence fits, per reference and
/// method (Strang, orders 4, 6, 8): where the error is asymptotic (`h ω`
/// small enough that the next term of the error is negligible) and far
/// above the rounding floor of the run (≈ 1e-13–1e-12 rad over 10 s; the
/// references themselves are exact to 1e-16). The faster references
/// (`symmetric_body_torque`: ω up to 7 rad/s; `point_force_gravity`: 4 rad/s
/// with a spin-up) need smaller steps; on `point_force_gravity` order 8 is
/// still approaching its asymptote when the rounding floor is reached (local
/// slopes 7.2, 7.5, 7.6, 7.7 from 48 to 96 steps).
fn step_counts(name: &str, order: u32) -> &'static [usize] {
    let fast = matches!(name, "symmetric_body_torque" | "point_force_gravity");
    match (order, name) {
        (2, _) => &[80, 160, 320, 640],
        (4, _) if fast => &[80, 160, 320, 640],
        (4, _) => &[40, 80, 160, 320],
        (6, "symmetric_body_torque") => &[64, 80, 96, 128],
        (6, "point_force_gravity") => &[80, 128, 160, 200],
        (6, _) => &[40, 64, 96, 128],
        (_, "symmetric_body_torque") => &[48, 56, 64, 72, 80],
        (_, "point_force_gravity") => &[64, 72, 80, 88, 96],
        (_, "damped_asymmetric") => &[32, 40, 48],
        (_, "asymmetric_world_torque") => &[48, 56, 64, 72],
        _ => &[24, 32, 40],
    }
}

/// The least-squares slope of `ln e` against `ln (1/n)`.
fn slope(points: &[(usize, f64)]) -> f64 {
    let xy: Vec<(f64, f64)> = points
        .iter()
        .map(|&(n, e)| (-(n as f64).ln(), e.ln()))
        .collect();
    let k = xy.len() as f64;
    let (mx, my) = (
        xy.iter().map(|p| p.0).sum::<f64>() / k,
        xy.iter().map(|p| p.1).sum::<f64>() / k,
    );
    let sxy: f64 = xy.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = xy.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
    sxy / sxx
}

/// Measured convergence orders of every composition on every reference:
/// the log–log slope of the 10 s attitude error against the step, within
/// ±0.3 of the nominal order — for the exact kicks and for the implicit
/// midpoint kick of the velocity law (`pd_controller`) alike.
#[test]
fn convergence_orders() {
    let mut failures = Vec::new();
    for name in NAMES {
        let r = load(name);
        for method in ForcedSplitting::ALL {
            let points: Vec<(usize, f64)> = step_counts(name, method.order())
                .iter()
                .map(|&n| (n, final_error(&r, method, n)))
                .collect();
            let p = slope(&points);
            let errors: Vec<String> = points.iter().map(|(n, e)| format!("{n}:{e:.1e}")).collect();
            println!(
                "{name:>24} {:>11}: order {p:.2}  ({})",
                method.name(),
                errors.join(" ")
            );
            if (p - method.order() as f64).abs() > 0.3 {
                failures.push(format!("{name} {}: {p:.2}", method.name()));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:?}");
}

/// Energy balance: the mechanical energy's change equals the work the
/// reference integrated alongside (`∫ τ·ω + F·v dt`, column `work`), at
/// every sample, to the method's accuracy (here rounding: ≤ 1e-12 of the
/// largest energy term).
#[test]
fn energy_change_is_the_work_done() {
    for name in NAMES {
        let r = load(name);
        let e0 = r.body.mechanical_energy(&r.start);
        let h = r.sample_dt() / 10.0;
        let mut p =
            ForcedPropagator::try_new(ForcedSplitting::DEFAULT, &r.body, 0.0, r.start).unwrap();
        let (mut worst, mut scale) = (0.0f64, e0.abs());
        for k in 1..r.samples.len() {
            for _ in 0..10 {
                p.try_advance(h).unwrap();
            }
            let work = r.samples[k][14];
            let s = p.forced_state();
            let e = r.body.mechanical_energy(&s);
            worst = worst.max((e - e0 - work).abs());
            // The largest term met: rounding is relative to it (the
            // falling body's kinetic and potential energies, ~9e3 J,
            // nearly cancel).
            let m = r.body.mass();
            scale = scale
                .max(s.rotation.energy(r.body.body()))
                .max(0.5 * m * s.velocity_world.length_squared())
                .max((m * r.body.gravity_world().dot(s.position_world)).abs())
                .max(work.abs());
        }
        println!("{name:>24}: max |ΔE − W| = {worst:.1e} J (scale {scale:.1e} J)");
        assert!(worst <= 1e-12 * scale, "{name}: {worst:e}");
    }
}

/// No inputs: every kick leaves `L` alone, and the rotation is bit for bit
/// the heavy-top splitting's with no gravity (the same free flows in the
/// same order); gravity alone moves the centre of mass on the exact
/// parabola and still exerts no torque.
#[test]
fn without_inputs_the_free_flow_bit_for_bit() {
    for moments in [DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.6, 0.6, 1.0)] {
        let rigid = RigidBody::try_from_principal_moments(moments).unwrap();
        let top = HeavyTop::try_from_principal(moments, DVec3::ZERO, 1.0, DVec3::ZERO).unwrap();
        for gravity in [DVec3::ZERO, DVec3::new(0.0, 0.0, -9.81)] {
            let body = ForcedBody::try_new(rigid, 2.0, gravity, Inputs::default()).unwrap();
            for (forced, heavy) in ForcedSplitting::ALL.into_iter().zip(HeavyTopSplitting::ALL) {
                assert_eq!(forced.name(), heavy.name());
                let rotation = PrincipalState {
                    world_from_principal: DQuat::from_rotation_x(0.4),
                    l_principal: DVec3::new(0.3, 1.2, -0.4),
                };
                let v0 = DVec3::new(1.0, -2.0, 3.0);
                let mut s = ForcedState {
                    rotation,
                    position_world: DVec3::ZERO,
                    velocity_world: v0,
                };
                let mut reference = rotation;
                for k in 0..200 {
                    forced.step(&body, &mut s, k as f64 * 0.05, 0.05);
                    heavy.step(&top, &mut reference, 0.05);
                    assert_eq!(s.rotation, reference, "{} step {k}", forced.name());
                }
                let t = 10.0;
                let x = v0 * t + 0.5 * gravity * t * t;
                assert!(
                    (s.position_world - x).length() < 1e-12 * x.length(),
                    "{}",
                    forced.name()
                );
            }
        }
    }
}

/// A sphere whose torque is parallel to its angular momentum turns about a
/// fixed axis at a rate growing linearly: the angle is
/// `θ = ω₀ t + τ t²/(2I)`. Each drift takes the midpoint rule of a linear
/// rate, exact, so every method meets the closed form to rounding: the
/// bound is 1e-13 of the 52.5 rad turned (up to 17 000 kicks adding to `L`).
#[test]
fn sphere_with_parallel_torque_closed_form() {
    let (inertia, omega0, tau) = (0.4, 1.5, 0.3);
    let axis = DVec3::new(1.0, -2.0, 2.0) / 3.0;
    let q0 = DQuat::from_axis_angle(DVec3::new(0.0, 0.6, 0.8), 0.9);
    let rigid = RigidBody::try_from_principal_moments(DVec3::splat(inertia)).unwrap();
    let body = ForcedBody::try_new(
        rigid,
        1.0,
        DVec3::ZERO,
        Inputs::default().with_torque_world(tau * axis),
    )
    .unwrap();
    for method in ForcedSplitting::ALL {
        let omega_body = q0.conjugate() * (omega0 * axis);
        let s0 = ForcedState::try_new(&rigid, q0, omega_body, DVec3::ZERO, DVec3::ZERO).unwrap();
        let mut p = ForcedPropagator::try_new(method, &body, 0.0, s0).unwrap();
        let mut worst = 0.0f64;
        for k in 1..=1000 {
            p.try_advance(0.01).unwrap();
            let t = k as f64 * 0.01;
            let theta = omega0 * t + tau * t * t / (2.0 * inertia);
            let exact = DQuat::from_axis_angle(axis, theta) * q0;
            worst = worst.max(rotation_angle_between(
                p.forced_state().rotation.world_from_principal,
                exact,
            ));
        }
        println!(
            "sphere, τ ∥ L, {:>11}: {worst:.1e} rad over 10 s",
            method.name()
        );
        let turned = omega0 * 10.0 + tau * 100.0 / (2.0 * inertia);
        assert!(worst < 1e-13 * turned, "{}: {worst:e}", method.name());
    }
}

/// A damped sphere: `ω = ω₀ e^{−ct/I}` (each kick is the exact decay, the
/// drift leaves `L` alone) and the angle `θ = ω₀ (I/c)(1 − e^{−ct/I})`
/// about the fixed axis (to the method's accuracy).
#[test]
fn damped_sphere_closed_form() {
    let (inertia, c, omega0) = (0.5, 0.2, 2.0);
    let axis = DVec3::new(0.0, 0.6, -0.8);
    let rigid = RigidBody::try_from_principal_moments(DVec3::splat(inertia)).unwrap();
    let body = ForcedBody::try_new(
        rigid,
        1.0,
        DVec3::ZERO,
        Inputs::default().with_angular_damping(c),
    )
    .unwrap();
    let s0 = ForcedState::try_new(
        &rigid,
        DQuat::IDENTITY,
        omega0 * axis,
        DVec3::ZERO,
        DVec3::ZERO,
    )
    .unwrap();
    let mut p = ForcedPropagator::try_new(ForcedSplitting::DEFAULT, &body, 0.0, s0).unwrap();
    let (mut worst_q, mut worst_w) = (0.0f64, 0.0f64);
    for k in 1..=1000 {
        p.try_advance(0.01).unwrap();
        let t = k as f64 * 0.01;
        let decay = (-c * t / inertia).exp();
        let s = p.forced_state();
        let omega = s.omega_world(rigid.principal_moments());
        worst_w = worst_w.max((omega - omega0 * decay * axis).length() / omega0);
        let theta = omega0 * inertia / c * (1.0 - decay);
        worst_q = worst_q.max(rotation_angle_between(
            s.rotation.world_from_principal,
            DQuat::from_axis_angle(axis, theta),
        ));
    }
    println!("damped sphere: ω {worst_w:.1e} (relative), attitude {worst_q:.1e} rad over 10 s");
    assert!(
        worst_w < 1e-13 && worst_q < 1e-12,
        "{worst_w:e} {worst_q:e}"
    );
}

/// A law that returns NaN stops the run with a typed error, and the state
/// before the failed step is kept.
#[test]
fn a_bad_law_is_reported() {
    let rigid = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0)).unwrap();
    let body = ForcedBody::try_new(
        rigid,
        1.0,
        DVec3::ZERO,
        Inputs::default().with_load(|t, _| {
            let tau = if t > 0.5 { DVec3::NAN } else { DVec3::X };
            (tau, DVec3::ZERO)
        }),
    )
    .unwrap();
    let s0 =
        ForcedState::try_new(&rigid, DQuat::IDENTITY, DVec3::Y, DVec3::ZERO, DVec3::ZERO).unwrap();
    let mut p = ForcedPropagator::try_new(ForcedSplitting::DEFAULT, &body, 0.0, s0).unwrap();
    let e = (0..100).find_map(|_| p.try_advance(0.1).err()).unwrap();
    assert!(
        matches!(e, kreisel_dynamics::DynamicsError::Diverged { .. }),
        "{e}"
    );
    assert!(p.forced_state().is_finite());
    assert!(p.time() <= 0.6 + 1e-12, "{}", p.time());
    assert!(p.try_advance(-1.0).is_err());
}

/// A constant world torque: `L_world(t) = L₀ + τ t` for any body, by
/// construction (each drift keeps `L_world`, the kicks' durations add up to
/// `h`), at any step and for every method, to rounding — the PDMV10 drift
/// of an asymmetric body included (it keeps `L_world` exactly too).
#[test]
fn world_torque_adds_up_exactly() {
    let tau = DVec3::new(0.2, 0.1, -0.3);
    for moments in [DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.6, 0.6, 1.0)] {
        let rigid = RigidBody::try_from_principal_moments(moments).unwrap();
        let body = ForcedBody::try_new(
            rigid,
            1.0,
            DVec3::ZERO,
            Inputs::default().with_torque_world(tau),
        )
        .unwrap();
        for method in ForcedSplitting::ALL {
            let s0 = ForcedState::try_new(
                &rigid,
                DQuat::from_rotation_y(0.3),
                DVec3::new(0.5, -0.3, 1.2),
                DVec3::ZERO,
                DVec3::ZERO,
            )
            .unwrap();
            let l0 = s0.rotation.l_world();
            let mut p = ForcedPropagator::try_new(method, &body, 0.0, s0).unwrap();
            let mut worst = 0.0f64;
            for k in 1..=100 {
                p.try_advance(0.1).unwrap();
                let expected = l0 + tau * (k as f64 * 0.1);
                worst = worst.max(
                    (p.forced_state().rotation.l_world() - expected).length() / expected.length(),
                );
            }
            assert!(worst < 1e-14, "{moments} {}: {worst:e}", method.name());
        }
    }
}
