//! Issue 25: the limits of the closed form through the CLI, against the
//! closed forms they tend to: a top tilted 1e-15 rad from upright, the
//! axis on the downward vertical (θ₀ = π) and next to it, a vanishing spin.

use serde_json::Value;

use crate::support::{json, raw_members, run_case, scratch_dir};

/// A JSON number of the report, exactly as written.
fn num(stdout: &str, key: &str) -> f64 {
    let raw = raw_members(stdout);
    raw[key]
        .parse()
        .unwrap_or_else(|e| panic!("{key}: {}: {e}", raw[key]))
}

fn rel(got: f64, want: f64) -> f64 {
    (got / want - 1.0).abs()
}

/// θ₀ = 1e-15 was "sleeping" (put on the pole) with a CSV starting at
/// θ = 0. Now it nutates like the linearised upright top (two circular
/// modes ω± = (a ± √(a² − 4Mgl/I₁))/2): θ_max/θ₀ = a/√(a² − 4Mgl/I₁),
/// T = 2π/√(a² − 4Mgl/I₁), ⟨φ̇⟩ = ω₋, the same as at θ₀ = 1e-8.
#[test]
fn a_top_1e_15_from_upright_nutates_in_a_tiny_band() {
    let (i1, i3, mgl, psi_dot): (f64, f64, f64, f64) = (0.3, 0.1, 2.0, 60.0);
    let a = i3 * psi_dot / i1;
    let root = (a * a - 4.0 * mgl / i1).sqrt();
    for theta in [1e-8, 1e-15] {
        let csv = scratch_dir().join("tiny_tilt.csv");
        let case = [i1, i3, mgl, theta, 0.0, 0.0, psi_dot];
        let run = run_case(&case, &["--format", "json", "--csv", csv.to_str().unwrap()]);
        let v = json(&run);
        assert_eq!(v["sleeping"], Value::Bool(false), "{theta}");
        assert_eq!(v["motion"], Value::from("cusps"), "{theta}");
        let out = &run.stdout;
        assert!(rel(num(out, "theta_min"), theta) < 1e-15);
        assert!(
            rel(num(out, "theta_max") / theta, a / root) < 1e-12,
            "{theta}"
        );
        let period = num(out, "nutation_period");
        assert!(rel(period, std::f64::consts::TAU / root) < 1e-12, "{theta}");
        assert!(rel(num(out, "mean_precession_rate"), 0.5 * (a - root)) < 1e-9);
        // The CSV starts at θ₀ and covers 3 periods of the band.
        let text = std::fs::read_to_string(&csv).unwrap();
        let first: Vec<f64> = text
            .lines()
            .nth(1)
            .unwrap()
            .split(',')
            .map(|x| x.parse().unwrap())
            .collect();
        assert!(
            rel(first[1], theta) < 1e-15,
            "{theta}: CSV starts at θ = {}",
            first[1]
        );
        let max = text
            .lines()
            .skip(1)
            .map(|l| l.split(',').nth(1).unwrap().parse::<f64>().unwrap())
            .fold(0.0, f64::max);
        assert!(rel(max / theta, a / root) < 1e-6, "{theta}: {max}");
    }
}

/// θ₀ = π with θ̇₀ = 0: the axis on the downward vertical, spinning (the
/// hanging top for Mgl > 0): θ stays π, so there is no nutation — motion,
/// nutation_period and mean_precession_rate (φ is undefined there) are all
/// null (a nutation period was reported with `motion: null`). Next to it
/// (θ₀ = π − 1e-6) the top nutates with the linearised hanging top's
/// period 2π/√(a² + 4Mgl/I₁) and π − θ between (a/√(a² + 4Mgl/I₁))·1e-6 and 1e-6.
#[test]
fn the_axis_on_the_downward_vertical_does_not_nutate() {
    let (i1, i3, mgl, psi_dot): (f64, f64, f64, f64) = (0.3, 0.1, 2.0, 60.0);
    let pi = std::f64::consts::PI;
    let run = run_case(&[i1, i3, mgl, pi, 0.0, 0.0, psi_dot], &["--format", "json"]);
    let v = json(&run);
    for key in ["motion", "nutation_period", "mean_precession_rate"] {
        assert_eq!(v[key], Value::Null, "{key}: {}", run.stdout);
    }
    assert_eq!(v["sleeping"], Value::Bool(false));
    assert_eq!(
        (num(&run.stdout, "theta_min"), num(&run.stdout, "theta_max")),
        (pi, pi)
    );
    // The figure says so too (its caption counted "3 nutation periods").
    let svg = scratch_dir().join("hanging.svg");
    let plot = run_case(
        &[i1, i3, mgl, pi, 0.0, 0.0, psi_dot],
        &["--plot", svg.to_str().unwrap()],
    );
    assert_eq!(plot.code, Some(0), "{}", plot.stderr);
    let svg = std::fs::read_to_string(&svg).unwrap();
    assert!(!svg.contains("nutation periods") && svg.contains("the axis stays where it is"));
    let text = run_case(&[i1, i3, mgl, pi, 0.0, 0.0, psi_dot], &[]);
    assert!(
        text.stdout.contains("\nnutation_period: none\n")
            && text.stdout.contains("\nmotion: none\n")
    );
    let a = i3 * psi_dot / i1;
    let root = (a * a + 4.0 * mgl / i1).sqrt();
    let near = run_case(
        &[i1, i3, mgl, pi - 1e-6, 0.0, 0.0, psi_dot],
        &["--format", "json"],
    );
    let v = json(&near);
    assert_eq!(v["motion"], Value::from("cusps"));
    let out = &near.stdout;
    assert!(rel(num(out, "nutation_period"), std::f64::consts::TAU / root) < 1e-9);
    assert!(rel(pi - num(out, "theta_max"), a / root * 1e-6) < 1e-8);
    assert!(rel(pi - num(out, "theta_min"), 1e-6) < 1e-9);
}

