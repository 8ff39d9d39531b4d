//! Mutated inputs through the `kreisel` binary: no panic, no run past
//! 10 s, never exit 0 with NaN or inf in the output.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use proptest::prelude::*;

use crate::mutate::{corpus_dir, mutated};

/// The binary under test (the release one under `cargo test --release`).
const KREISEL: &str = env!("CARGO_BIN_EXE_kreisel");

/// A run longer than this is a hang.
pub const TIME_LIMIT: Duration = Duration::from_secs(10);

/// Standard output kept for the checks (the rest is read and dropped).
const KEPT_OUTPUT: usize = 16 << 20;

/// The parsers, as the binary reaches them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parser {
    /// `kreisel inertia` on a mesh file of this extension (the fuzz target name).
    Mesh(&'static str),
    /// `kreisel simulate` on a scene file.
    Scene,
    /// `kreisel convert` on standard input.
    Convert,
}

impl Parser {
    /// Every parser.
    pub const ALL: [Parser; 7] = [
        Parser::Mesh("stl"),
        Parser::Mesh("obj"),
        Parser::Mesh("ply"),
        Parser::Mesh("gltf"),
        Parser::Mesh("glb"),
        Parser::Scene,
        Parser::Convert,
    ];

    /// The fuzz target (and corpus directory) of this parser.
    pub fn target(self) -> &'static str {
        match self {
            Parser::Mesh(ext) => ext,
            Parser::Scene => "scene_toml",
            Parser::Convert => "convert_lines",
        }
    }

    /// The input file's extension.
    pub fn extension(self) -> &'static str {
        match self {
            Parser::Mesh(ext) => ext,
            Parser::Scene => "toml",
            Parser::Convert => "txt",
        }
    }
}

/// What one run did wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Defect {
    /// Killed by a signal, exit status 101, or "panicked" on standard error.
    Panic(String),
    /// Still running after [`TIME_LIMIT`]; how much it had written by then.
    Hang { stdout_bytes: usize },
    /// Exit status 0 with a non-finite number (or, for JSON, invalid JSON).
    NonFinite(String),
}

impl Defect {
    /// A short name for counts and file names.
    pub fn kind(&self) -> &'static str {
        match self {
            Defect::Panic(_) => "panic",
            Defect::Hang { .. } => "hang",
            Defect::NonFinite(_) => "nonfinite",
        }
    }
}

/// One prepared run: the command line and its standard input.
pub struct Case {
    /// Arguments after `kreisel`.
    pub args: Vec<String>,
    /// Standard input.
    pub stdin: Vec<u8>,
    /// The scratch directory (the working directory).
    pub dir: PathBuf,
}

/// Writes `input` into `dir` for `parser` (with the files a mesh scene or a
/// glTF file may name beside it); the command line. `variant` picks the mass
/// model of a mesh (solid, `--shell`, `--hull`).
pub fn prepare(parser: Parser, input: &[u8], variant: usize, dir: &Path) -> Case {
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir).expect("scratch directory");
    let input_name = format!("input.{}", parser.extension());
    let (args, stdin) = match parser {
        Parser::Mesh(_) => {
            std::fs::write(dir.join(&input_name), input).expect("write input");
            // The external buffer of the glTF seed.
            let bin = Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../inertia/tests/fixtures/cube data.bin");
            let _ = std::fs::copy(bin, dir.join("cube data.bin"));
            let mut args = vec![
                "inertia".to_owned(),
                input_name,
                "--format".into(),
                "json".into(),
            ];
            match variant % 3 {
                1 => args.push("--shell".into()),
                2 => args.push("--hull".into()),
                _ => {}
            }
            (args, Vec::new())
        }
        Parser::Scene => {
            std::fs::write(dir.join(&input_name), input).expect("write input");
            std::fs::copy(corpus_dir("obj").join("cube.obj"), dir.join("cube.obj"))
                .expect("copy cube.obj");
            (vec!["simulate".to_owned(), input_name], Vec::new())
        }
        Parser::Convert => {
            let names = crate::targets::representation_names();
            let (from, to, flags, lines) = match input {
                [a, b, c, rest @ ..] => (*a, *b, *c, rest),
                _ => (0, 0, 0, &[][..]),
            };
            let mut args = vec![
                "convert".to_owned(),
                "--from".into(),
                names[usize::from(from) % names.len()].clone(),
                "--to".into(),
                names[usize::from(to) % names.len()].clone(),
            ];
            if flags & 1 == 1 {
                args.push("--degrees".into());
            }
            (args, lines.to_vec())
        }
    };
    Case {
        args,
        stdin,
        dir: dir.to_path_buf(),
    }
}

/// Reads everything, keeping the first `keep` bytes; how many were read.
fn drain(mut from: impl Read, keep: usize) -> (Vec<u8>, usize) {
    let mut kept = Vec::new();
    let mut total = 0;
    let mut buffer = [0u8; 1 << 16];
    while let Ok(n) = from.read(&mut buffer) {
        if n == 0 {
            break;
        }
        let room = keep.saturating_sub(kept.len()).min(n);
        kept.extend_from_slice(&buffer[..room]);
        total += n;
    }
    (kept, total)
}

/// Whether a token spells a non-finite number as Rust or JSON would.
fn non_finite_token(token: &str) -> bool {
    let t = token.trim_start_matches(['+', '-']).to_ascii_lowercase();
    t == "nan" || t == "inf" || t == "infinity"
}

