//! The tippe-top demo (`examples/tippe_top/`), run headless as CI runs it
//! (no display): the times it prints against the library's own run of the
//! same top computed here directly (`crates/dynamics/tests/common/tippe_top.rs`: the
//! events' times to the printed digits, the axis' horizontal passage
//! against a fine sampling of that run), the end state and the energy
//! against the library's, Jellett's λ held without drilling friction; the
//! chart and the GIF it writes are checked as files (signature, size,
//! frame count); bad arguments give one line and an error.
//!
//! The demo's modules are compiled into this test (as in `tests/dzhanibekov.rs`).

#[allow(dead_code)]
#[path = "../examples/tippe_top/main.rs"]
mod demo;

mod common;

use std::ffi::OsString;
use std::path::Path;

use glam::DVec3;
use kreisel::dynamics::{TableEventKind, TableMotion};

use common::tippe_top::{contensou_law, table_motion};

/// Runs the demo with `args` and no display; what it printed, or its error.
fn run_demo(args: &[&str]) -> Result<String, String> {
    let mut argv = vec![OsString::from("tippe_top")];
    argv.extend(args.iter().map(OsString::from));
    let mut out = Vec::new();
    demo::run(argv, None, &mut out).map_err(|e| e.to_string())?;
    Ok(String::from_utf8(out).expect("UTF-8 output"))
}

/// The line that starts with `prefix`.
fn line_starting<'a>(printed: &'a str, prefix: &str) -> &'a str {
    printed
        .lines()
        .find(|l| l.starts_with(prefix))
        .unwrap_or_else(|| panic!("no line starting {prefix:?} in\n{printed}"))
}

/// The number after `prefix` in `line`.
fn number_after(line: &str, prefix: &str) -> f64 {
    let at = line
        .find(prefix)
        .unwrap_or_else(|| panic!("no {prefix:?} in {line:?}"))
        + prefix.len();
    line[at..]
        .split(|c: char| !(c.is_ascii_digit() || "+-.e".contains(c)))
        .next()
        .and_then(|w| w.parse().ok())
        .unwrap_or_else(|| panic!("no number after {prefix:?} in {line:?}"))
}

/// The axis' height above the horizontal.
fn axis_z(run: &TableMotion) -> f64 {
    (run.state().world_from_body.normalize() * DVec3::Z).z
}

/// The time of the library's first event of `kind` at `contact`.
fn first(run: &TableMotion, contact: usize, pick: fn(&TableEventKind) -> bool) -> f64 {
    run.events()
        .iter()
        .find(|e| e.contact == Some(contact) && pick(&e.kind))
        .map(|e| e.time)
        .unwrap_or_else(|| panic!("no such event at #{contact}: {:?}", run.events()))
}

