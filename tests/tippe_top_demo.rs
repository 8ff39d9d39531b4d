//! The tippe-top demo (`examples/tippe_top/`), run headless as CI runs it
//! (no display): its printed inversion time against the library's own
//! answer computed here directly (same top, same step, the axis' crossing
//! of the horizontal interpolated linearly between steps) and against
//! Leine & Glocker's published 2.7 s; the chart and the GIF it writes are
//! checked as files (signature, size, frame count); bad arguments give one
//! line and an error.
//!
//! The demo's modules are compiled into this test (as in `tests/dzhanibekov.rs`).

#[allow(dead_code)]
#[path = "../examples/tippe_top/main.rs"]
mod demo;

use std::ffi::OsString;
use std::path::Path;

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel::dynamics::{Friction, GroundTop, SphereContact};

/// Runs the demo with `args` and no display; what it printed, or its error.
fn run_demo(args: &[&str]) -> Result<String, String> {
    let mut argv = vec![OsString::from("tippe_top")];
    argv.extend(args.iter().map(OsString::from));
    let mut out = Vec::new();
    demo::run(argv, None, &mut out).map_err(|e| e.to_string())?;
    Ok(String::from_utf8(out).expect("UTF-8 output"))
}

/// The number after `prefix` on the line that starts with it.
fn number_after(printed: &str, prefix: &str) -> f64 {
    let line = printed
        .lines()
        .find(|l| l.starts_with(prefix))
        .unwrap_or_else(|| panic!("no line starting {prefix:?} in\n{printed}"));
    line[prefix.len()..]
        .split_whitespace()
        .next()
        .and_then(|w| w.parse().ok())
        .unwrap_or_else(|| panic!("no number in {line:?}"))
}

/// The inversion time straight from the library: Leine & Glocker's top
/// (m = 6 g, I₁ = 8e-7, I₃ = 7e-7 kg m², R = 15 mm, a = 3 mm, θ₀ = 0.1 rad,
/// 180 rad/s, sliding μ = 0.3 at 1 mm/s), RK4 steps of `h`, the first
/// downward crossing of the horizontal by the axis, interpolated linearly.
fn library_inversion_time(h: f64, duration: f64) -> Option<f64> {
    let ball = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003)).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
    let friction = Friction::try_sliding(0.3, 1e-3).unwrap();
    let top = GroundTop::try_new(0.006, inertia, ball, friction, 9.81).unwrap();
    let q = DQuat::from_rotation_x(0.1);
    let mut s = top
        .try_state_on_ground(q, q * DVec3::new(0.0, 0.0, 180.0), DVec2::ZERO)
        .unwrap();
    let axis_z = |q: DQuat| (q.normalize() * DVec3::Z).z;
    let mut z_prev = axis_z(s.world_from_body);
    let mut found = None;
    let steps = (duration / h).round() as usize;
    top.try_advance(&mut s, 0.0, h, steps, |t, s| {
        let z = axis_z(s.world_from_body);
        if found.is_none() && z_prev > 0.0 && z <= 0.0 {
            found = Some(t - h * z / (z - z_prev));
        }
        z_prev = z;
    })
    .unwrap();
    found
}

#[test]
fn headless_demo_prints_the_inversion_time_and_writes_chart_and_gif() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("tippe_top_demo");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let (png, gif) = (dir.join("top.png"), dir.join("top.gif"));
    let printed = run_demo(&[
        "--headless",
        "--duration",
        "3",
        "--fps",
        "10",
        "--plot",
        png.to_str().unwrap(),
        "--gif",
        gif.to_str().unwrap(),
    ])
    .expect("the demo runs");
    eprintln!("{printed}");
    let t = number_after(&printed, "inverted at t = ");
    let reference = library_inversion_time(1e-5, 3.0).expect("the library's top inverts");
    eprintln!("demo {t} s, library {reference} s");
    // Printed to 1e-6 s; bisection on the step and linear interpolation
    // between steps agree far closer than that at h = 1e-5 s.
    assert!(
        (t - reference).abs() <= 1e-6,
        "demo {t} s, library {reference} s"
    );
    // Leine & Glocker (2003): 2.7 s, two digits published.
    assert!((t - 2.7).abs() < 0.05, "inverted at {t} s");
    // Jellett's λ is conserved whatever the friction: the demo's own budget line.
    let line = printed.lines().find(|l| l.starts_with("energy: ")).unwrap();
    let lambda: f64 = line.rsplit(" = ").next().unwrap().parse().unwrap();
    assert!(lambda <= 1e-10, "{line}");
    assert!(line.contains("never rose"), "{line}");

    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    assert_eq!(&bytes[12..16], b"IHDR");
    let size = |at: usize| u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap());
    assert_eq!((size(16), size(20)), (900, 780));
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
    assert_eq!(frames, 31);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn frictionless_top_does_not_invert() {
    let printed = run_demo(&["--headless", "--duration", "0.2", "--friction", "none"]).unwrap();
    assert!(printed.contains("not inverted within 0.2 s"), "{printed}");
    let line = printed.lines().find(|l| l.starts_with("energy: ")).unwrap();
    let e = number_after(line, "energy: E/E₀ = ");
    assert!((e - 1.0).abs() < 1e-4, "{line}");
}

#[test]
fn rolling_top_keeps_its_energy_and_jellett() {
    let printed = run_demo(&["--headless", "--duration", "0.5", "--friction", "rolling"]).unwrap();
    assert!(printed.contains("rolling without slipping"), "{printed}");
    assert!(printed.contains("not inverted within 0.5 s"), "{printed}");
    let line = printed.lines().find(|l| l.starts_with("energy: ")).unwrap();
    let e = number_after(line, "energy: E/E₀ = ");
    assert!((e - 1.0).abs() < 1e-4, "{line}");
    let lambda: f64 = line.rsplit(" = ").next().unwrap().parse().unwrap();
    assert!(lambda <= 1e-10, "{line}");
}

#[test]
fn bad_arguments_are_one_line_errors() {
    for (args, expected) in [
        (&["--friction", "coulomb"][..], "coulomb"),
        (&["--duration", "-1"][..], "--duration = -1 is out of range"),
        (&["--dt", "0.1"][..], "--dt = 0.1 is out of range"),
        (&["--mu", "-0.3"][..], "--mu = -0.3 is out of range"),
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
