//! A depth and size campaign against `kreisel inertia --urdf` (issue 25,
//! 3a and 3d): generated deep, huge and garbage robot descriptions, and
//! endless inputs (symbolic links to /dev/zero) as URDF, mesh and scene.
//! Every run must end with exit status 0 or 1 — never a signal (a stack
//! overflow aborts with 134), never a panic (101) — and a failure must be
//! one `kreisel: error:` line.

use std::path::{Path, PathBuf};

use super::support::run::Run;
use super::urdf::{robot_copy, urdf};

/// A fresh scratch folder for the campaign.
fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("kreisel-cli-urdf-campaign")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

/// Asserts a clean end: status 0 or 1, no panic, and at most one error
/// line, the last; returns the error line (empty on success).
fn clean(what: &str, run: &Run) -> String {
    assert!(
        matches!(run.code, Some(0 | 1)),
        "{what}: status {:?} (a signal is None; 134 is an abort)\n{}",
        run.code,
        run.stderr
    );
    assert!(!run.stderr.contains("panicked"), "{what}: {}", run.stderr);
    let errors: Vec<&str> = run
        .stderr
        .lines()
        .filter(|l| l.starts_with("kreisel: error:"))
        .collect();
    if run.code == Some(1) {
        assert_eq!(errors.len(), 1, "{what}: {}", run.stderr);
        assert_eq!(run.stderr.lines().last(), Some(errors[0]), "{what}");
        errors[0].to_owned()
    } else {
        assert!(errors.is_empty(), "{what}: {}", run.stderr);
        String::new()
    }
}

/// `<robot>` with `depth - 1` elements nested in it (optionally inside a link).
fn nested(depth: usize, in_link: bool, closed: bool) -> String {
    let (open, close) = if in_link {
        ("<link name=\"l\">", "</link>")
    } else {
        ("", "")
    };
    let inner = depth - 1 - usize::from(in_link);
    let closing = if closed {
        "</a>".repeat(inner)
    } else {
        String::new()
    };
    format!(
        "<?xml version=\"1.0\"?>\n<robot name=\"deep\">{open}{}{closing}{close}</robot>\n",
        "<a>".repeat(inner)
    )
}

/// A small deterministic generator of garbage bytes.
fn garbage(seed: u64, len: usize) -> Vec<u8> {
    const MARKUP: &[u8] = b"<<>>/a= \"'!-?[]&;\n\x00";
    let mut x = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    (0..len)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            // Mostly markup characters, so the parser goes deep into the text.
            MARKUP[(x % MARKUP.len() as u64) as usize]
        })
        .collect()
}

#[test]
fn deep_huge_and_garbage_urdfs_end_cleanly() {
    let dir = folder("urdfs");
    let toy = std::fs::read(robot_copy("campaign")).expect("toy robot");
    let mut inputs: Vec<(String, Vec<u8>)> = Vec::new();
    for depth in [5, 999, 1000, 1001, 14_000, 200_000] {
        for in_link in [false, true] {
            for closed in [true, false] {
                let name = format!("deep_{depth}_{in_link}_{closed}.urdf");
                inputs.push((name, nested(depth, in_link, closed).into_bytes()));
            }
        }
    }
    // Deep nesting hidden in comments and CDATA is no nesting at all.
    let hidden = format!(
        "<robot name=\"r\"><!--{}--><link name=\"l\"><![CDATA[{}]]></link></robot>",
        "<a>".repeat(50_000),
        "<a>".repeat(50_000)
    );
    inputs.push(("hidden.urdf".into(), hidden.into_bytes()));
    // A 1 MB attribute, 20,000 links, a huge number.
    let long_name = format!(
        "<robot name=\"{}\"><link name=\"l\"/></robot>",
        "n".repeat(1 << 20)
    );
    inputs.push(("long_name.urdf".into(), long_name.into_bytes()));
    let many: String = (0..20_000)
        .map(|i| format!("<link name=\"l{i}\"><collision><geometry><box size=\"1 1 1\"/></geometry></collision></link>"))
        .collect();
    inputs.push((
        "many.urdf".into(),
        format!("<robot name=\"r\">{many}</robot>").into_bytes(),
    ));
    let huge = "<robot name=\"r\"><link name=\"l\"><collision><geometry><sphere radius=\"1e308\"/></geometry></collision></link></robot>";
    inputs.push(("huge_number.urdf".into(), huge.as_bytes().to_vec()));
    // Garbage, and the toy robot cut short and with NUL and non-UTF-8 bytes.
    for seed in 0..8 {
        inputs.push((format!("garbage_{seed}.urdf"), garbage(seed, 4096)));
    }
    for cut in (0..toy.len()).step_by(toy.len() / 7) {
        inputs.push((format!("cut_{cut}.urdf"), toy[..cut].to_vec()));
    }
    let mut bad = toy.clone();
    bad[toy.len() / 2] = 0xff;
    inputs.push(("not_utf8.urdf".into(), bad));
    let mut nul = toy.clone();
    nul[toy.len() / 3] = 0;
    inputs.push(("nul.urdf".into(), nul));
    let mut aborts = 0;
    for (name, bytes) in &inputs {
        let path = dir.join(name);
        std::fs::write(&path, bytes).expect("write input");
        for args in [&[][..], &["--check"], &["--check", "--hull"]] {
            let run = urdf(&path, args);
            if run.code.is_none() || run.code == Some(134) {
                aborts += 1;
            }
            let line = clean(&format!("{name} {args:?}"), &run);
            if name.starts_with("deep_") {
                let depth: usize = name.split('_').nth(1).unwrap().parse().unwrap();
                if depth > 1000 {
                    assert!(
                        line.contains(&format!(
                            "{}:2: elements nested more than 1000 deep",
                            path.display()
                        )),
                        "{name}: {line}"
                    );
                } else {
                    assert!(!line.contains("nested more than"), "{name}: {line}");
                }
            }
        }
    }
    assert_eq!(aborts, 0);
}

