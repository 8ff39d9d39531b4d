//! The Dzhanibekov demo (`examples/dzhanibekov/`), run headless as CI runs
//! it (no display): the GIF, the ω(t) plot, and the printed flip period
//! against the mpmath reference of `tests/data/gen/dzhanibekov.py`.
//!
//! The demo's modules are compiled into this test, so the code under test
//! is the example's own `run`, with `DISPLAY` passed in.

#[allow(dead_code)]
#[path = "../examples/dzhanibekov/main.rs"]
mod demo;

use std::ffi::OsString;
use std::path::{Path, PathBuf};

/// One row of `tests/data/dzhanibekov/flips.csv`.
struct Reference {
    rate: String,
    perturbation: String,
    half_period: f64,
    growth_rate: f64,
    /// The first flip, from mpmath's ODE solver (not the elliptic formula).
    first_flip: f64,
}

fn reference(name: &str) -> Reference {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/dzhanibekov/flips.csv");
    let text = std::fs::read_to_string(&path).expect("reference data");
    let row = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split(',').collect::<Vec<_>>())
        .find(|r| r[0] == name)
        .expect("scenario");
    Reference {
        rate: row[2].to_owned(),
        perturbation: row[3].to_owned(),
        half_period: row[5].parse().unwrap(),
        growth_rate: row[6].parse().unwrap(),
        first_flip: row[7].parse().unwrap_or(f64::NAN),
    }
}

/// Runs the demo with `args`; its output or its error message.
fn run(args: &[&str], display: Option<&str>) -> Result<String, String> {
    let mut argv = vec![OsString::from("dzhanibekov")];
    argv.extend(args.iter().map(OsString::from));
    let mut out = Vec::new();
    demo::run(argv, display.map(OsString::from), &mut out).map_err(|e| e.to_string())?;
    Ok(String::from_utf8(out).expect("UTF-8 output"))
}

/// The instant of the first flip, from the `flip period:` line.
fn first_flip(output: &str) -> f64 {
    let line = output
        .lines()
        .find(|l| l.starts_with("flip period: "))
        .expect("flip period line");
    let (_, rest) = line.split_once("the first at ").expect("format");
    rest.trim_end_matches(" s)").parse().unwrap()
}

/// The (predicted, simulated) values of the `flip period:` line.
fn flip_periods(output: &str) -> (f64, f64) {
    let line = output
        .lines()
        .find(|l| l.starts_with("flip period: predicted "))
        .unwrap_or_else(|| panic!("no flip period line in\n{output}"));
    let rest = line.trim_start_matches("flip period: predicted ");
    let (x, rest) = rest.split_once(" s, simulated ").expect("format");
    let (y, _) = rest.split_once(" s").expect("format");
    (x.parse().unwrap(), y.parse().unwrap())
}

/// A fresh directory for one test's files.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("dzhanibekov_{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn headless_run_writes_the_gif_the_plot_and_the_flip_period() {
    let dir = scratch("files");
    let (gif, png) = (dir.join("flip.gif"), dir.join("omega.png"));
    let out = run(
        &[
            "--headless",
            "--duration",
            "6",
            "--fps",
            "8",
            "--gif-width",
            "320",
            "--gif",
            gif.to_str().unwrap(),
            "--plot",
            png.to_str().unwrap(),
        ],
        None,
    )
    .unwrap();
    // The flip period: simulated (sign changes of ω₂) against predicted
    // (elliptic_motion), and predicted against the 50-digit reference.
    let reference = reference("default");
    let (predicted, simulated) = flip_periods(&out);
    assert!(
        (simulated - predicted).abs() <= 1e-6 * predicted,
        "{predicted} vs {simulated}"
    );
    assert!(
        (predicted - reference.half_period).abs() <= 1e-9 * reference.half_period,
        "{predicted} vs mpmath {}",
        reference.half_period
    );
    let first = first_flip(&out);
    assert!(
        (first - reference.first_flip).abs() <= 1e-9,
        "first flip at {first} s, mpmath's ODE solver {}",
        reference.first_flip
    );
    assert!(out.contains(&format!(
        "λ = Ω √((I₂−I₁)(I₃−I₂)/(I₁I₃)) = {} 1/s",
        demo::report::significant(reference.growth_rate, 6)
    )));
    for needed in [
        "principal moments: I₁ = ",
        "drift over 6 s",
        "energy ",
        "|L| ",
    ] {
        assert!(out.contains(needed), "{needed} missing from\n{out}");
    }
    // The GIF: ≥ 30 frames of the requested size that change.
    let file = std::fs::File::open(&gif).unwrap();
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options.read_info(file).unwrap();
    assert_eq!((decoder.width(), decoder.height()), (320, 160));
    let mut frames = 0;
    let mut changed = 0;
    while let Some(frame) = decoder.read_next_frame().unwrap() {
        frames += 1;
        if frame.width > 1 {
            changed += 1;
        }
    }
    assert!(frames >= 30, "{frames} frames");
    assert!(changed >= frames - 2, "{changed} of {frames} frames change");
    // The plot: a PNG of the chart's size.
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let size = |at: usize| u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap());
    assert_eq!((size(16), size(20)), (960, 440));
}

