//! A ball dropped on the table (issue 26): Newton's restitution, the
//! bounces' times and heights against the closed form, the accumulation of
//! infinitely many bounces in finite time (the Zeno point) and rest.
//!
//! Closed form (centre dropped from h₀ = 1 m, radius R = 0.1 m, e = 0.9,
//! g = 9.81 m/s²): the bottom falls d = h₀ − R, strikes at
//! `t₁ = √(2d/g)` with `v₁ = √(2 g d)`; after impact n it rises at
//! `eⁿ v₁` to `R + e²ⁿ d`, strikes again `2 eⁿ v₁/g` later; the bounces
//! accumulate at `t∞ = t₁ + 2 e v₁/(g (1 − e))`.

mod common;

use kreisel_dynamics::TableMotion;

use common::bounces::{Bounces, assert_accumulates_at};
use common::bouncing_ball::{E, G, H0, R, dropped_ball};

fn ball_run(rtol: f64) -> TableMotion {
    dropped_ball(rtol)
}

/// `(t₁, v₁)`.
fn first_impact() -> (f64, f64) {
    let d = H0 - R;
    ((2.0 * d / G).sqrt(), (2.0 * G * d).sqrt())
}

#[test]
fn impact_times_and_apex_heights_follow_the_closed_form() {
    let mut run = ball_run(1e-12);
    let (t1, v1) = first_impact();
    assert!((t1 - 0.42835).abs() < 1e-5, "t1 = {t1}");
    let d = H0 - R;
    let bounces = Bounces { t1, v1, e: E, g: G };
    bounces.assert_followed(&mut run, 20, &|n| R + E.powi(2 * n) * d, &mut |_| {});
}

#[test]
fn the_bounces_accumulate_at_the_zeno_point_and_the_ball_rests() {
    let mut run = ball_run(1e-12);
    let (t1, v1) = first_impact();
    let zeno = t1 + 2.0 * E * v1 / (G * (1.0 - E));
    // t∞ = t₁ (1 + e)/(1 − e) = 19 t₁ = 8.138706 s (the "8.1384"
    // is a slip: 19 × 0.428353 = 8.13871).
    assert!(
        (zeno - 19.0 * t1).abs() < 1e-12 && (zeno - 8.138706).abs() < 1e-6,
        "{zeno}"
    );
    run.try_advance_to(20.0).unwrap();
    assert!(run.is_resting());
    // At rest on the table: the centre at R, no speed.
    let s = run.state();
    assert!((s.com_world.z - R).abs() < 1e-12 && s.velocity_world.length() < 1e-9);
    // Each rebound is e times its approach, to rounding, but the last:
    // there the bounces are summed and the contact closes.
    let (followed, last_approach) = assert_accumulates_at(&run, zeno, E);
    assert!(followed > 100, "{followed} bounces followed");
    assert!(E * last_approach <= kreisel_dynamics::TABLE_ACCUMULATION * 1.0);
}