#[test]
fn headless_demo_prints_the_library_times_and_writes_chart_and_gif() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("tippe_top_demo");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let (png, gif) = (dir.join("top.png"), dir.join("top.gif"));
    let printed = run_demo(&[
        "--headless",
        "--fps",
        "10",
        "--plot",
        png.to_str().unwrap(),
        "--gif",
        gif.to_str().unwrap(),
    ])
    .expect("the demo runs");
    eprintln!("{printed}");

    // The library's run of the same top (ball and stem, μ = 0.3,
    // Contensou radius 0.5 mm, plastic, tolerance 1e-10), sampled every
    // 1e-4 s up to the stem's landing: the axis' crossings of the
    // horizontal (nutating, it crosses more than once), interpolated
    // linearly between samples.
    let mut run = table_motion(contensou_law(), 1e-10);
    let mut crossings = Vec::new();
    let mut z_prev = axis_z(&run);
    for k in 1..=13_700 {
        let t = f64::from(k) * 1e-4;
        run.try_advance_to(t).unwrap();
        let z = axis_z(&run);
        if (z > 0.0) != (z_prev > 0.0) {
            crossings.push(t - 1e-4 * z / (z - z_prev));
        }
        z_prev = z;
    }
    assert!(
        !crossings.is_empty(),
        "the library's top passes the horizontal"
    );
    let line = line_starting(&printed, "t = ");
    assert!(line.contains("the axis passes the horizontal"), "{line}");
    // Linear interpolation over 1e-4 s is good to ≈ 1e-8 s here; printed
    // to 1e-6 s.
    for (printed_at, library) in [
        (number_after(line, "t = "), crossings[0]),
        (
            number_after(line, "the last at t = "),
            crossings[crossings.len() - 1],
        ),
    ] {
        assert!(
            (printed_at - library).abs() <= 1e-6,
            "demo {printed_at} s, library {library} s"
        );
    }
    assert!(
        line.contains(&format!("it passes it {} times", crossings.len())),
        "{line}: {crossings:?}"
    );
    assert!(
        (crossings[crossings.len() - 1] - 1.017).abs() < 0.01,
        "{crossings:?}"
    );

    // The same top built here from the shared test problem, advanced
    // through the demo's output grid (which the engine's last step of each
    // interval meets exactly): the same motion, so the printed times are
    // the library's event times to the printed digits.
    let mut same = table_motion(contensou_law(), 1e-10);
    for (t, _) in demo::headless::grid(8.0, demo::headless::SAMPLES, 10.0) {
        same.try_advance_to(t).unwrap();
    }
    // A different grid (the last step of each interval shortened
    // elsewhere) moves the events on the tolerance's scale: the landing by
    // 9e-10 s, the stem's last lift-off (after the rocking's accumulation,
    // impacts down to nm/s) by 1e-7 s (measured).
    run.try_advance_to(8.0).unwrap();
    let last_lift = |r: &TableMotion| {
        r.events()
            .iter()
            .rfind(|e| e.contact == Some(1) && e.kind == TableEventKind::LiftOff)
            .map(|e| e.time)
            .unwrap()
    };
    let impact = |k: &TableEventKind| matches!(k, TableEventKind::Impact { .. });
    let (a, b) = (first(&same, 1, impact), first(&run, 1, impact));
    assert!((a - b).abs() < 1e-8, "landing {a} s, {b} s");
    let (a, b) = (last_lift(&same), last_lift(&run));
    assert!(
        (a - b).abs() < 1e-6,
        "the stem's last lift-off {a} s, {b} s"
    );
    let run = same;
    let times: Vec<String> = run
        .events()
        .iter()
        .map(|e| format!("t = {:.6} s", e.time))
        .collect();
    let event_lines: Vec<&str> = printed.lines().filter(|l| l.starts_with("t = ")).collect();
    assert!(event_lines.len() >= 4, "{printed}");
    for line in &event_lines[1..] {
        assert!(
            times.iter().any(|t| line.starts_with(t.as_str())),
            "{line}: not a time of the library's events"
        );
    }
    // The stem lands (plastic) and throws the ball off the table.
    let landing = first(&run, 1, |k| matches!(k, TableEventKind::Impact { .. }));
    let lift_off = first(&run, 0, |k| *k == TableEventKind::LiftOff);
    assert_eq!(lift_off, landing);
    let line = line_starting(&printed, &format!("t = {landing:.6} s: the stem strikes"));
    assert!(
        line.contains("the ball lifts off") && line.ends_with(": on the stem"),
        "{line}"
    );
    assert!((landing - 1.371).abs() < 1e-3, "{landing}");
    // It falls back onto the ball and rocks: the ball's next contact
    // after the lift-off, printed at the library's time; the rocking's
    // impacts accumulate (the last change of contacts of the burst).
    let back = run
        .events()
        .iter()
        .find(|e| e.contact == Some(0) && e.time > lift_off)
        .expect("the ball touches the table again");
    let line = line_starting(
        &printed,
        &format!("t = {:.6} s: the ball strikes", back.time),
    );
    let settled = run
        .events()
        .iter()
        .rfind(|e| matches!(e.kind, TableEventKind::Impact { .. }) && e.time < back.time + 0.5)
        .unwrap();
    assert!(
        line.contains("rocks between ball and stem")
            && line.contains(&format!("accumulating by t ≈ {:.4} s", settled.time))
            && line.ends_with(": on the ball and the stem"),
        "{line}"
    );
    assert!(back.time > 3.5 && back.time < 5.0, "{}", back.time);
    // The end state and the energy: the library's.
    let line = line_starting(&printed, "at t = 8 s: θ = ");
    let theta = axis_z(&run).acos().to_degrees();
    assert_eq!(
        format!("{:.2}", number_after(line, "θ = ")),
        format!("{theta:.2}")
    );
    let body = run.body();
    let e0 = {
        let start = table_motion(contensou_law(), 1e-10);
        start.body().energy(start.state())
    };
    let ratio = body.energy(run.state()) / e0;
    let line = line_starting(&printed, "energy: ");
    assert_eq!(
        format!("{:.4}", number_after(line, "E/E₀ = ")),
        format!("{ratio:.4}")
    );
    assert!(ratio < 0.9, "{line}");
    // Friction and impacts only take energy away.
    assert!(
        line.ends_with("it never rose between the observed instants"),
        "{line}"
    );
    // Contensou's drilling torque changes Jellett's λ even while the ball
    // alone touches (what turns this top over).
    let line = line_starting(&printed, "Jellett's λ");
    let drift = number_after(line, "max |Δλ|/|λ| = ");
    assert!(line.contains("the ball alone (") && drift > 0.1, "{line}");

    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    assert_eq!(&bytes[12..16], b"IHDR");
    let size = |at: usize| u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap());
    assert_eq!((size(16), size(20)), (900, 760));
    assert!(bytes.len() > 20_000, "{} bytes", bytes.len());

    let file = std::fs::File::open(&gif).unwrap();
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options.read_info(file).expect("a GIF");
    assert_eq!((decoder.width(), decoder.height()), (640, 300));
    let mut frames = 0;
    while decoder.read_next_frame().expect("a frame").is_some() {
        frames += 1;
    }
    // One frame per 0.1 s of simulated time, both ends included.
    assert_eq!(frames, 81);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn without_drilling_friction_the_top_rolls_and_keeps_jellett() {
    // Point contacts: the ball's slip stops, it rolls, Jellett's λ about
    // the ball is constant (Jellett 1872) and the top does not invert.
    let printed = run_demo(&[
        "--headless",
        "--duration",
        "1",
        "--contensou-radius",
        "0",
        "--events",
    ])
    .unwrap();
    assert!(
        printed.contains("point contacts (no drilling friction)"),
        "{printed}"
    );
    assert!(
        printed.contains("the axis stays above the horizontal for 1 s"),
        "{printed}"
    );
    let sticks: Vec<&str> = printed
        .lines()
        .filter(|l| l.ends_with("contact #0 sticks"))
        .collect();
    assert_eq!(sticks.len(), 1, "{printed}");
    let line = line_starting(&printed, "Jellett's λ");
    let drift = number_after(line, "the ball alone (1 s): max |Δλ|/|λ| = ");
    assert!(drift <= 1e-9, "{line}");
}

