//! Torques and damping on managed free bodies, against closed forms.
//!
//! rapier 0.36 keeps a torque given by `RigidBody::add_torque` until
//! `reset_torques` (it is applied at every step), adds `I_w⁻¹ τ h` to ω at
//! each of its `num_solver_iterations` (4) substeps `h = dt/4`, and
//! multiplies ω by `1/(1 + dt·c)` once per step for an angular damping
//! `c` (`RigidBodyVelocity::apply_damping`, at the velocity writeback).
//! The adapter turns rapier's change of ω over the step into a kick of L,
//! half before the exact flow over dt and half after it: Strang
//! splitting, second order in dt.
//!
//! `cargo test -p kreisel-rapier --test torque_damping -- --nocapture`
//! prints the errors of both engines.

mod common;

use common::{angle, attitude, body_with_moments, d, free_world, l_world, managed, tumbling_body};
use glam::{DQuat, DVec3};
use kreisel_rapier::ExactRotation;
use rapier3d::prelude::*;

/// Sphere moment, kg·m², and the magnitudes of ω₀ (rad/s) and τ (N·m).
const C: f32 = 0.5;
const OMEGA: f32 = 2.0;
const TAU: f32 = 0.5;
/// The time the torque acts, s.
const T: f64 = 2.0;

/// A sphere-inertia body spun about n with a constant torque `tau_dir`·|τ|,
/// stepped `T` seconds at `dt` by rapier alone or with the adapter: its
/// final attitude and L_world, and the start (R₀, ω₀, τ) in f64.
fn sphere_with_torque(
    dt: f32,
    with_adapter: bool,
    tau_dir: Vector,
) -> (DQuat, DVec3, [DVec3; 2], DQuat) {
    let mut world = free_world();
    world.integration_parameters.dt = dt;
    let n = Vector::new(1.0, 2.0, 2.0) / 3.0;
    let handle = body_with_moments(
        &mut world,
        Vector::splat(C),
        Rotation::IDENTITY,
        Vector::ZERO,
        Rotation::from_scaled_axis(Vector::new(0.3, -0.7, 0.2)),
        n * OMEGA,
    );
    world.bodies[handle].add_torque(tau_dir * TAU, true);
    let q0 = attitude(&world.bodies[handle]);
    let start = [d(world.bodies[handle].angvel()), d(tau_dir * TAU)];
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
    let (q, l) = if with_adapter {
        let now = exact.rotation(handle).unwrap();
        (now.world_from_body, now.l_world)
    } else {
        let rb = &world.bodies[handle];
        (attitude(rb), l_world(rb))
    };
    (q, l, start, q0)
}

/// The sphere's motion under a constant torque by RK4 on
/// `q̇ = ½ (0, ω(t)) ⊗ q`, `ω(t) = ω₀ + τ t / c` (world axes), with 20 000
/// steps: an independent reference (≈1e-14 rad).
fn sphere_reference(q0: DQuat, omega0: DVec3, tau: DVec3, t: f64) -> DQuat {
    let c = f64::from(C);
    let f = |time: f64, q: DQuat| {
        let w = omega0 + tau * (time / c);
        DQuat::from_xyzw(w.x, w.y, w.z, 0.0) * q * 0.5
    };
    let n = 20_000;
    let h = t / n as f64;
    let mut q = q0;
    for k in 0..n {
        let t0 = k as f64 * h;
        let k1 = f(t0, q);
        let k2 = f(t0 + h / 2.0, q + k1 * (h / 2.0));
        let k3 = f(t0 + h / 2.0, q + k2 * (h / 2.0));
        let k4 = f(t0 + h, q + k3 * h);
        q = (q + (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0)).normalize();
    }
    q
}

#[test]
fn a_torque_along_the_spin_is_exact_to_rounding() {
    let n = Vector::new(1.0, 2.0, 2.0) / 3.0;
    for dt in [1.0 / 30.0, 1.0 / 60.0, 1.0 / 120.0, 1.0 / 240.0] {
        let (q, l, [omega0, tau], q0) = sphere_with_torque(dt, true, n);
        let (q_alone, ..) = sphere_with_torque(dt, false, n);
        let t = (T / f64::from(dt)).round() * f64::from(dt);
        let c = f64::from(C);
        // Rotation about the fixed axis by |ω₀| t + |τ| t²/(2c); L = c ω₀ + τ t.
        let axis = omega0.normalize();
        let q_exact =
            DQuat::from_axis_angle(axis, omega0.length() * t + tau.length() * t * t / (2.0 * c))
                * q0;
        let l_exact = c * omega0 + tau * t;
        let (e, e_alone) = (angle(q, q_exact), angle(q_alone, q_exact));
        println!(
            "τ ∥ ω, dt = {dt:.5}: attitude error with adapter {e:.2e} rad, rapier alone {e_alone:.2e} rad"
        );
        // K½ Φ K½ is exact here (the rotations commute, ω is linear in t):
        // what is left is the f32 rounding of ω, ≤ 2ε per step of the angle.
        let noise = T / f64::from(dt) * 2.0 * f64::from(f32::EPSILON) * 6.0;
        assert!(e <= noise, "{e:e} > {noise:e}");
        assert!((l - l_exact).length() <= noise * l_exact.length());
        assert!(e_alone > 10.0 * e, "{e_alone:e} vs {e:e}");
    }
}

#[test]
fn a_torque_across_the_spin_is_second_order_in_dt() {
    let across = Vector::new(2.0, -2.0, 1.0) / 3.0 * 4.0;
    // Above the f32 floor: ω read back from rapier rounds the kick to
    // ε|ω| per step, ~3e-5 rad over 240 steps (the τ ∥ ω case shows it).
    let dts = [1.0 / 10.0, 1.0 / 20.0, 1.0 / 40.0];
    let (mut errors, mut alone) = (Vec::new(), Vec::new());
    for dt in dts {
        let (q, _, [omega0, tau], q0) = sphere_with_torque(dt, true, across);
        let (q_alone, ..) = sphere_with_torque(dt, false, across);
        let t = (T / f64::from(dt)).round() * f64::from(dt);
        let reference = sphere_reference(q0, omega0, tau, t);
        let (e, e_alone) = (angle(q, reference), angle(q_alone, reference));
        println!(
            "τ ⊥ ω, dt = {dt:.5}: attitude error with adapter {e:.3e} rad, rapier alone {e_alone:.3e} rad"
        );
        errors.push(e);
        alone.push(e_alone);
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
        assert!((1.8..=2.2).contains(&order), "order {order}");
    }
}

/// An asymmetric body tumbling under a constant world torque:
/// `L_world(t) = L₀ + τ t` whatever the attitude does.
#[test]
fn constant_torque_on_an_asymmetric_body_adds_tau_t_to_l() {
    let mut world = free_world();
    let dt = world.integration_parameters.dt;
    let handle = tumbling_body(&mut world);
    let tau = Vector::new(0.3, -0.2, 0.5);
    world.bodies[handle].add_torque(tau, true);
    let mut exact = managed(&mut world, handle);
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
    let mut exact = managed(&mut world, handle);
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