/// A symbolic link `name` in `dir` to /dev/zero.
#[cfg(unix)]
fn zero(dir: &Path, name: &str) -> PathBuf {
    let link = dir.join(name);
    std::os::unix::fs::symlink("/dev/zero", &link).expect("symlink");
    link
}

/// Runs the binary with its address space limited to 4 GB: a reader without
/// a size cap fails to allocate there and aborts.
#[cfg(unix)]
fn limited(args: &[&str]) -> Run {
    let script = format!(
        "ulimit -v 4000000 && exec \"$0\" {}",
        (1..=args.len())
            .map(|i| format!("\"${i}\""))
            .collect::<Vec<_>>()
            .join(" ")
    );
    let mut all = vec!["-c", script.as_str(), super::support::run::KREISEL];
    all.extend_from_slice(args);
    let output = std::process::Command::new("sh")
        .args(&all)
        .stdin(std::process::Stdio::null())
        .output()
        .expect("sh");
    Run {
        code: output.status.code(),
        stdout: String::from_utf8_lossy(&output.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&output.stderr).into_owned(),
    }
}

#[test]
#[cfg(unix)]
fn endless_inputs_are_refused_at_their_size_limit() {
    let dir = folder("zero");
    let s = |p: &Path| p.to_str().expect("UTF-8 path").to_owned();
    // The URDF itself and a scene: 64 MiB.
    let robot = zero(&dir, "robot.urdf");
    let run = limited(&["inertia", "--urdf", &s(&robot)]);
    assert_eq!(
        clean("zero urdf", &run),
        format!(
            "kreisel: error: cannot read URDF file {}: larger than 64 MiB, the limit for a URDF file (is it a device or an endless stream?)",
            robot.display()
        )
    );
    let scene = zero(&dir, "scene.toml");
    let run = limited(&["simulate", &s(&scene)]);
    assert!(
        clean("zero scene", &run).starts_with(&format!(
            "kreisel: error: cannot read scene file {}: larger than 64 MiB, the limit for a scene file",
            scene.display()
        )),
        "{}",
        run.stderr
    );
    // Meshes: 1 GiB, read one at a time.
    for name in ["m.obj", "m.stl", "m.ply", "m.gltf"] {
        let mesh = zero(&dir, name);
        let run = limited(&["inertia", &s(&mesh)]);
        assert!(
            clean(name, &run).starts_with(&format!(
                "kreisel: error: cannot read {}: larger than 1 GiB, the limit for a mesh file",
                mesh.display()
            )),
            "{name}: {}",
            run.stderr
        );
    }
    // A mesh of a URDF: that link cannot be integrated, named with the reason.
    let text = "<robot name=\"r\"><link name=\"a\"><collision><geometry><mesh filename=\"m.obj\"/></geometry></collision></link></robot>\n";
    let with_mesh = dir.join("with_mesh.urdf");
    std::fs::write(&with_mesh, text).unwrap();
    let run = limited(&["inertia", "--urdf", &s(&with_mesh)]);
    assert_eq!(
        clean("zero mesh in urdf", &run),
        "kreisel: error: 1 link(s) kept their old inertial, their geometry could not be integrated: a"
    );
    let row = super::urdf::table_row(&run.stderr, "a");
    assert!(
        row.contains("cannot read m.obj: larger than 1 GiB"),
        "{row}"
    );
    // Standard input (convert): its 1 MiB line limit.
    let run = std::process::Command::new("sh")
        .args([
            "-c",
            "ulimit -v 4000000 && exec \"$0\" convert --from quat --to matrix < /dev/zero",
            super::support::run::KREISEL,
        ])
        .output()
        .expect("sh");
    assert_eq!(run.status.code(), Some(1));
    assert_eq!(
        String::from_utf8_lossy(&run.stderr),
        "kreisel: error: line 1: line is longer than 1048576 bytes\n"
    );
}
