//! `--threads N`: the CSV is byte-identical for any N; N = 0 is a one-line
//! error.

use crate::support::{body, simulate, simulation};

/// Several heavy tops, asymmetric free bodies and driven bodies.
fn scene() -> String {
    let mut scene = simulation(
        0.5,
        1e-3,
        "output_interval = 0.05\ngravity = [0.0, 0.0, -9.81]",
    );
    for i in 0..6 {
        let f = f64::from(i);
        scene += &body(
            [0.02, 0.02 + 1e-3 * f, 0.015],
            [0.3, 0.1 * f, 40.0 + f],
            "pivot = [0.0, 0.0, -0.1]",
        );
        scene += &body([1.0, 2.0 + 0.1 * f, 3.0], [0.01, 1.0 + f, 0.2], "");
        scene += &body(
            [1.0, 2.0, 3.0 - 0.1 * f],
            [0.5, 0.1, 1.0],
            &format!("torque_body = [0.1, {f:?}, 0.0]\nforce = [0.0, 1.0, 0.0]"),
        );
    }
    scene
}

#[test]
fn the_csv_is_byte_identical_on_any_number_of_threads() {
    let scene = scene();
    let one = simulate("threads.toml", &scene, &["--threads", "1"]);
    assert_eq!(one.code, Some(0), "{}", one.stderr);
    // 18 bodies, 11 rows each, and a header.
    assert_eq!(one.stdout.lines().count(), 1 + 18 * 11);
    for n in ["3", "2"] {
        let many = simulate("threads.toml", &scene, &["--threads", n]);
        assert_eq!(many.code, Some(0), "{}", many.stderr);
        assert!(one.stdout == many.stdout, "--threads {n} differs from 1");
    }
    // The default (all cores) too.
    assert!(one.stdout == simulate("threads.toml", &scene, &[]).stdout);
}

#[test]
fn zero_threads_is_a_one_line_error() {
    let run = simulate("threads_zero.toml", &scene(), &["--threads", "0"]);
    let line = run.error_line(1);
    assert!(
        line.contains("--threads") && line.contains("at least 1"),
        "{line}"
    );
}
