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
    // Numbers out of range and a GIF that is not a .gif are refused before
    // the run, in one line, writing nothing (once: --spin-rate 1e300 printed
    // λ = inf "stable", --gif x.png wrote a GIF into x.png, --dt 1e-12
    // without --duration ran 1e13 steps).
    let png = dir.join("x.png");
    let png_arg = png.to_str().unwrap().to_owned();
    for (args, expected) in [
        (
            vec!["--spin-rate", "1e300"],
            "--spin-rate = 1e300 is out of range",
        ),
        (
            vec!["--spin-rate", "inf"],
            "--spin-rate = inf is out of range",
        ),
        (vec!["--spin-rate=-3"], "--spin-rate = -3 is out of range"),
        (vec!["--dt", "1e-12"], "--dt = 1e-12 is out of range"),
        (vec!["--dt=-0.001"], "--dt = -0.001 is out of range"),
        (vec!["--dt", "2"], "--dt = 2 is out of range"),
        (
            vec!["--dt", "0.05", "--duration", "0.01"],
            "(must be at most --duration",
        ),
        (
            vec!["--spin-rate", "100", "--dt", "0.01"],
            "the handle may turn at most 0.5 rad per step",
        ),
        (
            vec!["--duration", "1e6"],
            "--duration = 1000000 is out of range",
        ),
        (vec!["--duration", "0"], "--duration = 0 is out of range"),
        (
            vec!["--duration", "100", "--dt", "1e-7"],
            "at most 1e8 steps",
        ),
        (
            vec!["--gif", &png_arg],
            "x.png: the GIF is written to a .gif file",
        ),
    ] {
        let message = run(&args, None).expect_err("refused");
        assert!(message.contains(expected), "{args:?}: {message}");
        assert!(
            !message.contains('\n') && message.len() < 200,
            "{args:?}: {message}"
        );
        assert!(!png.exists());
    }
    let gif = dir.join("X.GIF");
    run(
        &[
            "--headless",
            "--duration",
            "0.1",
            "--gif-width",
            "160",
            "--gif",
            gif.to_str().unwrap(),
        ],
        None,
    )
    .expect("a .GIF is a GIF");
    assert!(gif.exists());
}

/// The frames of a headless run with `--gif-width width`, rendered as the
/// GIF recorder renders them (every 1/15 s of simulated time).
fn rendered_frames(duration: f64, width: usize) -> Vec<Vec<u32>> {
    use demo::chart::History;
    use demo::frame::{FrameRenderer, Overlay, STRIP_SAMPLE_INTERVAL, STRIP_WINDOW};
    use demo::physics::{Handle, Prediction, Simulation, Spin, SpinAxis};
    let handle = Handle::load(Path::new(demo::options::DEFAULT_MESH), 7850.0).unwrap();
    let spin = Spin {
        axis: SpinAxis::Intermediate,
        rate: std::f64::consts::TAU,
        perturbation: 0.05,
    };
    let prediction = Prediction::new(handle.moments(), &spin);
    let dt = 1e-3;
    let method = kreisel::dynamics::FreeBodyMethod::Auto;
    let mut sim = Simulation::new(method, &handle, &spin, dt).unwrap();
    let mut renderer = FrameRenderer::new(
        width,
        width / 2,
        &handle,
        spin.rate,
        spin.omega_bound(handle.moments()),
    );
    let mut strip = History::new(Some(STRIP_WINDOW));
    let (mut next_frame, mut next_sample) = (0.0, 0.0);
    let mut frames = Vec::new();
    for i in 0..=(duration / dt).round() as u64 {
        if i > 0 {
            sim.step().unwrap();
        }
        let t = sim.time();
        if t + 0.5 * dt >= next_sample {
            strip.push(t, sim.omega_principal());
            next_sample += STRIP_SAMPLE_INTERVAL;
        }
        if t + 0.5 * dt >= next_frame {
            let overlay = Overlay::of(&sim, &prediction, None);
            let image = renderer.draw(&handle, &sim, &strip, &overlay).unwrap();
            frames.push(image.pixels.clone());
            next_frame += 1.0 / 15.0;
        }
    }
    frames
}