#[test]
fn bad_arguments_are_one_line_errors() {
    for (args, expected) in [
        (&["--friction", "sliding"][..], "--friction"),
        (&["--duration", "-1"][..], "--duration = -1 is out of range"),
        (
            &["--tolerance", "0.1"][..],
            "--tolerance = 0.1 is out of range",
        ),
        (&["--mu", "-0.3"][..], "--mu = -0.3 is out of range"),
        (
            &["--contensou-radius", "-1"][..],
            "--contensou-radius = -1 is out of range",
        ),
        (
            &["--restitution", "1.5"][..],
            "--restitution = 1.5 is out of range",
        ),
        (
            &["--plot", "chart.jpg"][..],
            "the plot is written as .png or .svg",
        ),
        (
            &["--gif", "anim.png"][..],
            "the GIF is written to a .gif file",
        ),
        (
            &["--plot", "/no/such/dir/c.png"][..],
            "no directory /no/such/dir",
        ),
        (&["--speed", "2"][..], "--speed"),
    ] {
        let e = run_demo(args).expect_err("a bad argument");
        assert!(e.contains(expected), "{args:?}: {e}");
        assert_eq!(e.lines().count(), 1, "{args:?}: {e}");
    }
}

#[test]
fn readme_example_prints_what_the_readme_shows() {
    const COMMAND: &str = "cargo run --release --example tippe_top -- ";
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let lines: Vec<&str> = readme.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.starts_with(COMMAND))
        .expect("the README's tippe-top command");
    let rest = &lines[at + 1..];
    let open = rest
        .iter()
        .position(|l| *l == "```text")
        .expect("a ```text block");
    assert!(rest[..open].iter().any(|l| l.trim() == "prints"));
    let expected: Vec<&str> = rest[open + 1..]
        .iter()
        .take_while(|l| !l.starts_with("```"))
        .copied()
        .collect();
    // The chart goes to a scratch directory; its README path (under
    // target/, ignored by git) is put back.
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("tippe_top_readme");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scratch = format!("{}/", dir.display());
    let args: Vec<String> = lines[at][COMMAND.len()..]
        .split_whitespace()
        .map(|a| a.replace("target/", &scratch))
        .collect();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let printed = run_demo(&args).expect("the README's command runs");
    let printed = printed.replace(&scratch, "target/");
    assert_eq!(printed.lines().collect::<Vec<_>>(), expected);
}
