//! `--plot`: valid PNG and SVG files of the expected size beside an
//! unchanged CSV, the separatrices drawn only where they exist, the bodies
//! named when there are more than drawn, and one-line errors leaving no
//! files.

use crate::support::{Run, body, kreisel, scratch, scratch_dir, simulation, workspace};

/// Figure width and the height for n drawn bodies (70 + 350 n + 10 px).
const WIDTH: u32 = 1400;
fn height(bodies: u32) -> u32 {
    70 + 350 * bodies + 10
}

/// The stroke colour of the separatrices in the SVG.
const SEPARATRIX: &str = "stroke=\"#c83228\"";

/// Runs `kreisel simulate SCENE ARGS...`.
fn simulate(scene: &std::path::Path, args: &[&str]) -> Run {
    let mut all = vec!["simulate", scene.to_str().unwrap()];
    all.extend_from_slice(args);
    kreisel(&all)
}

/// A fresh path in the scratch directory (removed if present).
fn fresh(name: &str) -> std::path::PathBuf {
    let path = scratch_dir().join(name);
    let _ = std::fs::remove_file(&path);
    path
}

/// The width and height in a PNG's IHDR chunk, after checking the signature.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    assert_eq!(&bytes[12..16], b"IHDR", "IHDR first");
    let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    assert_eq!(be(8), 13, "IHDR length");
    assert_eq!(
        &bytes[bytes.len() - 8..bytes.len() - 4],
        b"IEND",
        "ends with IEND"
    );
    (be(16), be(20))
}

/// The SVG parsed as XML: its root's width and height and the whole text.
fn svg_size(text: &str) -> (u32, u32) {
    let doc = roxmltree::Document::parse(text).expect("well-formed XML");
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    let number = |name: &str| root.attribute(name).unwrap().parse().unwrap();
    (number("width"), number("height"))
}

