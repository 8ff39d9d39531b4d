//! The edges of the tippe top's inversion window in the inertia ratio, and
//! the spin after a complete inversion.
//!
//! For a ball-ended top with `α = a/R` (the centre of mass `a` from the
//! ball's centre) and any sliding friction, Rauch-Wojciechowski and
//! co-workers (SIGMA 10 (2014) 017; Bou-Rabee, Marsden & Romero, SIAM J.
//! Appl. Dyn. Syst. 3 (2004) 352) classify where the top ends, by the ratio
//! `r = I₁/I₃`:
//!
//! ```text
//! r < 1 − α          the upright spin (θ = 0) is stable: the top rises to it
//! 1 − α < r < 1 + α  upright is unstable; with λ > λ_thres the top
//!                    turns over fully (θ → π)
//! r > 1 + α          both vertical spins are unstable for this λ: the top
//!                    ends tilted, rolling without slip on the state
//!                    φ̇² = m g R α / (α I₃ + (I₁ − I₃) cos θ),
//!                    |λ| = |φ̇| R [I₁ sin²θ + I₃ (cos θ − α)²]
//! ```
//!
//! Each edge is crossed here by two tops 2 % on either side of it, all with
//! the same start (Leine & Glocker's geometry and spin, viscous friction),
//! and where the window gives a threshold the spin is well above it. The
//! references are these inequalities and the tilted state's equations,
//! solved here by bisection: nothing the integrator computes.

mod common;

use glam::{DMat3, DQuat, DVec2, DVec3};
use std::f64::consts::PI;

use kreisel_dynamics::{AdaptiveTolerance, Friction, GroundTop, GroundTopState, SphereContact};

use common::tippe_top::{A, G, I1, I3, M, OMEGA0, R, THETA0};

/// `α = a/R` of Leine & Glocker's top.
const ALPHA: f64 = A / R;

/// A top with `I₁ = ratio · I₃` after `duration` s, spun at `spin` rad/s
/// about its axis from θ₀: the top, its state and the largest relative
/// change of Jellett's λ on the way.
fn run(ratio: f64, spin: f64, duration: f64) -> (GroundTop, GroundTopState, f64) {
    let sphere = SphereContact::try_new(R, DVec3::new(0.0, 0.0, A)).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(ratio * I3, ratio * I3, I3));
    let friction = Friction::try_viscous(0.3).unwrap();
    let top = GroundTop::try_new(M, inertia, sphere, friction, G).unwrap();
    let q = DQuat::from_rotation_x(THETA0);
    let mut s = top
        .try_state_on_ground(q, q * DVec3::new(0.0, 0.0, spin), DVec2::ZERO)
        .unwrap();
    let lambda0 = top.jellett(&s);
    let mut drift = 0.0f64;
    let tol = AdaptiveTolerance::try_new(1e-11, 1e-13).unwrap();
    top.try_advance_adaptive(&mut s, 0.0, duration, tol, |_, s| {
        drift = drift.max((top.jellett(s) / lambda0 - 1.0).abs());
    })
    .unwrap();
    (top, s, drift)
}

/// The tilt θ of the symmetry axis, rad (atan2: exact near 0 and π).
fn tilt(s: &GroundTopState) -> f64 {
    let axis = s.world_from_body.normalize() * DVec3::Z;
    axis.truncate().length().atan2(axis.z)
}

/// [`run`]'s tilt, slip speed (m/s) and λ drift.
fn end_state(ratio: f64, spin: f64, duration: f64) -> (f64, f64, f64) {
    let (top, s, drift) = run(ratio, spin, duration);
    (tilt(&s), top.slip_velocity(&s).length(), drift)
}

/// Jellett's λ of a spin `spin` about the axis tilted by θ₀, by hand:
/// `L = I₃ ω ê₃`, `λ = L·(R ẑ − a ê₃) = I₃ ω (R cos θ₀ − a)`.
fn lambda_of_spin(spin: f64) -> f64 {
    I3 * spin * (R * THETA0.cos() - A)
}

/// The threshold `λ_thres = √(m g R³ I₃ α) (1 + α)² / √(1 + α − r)`.
fn lambda_threshold(ratio: f64) -> f64 {
    (M * G * R.powi(3) * I3 * ALPHA).sqrt() * (1.0 + ALPHA).powi(2) / (1.0 + ALPHA - ratio).sqrt()
}