/// Mean and largest per-channel error of a GIF against its source frames.
fn gif_error(bytes: &[u8], frames: &[Vec<u32>]) -> (f64, i32) {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options.read_info(bytes).unwrap();
    let w = usize::from(decoder.width());
    let mut canvas = vec![0u32; frames[0].len()];
    let (mut sum, mut max, mut n) = (0u64, 0i32, 0u64);
    let mut k = 0;
    while let Some(f) = decoder.read_next_frame().unwrap() {
        let (left, top, fw) = (
            usize::from(f.left),
            usize::from(f.top),
            usize::from(f.width),
        );
        for (i, p) in f.buffer.chunks_exact(4).enumerate() {
            if p[3] != 0 {
                canvas[(top + i / fw) * w + left + i % fw] =
                    (u32::from(p[0]) << 16) | (u32::from(p[1]) << 8) | u32::from(p[2]);
            }
        }
        for (&a, &b) in frames[k].iter().zip(&canvas) {
            let e = (0..3)
                .map(|s| (((a >> (8 * s)) & 0xFF) as i32 - ((b >> (8 * s)) & 0xFF) as i32).abs())
                .max()
                .unwrap();
            sum += e as u64;
            max = max.max(e);
            n += 1;
        }
        k += 1;
    }
    assert_eq!(k, frames.len());
    (sum as f64 / n as f64, max)
}

/// The GIF is streamed with its palette from the first frames (8 M pixels:
/// 40 frames at the default 640 × 320, 2.7 s of the run); here at 320 × 160
/// with the same 40 frames against a palette from all 151 frames of the
/// default 10 s run: the error it adds is small, and the memory it holds is
/// the window, whatever the number of frames.
#[test]
fn streamed_palette_keeps_the_quality_of_a_global_one() {
    use demo::gif_out::{GifStream, write_gif};
    let (w, h) = (320usize, 160usize);
    let frames = rendered_frames(10.0, w);
    assert_eq!(frames.len(), 151);
    let mut all = Vec::new();
    write_gif(&mut all, w as u16, h as u16, &frames, 7).unwrap();
    let window = 40 * w * h;
    let mut stream = GifStream::new(Vec::new(), w as u16, h as u16, 7, window).unwrap();
    let mut held = 0;
    for f in &frames {
        stream.push(f).unwrap();
        held = held.max(stream.held_frames());
    }
    let (streamed, stats) = stream.finish().unwrap();
    assert_eq!(held, 39, "frames held back for the palette");
    assert_eq!(stats.frames, 151);
    let (mean_all, max_all) = gif_error(&all, &frames);
    let (mean_stream, max_stream) = gif_error(&streamed, &frames);
    println!(
        "palette from all frames: mean {mean_all:.3}, max {max_all}, {} bytes; \
         from the first 40: mean {mean_stream:.3}, max {max_stream}, {} bytes",
        all.len(),
        streamed.len()
    );
    assert!(
        mean_stream <= 1.2 * mean_all + 0.05,
        "{mean_stream} vs {mean_all}"
    );
    assert!(max_stream <= max_all + 8, "{max_stream} vs {max_all}");
}

/// The GIF and the plot are written to a temporary file beside the target
/// and renamed over it on success: a run whose output cannot be put in
/// place leaves the target as it was and no temporary file; a successful
/// run replaces an old file whole.
#[test]
fn outputs_are_all_or_nothing() {
    let dir = scratch("atomic");
    let listing = |dir: &Path| {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    };
    // A directory in the way: the run completes, the rename fails.
    for (option, name) in [("--gif", "flip.gif"), ("--plot", "omega.png")] {
        let target = dir.join(name);
        std::fs::create_dir(&target).unwrap();
        std::fs::write(target.join("keep"), b"x").unwrap();
        let args = [
            "--headless",
            "--duration",
            "0.2",
            "--gif-width",
            "160",
            option,
            target.to_str().unwrap(),
        ];
        let message = run(&args, None).expect_err("refused");
        assert!(
            message.contains(name) && !message.contains('\n'),
            "{message}"
        );
        assert_eq!(listing(&target), ["keep"]);
        std::fs::remove_dir_all(&target).unwrap();
        assert!(listing(&dir).is_empty(), "{:?}", listing(&dir));
    }
    // An old file is replaced by the whole new GIF.
    let gif = dir.join("old.gif");
    std::fs::write(&gif, b"not a gif").unwrap();
    let out = run(
        &[
            "--headless",
            "--duration",
            "0.5",
            "--gif-width",
            "160",
            "--gif",
            gif.to_str().unwrap(),
        ],
        None,
    )
    .unwrap();
    assert!(out.contains("(8 frames, "), "{out}");
    let bytes = std::fs::read(&gif).unwrap();
    assert!(bytes.starts_with(b"GIF89a") && bytes.ends_with(&[0x3B]));
    assert_eq!(listing(&dir), ["old.gif"]);
}