#[test]
fn integrators_time_the_flips_to_the_reference() {
    // A fast, slightly perturbed spin: three flips in 3.5 s.
    let r = reference("fast_small");
    for (method, dt) in [("splitting8", "0.005"), ("rk4", "0.0005"), ("auto", "0.01")] {
        let out = run(
            &[
                "--headless",
                "--duration",
                "3.5",
                "--spin-rate",
                &r.rate,
                "--perturbation",
                &r.perturbation,
                "--method",
                method,
                "--dt",
                dt,
            ],
            None,
        )
        .unwrap();
        let (predicted, simulated) = flip_periods(&out);
        assert!(
            (simulated - r.half_period).abs() <= 1e-6 * r.half_period,
            "{method}: {simulated} vs {}",
            r.half_period
        );
        assert!((predicted - r.half_period).abs() <= 1e-9 * r.half_period);
        let first = first_flip(&out);
        assert!(
            (first - r.first_flip).abs() <= 1e-6 * r.first_flip,
            "{method}: first flip {first} vs {}",
            r.first_flip
        );
    }
}

#[test]
fn stable_axes_do_not_flip() {
    for axis in ["major", "minor"] {
        let out = run(
            &["--headless", "--duration", "4", "--spin-axis", axis],
            None,
        )
        .unwrap();
        assert!(
            out.contains(&format!(
                "flip period: none predicted (spin about the {axis} axis is stable), 0 flips simulated"
            )),
            "{out}"
        );
    }
}

#[test]
fn without_a_display_it_runs_headless() {
    let out = run(&["--duration", "0.5"], None).unwrap();
    assert!(out.contains("no display (DISPLAY is not set): running headless"));
    assert!(out.contains("flip period: predicted "));
    let out = run(&["--duration", "0.5"], Some(":4321")).unwrap();
    assert!(out.contains("no display (DISPLAY=:4321 but no X server socket /tmp/.X11-unix/X4321)"));
}

#[test]
fn bad_input_is_one_line_of_error() {
    let dir = scratch("bad");
    let jpg = dir.join("omega.jpg");
    for (args, expected) in [
        (vec!["--spin-rate", "0"], "--spin-rate = 0 is out of range"),
        (vec!["--dt", "NaN"], "--dt = NaN is out of range"),
        (vec!["--mesh", "no/such/file.obj"], "no/such/file.obj"),
        (vec!["--method", "euler"], "euler"),
        (
            vec!["--plot", jpg.to_str().unwrap()],
            "is written as .png or .svg",
        ),
        (vec!["--spin-axis", "diagonal"], "diagonal"),
        (vec!["--frobnicate"], "--frobnicate"),
        (
            vec!["--gif", "no/such/dir/flip.gif"],
            "no/such/dir/flip.gif: no directory no/such/dir",
        ),
    ] {
        let mut full = vec!["--headless", "--duration", "0.1"];
        full.extend(args.iter().copied());
        assert!(!jpg.exists());
        let message = run(&full, None).expect_err("refused");
        assert!(message.contains(expected), "{args:?}: {message}");
        assert!(!message.contains('\n'), "{args:?}: {message}");
    }
    // A GIF too large for memory is refused before the run.
    let gif = dir.join("long.gif");
    let message = run(
        &[
            "--headless",
            "--duration",
            "1000",
            "--gif",
            gif.to_str().unwrap(),
        ],
        None,
    )
    .expect_err("refused");
    assert!(
        message.starts_with("the GIF would have 15001 frames of 640 x 320 pixels"),
        "{message}"
    );
    assert!(!gif.exists());
}
