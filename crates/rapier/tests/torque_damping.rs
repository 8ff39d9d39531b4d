//! Torques and damping on managed free bodies, against closed forms.
//!
//! rapier 0.36 keeps a torque given by `RigidBody::add_torque` until
//! `reset_torques` (it is applied at every step), adds `I_w⁻¹ τ h` to ω at
//! each of its `num_solver_iterations` (4) substeps `h = dt/4`, and
//! multiplies ω by `1/(1 + dt·c)` once per step for an angular damping
//! `c` (`RigidBodyVelocity::apply_damping`, at the velocity writeback).
//! The adapter turns rapier's change of ω over the step into a kick of L
//! at the step's start, then the exact flow over dt: Lie–Trotter
//! splitting, first order in dt.
//!
//! `cargo test -p kreisel-rapier --test torque_damping -- --nocapture`
//! prints the errors of both engines.

mod common;

use common::{angle, attitude, body_with_moments, d, free_world, l_world};
use glam::{DQuat, DVec3};
use kreisel_rapier::ExactRotation;
use rapier3d::prelude::*;

/// Sphere moment, kg·m², and the magnitudes of ω₀ (rad/s) and τ (N·m).
const C: f32 = 0.5;
const OMEGA: f32 = 2.0;
const TAU: f32 = 0.5;
/// The time the torque acts, s.
const T: f64 = 2.0;

/// A sphere-inertia body spun about n with a constant torque along n,
/// stepped `T` seconds at `dt` by rapier alone or with the adapter:
/// the attitude's and L's errors against the closed form
///
/// ```text
/// R(t) = Rot(n, |ω₀| t + |τ| t²/(2c)) R₀,   L(t) = c ω₀ + τ t
/// ```
fn sphere_with_torque(dt: f32, with_adapter: bool) -> (f64, f64) {
    let mut world = free_world();
    world.integration_parameters.dt = dt;
    let n = Vector::new(1.0, 2.0, 2.0) / 3.0;
    // ω₀ and τ are n times powers of two: exactly parallel in f32.
    let handle = body_with_moments(
        &mut world,
        Vector::splat(C),
        Rotation::IDENTITY,
        Vector::ZERO,
        Rotation::from_scaled_axis(Vector::new(0.3, -0.7, 0.2)),
        n * OMEGA,
    );
    world.bodies[handle].add_torque(n * TAU, true);
    let q0 = attitude(&world.bodies[handle]);
    let (n64, c) = (d(n).normalize(), f64::from(C));
    let (omega, tau) = (
        f64::from(OMEGA) * d(n).length(),
        f64::from(TAU) * d(n).length(),
    );
    let mut exact = ExactRotation::new();
    if with_adapter {
        exact
            .manage(&mut world.bodies, &world.colliders, handle)
            .unwrap();
    }
    let steps = (T / f64::from(dt)).round() as usize;
    for _ in 0..steps {
        if with_adapter {
            exact.step_world(&mut world).unwrap();
        } else {
            world.step();
        }
    }
    let t = steps as f64 * f64::from(dt);
    let phi = omega * t + tau * t * t / (2.0 * c);
    let q_exact = DQuat::from_axis_angle(n64, phi) * q0;
    let l_exact = n64 * (c * omega + tau * t);
    let (q, l) = if with_adapter {
        let now = exact.rotation(handle).unwrap();
        (now.world_from_body, now.l_world)
    } else {
        let rb = &world.bodies[handle];
        (attitude(rb), l_world(rb))
    };
    (angle(q, q_exact), (l - l_exact).length() / l_exact.length())
}

#[test]
fn constant_torque_on_a_sphere_is_first_order_in_dt() {
    let dts = [1.0 / 30.0, 1.0 / 60.0, 1.0 / 120.0, 1.0 / 240.0];
    let (mut errors, mut alone) = (Vec::new(), Vec::new());
    for dt in dts {
        let (q_with, l_with) = sphere_with_torque(dt, true);
        let (q_alone, l_alone) = sphere_with_torque(dt, false);
        // The splitting's leading error: the kick at the step's start
        // turns the body ahead by |τ| t dt / (2c).
        let leading = f64::from(TAU) * T * f64::from(dt) / (2.0 * f64::from(C));
        println!(
            "dt = {dt:.5}: attitude error with adapter {q_with:.3e} rad \
             (leading term |τ| t dt/2c = {leading:.3e}), rapier alone {q_alone:.3e} rad; \
             L error {l_with:.1e} / {l_alone:.1e}"
        );
        // L = L₀ + τt to f32 rounding per step (rapier's ω carries the kick).
        let bound = T / f64::from(dt) * 2.0 * f64::from(f32::EPSILON);
        assert!(l_with <= bound, "{l_with:e} > {bound:e}");
        // The splitting's error is its leading term, to the f32 rounding
        // of ω accumulated over the steps (≤ 2ε per step of the angle φ).
        let phi = f64::from(OMEGA) * T + f64::from(TAU) * T * T / (2.0 * f64::from(C));
        let noise = T / f64::from(dt) * 2.0 * f64::from(f32::EPSILON) * phi;
        assert!(
            (q_with - leading).abs() <= noise,
            "{q_with:e} vs {leading:e} ± {noise:.1e}"
        );
        errors.push(q_with);
        alone.push(q_alone);
    }
    for (k, pair) in alone.windows(2).enumerate() {
        println!(
            "rapier alone, order {} → {}: {:.3}",
            k,
            k + 1,
            (pair[0] / pair[1]).log2()
        );
    }
    for (k, pair) in errors.windows(2).enumerate() {
        let order = (pair[0] / pair[1]).log2();
        println!("order {} → {}: {order:.3}", k, k + 1);
        assert!((0.9..=1.1).contains(&order), "order {order}");
    }
}