/// A steady precession has no nutation either: motion null, no period,
/// its precession rate φ̇₀.
#[test]
fn a_steady_precession_reports_no_nutation_period() {
    // Slow steady precession at θ = 0.5, ω₃ = 20 (I₁ = 1, I₃ = 0.5, Mgl = 1):
    // I₁ cos θ φ̇² − I₃ω₃ φ̇ + Mgl = 0.
    let (theta, omega3) = (0.5_f64, 20.0);
    let c = theta.cos();
    let slow = kreisel_dynamics::LagrangeTop::new(1.0, 0.5, 1.0)
        .steady_precession_rates(omega3, theta)
        .unwrap()
        .slow;
    assert!(rel(slow, (10.0 - (100.0 - 4.0 * c).sqrt()) / (2.0 * c)) < 1e-14);
    let run = run_case(
        &[1.0, 0.5, 1.0, theta, 0.0, slow, omega3 - slow * c],
        &["--format", "json"],
    );
    let v = json(&run);
    assert_eq!(v["motion"], Value::Null, "{}", run.stdout);
    assert_eq!(v["nutation_period"], Value::Null, "{}", run.stdout);
    assert_eq!(num(&run.stdout, "mean_precession_rate"), slow);
}

/// ψ̇₀ → 0⁺: the pendulum that swings almost through the bottom,
/// T = 2K(cos²(θ₀/2))/√(Mgl/I₁), ⟨φ̇⟩ = π/T (K by the AGM), from 1e-10 down
/// to 1e-300 rad/s (which was refused as "too large": 1 + u₁ underflowed).
/// 5e-324 rad/s, whose I₃ω₃/I₁ underflows to 0, is refused as too small.
#[test]
fn a_vanishing_spin_tends_to_the_pendulum() {
    let (i1, i3, mgl, theta): (f64, f64, f64, f64) = (0.3, 0.1, 2.0, 0.5);
    let m = (0.5 * theta).cos().powi(2);
    let (mut x, mut y) = (1.0_f64, (1.0 - m).sqrt());
    for _ in 0..10 {
        (x, y) = (0.5 * (x + y), (x * y).sqrt());
    }
    let period = std::f64::consts::PI / x / (mgl / i1).sqrt();
    for psi_dot in [1e-10, 1e-100, 1e-140, 1e-200, 1e-300] {
        let run = run_case(
            &[i1, i3, mgl, theta, 0.0, 0.0, psi_dot],
            &["--format", "json"],
        );
        let v = json(&run);
        assert_eq!(v["motion"], Value::from("cusps"));
        assert!(rel(num(&run.stdout, "nutation_period"), period) < 1e-13);
        let mean = num(&run.stdout, "mean_precession_rate");
        assert!(
            rel(mean, std::f64::consts::PI / period) < 1e-11,
            "{psi_dot}: {mean}"
        );
    }
    let run = run_case(&[i1, i3, mgl, theta, 0.0, 0.0, 5e-324], &[]);
    let line = run.error_line(1);
    assert!(line.contains("--psi-dot0: 5e-324: too small"), "{line}");
    // Below the resolution in θ₀ with a stable spin: too small, naming θ₀.
    let run = run_case(&[i1, i3, mgl, 1e-90, 0.0, 0.0, 60.0], &[]);
    let line = run.error_line(1);
    assert!(line.contains("--theta0: 1e-90: too small"), "{line}");
}