#[test]
fn png_beside_an_unchanged_csv() {
    let scene = workspace("examples/scenes/dzhanibekov.toml");
    let (csv, png) = (fresh("dzh.csv"), fresh("dzh.png"));
    let run = simulate(
        &scene,
        &[
            "--output",
            csv.to_str().unwrap(),
            "--plot",
            png.to_str().unwrap(),
        ],
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert!(
        run.stdout.is_empty() && run.stderr.is_empty(),
        "{}",
        run.stderr
    );
    let plain = simulate(&scene, &[]);
    assert_eq!(
        std::fs::read_to_string(&csv).unwrap(),
        plain.stdout,
        "the same CSV"
    );
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(png_size(&bytes), (WIDTH, height(1)));
    // The CSV on standard output, the figure to a file.
    let png2 = fresh("dzh2.png");
    let run = simulate(&scene, &["--plot", png2.to_str().unwrap()]);
    assert_eq!(run.stdout, plain.stdout);
    assert_eq!(std::fs::read(&png2).unwrap(), bytes, "deterministic");
}

#[test]
fn svg_with_separatrices_only_for_asymmetric_free_bodies() {
    let bodies = [
        body([1.0, 2.0, 3.0], [0.01, 1.0, 0.0], "name = \"handle\""),
        body([1.0, 1.0, 2.0], [0.3, 0.0, 1.0], "name = \"disc\""),
    ];
    let with = |list: &[&String]| {
        let scene = format!(
            "{}{}",
            simulation(5.0, 0.01, ""),
            list.iter().map(|s| s.as_str()).collect::<String>()
        );
        let path = scratch(&format!("sep{}.toml", list.len()), scene);
        let svg = fresh(&format!("sep{}.svg", list.len()));
        let run = simulate(&path, &["--plot", svg.to_str().unwrap()]);
        assert_eq!(run.code, Some(0), "{}", run.stderr);
        std::fs::read_to_string(&svg).unwrap()
    };
    let both = with(&[&bodies[0], &bodies[1]]);
    assert_eq!(svg_size(&both), (WIDTH, height(2)));
    assert!(both.contains(SEPARATRIX));
    assert!(both.contains("body `handle`") && both.contains("body `disc`"));
    assert!(both.contains("two equal moments: no separatrices"));
    assert!(!both.contains("NaN") && !both.contains("inf"));
    let disc = with(&[&bodies[1]]);
    assert_eq!(svg_size(&disc), (WIDTH, height(1)));
    assert!(!disc.contains(SEPARATRIX), "a symmetric body has none");
}

#[test]
fn more_bodies_than_drawn_are_named() {
    let scene: String = std::iter::once(simulation(1.0, 0.1, ""))
        .chain((1..=6).map(|k| {
            body(
                [1.0, 2.0, 3.0],
                [0.1 * f64::from(k), 1.0, 0.0],
                &format!("name = \"b{k}\""),
            )
        }))
        .collect();
    let path = scratch("six.toml", scene);
    let svg = fresh("six.svg");
    let run = simulate(&path, &["--plot", svg.to_str().unwrap()]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert_eq!(svg_size(&text), (WIDTH, height(4)));
    assert!(
        text.contains("showing the first 4 of 6 bodies: b1, b2, b3, b4"),
        "{}",
        &text[..600]
    );
    assert!(!text.contains("body `b5`"));
    assert!(!text.contains("drawn: 1 row in"), "not thinned");
    // The CSV still has all six.
    assert_eq!(
        run.stdout.lines().filter(|l| l.contains(",b6,")).count(),
        11
    );
}

#[test]
fn long_runs_are_thinned_and_say_so() {
    let scene = format!(
        "{}{}",
        simulation(100.0, 0.01, ""),
        body([1.0, 2.0, 3.0], [0.01, 1.0, 0.0], "")
    );
    let path = scratch("long_plot.toml", scene);
    let svg = fresh("long.svg");
    let run = simulate(&path, &["--plot", svg.to_str().unwrap()]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert_eq!(run.stdout.lines().count(), 10_002, "header and every row");
    let text = std::fs::read_to_string(&svg).unwrap();
    assert_eq!(svg_size(&text), (WIDTH, height(1)));
    // 4000 kept rows halve to 2000 twice: 1 in 4 of 10 001 rows.
    assert!(
        text.contains("drawn: 1 row in 4 of the 10001 rows per body, and the last"),
        "{}",
        &text[..800]
    );
}

#[test]
fn bad_plot_paths_are_one_line_and_leave_no_files() {
    let scene = workspace("examples/scenes/dzhanibekov.toml");
    let csv = fresh("bad_plot.csv");
    let run = simulate(
        &scene,
        &["--output", csv.to_str().unwrap(), "--plot", "run.jpg"],
    );
    let line = run.error_line(1);
    assert!(
        line.contains("--plot: run.jpg: unknown image format"),
        "{line}"
    );
    assert!(!csv.exists());
    // Never over the scene or the CSV.
    let copy = scratch("plot_scene.svg", std::fs::read(&scene).unwrap());
    let run = simulate(&copy, &["--plot", copy.to_str().unwrap()]);
    assert!(run.error_line(1).contains("refusing to overwrite it"));
    let same = fresh("same.svg");
    let run = simulate(
        &scene,
        &[
            "--output",
            same.to_str().unwrap(),
            "--plot",
            same.to_str().unwrap(),
        ],
    );
    assert!(run.error_line(1).contains("--plot: "));
    assert!(!same.exists());
    let missing = scratch_dir().join("no/such/dir/run.png");
    let run = simulate(
        &scene,
        &[
            "--output",
            csv.to_str().unwrap(),
            "--plot",
            missing.to_str().unwrap(),
        ],
    );
    let line = run.error_line(1);
    assert!(line.contains("cannot create the file"), "{line}");
    assert!(!csv.exists(), "no CSV without its figure");
}

#[test]
fn a_diverging_run_leaves_no_figure() {
    // rk4 at a step far beyond its stability: the run stops with an error.
    let scene = format!(
        "{}{}",
        simulation(100.0, 5.0, "method = \"rk4\""),
        body([1.0, 2.0, 3.0], [0.5, 3.0, 1.0], "")
    );
    let path = scratch("diverge_plot.toml", scene);
    let png = fresh("diverge.png");
    let run = simulate(&path, &["--plot", png.to_str().unwrap()]);
    assert_eq!(run.code, Some(1), "{}", run.stderr);
    assert!(run.stderr.contains("diverged"), "{}", run.stderr);
    assert!(!png.exists());
}
