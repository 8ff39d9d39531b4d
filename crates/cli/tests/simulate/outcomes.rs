//! What a run leaves behind when it does not end normally (issue 25):
//! no row holds a number that is not finite; a stepping method beyond its
//! step limit says so; a run stopped at a contact event keeps its rows and
//! its figure up to the event, any other failure writes nothing; a SIGINT
//! or SIGTERM removes the temporary output, and a stale one of a killed
//! process goes at the next run.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::support::{body, scratch, scratch_dir, simulate, simulate_file, simulation, workspace};

/// A fresh directory under the scratch directory.
fn fresh_dir(name: &str) -> PathBuf {
    let dir = scratch_dir().join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

/// The names in `dir`, sorted.
fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// Regression: a free body with `force = [1e200, 0, 0]` exited 0 with
/// `energy = inf` in every row after the first (and wrote its --plot);
/// `torque_body = [0, 0, 1e160]` and `torque = [1e300, 0, 0]` likewise
/// (by the issue). Now each stops at t = 0.1 s with one line, no row holds
/// a number that is not finite, and neither --output nor --plot is written.
#[test]
fn overflowing_inputs_stop_before_a_row_that_is_not_finite() {
    for (k, input) in [
        "force = [1e200, 0, 0]",
        "torque_body = [0, 0, 1e160]",
        "torque = [1e300, 0, 0]",
    ]
    .into_iter()
    .enumerate()
    {
        let scene = format!(
            "{}{}",
            simulation(1.0, 0.1, ""),
            body([1.0, 2.0, 3.0], [0.1, 1.0, 0.0], input)
        );
        let run = simulate(
            &format!("overflow_{k}.toml"),
            &scene,
            &["--columns", "t,energy,x,vx,wx,wz,lx,lz"],
        );
        assert_eq!(run.code, Some(1), "{input}: {}", run.stderr);
        assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
        assert!(
            run.stderr
                .contains("body `body1`: method splitting6 diverged at t = 0.1 s ("),
            "{input}: {}",
            run.stderr
        );
        // The row at t = 0 only, every number finite.
        let lines: Vec<&str> = run.stdout.lines().collect();
        assert_eq!(lines.len(), 2, "{input}: {}", run.stdout);
        for field in lines[1].split(',') {
            assert!(
                field.parse::<f64>().unwrap().is_finite(),
                "{input}: {field}"
            );
        }
        // With --output and --plot: nothing written, the old file kept.
        let dir = fresh_dir(&format!("overflow_{k}"));
        let (csv, png) = (dir.join("run.csv"), dir.join("run.png"));
        fs::write(&csv, "old\n").unwrap();
        let path = scratch(&format!("overflow_{k}.toml"), &scene);
        let run = simulate_file(
            &path,
            &[
                "--output",
                csv.to_str().unwrap(),
                "--plot",
                png.to_str().unwrap(),
            ],
        );
        assert_eq!(run.code, Some(1), "{}", run.stderr);
        assert_eq!(fs::read_to_string(&csv).unwrap(), "old\n");
        assert_eq!(entries(&dir), ["run.csv"], "{input}");
    }
    // The force's message says what to change: not dt.
    let scene = format!(
        "{}{}",
        simulation(1.0, 0.1, ""),
        body([1.0, 2.0, 3.0], [0.1, 1.0, 0.0], "force = [1e200, 0, 0]")
    );
    let run = simulate("overflow_force.toml", &scene, &[]);
    let line = run.stderr.trim_end();
    assert!(
        line.ends_with("(its energy is no longer finite); the scene's torques, forces or speeds are too large for f64"),
        "{line}"
    );
}

/// The scene of the issue: `strang` at dt = 0.5 s on a body spinning at
/// |ω| = 30 rad/s (`I` = (1, 2, 3), ω = (1, 30, 0.5)).
fn strang_scene(dt: f64) -> String {
    format!(
        "{}{}",
        simulation(20.0, dt, "method = \"strang\""),
        body([1.0, 2.0, 3.0], [1.0, 30.0, 0.5], "name = \"fast\"")
    )
}

/// Regression: strang at dt = 0.5 with |ω| = 30 swung the energy between
/// 0.67 and 1.98 times its start (inside the factor-10 guard) and exited 0
/// without a word. Now --explain prints dt·ω_max against strang's step
/// limit and the run warns on standard error (it still runs: exit 0).
#[test]
fn a_method_beyond_its_step_limit_says_so() {
    let run = simulate("strang_dt05.toml", &strang_scene(0.5), &[]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let warning = "body `fast`: dt·ω_max = 30.014 is beyond strang's step limit 1.8 \
                   (energy errors above 10 % or failed steps); use dt <= 3.00e-2 s or the \
                   default method (auto)\n";
    assert!(
        run.stderr.starts_with("kreisel: warning: "),
        "{}",
        run.stderr
    );
    assert!(run.stderr.ends_with(warning), "{}", run.stderr);
    assert_eq!(run.stderr.lines().count(), 1);
    // The rows it warns about: the energy is far from its start.
    let energies: Vec<f64> = run
        .stdout
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(9).unwrap().parse().unwrap())
        .collect();
    let (lo, hi) = energies
        .iter()
        .fold((f64::MAX, 0.0f64), |(lo, hi), &e| (lo.min(e), hi.max(e)));
    assert!(
        lo < 0.8 * energies[0] && hi > 1.5 * energies[0],
        "{lo} {hi}"
    );
    let explain = simulate("strang_dt05.toml", &strang_scene(0.5), &["--explain"]);
    assert_eq!(
        explain.stdout,
        "fast: free body stepped by strang (order 2) every dt (the method chosen); \
         dt·ω_max = 30.014 (strang's step limit 1.8: beyond it)\n"
    );
    // Inside the limit: no warning, and --explain says how far inside.
    let run = simulate(
        "strang_dt001.toml",
        &strang_scene(0.01),
        &["--output", "/dev/null"],
    );
    assert_eq!((run.code, run.stderr.as_str()), (Some(0), ""));
    let explain = simulate("strang_dt001.toml", &strang_scene(0.01), &["--explain"]);
    assert!(
        explain
            .stdout
            .ends_with("dt·ω_max = 0.600 (strang's step limit 1.8)\n"),
        "{}",
        explain.stdout
    );
    // The exact default has no limit, hence no note.
    let explain = simulate(
        "strang_auto.toml",
        &strang_scene(0.5),
        &["--explain", "--method", "auto"],
    );
    assert!(!explain.stdout.contains("dt·ω_max"), "{}", explain.stdout);
}

/// Regression: the stem scene stops at a touchdown; with --output the CSV
/// held the rows before it but --plot wrote nothing. Now both hold the
/// motion up to the event, and the run exits 1 with the one-line event.
#[test]
fn a_run_stopped_at_an_event_keeps_its_rows_and_figure() {
    let dir = fresh_dir("event");
    let (csv, png) = (dir.join("stem.csv"), dir.join("stem.png"));
    fs::write(&csv, "old\n").unwrap();
    let run = simulate_file(
        &workspace("examples/scenes/tippe_top_stem.toml"),
        &[
            "--output",
            csv.to_str().unwrap(),
            "--plot",
            png.to_str().unwrap(),
        ],
    );
    let line = run.error_line(1);
    assert!(line.contains("touches down at t = 3.82"), "{line}");
    assert_eq!(entries(&dir), ["stem.csv", "stem.png"]);
    let text = fs::read_to_string(&csv).unwrap();
    let last: f64 = text
        .lines()
        .last()
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(text.starts_with("t,body,"), "{}", &text[..40]);
    // Rows every 0.01 s up to the last before the touchdown.
    assert!((3.81..3.83).contains(&last), "{last}");
    assert_eq!(text.lines().count(), 1 + 383);
    assert!(fs::read(&png).unwrap().starts_with(b"\x89PNG"));
}

/// A divergence writes nothing: an existing --output file stays as it was
/// (the rows before it were moved by a step far beyond the method's
/// stability, not a motion to keep), and no --plot appears.
#[test]
fn a_divergence_writes_nothing() {
    let dir = fresh_dir("diverged");
    let (csv, png) = (dir.join("run.csv"), dir.join("run.png"));
    fs::write(&csv, "old\n").unwrap();
    let scene = format!(
        "{}{}",
        simulation(1.0, 0.01, ""),
        body([1.0, 2.0, 3.0], [1e4, 200.0, 0.0], "name = \"fast\"")
    );
    let path = scratch("diverged_rk4.toml", &scene);
    let run = simulate_file(
        &path,
        &[
            "--method",
            "rk4",
            "--output",
            csv.to_str().unwrap(),
            "--plot",
            png.to_str().unwrap(),
        ],
    );
    assert_eq!(run.code, Some(1), "{}", run.stderr);
    assert!(
        run.stderr.contains("method rk4 diverged at t = 0.01 s"),
        "{}",
        run.stderr
    );
    assert_eq!(fs::read_to_string(&csv).unwrap(), "old\n");
    assert_eq!(entries(&dir), ["run.csv"]);
}

/// A run long enough to be interrupted: rk4 on one body, a row every step.
fn long_scene() -> String {
    format!(
        "{}{}",
        simulation(1e5, 1e-4, "method = \"rk4\""),
        body([1.0, 2.0, 3.0], [0.1, 1.0, 0.0], "")
    )
}

/// The temporary files in `dir`.
fn temporaries(dir: &Path) -> Vec<String> {
    entries(dir)
        .into_iter()
        .filter(|f| f.ends_with(".tmp"))
        .collect()
}

/// Regression: SIGINT and SIGTERM left `.NAME.kreisel-PID-0.tmp` (80-117 MB
/// seen) beside the output. Now the temporary file is removed, the old
/// output is untouched and the exit status is the shell's (130, 143).
#[cfg(unix)]
#[test]
fn a_signal_removes_the_temporary_output() {
    for (signal, status) in [("INT", 130), ("TERM", 143)] {
        let dir = fresh_dir(&format!("signal_{signal}"));
        let csv = dir.join("run.csv");
        fs::write(&csv, "old\n").unwrap();
        let scene = scratch(&format!("long_{signal}.toml"), long_scene());
        let mut child = Command::new(env!("CARGO_BIN_EXE_kreisel"))
            .args([
                "simulate",
                scene.to_str().unwrap(),
                "--output",
                csv.to_str().unwrap(),
            ])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        // Wait until the temporary file holds rows.
        let start = Instant::now();
        loop {
            let written = temporaries(&dir)
                .iter()
                .any(|t| fs::metadata(dir.join(t)).is_ok_and(|m| m.len() > 100_000));
            if written {
                break;
            }
            assert!(
                start.elapsed() < Duration::from_secs(60),
                "no temporary file: {:?}",
                entries(&dir)
            );
            std::thread::sleep(Duration::from_millis(20));
        }
        let killed = Command::new("kill")
            .args([&format!("-{signal}"), &child.id().to_string()])
            .status()
            .unwrap();
        assert!(killed.success());
        let exit = child.wait().unwrap();
        assert_eq!(exit.code(), Some(status), "SIG{signal}: {exit:?}");
        assert_eq!(entries(&dir), ["run.csv"], "SIG{signal}");
        assert_eq!(fs::read_to_string(&csv).unwrap(), "old\n");
    }
}

/// After a SIGKILL (which cannot be caught) the temporary file stays; the
/// next run writing the same output removes it (its process is gone), and
/// keeps one of a live process and another output's.
#[test]
fn the_next_run_removes_a_stale_temporary() {
    let dir = fresh_dir("stale");
    let csv = dir.join("run.csv");
    // Above Linux's largest pid (2^22): no such process.
    let stale = dir.join(".run.csv.kreisel-4194305-0.tmp");
    fs::write(&stale, "half a row").unwrap();
    let other = dir.join(".other.csv.kreisel-4194305-0.tmp");
    fs::write(&other, "x").unwrap();
    // This test's own process is alive.
    let live = dir.join(format!(".run.csv.kreisel-{}-0.tmp", std::process::id()));
    fs::write(&live, "x").unwrap();
    let scene = format!(
        "{}{}",
        simulation(1.0, 0.1, ""),
        body([1.0, 2.0, 3.0], [0.1, 1.0, 0.0], "")
    );
    let path = scratch("stale.toml", &scene);
    let run = simulate_file(&path, &["--output", csv.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (Some(0), ""));
    let mut expected = vec![
        ".other.csv.kreisel-4194305-0.tmp".to_owned(),
        live.file_name().unwrap().to_string_lossy().into_owned(),
        "run.csv".to_owned(),
    ];
    if !Path::new("/proc/self").exists() {
        // Without /proc nothing is known to be dead: nothing is removed.
        expected.push(".run.csv.kreisel-4194305-0.tmp".to_owned());
    }
    expected.sort();
    assert_eq!(entries(&dir), expected);
}
