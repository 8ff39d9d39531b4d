//! Bodies on the table (`friction = "coulomb"`, issue 26): the example
//! scenes `bouncing_ball.toml` and `tippe_top_coulomb.toml` run at any
//! `dt` — the user's step is only the grid of the rows, the motion takes
//! its own error-controlled steps — and give the same state at t = 1 s;
//! `--events FILE` lists the impacts at their closed-form times, written
//! whole or not at all; every bad key is a one-line error at its line.

use crate::support::{scratch, simulate_file, workspace};

/// The columns compared between runs.
const COLUMNS: &str = "t,qw,qx,qy,qz,wx,wy,wz,x,y,z,vx,vy,vz,energy";

/// `scene` (a file of `examples/scenes`) with `duration`, `dt` and no
/// `output_interval` (a row after every step), written to a scratch file.
fn variant(scene: &str, duration: f64, dt: f64, tag: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string(workspace(&format!("examples/scenes/{scene}"))).unwrap();
    let lines: Vec<String> = text
        .lines()
        .filter(|l| !l.starts_with("output_interval"))
        .map(|l| {
            if l.starts_with("dt = ") {
                format!("dt = {dt:?}")
            } else if l.starts_with("duration = ") {
                format!("duration = {duration:?}")
            } else {
                l.to_owned()
            }
        })
        .collect();
    scratch(&format!("{tag}_{scene}"), lines.join("\n") + "\n")
}

/// The numbers of the last row of a run with [`COLUMNS`] (exit 0, nothing
/// on standard error), and how many rows it wrote.
fn last_row(path: &std::path::Path) -> (Vec<f64>, usize) {
    let run = simulate_file(path, &["--columns", COLUMNS]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert!(run.stderr.is_empty(), "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines[0], COLUMNS);
    let last = lines.last().unwrap();
    let numbers = last.split(',').map(|x| x.parse().unwrap()).collect();
    (numbers, lines.len() - 1)
}

/// The largest difference between two rows' attitudes (rad, up to sign),
/// positions (m) and relative energies.
fn differences(a: &[f64], b: &[f64]) -> (f64, f64, f64) {
    let q = |r: &[f64]| glam::DQuat::from_xyzw(r[2], r[3], r[4], r[1]).normalize();
    let angle = kreisel_kinematics::rotation_angle_between(q(a), q(b));
    let position = glam::DVec3::new(a[8] - b[8], a[9] - b[9], a[10] - b[10]).length();
    let energy = ((a[14] - b[14]) / b[14]).abs();
    (angle, position, energy)
}

#[test]
fn the_table_scenes_read_the_same_at_one_second_at_any_dt() {
    // The default tolerance, rtol = atol = 1e-10: the tippe top's attitude
    // error measured 280 rtol after its first turn (the library's
    // `table_tolerance` docs), so runs on two grids agree within 3e-8 rad.
    for (scene, bound) in [
        ("tippe_top_coulomb.toml", 3e-8),
        ("bouncing_ball.toml", 1e-10),
    ] {
        let reference = last_row(&variant(scene, 1.0, 1e-3, "ms"));
        assert_eq!(reference.1, 1001);
        for (dt, rows) in [(1.0 / 60.0, 61), (1e-5, 100_001)] {
            let run = last_row(&variant(scene, 1.0, dt, "grid"));
            assert_eq!(run.1, rows, "{scene} at dt = {dt}");
            assert!((run.0[0] - 1.0).abs() < 1e-12);
            let (angle, position, energy) = differences(&run.0, &reference.0);
            eprintln!(
                "{scene}: dt = {dt:e} vs 1e-3 at t = 1 s: {angle:.1e} rad, {position:.1e} m, \
                 energy {energy:.1e}"
            );
            assert!(angle < bound, "{scene} at dt = {dt}: {angle:e} rad");
            assert!(
                position < bound * 0.02,
                "{scene} at dt = {dt}: {position:e} m"
            );
            assert!(energy < bound, "{scene} at dt = {dt}: {energy:e}");
        }
    }
}

/// The rows of an `--events` file: its fields.
fn event_rows(path: &std::path::Path) -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("time,body,contact,kind,approach_speed,rebound_speed,accumulation_time")
    );
    lines
        .map(|l| l.split(',').map(str::to_owned).collect())
        .collect()
}

