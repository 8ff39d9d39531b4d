//! Several contact shapes on one body (`[[body.contact]]`): the first is
//! the one it stands on, the others are watched for touchdown.
//! `examples/scenes/tippe_top_stem.toml`, Leine & Glocker's tippe top with
//! its stem ball, stops at the stem's touchdown at the time (and approach
//! speed) of the committed scipy generator of the same equations
//! (`tests/data/contact/tippe_top_touchdown.csv`, `python3
//! tests/data/gen/tippe_top.py --touchdown`), with the rows before it
//! written and unchanged by the watching; every bad watched contact is a
//! one-line error at its line.

use crate::ground::{DOWN, check};
use crate::support::{scratch, simulate_file, workspace};

/// The generator's sliding (ε = 1 mm/s) touchdown: time, s (rtol 1e-13),
/// and approach speed, m/s.
fn generator_touchdown() -> (f64, f64) {
    let path = workspace("tests/data/contact/tippe_top_touchdown.csv");
    let text = std::fs::read_to_string(&path).unwrap();
    let row: Vec<f64> = text
        .lines()
        .find_map(|l| l.strip_prefix("sliding,"))
        .expect("a sliding row")
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    (row[0], row[2])
}

/// The number after `before` in `message`, up to the next space.
fn number_after(message: &str, before: &str) -> f64 {
    let start = message.find(before).unwrap_or_else(|| panic!("{message}")) + before.len();
    message[start..]
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap_or_else(|e| panic!("{e}: {message}"))
}

#[test]
fn the_tippe_top_stem_scene_stops_at_the_generators_touchdown_time() {
    let path = workspace("examples/scenes/tippe_top_stem.toml");
    let explain = simulate_file(&path, &["--explain"]);
    assert!(
        explain.stdout.contains(
            "friction sliding; 1 further contact watched; lift-off or a touchdown stops the run"
        ),
        "{}",
        explain.stdout
    );
    let run = simulate_file(&path, &[]);
    assert_eq!(run.code, Some(1), "{}", run.stderr);
    let message = run.stderr.lines().last().unwrap_or_default();
    // The stem's table starts at line 32 of the scene.
    let prefix = format!(
        "kreisel: error: {}:32: body `tippe`: [[body.contact]] #2 touches down at t = ",
        path.display()
    );
    assert!(message.starts_with(&prefix), "{message}");
    assert!(
        message.ends_with("the impact is not modelled; the run stops there"),
        "{message}"
    );
    let time = number_after(message, "touches down at t = ");
    let speed = number_after(message, "(approach speed ");
    let (t_ref, speed_ref) = generator_touchdown();
    eprintln!(
        "{message}\ngenerator: {t_ref} s, {speed_ref} m/s; Δt/t = {:.1e}",
        (time - t_ref).abs() / t_ref
    );
    assert!((time - t_ref).abs() <= 1e-6 * t_ref, "{time} vs {t_ref}");
    assert!(
        (speed / speed_ref - 1.0).abs() < 1e-5,
        "{speed} vs {speed_ref}"
    );
    // The rows before it are written, every 0.01 s up to 3.82 s, and they
    // are the rows of the same top without the stem, bit for bit.
    let rows: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(rows.len(), 1 + 383, "{}", rows.last().unwrap());
    let last_t: f64 = rows[383].split(',').next().unwrap().parse().unwrap();
    assert!(last_t < time && time - last_t < 0.01, "{last_t} vs {time}");
    let plain = workspace("examples/scenes/tippe_top.toml");
    let text = std::fs::read_to_string(&plain).unwrap();
    assert!(text.contains("duration = 4.0\n"));
    let no_stem = scratch(
        "tippe_top_no_stem.toml",
        text.replace("duration = 4.0\n", "duration = 3.83\n"),
    );
    let plain_run = simulate_file(&no_stem, &[]);
    assert_eq!(plain_run.code, Some(0), "{}", plain_run.stderr);
    let plain_rows: Vec<&str> = plain_run.stdout.lines().collect();
    assert_eq!(rows[..], plain_rows[..rows.len()]);
}