/// The first non-finite number of `parser`'s output, if any (user-given
/// names, the CSV's `body` column, are not numbers).
fn find_non_finite(parser: Parser, stdout: &str) -> Option<String> {
    match parser {
        Parser::Mesh(_) => match serde_json::from_str::<serde_json::Value>(stdout) {
            // JSON has no NaN or inf: valid JSON holds only finite numbers.
            Ok(_) => None,
            Err(e) => Some(format!("invalid JSON ({e})")),
        },
        Parser::Scene => stdout.lines().skip(1).find_map(|row| {
            row.split(',')
                .enumerate()
                .filter(|&(k, _)| k != 1)
                .find(|(_, field)| !field.parse::<f64>().is_ok_and(f64::is_finite))
                .map(|(k, field)| format!("column {k} = {field:?} in row {row:?}"))
        }),
        Parser::Convert => stdout
            .split([',', '\n'])
            .find(|field| {
                non_finite_token(field) || field.parse::<f64>().is_err() && !field.is_empty()
            })
            .map(|field| format!("{field:?}")),
    }
}

/// How one run ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Outcome {
    /// The exit status (`None`: killed by a signal or by us).
    pub code: Option<i32>,
    /// What it did wrong, if anything.
    pub defect: Option<Defect>,
}

/// Runs a prepared case and judges it.
pub fn run(parser: Parser, case: &Case) -> Outcome {
    let mut child = Command::new(KREISEL)
        .args(&case.args)
        .current_dir(&case.dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn kreisel");
    let mut pipe = child.stdin.take().expect("stdin");
    let stdin = case.stdin.clone();
    let writer = std::thread::spawn(move || {
        let _ = pipe.write_all(&stdin);
    });
    let out = child.stdout.take().expect("stdout");
    let err = child.stderr.take().expect("stderr");
    let out = std::thread::spawn(move || drain(out, KEPT_OUTPUT));
    let err = std::thread::spawn(move || drain(err, 1 << 16));
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break Some(status);
        }
        if start.elapsed() > TIME_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(2));
    };
    let _ = writer.join();
    let (stdout, stdout_bytes) = out.join().expect("stdout reader");
    let (stderr, _) = err.join().expect("stderr reader");
    let stderr = String::from_utf8_lossy(&stderr);
    let Some(status) = status else {
        return Outcome {
            code: None,
            defect: Some(Defect::Hang { stdout_bytes }),
        };
    };
    let code = status.code();
    let defect = if code.is_none() || code == Some(101) || stderr.contains("panicked") {
        Some(Defect::Panic(format!("{status}: {}", stderr.trim())))
    } else if status.success() {
        find_non_finite(parser, &String::from_utf8_lossy(&stdout)).map(Defect::NonFinite)
    } else {
        None
    };
    Outcome { code, defect }
}

/// A scratch directory under the target directory.
pub fn scratch(name: &str) -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("fuzz_{name}"))
}

/// Cases per parser in CI: each is a process (a few ms in debug).
const CI_CASES: u32 = 24;

fn check(parser: Parser, input: &[u8], variant: usize) -> Result<(), TestCaseError> {
    let dir = scratch(&format!("ci_{}", parser.target()));
    let case = prepare(parser, input, variant, &dir);
    let defect = run(parser, &case).defect;
    prop_assert!(
        defect.is_none(),
        "kreisel {} (in {}): {defect:?}",
        case.args.join(" "),
        dir.display()
    );
    Ok(())
}

proptest! {
    #![proptest_config(crate::mutate::ci_config(CI_CASES))]

    #[test]
    fn inertia_stl_through_cli(bytes in mutated("stl"), variant in 0usize..3) {
        check(Parser::Mesh("stl"), &bytes, variant)?;
    }

    #[test]
    fn inertia_obj_through_cli(bytes in mutated("obj"), variant in 0usize..3) {
        check(Parser::Mesh("obj"), &bytes, variant)?;
    }

    #[test]
    fn inertia_ply_through_cli(bytes in mutated("ply"), variant in 0usize..3) {
        check(Parser::Mesh("ply"), &bytes, variant)?;
    }

    #[test]
    fn inertia_gltf_through_cli(bytes in mutated("gltf"), variant in 0usize..3) {
        check(Parser::Mesh("gltf"), &bytes, variant)?;
    }

    #[test]
    fn inertia_glb_through_cli(bytes in mutated("glb"), variant in 0usize..3) {
        check(Parser::Mesh("glb"), &bytes, variant)?;
    }

    #[test]
    fn simulate_through_cli(bytes in mutated("scene_toml")) {
        check(Parser::Scene, &bytes, 0)?;
    }

    #[test]
    fn convert_through_cli(bytes in mutated("convert_lines")) {
        check(Parser::Convert, &bytes, 0)?;
    }
}

#[test]
fn non_finite_numbers_are_recognised() {
    let csv = "t,body,qw\n0,nan,1\n0.5,x,NaN\n";
    assert!(
        find_non_finite(Parser::Scene, csv)
            .unwrap()
            .contains("column 2")
    );
    assert_eq!(find_non_finite(Parser::Scene, "t,body,qw\n0,inf,1\n"), None);
    assert!(find_non_finite(Parser::Convert, "1,0,0,0\n-inf,0,0\n").is_some());
    assert_eq!(find_non_finite(Parser::Convert, "1,0,1e-300,0\n"), None);
    assert!(find_non_finite(Parser::Mesh("stl"), "{\"mass\": NaN}").is_some());
    assert_eq!(
        find_non_finite(Parser::Mesh("stl"), "{\"mass\": 1e-3}"),
        None
    );
}