#[test]
fn the_ball_strikes_first_at_0_42835_s_and_rests_at_the_zeno_point() {
    let events = scratch("ball_events.csv", "");
    let path = workspace("examples/scenes/bouncing_ball.toml");
    let run = simulate_file(
        &path,
        &["--events", events.to_str().unwrap(), "--columns", "t,z,vz"],
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let rows = event_rows(&events);
    // t₁ = √(2 (h − R)/g), v₁ = g t₁; each rebound e times its approach.
    let (g, e): (f64, f64) = (9.81, 0.9);
    let t1 = (2.0 * 0.9 / g).sqrt();
    let first = &rows[0];
    assert_eq!(first[1..4], ["ball", "1", "impact"], "{first:?}");
    let time: f64 = first[0].parse().unwrap();
    assert!((time - 0.42835).abs() < 5e-6, "{time}");
    assert!((time - t1).abs() < 1e-12, "{time} vs {t1}");
    let (approach, rebound): (f64, f64) = (first[4].parse().unwrap(), first[5].parse().unwrap());
    assert!((approach - g * t1).abs() < 1e-10 && (rebound - e * approach).abs() < 1e-12);
    // The bounces accumulate at t₁ (1 + e)/(1 − e), the ball rests there.
    let zeno = t1 * (1.0 + e) / (1.0 - e);
    let rest = rows.last().unwrap();
    assert_eq!(rest[1..4], ["ball", "", "rest"], "{rest:?}");
    let rest_time: f64 = rest[0].parse().unwrap();
    assert!((rest_time - zeno).abs() < 1e-9, "{rest_time} vs {zeno}");
    // The rows end at rest on the table: z = R, no speed.
    let last: Vec<f64> = run
        .stdout
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    assert_eq!(last[0], 10.0);
    assert!((last[1] - 0.1).abs() < 1e-12 && last[2] == 0.0, "{last:?}");
}

#[test]
fn the_tippe_top_turns_over_onto_its_stem_and_its_energy_never_rises() {
    let events = scratch("tippe_events.csv", "");
    let path = workspace("examples/scenes/tippe_top_coulomb.toml");
    let run = simulate_file(
        &path,
        &[
            "--events",
            events.to_str().unwrap(),
            "--columns",
            "t,qx,qy,energy",
        ],
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let rows: Vec<Vec<f64>> = run
        .stdout
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 301);
    for pair in rows.windows(2) {
        // Friction and plastic impacts only dissipate (rounding aside).
        assert!(pair[1][3] <= pair[0][3] * (1.0 + 1e-12), "{pair:?}");
    }
    // The axis e₃ (towards the stem): its world z = 1 − 2 (qx² + qy²).
    let axis_z = |r: &[f64]| 1.0 - 2.0 * (r[1] * r[1] + r[2] * r[2]);
    assert!(axis_z(&rows[0]) > 0.99);
    assert!(axis_z(rows.last().unwrap()) < -0.99, "{:?}", rows.last());
    // The stem (table #2) strikes the table once the top has turned over,
    // and the ball (#1) lifts off there.
    let table = event_rows(&events);
    let stem = table
        .iter()
        .position(|r| r[2] == "2" && r[3] == "impact")
        .expect("the stem strikes the table");
    let t_stem: f64 = table[stem][0].parse().unwrap();
    let turned = rows.iter().find(|r| axis_z(r) < 0.0).expect("turns over")[0];
    assert!(
        t_stem > turned,
        "{t_stem} before the horizontal at {turned}"
    );
    assert!(
        table[stem..]
            .iter()
            .any(|r| r[0] == table[stem][0] && r[2] == "1" && r[3] == "lift_off"),
        "{table:?}"
    );
}

/// Runs `scene` (a body on the table whose contact tables are `contacts`,
/// `extra` keys in the body) and checks the one error line: its line and
/// every needle.
fn check_error(name: &str, extra: &str, contacts: &str, line: u32, needles: &[&str]) {
    let scene = format!(
        "[simulation]\nduration = 1.0\ndt = 0.01\ngravity = [0, 0, -9.81]\n\
         [[body]]\nmass = 1.0\ninertia = [0.004, 0.004, 0.004]\nangular_velocity = [0, 0, 0]\n\
         {extra}{contacts}"
    );
    let path = scratch(name, scene);
    let run = simulate_file(&path, &[]);
    let message = run.error_line(1);
    let prefix = format!("kreisel: error: {}:{line}: body `body1`: ", path.display());
    assert!(message.starts_with(&prefix), "{message}\nexpected {prefix}");
    for needle in needles {
        assert!(message.contains(needle), "{needle} not in {message}");
    }
}

/// A `[[body.contact]]` ball of radius 0.1 m with `friction` and `keys`.
fn ball(friction: &str, keys: &str) -> String {
    format!("[[body.contact]]\nshape = \"sphere\"\nradius = 0.1\nfriction = \"{friction}\"\n{keys}")
}

#[test]
fn bad_coulomb_keys_are_one_line_errors_at_their_line() {
    // Lines: 1-4 [simulation], 5 [[body]] … 8 angular_velocity, then extra
    // keys, then the contact tables.
    let coulomb = |keys: &str| ball("coulomb", keys);
    check_error(
        "mu.toml",
        "",
        &coulomb("mu = -0.1\n"),
        13,
        &["`contact.mu` must be finite and ≥ 0, got -0.1"],
    );
    check_error(
        "restitution.toml",
        "",
        &coulomb("mu = 0.3\nrestitution = 1.5\n"),
        14,
        &["`contact.restitution` must lie in [0, 1], got 1.5"],
    );
    check_error(
        "tangential.toml",
        "",
        &coulomb("mu = 0.3\ntangential_restitution = -1\n"),
        14,
        &["`contact.tangential_restitution` must lie in [0, 1], got -1"],
    );
    check_error(
        "contensou.toml",
        "",
        &coulomb("mu = 0.3\ncontensou_radius = -5e-4\n"),
        14,
        &["`contact.contensou_radius` must be finite and ≥ 0, got -0.0005"],
    );
    check_error(
        "rolling.toml",
        "",
        &coulomb("mu = 0.3\nrolling_resistance = -1e-3\n"),
        14,
        &["`contact.rolling_resistance` must be finite and ≥ 0, got -0.001"],
    );
    check_error(
        "no_mu.toml",
        "",
        &coulomb(""),
        12,
        &["`contact.mu` is missing", "coulomb"],
    );
    check_error(
        "slip.toml",
        "",
        &coulomb("mu = 0.3\nslip_velocity = 1e-3\n"),
        14,
        &["`contact.slip_velocity` is only for friction \"sliding\""],
    );
    // Mixed with another model on one body: at the other friction's line.
    check_error(
        "mixed.toml",
        "",
        &(coulomb("mu = 0.3\n") + &ball("sliding", "mu = 0.3\n")),
        17,
        &["\"sliding\" cannot be mixed with \"coulomb\" on one body (line 12)"],
    );
    // A table without friction on a body on the table.
    let bare = "[[body.contact]]\nshape = \"sphere\"\nradius = 0.1\n";
    check_error(
        "bare.toml",
        "",
        &(coulomb("mu = 0.3\n") + bare),
        15,
        &["`contact.friction` is missing", "table #2"],
    );
    // The keys of "coulomb" on another model.
    check_error(
        "e_on_sliding.toml",
        "",
        &ball("sliding", "mu = 0.3\nrestitution = 0.5\n"),
        14,
        &["`contact.restitution` is only for friction \"coulomb\""],
    );
    check_error(
        "unknown.toml",
        "",
        &ball("coulmb", "mu = 0.3\n"),
        12,
        &["unknown friction model `coulmb`", "rolling, coulomb)"],
    );
    // Loads, and a start inside the table.
    check_error(
        "torque.toml",
        "torque = [0, 0, 1]\n",
        &coulomb("mu = 0.3\n"),
        9,
        &["`torque`: applied loads are not modelled for a body on the table"],
    );
    check_error(
        "sunk.toml",
        "position = [0, 0, 0.05]\n",
        &coulomb("mu = 0.3\n"),
        9,
        &[
            "`position`: [[body.contact]] #1 is below the table at the start (its lowest point at z = -0.05 m)",
        ],
    );
}

#[test]
fn the_events_file_is_written_whole_or_not_at_all() {
    let scene = workspace("examples/scenes/bouncing_ball.toml");
    // Not over the scene.
    let run = simulate_file(&scene, &["--events", scene.to_str().unwrap()]);
    let message = run.error_line(1).to_owned();
    assert!(message.contains("--events"), "{message}");
    // A run that fails (a free body beyond RK4's stability beside the
    // ball) leaves an existing events file as it was.
    let text = std::fs::read_to_string(&scene).unwrap().replace(
        "gravity = [0.0, 0.0, -9.81]",
        "gravity = [0.0, 0.0, -9.81]\nmethod = \"rk4\"",
    ) + "\n[[body]]\nname = \"fast\"\nmass = 1\ninertia = [1, 2, 3]\n\
          angular_velocity = [1e4, 1e2, 0]\n";
    let failing = scratch("failing_ball.toml", text);
    let events = scratch("kept_events.csv", "old\n");
    let run = simulate_file(&failing, &["--events", events.to_str().unwrap()]);
    assert_eq!(run.code, Some(1), "{}", run.stderr);
    assert!(run.stderr.contains("body `fast`"), "{}", run.stderr);
    assert_eq!(std::fs::read_to_string(&events).unwrap(), "old\n");
}

#[test]
fn a_ball_thrown_above_the_table_lands_at_the_closed_form_time() {
    // The centre at 1 m thrown at (1, 0, 2) m/s: the bottom reaches the
    // table when 0.9 + 2 t − g t²/2 = 0; frictionless, x = t throughout.
    let text = std::fs::read_to_string(workspace("examples/scenes/bouncing_ball.toml"))
        .unwrap()
        .replace("duration = 10.0", "duration = 1.0")
        .replace(
            "position = [0.0, 0.0, 1.0]",
            "position = [0.0, 0.0, 1.0]\nvelocity = [1.0, 0.0, 2.0]",
        );
    let path = scratch("thrown_ball.toml", text);
    let events = scratch("thrown_events.csv", "");
    let run = simulate_file(
        &path,
        &["--events", events.to_str().unwrap(), "--columns", "t,x,vx"],
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let g: f64 = 9.81;
    let landing = (2.0 + (4.0 + 2.0 * g * 0.9).sqrt()) / g;
    let first = &event_rows(&events)[0];
    let (time, approach): (f64, f64) = (first[0].parse().unwrap(), first[4].parse().unwrap());
    assert!((time - landing).abs() < 1e-12, "{time} vs {landing}");
    assert!((approach - (g * landing - 2.0)).abs() < 1e-10, "{approach}");
    let last = run.stdout.lines().last().unwrap();
    let numbers: Vec<f64> = last.split(',').map(|x| x.parse().unwrap()).collect();
    assert!(
        (numbers[1] - 1.0).abs() < 1e-12 && numbers[2] == 1.0,
        "{last}"
    );
}