/// The tilted rolling state's θ for `I₁ = ratio · I₃` and Jellett's `λ`:
/// the root of `φ̇(θ) R [I₁ sin²θ + I₃ (cos θ − α)²] = λ` in `(lo, hi)`,
/// where the residual changes sign.
fn tilted_state(ratio: f64, lambda: f64, (mut lo, mut hi): (f64, f64)) -> f64 {
    let i1 = ratio * I3;
    let residual = |th: f64| {
        let rate = (M * G * R * ALPHA / (ALPHA * I3 + (i1 - I3) * th.cos())).sqrt();
        rate * R * (i1 * th.sin().powi(2) + I3 * (th.cos() - ALPHA).powi(2)) - lambda
    };
    assert!(residual(lo).signum() != residual(hi).signum());
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if residual(mid).signum() == residual(lo).signum() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The upper edge `r = 1 + α = 1.2`: at `r = 1.176` (inside) the spin is
/// 1.3 λ_thres and the top turns over; at `r = 1.224` (outside, no
/// threshold) the same spin leaves it tilted on the rolling state.
#[test]
fn the_upper_edge_separates_inversion_from_the_tilted_state() {
    let inside = (1.0 + ALPHA) * 0.98;
    let outside = (1.0 + ALPHA) * 1.02;
    let spin = 1.3 * lambda_threshold(inside) / lambda_of_spin(1.0);
    let (theta_in, _, drift_in) = end_state(inside, spin, 40.0);
    let (theta_out, slip_out, drift_out) = end_state(outside, spin, 80.0);
    // The tilted state exists only while α I₃ + (I₁ − I₃) cos θ > 0.
    let limit = (-ALPHA / (outside - 1.0)).acos();
    let expected = tilted_state(outside, lambda_of_spin(spin), (1.6, limit - 1e-9));
    eprintln!(
        "spin {spin:.3} rad/s; r = {inside:.3}: θ {:.4}°; r = {outside:.3}: θ {:.6}° vs {:.6}° \
         (slip {slip_out:.1e} m/s); λ drift {drift_in:.1e}, {drift_out:.1e}",
        theta_in.to_degrees(),
        theta_out.to_degrees(),
        expected.to_degrees()
    );
    // Measured (tol 1e-11): inside 177.377° after 40 s; outside after 80 s
    // 146.028139° against 146.028143° (7e-8 rad, still settling), slip
    // 4.8e-8 m/s; λ drift 1.0e-11 and 8.5e-11.
    assert!(theta_in > 175f64.to_radians(), "{theta_in}");
    assert!(slip_out < 1e-6, "{slip_out}");
    assert!(
        (theta_out - expected).abs() < 1e-6,
        "{theta_out} vs {expected}"
    );
    assert!(drift_in < 1e-10 && drift_out < 1e-10);
}

/// The lower edge `r = 1 − α = 0.8`: at `r = 0.816` (inside, spin far
/// above its threshold) the top turns over; at `r = 0.784` (outside) the
/// upright spin is stable and the same top rises back to it.
#[test]
fn the_lower_edge_separates_inversion_from_rising_upright() {
    let inside = (1.0 - ALPHA) * 1.02;
    let outside = (1.0 - ALPHA) * 0.98;
    let spin = 180.0;
    assert!(lambda_of_spin(spin) > 2.0 * lambda_threshold(inside));
    let (theta_in, _, drift_in) = end_state(inside, spin, 120.0);
    let (theta_out, slip_out, drift_out) = end_state(outside, spin, 120.0);
    eprintln!(
        "r = {inside:.3}: θ {:.4}°; r = {outside:.3}: θ {:.3e}° (slip {slip_out:.1e} m/s); \
         λ drift {drift_in:.1e}, {drift_out:.1e}",
        theta_in.to_degrees(),
        theta_out.to_degrees(),
    );
    // Measured (tol 1e-11): inside, θ first falls (0.995° at 20 s, 1.44° at
    // 40 s), then rises through 19° at 80 s to 179.9999° at 120 s;
    // outside, θ falls by ×3.5 every 20 s to 1.1e-3° at 120 s; λ drift
    // 4.7e-11 and 1.1e-13.
    assert!(theta_in > 175f64.to_radians(), "{theta_in}");
    assert!(theta_out < 1e-3 * THETA0, "{theta_out}");
    assert!(drift_in < 1e-10 && drift_out < 1e-10);
}

/// The final spin after a complete inversion on Leine & Glocker's top, run
/// until its axis is vertical to round-off. By hand from λ: at the start
/// `L = I₃ ω₀ ê₃`, `λ = I₃ ω₀ (R cos θ₀ − a)`; spinning upside down on the
/// ball (`ê₃ = −ẑ`, ω = ω_z ẑ), `λ = I₃ ω_z (R + a)`, so
/// `ω_z = ω₀ (cos θ₀ − α)/(1 + α)`, and the spin about the body axis
/// changed sign.
#[test]
fn after_a_complete_inversion_the_spin_is_jelletts() {
    let (top, s, drift) = run(I1 / I3, OMEGA0, 150.0);
    let omega = top.omega_world(&s);
    let expected = OMEGA0 * (THETA0.cos() - ALPHA) / (1.0 + ALPHA);
    let spin_body = (s.world_from_body.normalize().conjugate() * omega).z;
    let off = PI - tilt(&s);
    eprintln!(
        "after 150 s: π − θ {off:.1e} rad, ω {omega} vs ω_z {expected} rad/s \
         ({:.1e} relative), λ drift {drift:.1e}",
        omega.z / expected - 1.0
    );
    assert!(off < 1e-6, "{off}");
    assert!(
        (omega.z / expected - 1.0).abs() < 1e-8,
        "{omega} vs {expected}"
    );
    assert!(omega.truncate().length() < 1e-5 * expected);
    assert!(spin_body < 0.0);
    assert!(drift < 1e-10);
}
