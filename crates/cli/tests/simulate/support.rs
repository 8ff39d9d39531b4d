//! Shared helpers: write scenes, run `kreisel simulate`, parse its CSV.

use std::path::{Path, PathBuf};

use glam::{DQuat, DVec3};

#[path = "../common/run.rs"]
mod run;
pub use run::Run;

/// The header `kreisel simulate` must write.
pub const HEADER: &str = "t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz";

/// `[simulation]` with `duration` and `dt`, and whatever `extra` adds.
pub fn simulation(duration: f64, dt: f64, extra: &str) -> String {
    format!("[simulation]\nduration = {duration:?}\ndt = {dt:?}\n{extra}\n")
}

/// A `[[body]]` with principal moments and a body-frame angular velocity.
pub fn body(moments: [f64; 3], omega: [f64; 3], extra: &str) -> String {
    format!("[[body]]\nmass = 1.0\ninertia = {moments:?}\nangular_velocity = {omega:?}\n{extra}\n")
}

/// The scratch directory of this test target (created on first use).
pub fn scratch_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("kreisel-cli-simulate");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

/// Writes `contents` to a fresh file in the scratch directory.
pub fn scratch(name: &str, contents: impl AsRef<[u8]>) -> PathBuf {
    let path = scratch_dir().join(name);
    std::fs::write(&path, contents).expect("write scratch file");
    path
}

/// A path relative to the workspace root.
pub fn workspace(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(relative)
}

/// Runs `kreisel simulate PATH ARGS...`.
pub fn simulate_file(path: &Path, args: &[&str]) -> Run {
    let path = path.to_str().expect("test paths are UTF-8");
    let mut all = vec!["simulate", path];
    all.extend_from_slice(args);
    run::kreisel(&all, Vec::new())
}

/// Runs the example scene `examples/scenes/NAME.toml` with `--events` and
/// `--columns COLUMNS`: the events file's text and the last row's numbers.
pub fn scene_events_and_last_row(name: &str, columns: &str) -> (String, Vec<f64>) {
    let dir = scratch_dir();
    let events = dir.join(format!("{name}_events.csv"));
    let rows = dir.join(format!("{name}.csv"));
    let run = simulate_file(
        &workspace(&format!("examples/scenes/{name}.toml")),
        &[
            "--events",
            events.to_str().unwrap(),
            "--columns",
            columns,
            "--output",
            rows.to_str().unwrap(),
        ],
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let csv = std::fs::read_to_string(&rows).unwrap();
    let last = csv.lines().last().unwrap().split(',');
    (
        std::fs::read_to_string(&events).unwrap(),
        last.map(|v| v.parse().unwrap()).collect(),
    )
}

/// Writes the scene to scratch file `name` and runs it.
pub fn simulate(name: &str, scene: &str, args: &[&str]) -> Run {
    simulate_file(&scratch(name, scene), args)
}

/// Runs `kreisel ARGS...` (no scene written).
pub fn kreisel(args: &[&str]) -> Run {
    run::kreisel(args, Vec::new())
}

/// One row of the CSV.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// Time, s.
    pub t: f64,
    /// Body name.
    pub body: String,
    /// world_from_body.
    pub q: DQuat,
    /// Body-frame angular velocity.
    pub omega: DVec3,
    /// Total energy.
    pub energy: f64,
    /// World-frame angular momentum.
    pub l: DVec3,
}

impl Run {
    /// Asserts success with nothing on standard error; the rows after the
    /// (checked) header.
    pub fn rows(&self) -> Vec<Row> {
        assert_eq!(self.code, Some(0), "stderr: {}", self.stderr);
        assert!(self.stderr.is_empty(), "stderr: {}", self.stderr);
        parse_csv(&self.stdout)
    }
}

/// The rows of CSV text whose first line must be [`HEADER`].
pub fn parse_csv(text: &str) -> Vec<Row> {
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some(HEADER),
        "{}",
        &text[..text.len().min(300)]
    );
    lines
        .map(|line| {
            let fields: Vec<&str> = line.split(',').collect();
            assert_eq!(fields.len(), 13, "{line}");
            let n: Vec<f64> = fields
                .iter()
                .enumerate()
                .filter(|(i, _)| *i != 1)
                .map(|(_, f)| f.parse().unwrap_or_else(|e| panic!("{f} in {line}: {e}")))
                .collect();
            Row {
                t: n[0],
                body: fields[1].to_owned(),
                q: DQuat::from_xyzw(n[2], n[3], n[4], n[1]),
                omega: DVec3::new(n[5], n[6], n[7]),
                energy: n[8],
                l: DVec3::new(n[9], n[10], n[11]),
            }
        })
        .collect()
}

/// Largest relative deviation of `values` from the first one.
pub fn max_relative_drift(values: impl IntoIterator<Item = f64>) -> f64 {
    let mut values = values.into_iter();
    let first = values.next().expect("at least one value");
    values.fold(0.0, |worst: f64, v| {
        worst.max((v - first).abs() / first.abs())
    })
}

/// Largest component difference of two quaternions (no sign freedom).
pub fn quat_diff(a: DQuat, b: DQuat) -> f64 {
    (a - b).length()
}
