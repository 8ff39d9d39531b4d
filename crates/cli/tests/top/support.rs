//! Shared helpers: run `kreisel top`, parse its JSON, ask the library.

use std::path::{Path, PathBuf};

use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial, LagrangeTopMotion};

#[path = "../common/run.rs"]
mod run;
pub use run::{Run, kreisel};

/// One top: I₁, I₃, Mgl, θ₀, θ̇₀, φ̇₀, ψ̇₀.
pub type Case = [f64; 7];

/// Tops of every kind: cusps (fast and slow), loops, waves, hanging,
/// free (Mgl = 0), through the vertical.
pub const CASES: [Case; 7] = [
    [0.3, 0.1, 2.0, 0.5, 0.0, 0.0, 60.0],
    [1.0, 0.5, 1.0, 1.0, 0.0, -1.0, 8.0],
    [1.0, 0.5, 1.0, 1.0, 0.0, 0.3, 8.0],
    [1.25, 0.5, 1.0, 0.8, 0.4, 0.2, 3.0],
    [1.0, 0.5, -2.0, 2.5, 0.3, 0.5, 4.0],
    [2.0, 1.0, 0.0, 0.7, 0.2, 0.3, 5.0],
    [1.0, 0.5, 1.0, 0.3, -2.0, 0.0, 10.0],
];

/// The command-line arguments of a case (after `top`).
pub fn case_args(c: &Case) -> Vec<String> {
    let names = [
        "--i1",
        "--i3",
        "--mgl",
        "--theta0",
        "--theta-dot0",
        "--phi-dot0",
        "--psi-dot0",
    ];
    let mut args = vec!["top".to_owned()];
    for (name, value) in names.iter().zip(c) {
        args.push((*name).to_owned());
        args.push(format!("{value:?}"));
    }
    args
}

/// Runs `kreisel top` for a case with extra arguments.
pub fn run_case(c: &Case, extra: &[&str]) -> Run {
    let mut args = case_args(c);
    args.extend(extra.iter().map(|s| (*s).to_owned()));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    kreisel(&args, "")
}

/// The library's motion for a case.
pub fn motion(c: &Case) -> LagrangeTopMotion {
    LagrangeTop::try_new(c[0], c[1], c[2])
        .expect("valid top")
        .try_solve(LagrangeTopInitial {
            theta: c[3],
            theta_dot: c[4],
            phi_dot: c[5],
            psi_dot: c[6],
            ..LagrangeTopInitial::default()
        })
        .expect("valid initial conditions")
}

/// Parses a successful run's JSON.
pub fn json(run: &Run) -> serde_json::Value {
    assert_eq!(run.code, Some(0), "stderr: {}", run.stderr);
    assert!(run.stderr.is_empty(), "stderr: {}", run.stderr);
    serde_json::from_str(&run.stdout).unwrap_or_else(|e| panic!("{e}: {}", run.stdout))
}

/// The members of the JSON object as written, `key → raw value text`
/// (the report has one member per line). Numbers are then parsed with
/// `f64::from_str`, which is exact (serde_json's default parser is not).
pub fn raw_members(stdout: &str) -> std::collections::BTreeMap<String, String> {
    stdout
        .lines()
        .filter_map(|line| {
            let (key, value) = line.trim().split_once("\": ")?;
            Some((
                key.trim_start_matches('"').to_owned(),
                value.trim_end_matches(',').to_owned(),
            ))
        })
        .collect()
}

/// The scratch directory of this test target (created on first use).
pub fn scratch_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("kreisel-cli-top");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}
