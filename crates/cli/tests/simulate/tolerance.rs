//! `tolerance`: the scene asks for an accuracy, the plan picks the cheapest
//! method that meets it, `--explain` says which, and the rows stay within
//! it of the default run (rounding level; the library tests check both
//! against mpmath references in `crates/dynamics/tests/world_tolerance.rs`).

use kreisel_kinematics::rotation_angle_between;

use crate::support::{body, simulate, simulation};

fn scene(tolerance: &str, interval: &str) -> String {
    simulation(10.0, 0.01, &format!("{tolerance}{interval}"))
        + &body(
            [1.0, 2.0, 3.0],
            [0.2, 1.0, 0.1],
            "name = \"wheel\"\ntorque_body = [0.5, 0.0, 0.0]",
        )
        + &body([1.0, 2.0, 3.0], [0.2, 1.0, 0.1], "name = \"free\"")
}

#[test]
fn explain_says_what_the_tolerance_chose() {
    let run = simulate(
        "tolerance_explain.toml",
        &scene("tolerance = 1e-6\n", ""),
        &["--explain"],
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with("wheel: forced free body: "),
        "{lines:?}"
    );
    assert!(
        lines[0].contains("; tolerance 1e-6 rad over 10 s: "),
        "{lines:?}"
    );
    // Every step written: RK4 every dt costs less than the exact solution.
    assert!(
        lines[1].starts_with("free: free body stepped by rk4")
            && lines[1].contains("; tolerance 1e-6 rad over 10 s: rk4, predicted"),
        "{lines:?}"
    );
    // Rows every 0.1 s: the exact solution, evaluated at the rows only.
    let sparse = simulate(
        "tolerance_explain.toml",
        &scene("tolerance = 1e-6\n", "output_interval = 0.1\n"),
        &["--explain"],
    );
    let free = sparse.stdout.lines().nth(1).unwrap_or_default();
    assert!(
        free.starts_with("free: asymmetric free body: exact")
            && free.ends_with(
                "exact, no truncation error, about 1.60e3 ns per simulated s (default: 1.60e3)"
            ),
        "{free}"
    );
}

#[test]
fn the_rows_stay_within_the_tolerance_of_the_default_run() {
    let exact = simulate("tolerance_default.toml", &scene("", ""), &[]);
    assert_eq!(exact.code, Some(0), "{}", exact.stderr);
    for tol in [1e-3, 1e-6, 1e-9] {
        let run = simulate(
            "tolerance_run.toml",
            &scene(&format!("tolerance = {tol:e}\n"), ""),
            &[],
        );
        assert_eq!(run.code, Some(0), "{}", run.stderr);
        let (rows, reference) = (run.rows(), exact.rows());
        assert_eq!(rows.len(), reference.len());
        let worst = rows
            .iter()
            .zip(&reference)
            .map(|(a, b)| {
                assert_eq!((a.t, &a.body), (b.t, &b.body));
                rotation_angle_between(a.q, b.q)
            })
            .fold(0.0, f64::max);
        println!("tolerance {tol:e}: worst {worst:.1e} rad");
        assert!(worst <= tol, "{tol:e}: {worst:e}");
    }
}

#[test]
fn bad_tolerances_give_one_line_naming_the_key() {
    for (value, args, needle) in [
        (
            "-1.0",
            &[][..],
            "`tolerance` must be positive and finite, got -1",
        ),
        (
            "nan",
            &[][..],
            "`tolerance` must be positive and finite, got NaN",
        ),
        (
            "1e-6",
            &["--method", "rk4"][..],
            "`tolerance` chooses the method itself, but the method is `rk4`: remove `method` (or --method) or `tolerance`",
        ),
    ] {
        let run = simulate(
            "tolerance_bad.toml",
            &scene(&format!("tolerance = {value}\n"), ""),
            args,
        );
        assert_eq!(run.code, Some(1));
        let line = run.error_line(1);
        assert!(line.contains("tolerance_bad.toml:4: "), "{line}");
        assert!(line.ends_with(needle), "{line}");
    }
}
