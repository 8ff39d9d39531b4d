//! Integration tests of `kreisel stability`, run through the real binary:
//! the JSON against the notes' closed forms, the map's boundary, the
//! figures, and one-line errors for bad arguments and states.

#[path = "../common/run.rs"]
mod run;

use std::path::{Path, PathBuf};

use run::kreisel;

/// A path under the repository root.
fn repo(path: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(path)
        .display()
        .to_string()
}

fn scratch_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("kreisel-cli-stability");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

fn json(args: &[&str]) -> serde_json::Value {
    let run = kreisel(args, "");
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    serde_json::from_str(&run.stdout).unwrap_or_else(|e| panic!("{e}: {}", run.stdout))
}

// The scene's top: 1 kg, I = (0.02, 0.02, 0.01) about the centre of mass,
// 0.1 m above the pivot: I₁ = 0.03 about the pivot.
const I1: f64 = 0.03;
const I3: f64 = 0.01;
const MGL: f64 = 9.81 * 0.1;

/// Both tops of `sleeping_top.toml` against the notes' §3.11, to 1e-12.
#[test]
fn the_json_gives_the_notes_growth_rate_and_precession_frequencies() {
    let doc = json(&[
        "stability",
        &repo("examples/scenes/sleeping_top.toml"),
        "--format",
        "json",
    ]);
    let bodies = doc["bodies"].as_array().unwrap();
    assert_eq!(bodies.len(), 2);
    for body in bodies {
        let motion = &body["steady_motions"][0];
        assert_eq!(motion["kind"], "sleeping top");
        let spin = motion["parameters"]["spin"].as_f64().unwrap();
        let discriminant = (I3 * spin).powi(2) - 4.0 * I1 * MGL;
        let zero: Vec<&str> = motion["zero_modes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|z| z["kind"].as_str().unwrap())
            .collect();
        assert_eq!(zero, ["Casimir", "momentum"]);
        match body["name"].as_str().unwrap() {
            "slow" => {
                assert_eq!(motion["verdict"], "unstable");
                let growth = motion["growth_rate"].as_f64().unwrap();
                let expected = (-discriminant).sqrt() / (2.0 * I1);
                assert!(
                    (growth / expected - 1.0).abs() < 1e-12,
                    "{growth} vs {expected}"
                );
            }
            "fast" => {
                assert_eq!(motion["verdict"], "stable");
                let mut space: Vec<f64> = motion["space_frequencies"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|v| v.as_f64().unwrap())
                    .collect();
                space.sort_by(f64::total_cmp);
                space.dedup();
                let p = [
                    (I3 * spin - discriminant.sqrt()) / (2.0 * I1),
                    (I3 * spin + discriminant.sqrt()) / (2.0 * I1),
                ];
                assert_eq!(space.len(), 2);
                for (found, expected) in space.iter().zip(p) {
                    assert!(
                        (found / expected - 1.0).abs() < 1e-12,
                        "{found} vs {expected}"
                    );
                }
                assert_eq!(motion["frame"], "body");
            }
            other => panic!("{other}"),
        }
    }
}

/// The map's bisected boundary against √(4 I₁ M g l)/I₃, in the JSON; the
/// grid's verdicts flip once.
#[test]
fn a_sweep_s_boundary_is_the_closed_form() {
    let doc = json(&[
        "stability",
        &repo("examples/scenes/sleeping_top.toml"),
        "--body",
        "fast",
        "--format",
        "json",
        "--sweep",
        "spin=0:80:41",
    ]);
    let map = &doc["bodies"][0]["steady_motions"][0]["map"];
    let boundaries = map["boundaries"].as_array().unwrap();
    assert_eq!(boundaries.len(), 1);
    let found = boundaries[0]["at"][0].as_f64().unwrap();
    let expected = (4.0 * I1 * MGL).sqrt() / I3;
    assert!(
        (found / expected - 1.0).abs() < 1e-12,
        "{found} vs {expected}"
    );
    assert!((boundaries[0]["closed_form"].as_f64().unwrap() / expected - 1.0).abs() < 1e-14);
    let verdicts: Vec<&str> = map["verdicts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert_eq!(verdicts.len(), 41);
    let flips = verdicts
        .windows(2)
        .filter(|w| (w[0] == "unstable") != (w[1] == "unstable"))
        .count();
    assert_eq!(flips, 1);
}

#[test]
fn plots_are_written_as_png_and_svg() {
    for (name, magic) in [("map.png", &b"\x89PNG"[..]), ("map.svg", &b"<svg"[..])] {
        let path = scratch_dir().join(name);
        let _ = std::fs::remove_file(&path);
        let path_text = path.display().to_string();
        let run = kreisel(
            &[
                "stability",
                &repo("examples/scenes/sleeping_top.toml"),
                "--body",
                "fast",
                "--sweep",
                "spin=0:80:20",
                "--sweep",
                "gravity=1:20:10",
                "--plot",
                &path_text,
            ],
            "",
        );
        assert_eq!(run.code, Some(0), "{}", run.stderr);
        let bytes = std::fs::read(&path).unwrap();
        let start = bytes.iter().position(|&b| b == magic[0]).unwrap_or(0);
        assert!(bytes[start..].starts_with(magic), "{name}");
    }
}

#[test]
fn bad_arguments_and_states_get_one_line() {
    let scene = repo("examples/scenes/sleeping_top.toml");
    let cases: [(&[&str], &str); 5] = [
        (
            &["--body", "medium"],
            "--body: no body \"medium\" in the scene (it has fast, slow)",
        ),
        (
            &["--plot", "x.png"],
            "--plot: draws one body's map: give --sweep, and --body when the scene has several bodies",
        ),
        (
            &[
                "--sweep",
                "spin=0:1:3",
                "--sweep",
                "gravity=1:2:3",
                "--sweep",
                "com_offset=0.1:0.2:3",
            ],
            "--sweep: give one or two sweeps (a map of one or two parameters)",
        ),
        (
            &["--body", "fast", "--sweep", "spin=0:1:3", "--plot", "x.jpg"],
            "--plot x.jpg: the file name must end in .png or .svg",
        ),
        (
            &["--sweep", "tilt=0:1:3"],
            "body \"fast\": sweep tilt: a sleeping top has no tilt (it has spin, com_offset, gravity)",
        ),
    ];
    for (extra, message) in cases {
        let mut args = vec!["stability", scene.as_str()];
        args.extend_from_slice(extra);
        let run = kreisel(&args, "");
        let line = run.error_line(1);
        assert!(line.ends_with(message), "{line}");
    }
    // A nutating top: no steady motion near its state, with the residual.
    let run = kreisel(&["stability", &repo("examples/scenes/heavy_top.toml")], "");
    let line = run.error_line(1);
    assert!(
        line.contains("body \"top\": no steady motion near this state: relative residual 7.307e-3"),
        "{line}"
    );
    // Usage errors: clap's, exit 2, naming the sweep.
    for (sweep, says) in [
        ("omega=0:1:3", "unknown parameter \"omega\""),
        ("spin=0:1:1", "N = 1: a sweep needs at least 2 values"),
    ] {
        let run = kreisel(&["stability", &scene, "--sweep", sweep], "");
        assert_eq!(run.code, Some(2));
        assert!(run.stderr.contains(says), "{}", run.stderr);
    }
}

/// `steady = "slow_precession"` names the steady motion at the state's
/// tilt and spin (Bruls' top, horizontal, 150 rad/s, nutating: no steady
/// motion near it); its nutation frequency is the effective potential's,
/// `√((k − 2φ̇ cos θ)² + φ̇² sin²θ)` with `k = I₃ω₃/I₁`, at θ = π/2:
/// `√(k² + φ̇²)`, `φ̇ = M g l/(I₃ω₃)`. A name it does not know is one line
/// with the key's line.
#[test]
fn a_scene_names_its_steady_motion() {
    let bruls = std::fs::read_to_string(repo("examples/scenes/heavy_top.toml")).unwrap();
    let named = bruls.replace(
        "pivot = [0.0, -1.0, 0.0]",
        "pivot = [0.0, -1.0, 0.0]\nsteady = \"slow_precession\"",
    );
    assert_ne!(named, bruls);
    let path = scratch_dir().join("bruls_steady.toml");
    std::fs::write(&path, &named).unwrap();
    let doc = json(&["stability", &path.display().to_string(), "--format", "json"]);
    let motion = &doc["bodies"][0]["steady_motions"][0];
    assert_eq!(motion["kind"], "slow steady precession");
    assert_eq!(motion["verdict"], "stable");
    let (i1, i3, mgl, spin): (f64, f64, f64, f64) = (0.234375 + 15.0, 0.46875, 15.0 * 9.81, 150.0);
    let phi_dot = mgl / (i3 * spin);
    let expected = ((i3 * spin / i1).powi(2) + phi_dot * phi_dot).sqrt();
    let found = motion["eigenvalues"][0][1].as_f64().unwrap().abs();
    assert!(
        (found / expected - 1.0).abs() < 1e-12,
        "{found} vs {expected}"
    );
    let bad = bruls.replace(
        "pivot = [0.0, -1.0, 0.0]",
        "pivot = [0.0, -1.0, 0.0]\nsteady = \"wobbling\"",
    );
    std::fs::write(&path, &bad).unwrap();
    let run = kreisel(&["stability", &path.display().to_string()], "");
    let line = run.error_line(1);
    assert!(
        line.ends_with(":18: body `top`: `steady`: unknown steady motion \"wobbling\" (one of nearest, sleeping, hanging, slow_precession, fast_precession)"),
        "{line}"
    );
}
