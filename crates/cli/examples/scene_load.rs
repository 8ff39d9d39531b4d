//! Measures how `kreisel simulate` scales with the number of bodies in a
//! scene: writes scenes of N bodies (one step each) and times the release
//! binary on them, loading + one step + writing 2N rows. Spheres measure
//! the scene loading itself; asymmetric bodies add the exact solution's
//! per-body set-up (its elliptic-function tables).
//!
//! ```sh
//! cargo build --release -p kreisel-cli
//! cargo run --release -p kreisel-cli --example scene_load -- 100000
//! ```
//!
//! Prints one line per N (N/4, N/2, N): seconds and microseconds per body.
//! Linear scaling means a constant µs per body.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .map_or(100_000, |a| a.parse().expect("N, a whole number"));
    let target = std::env::var("CARGO_TARGET_DIR").map_or_else(
        |_| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../target"),
        PathBuf::from,
    );
    let binary = target.join("release/kreisel");
    assert!(
        binary.exists(),
        "build the release binary first: cargo build --release -p kreisel-cli"
    );
    let dir = std::env::temp_dir();
    for (kind, inertia) in [
        ("spheres", "[1.0, 1.0, 1.0]"),
        ("asymmetric", "[1.0, 2.0, 2.5]"),
    ] {
        for count in [n / 4, n / 2, n] {
            run(&binary, &dir, kind, inertia, count);
        }
    }
}

/// Writes a scene of `count` bodies of moments `inertia` and times one run.
fn run(binary: &Path, dir: &Path, kind: &str, inertia: &str, count: usize) {
    let path = dir.join(format!("kreisel_scene_load_{kind}_{count}.toml"));
    let mut text = String::from("[simulation]\nduration = 0.01\ndt = 0.01\n");
    for i in 0..count {
        text.push_str(&format!(
            "[[body]]\nname = \"b{i}\"\nmass = 1.0\ninertia = {inertia}\n\
                 angular_velocity = [0.01, 1.0, 0.0]\n"
        ));
    }
    std::fs::write(&path, text).expect("write the scene");
    let start = Instant::now();
    let status = Command::new(binary)
        .arg("simulate")
        .arg(&path)
        .stdout(Stdio::null())
        .status()
        .expect("run kreisel");
    let seconds = start.elapsed().as_secs_f64();
    assert!(status.success(), "kreisel failed on {}", path.display());
    let _ = writeln!(
        std::io::stdout(),
        "{count:>8} {kind:<10}: {seconds:.3} s ({:.1} µs per body)",
        1e6 * seconds / count as f64
    );
    let _ = std::fs::remove_file(&path);
}
