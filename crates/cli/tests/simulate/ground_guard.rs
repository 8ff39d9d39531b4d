//! The guard of bodies on the ground (issue 25): `examples/scenes/tippe_top.toml`
//! at a game frame used to exit 0 with |q| ≈ 0.045 and the top 12 cm
//! below the table; with μ = 1000 it gained 0.32 % energy with exit 0.
//! Now each stops with one line that names the body, the time, what
//! drifted and the step; at a step that resolves the motion it runs.

use crate::support::{scratch, simulate_file, workspace};

/// The tippe-top scene with `key = value` lines replaced.
fn tippe(name: &str, changes: &[(&str, &str)]) -> std::path::PathBuf {
    let text = std::fs::read_to_string(workspace("examples/scenes/tippe_top.toml")).unwrap();
    let lines: Vec<String> = text
        .lines()
        .map(|line| {
            changes
                .iter()
                .find(|(key, _)| line.starts_with(&format!("{key} = ")))
                .map_or_else(
                    || line.to_owned(),
                    |(key, value)| format!("{key} = {value}"),
                )
        })
        .collect();
    scratch(name, lines.join("\n"))
}

#[test]
fn a_game_frame_stops_with_the_time_of_its_first_frame() {
    let frame = "0.016666666666666666";
    let path = tippe(
        "guard_frame.toml",
        &[("dt", frame), ("output_interval", frame)],
    );
    let run = simulate_file(&path, &[]);
    assert_eq!(run.code, Some(1), "{}", run.stdout);
    let message = run.stderr.lines().last().unwrap_or_default();
    let expected = format!(
        "kreisel: error: {}: body `tippe`: the ground contact's check failed at t = {frame} s: \
         |q| went from 1 to ",
        path.display()
    );
    assert!(message.starts_with(&expected), "{message}");
    assert!(
        message.ends_with(&format!(
            "(steps of {frame} s are too large for this motion: use a smaller dt)"
        )),
        "{message}"
    );
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
}

#[test]
fn friction_too_stiff_for_the_step_stops_where_the_energy_rises() {
    let path = tippe("guard_stiff.toml", &[("mu", "1000")]);
    let run = simulate_file(&path, &[]);
    assert_eq!(run.code, Some(1), "{}", run.stdout);
    let message = run.stderr.lines().last().unwrap_or_default();
    assert!(
        message.contains("body `tippe`: the ground contact's check failed at t = ")
            && message.contains("the energy rose from ")
            && message.contains("under friction that only dissipates"),
        "{message}"
    );
}

#[test]
fn a_step_that_resolves_the_motion_runs() {
    let path = tippe(
        "guard_fine.toml",
        &[
            ("dt", "1e-4"),
            ("duration", "0.5"),
            ("output_interval", "0.1"),
        ],
    );
    let run = simulate_file(&path, &["--columns", "t,z"]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert_eq!(run.stdout.lines().count(), 1 + 6);
}
