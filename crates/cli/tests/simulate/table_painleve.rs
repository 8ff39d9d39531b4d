//! Painlevé's case on the table is bad input (issue 26): a friction
//! coefficient beyond the bound of the slip a body reaches gives one line
//! naming the body and its contact's `mu` key at its line, exit status 1,
//! and no output file — at the start (here) and during the run (the unit
//! test `a_painleve_case_during_the_run_names_the_slipping_mu` in
//! `src/simulate/stop.rs`).

use crate::support::{scratch, simulate_file};

/// Painlevé's rod: 1 kg, 1 m long (`I = m L²/12` about its middle), a
/// ball of radius `R` at its lower end as its contact, leaning at
/// `θ = atan 2` and sliding end first at 1 m/s. With `ρ` the contact point
/// from the centre of mass, the normal force's coefficient in the gap's
/// acceleration is, for the slip `−x̂`,
///
/// ```text
/// κ = 1/m + (l cos θ)²/I − μ l cos θ (l sin θ + R)/I      (l = L/2)
/// ```
///
/// negative beyond `μ* = (1/m + (l cos θ)²/I) I/(l cos θ (l sin θ + R))`
/// (Painlevé's 4/3 for `R → 0` at this angle).
const L_HALF: f64 = 0.5;
const R: f64 = 0.001;
const I: f64 = 1.0 / 12.0;

fn theta() -> f64 {
    2.0f64.atan()
}

/// `κ` of the rod at friction `mu`, 1/kg.
fn kappa(mu: f64) -> f64 {
    let (s, c) = theta().sin_cos();
    1.0 + (L_HALF * c).powi(2) / I - mu * L_HALF * c * (L_HALF * s + R) / I
}

/// The scene of the rod with friction `mu` (its `mu` key on line 20).
fn rod(mu: f64) -> String {
    let half = theta() / 2.0;
    format!(
        "# Painlevé's rod, sliding end first\n[simulation]\nduration = 0.2\ndt = 0.01\n\
         gravity = [0.0, 0.0, -9.81]\n\n[[body]]\nname = \"rod\"\nmass = 1.0\n\
         inertia = [0.001, {I:?}, {I:?}]\norientation = [{:?}, 0.0, {:?}, 0.0]\n\
         angular_velocity = [0.0, 0.0, 0.0]\nvelocity = [-1.0, 0.0, 0.0]\n\n\
         [[body.contact]]\nshape = \"sphere\"\nradius = {R:?}\ncenter = [-{L_HALF:?}, 0.0, 0.0]\n\
         friction = \"coulomb\"\nmu = {mu:?}\n",
        half.cos(),
        -half.sin()
    )
}

/// Runs the scene at `path` with `--output` (an existing file) and
/// `--events` (none yet): one error line, neither file written; the line.
fn refused(path: &std::path::Path) -> String {
    let output = path.with_extension("csv");
    std::fs::write(&output, "kept\n").unwrap();
    let events = path.with_extension("events.csv");
    let _ = std::fs::remove_file(&events);
    let run = simulate_file(
        path,
        &[
            "--output",
            output.to_str().unwrap(),
            "--events",
            events.to_str().unwrap(),
        ],
    );
    let message = run.error_line(1).to_owned();
    assert_eq!(std::fs::read_to_string(&output).unwrap(), "kept\n");
    assert!(!events.exists(), "{}", events.display());
    message
}

/// The compliance a message prints, 1/kg.
fn compliance_in(message: &str) -> f64 {
    let after = message.split("(compliance ").nth(1).expect("compliance");
    after.split(' ').next().unwrap().parse().unwrap()
}

#[test]
fn painleves_rod_beyond_the_bound_names_its_mu_at_its_line() {
    let bound = (1.0 + (L_HALF * theta().cos()).powi(2) / I) * I
        / (L_HALF * theta().cos() * (L_HALF * theta().sin() + R));
    assert!((bound - 4.0 / 3.0).abs() < 0.01, "{bound}");
    // Below the bound the rod slides (and sticks): the run succeeds.
    let below = scratch("painleve_below.toml", rod(0.98 * bound));
    let run = simulate_file(&below, &[]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    // Beyond it: one line at `mu` (line 20), nothing written.
    let mu = 2.0;
    let path = scratch("painleve_rod.toml", rod(mu));
    let message = &refused(&path);
    let prefix = format!(
        "kreisel: error: {}:20: body `rod`: `contact.mu` = 2 of [[body.contact]] #1 is beyond the \
         Painlevé bound of its slip (the contact is indeterminate at t = 0 s",
        path.display()
    );
    assert!(message.starts_with(&prefix), "{message}\nexpected {prefix}");
    let printed = compliance_in(message);
    assert!(
        (printed - kappa(mu)).abs() < 1e-12,
        "{printed} vs the closed form {}",
        kappa(mu)
    );
}