/// `[[body.contact]]` tables: a sphere of radius 0.015 at the centre of
/// mass (lines 10–13, a blank line), then `watched` (from line 15).
fn with_watched(watched: &str) -> String {
    format!(
        "[[body.contact]]\nshape = \"sphere\"\nradius = 0.015\nfriction = \"none\"\n\n\
         [[body.contact]]\n{watched}"
    )
}

#[test]
fn bad_watched_contacts_are_one_line_errors_at_their_line() {
    let stem = "shape = \"sphere\"\nradius = 0.005\ncenter = [0, 0, 0.016]\n";
    let only_first = "is only for the first contact (the one touching): [[body.contact]] #2 \
                      is watched for touchdown and exerts no force";
    check(
        "w_friction.toml",
        DOWN,
        &with_watched(&format!("{stem}friction = \"sliding\"\n")),
        19,
        &["`contact.friction`", only_first],
    );
    check(
        "w_mu.toml",
        DOWN,
        &with_watched(&format!("{stem}mu = 0.3\n")),
        19,
        &["`contact.mu`", only_first],
    );
    check(
        "w_slip.toml",
        DOWN,
        &with_watched(&format!("{stem}slip_velocity = 1e-3\n")),
        19,
        &["`contact.slip_velocity`", only_first],
    );
    // Below the plane at the start: its lowest point at
    // 0.015 − 0.02 − 0.005 = −0.01 m.
    check(
        "w_below.toml",
        DOWN,
        &with_watched("shape = \"sphere\"\nradius = 0.005\ncenter = [0, 0, -0.02]\n"),
        15,
        &[
            "[[body.contact]] #2 is at or below the plane at the start",
            "z = -0.01",
            "must start above the plane",
        ],
    );
    // Touching exactly (gap 0) is not above.
    check(
        "w_touching.toml",
        DOWN,
        &with_watched("shape = \"sphere\"\nradius = 0.015\ncenter = [0.001, 0, 0]\n"),
        15,
        &["[[body.contact]] #2 is at or below the plane", "z = 0 m"],
    );
    // Its shape is checked as the first one's.
    check(
        "w_no_radius.toml",
        DOWN,
        &with_watched("shape = \"sphere\"\ncenter = [0, 0, 0.016]\n"),
        16,
        &["`contact.radius` is missing"],
    );
    check(
        "w_disk_no_normal.toml",
        DOWN,
        &with_watched("shape = \"disk\"\nradius = 0.01\ncenter = [0, 0, 0.016]\n"),
        16,
        &["`contact.normal` is missing"],
    );
    // The first needs its friction.
    check(
        "w_first_no_friction.toml",
        DOWN,
        &format!("[[body.contact]]\n{stem}"),
        11,
        &["`contact.friction` is missing"],
    );
    // At most 1 + 4 tables: the sixth is named.
    let far = "[[body.contact]]\nshape = \"sphere\"\nradius = 0.005\ncenter = [0, 0, 0.05]\n";
    check(
        "w_six.toml",
        DOWN,
        &with_watched(&format!("{stem}{}", far.repeat(4))),
        31,
        &["6 [[body.contact]] tables: at most 5"],
    );
    // Five are fine: the run goes on.
    let five = scratch(
        "w_five.toml",
        format!(
            "[simulation]\nduration = 0.01\ndt = 1e-3\n{DOWN}\n\
             [[body]]\nname = \"b\"\nmass = 0.006\ninertia = [8e-7, 8e-7, 7e-7]\n\
             angular_velocity = [0, 0, 180]\n{}",
            with_watched(&format!("{stem}{}", far.repeat(3)))
        ),
    );
    let run = simulate_file(&five, &[]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
}
