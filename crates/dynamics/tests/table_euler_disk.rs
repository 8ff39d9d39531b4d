//! Euler's disk spinning down (issue 26): a thin disk rolling on its rim
//! under Moffatt's air layer (`AirLayer`: the viscous dissipation of the
//! air between disk and table, Moffatt, Nature 404 (2000) 833) follows
//! Moffatt's finite-time singularity
//!
//! ```text
//! sin³α = k (t₀ − t),   k = 2π μ_air a / M,      Ω ∝ (t₀ − t)^(−1/6),   Ω² sin α = 4 g / a
//! ```
//!
//! — the reference: Moffatt's law from the rolling disk's energy
//! `E = (3/2) M g a sin α` and its steady precession (closed forms, not
//! the code's), fitted over two decades of `t₀ − t` (3 s to 0.03 s).
//! The run starts in the exact steady rolling with the centre at rest
//! (`Ω² sin α₀ = 4 g/a`, `ω = −Ω sin α₀ û`, û the rim's lowest direction).
//! Friction μ = 5 keeps the rim rolling to the end of Moffatt's regime
//! (at μ = 0.5 the disk hops at Moffatt's breakdown, 60 ms before t₀, and
//! slips: `tests/table_regressions.rs`).

use glam::DVec3;
use kreisel_dynamics::TableMotion;

mod common;

use common::euler_disk::{A, G, M, MU_AIR, rolling_disk};

/// `(t, sin α, Ω, E)` of the run now (`Ω` the precession of the axis).
fn sample(run: &TableMotion) -> (f64, f64, f64, f64) {
    let state = run.state();
    let n = state.world_from_body.normalize() * DVec3::Z;
    let dn = run.body().omega_world(state).cross(n);
    let horizontal = DVec3::new(n.x, n.y, 0.0);
    let precession = horizontal.cross(dn).z / horizontal.length_squared();
    (
        run.time(),
        DVec3::Z.cross(n).length(),
        precession,
        run.body().energy(state),
    )
}

/// Least squares `y = p + q x`: `(p, q)`.
fn line(points: &[(f64, f64)]) -> (f64, f64) {
    let n = points.len() as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x, b + y));
    let (mx, my) = (sx / n, sy / n);
    let sxy: f64 = points.iter().map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = points.iter().map(|(x, _)| (x - mx) * (x - mx)).sum();
    let q = sxy / sxx;
    (my - q * mx, q)
}

#[test]
fn eulers_disk_follows_moffatts_law_over_two_decades() {
    let alpha0: f64 = 0.2;
    let k = 2.0 * std::f64::consts::PI * MU_AIR * A / M;
    // Moffatt's t₀ from the start (the floor's correction is below 1e-4 here).
    let t0_moffatt = alpha0.sin().powi(3) / k;
    let mut run = rolling_disk(5.0, 1e-5 * A, alpha0, 1e-10);
    let e0 = run.body().energy(run.state());
    let mut samples = vec![sample(&run)];
    // Frames of 1 ms, 0.1 ms once sin α < 0.08, until sin α < 0.015
    // (τ ≈ 2 ms before t₀).
    let mut t = 0.0;
    while samples.last().unwrap().1 > 0.015 {
        t += if samples.last().unwrap().1 > 0.08 {
            1e-3
        } else {
            1e-4
        };
        run.try_advance_to(t).unwrap();
        samples.push(sample(&run));
        assert!(
            t < 2.0 * t0_moffatt,
            "still at sin α = {} at {t} s",
            samples.last().unwrap().1
        );
    }
    // Energy never rises.
    for w in samples.windows(2) {
        assert!(w[1].3 <= w[0].3 + 1e-13 * e0, "energy rose at {} s", w[1].0);
    }
    // sin³α is linear in t: fitted over τ = t₀ − t from 3 s to 0.03 s
    // (two decades; t₀ from the fit itself, refined twice; below 0.03 s
    // the steady rolling breaks down as Moffatt's τ* = (2a/9g)^{3/5} k^{1/5}
    // ≈ 4 ms nears).
    let mut t0_fit = t0_moffatt;
    let mut k_fit = k;
    for _ in 0..3 {
        let window: Vec<(f64, f64)> = samples
            .iter()
            .filter(|s| (0.03..=3.0).contains(&(t0_fit - s.0)))
            .map(|s| (s.0, s.1.powi(3)))
            .collect();
        let (p, q) = line(&window);
        (k_fit, t0_fit) = (-q, -p / q);
    }
    let mut logs_alpha = Vec::new();
    let mut logs_omega = Vec::new();
    let mut worst: (f64, f64) = (0.0, 0.0);
    for s in samples
        .iter()
        .filter(|s| (0.03..=3.0).contains(&(t0_fit - s.0)))
    {
        let tau = t0_fit - s.0;
        let law = (k_fit * tau).powf(1.0 / 3.0);
        let steady = s.2 * s.2 * s.1 * A / (4.0 * G);
        worst.0 = worst.0.max((s.1 / law - 1.0).abs());
        worst.1 = worst.1.max((steady - 1.0).abs());
        logs_alpha.push((tau.ln(), s.1.ln()));
        logs_omega.push((tau.ln(), s.2.abs().ln()));
    }
    let (_, slope_alpha) = line(&logs_alpha);
    let (_, slope_omega) = line(&logs_omega);
    eprintln!(
        "k {k_fit:.6e} (Moffatt {k:.6e}), t0 {t0_fit:.6} s (Moffatt {t0_moffatt:.6}), \
         α ∝ τ^{slope_alpha:.5}, Ω ∝ τ^{slope_omega:.5}, worst |sin α/law − 1| {:.2e}, \
         worst |Ω² sin α a/4g − 1| {:.2e}, steps {:?}",
        worst.0,
        worst.1,
        run.stats()
    );
    // Measured (release, tolerance 1e-10): k 2.2 % below Moffatt's, sin α
    // on the fitted law to 1.5 %, α ∝ τ^0.3357, Ω ∝ τ^-0.1642; Ω² sin α
    // a/4g drifts from 1 to 0.92 (the centre starts to circle: Moffatt's
    // relation is the centre-at-rest rolling's). Moffatt's law is the
    // small-tilt, quasi-steady asymptote: O(α) and O(τ*/τ) off.
    assert!(
        (slope_alpha - 1.0 / 3.0).abs() < 0.005,
        "α ∝ τ^{slope_alpha}"
    );
    assert!(
        (slope_omega + 1.0 / 6.0).abs() < 0.01,
        "Ω ∝ τ^{slope_omega}"
    );
    assert!(worst.0 < 0.02, "sin α off the fitted law by {}", worst.0);
    assert!(worst.1 < 0.1, "Ω² sin α a/4g off 1 by {}", worst.1);
    assert!((k_fit / k - 1.0).abs() < 0.03, "k {k_fit} vs Moffatt {k}");
}