/// An asymmetric body tumbling under a constant world torque:
/// `L_world(t) = L₀ + τ t` whatever the attitude does.
#[test]
fn constant_torque_on_an_asymmetric_body_adds_tau_t_to_l() {
    let mut world = free_world();
    let dt = world.integration_parameters.dt;
    let handle = body_with_moments(
        &mut world,
        Vector::new(0.2, 0.45, 0.6),
        Rotation::from_scaled_axis(Vector::new(0.3, -0.2, 0.5)),
        Vector::new(0.1, -0.05, 0.2),
        Rotation::from_scaled_axis(Vector::new(-0.4, 1.1, 0.2)),
        Vector::new(0.4, 2.5, -0.3),
    );
    let tau = Vector::new(0.3, -0.2, 0.5);
    world.bodies[handle].add_torque(tau, true);
    let mut exact = ExactRotation::new();
    exact
        .manage(&mut world.bodies, &world.colliders, handle)
        .unwrap();
    let l0 = exact.rotation(handle).unwrap().l_world;
    let steps = 120;
    let mut worst = 0.0f64;
    let mut l_max = l0.length();
    for k in 1..=steps {
        exact.step_world(&mut world).unwrap();
        let t = k as f64 * f64::from(dt);
        let expected = l0 + d(tau) * t;
        let l = exact.rotation(handle).unwrap().l_world;
        l_max = l_max.max(expected.length());
        worst = worst.max((l - expected).length());
    }
    // Each kick comes through rapier's f32 ω (and its f32 world inertia):
    // a few f32 roundings of |L| per step.
    let bound = steps as f64 * 2.0 * f64::from(f32::EPSILON) * l_max;
    println!("worst |L − (L₀ + τt)| = {worst:.2e} (bound {bound:.2e}, |L| ≤ {l_max:.2})");
    assert!(worst <= bound, "{worst:e} > {bound:e}");
    // The torque moved L far more than that.
    assert!(d(tau).length() * 2.0 > 1e3 * bound);
}

/// rapier's angular damping on a managed free body: ω ← ω/(1 + dt·c)
/// each step (the factor rounded to f32 as rapier computes it), so
/// `|L_n| = |L₀| fⁿ` and L keeps its direction.
#[test]
fn angular_damping_scales_l_by_rapiers_factor() {
    let mut world = free_world();
    let dt = world.integration_parameters.dt;
    let damping = 0.8f32;
    let handle = body_with_moments(
        &mut world,
        Vector::new(0.2, 0.45, 0.6),
        Rotation::from_scaled_axis(Vector::new(0.3, -0.2, 0.5)),
        Vector::ZERO,
        Rotation::from_scaled_axis(Vector::new(-0.4, 1.1, 0.2)),
        Vector::new(0.4, 2.5, -0.3),
    );
    world.bodies[handle].set_angular_damping(damping);
    let mut exact = ExactRotation::new();
    exact
        .manage(&mut world.bodies, &world.colliders, handle)
        .unwrap();
    let l0: DVec3 = exact.rotation(handle).unwrap().l_world;
    let factor = f64::from(1.0f32 / (1.0f32 + dt * damping));
    let steps = 120;
    let (mut worst_norm, mut worst_dir) = (0.0f64, 0.0f64);
    for k in 1..=steps {
        exact.step_world(&mut world).unwrap();
        let l = exact.rotation(handle).unwrap().l_world;
        let expected = l0.length() * factor.powi(k);
        worst_norm = worst_norm.max((l.length() - expected).abs() / expected);
        worst_dir = worst_dir.max(l.normalize().angle_between(l0.normalize()));
    }
    let bound = steps as f64 * 2.0 * f64::from(f32::EPSILON);
    println!(
        "|L| after {steps} steps: {:.6} of the start (fⁿ = {:.6}); worst relative error {worst_norm:.2e}, \
         direction {worst_dir:.2e} rad (bound {bound:.1e})",
        exact.rotation(handle).unwrap().l_world.length() / l0.length(),
        factor.powi(steps)
    );
    assert!(worst_norm <= bound && worst_dir <= bound);
    // Damping took 55 % of L away, a figure the bound cannot hide.
    assert!(factor.powi(steps) < 0.5);
}
