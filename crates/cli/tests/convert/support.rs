//! Shared helpers: run the `kreisel` binary, read the reference CSV files,
//! and track the largest error seen.

use std::collections::HashMap;
use std::f64::consts::{PI, TAU};
use std::path::{Path, PathBuf};

use glam::{DQuat, DVec3};

#[path = "../common/run.rs"]
mod run;
pub use run::{KREISEL, Run, kreisel};

impl Run {
    /// Asserts success and returns the output lines as numbers, each line
    /// holding `width` comma-separated numbers without spaces.
    pub fn rows(&self, width: usize) -> Vec<Vec<f64>> {
        assert_eq!(self.code, Some(0), "stderr: {}", self.stderr);
        assert!(self.stderr.is_empty(), "stderr: {}", self.stderr);
        parse_rows(&self.stdout, width)
    }

    /// The lines of standard error.
    pub fn stderr_lines(&self) -> Vec<&str> {
        self.stderr.lines().collect()
    }
}

/// Parses lines of `width` comma-separated numbers (no spaces allowed).
pub fn parse_rows(text: &str, width: usize) -> Vec<Vec<f64>> {
    text.lines()
        .map(|line| {
            assert!(!line.contains(' '), "spaces in output line {line:?}");
            let row: Vec<f64> = line
                .split(',')
                .map(|t| match t.parse() {
                    Ok(v) => v,
                    Err(e) => panic!("output {line:?}: {t:?}: {e}"),
                })
                .collect();
            assert_eq!(row.len(), width, "output line {line:?}");
            row
        })
        .collect()
}

/// `kreisel convert --from FROM --to TO [extra...]`.
pub fn convert(from: &str, to: &str, extra: &[&str], stdin: impl Into<Vec<u8>>) -> Run {
    let mut args = vec!["convert", "--from", from, "--to", to];
    args.extend_from_slice(extra);
    kreisel(&args, stdin)
}

/// A fresh path in the test scratch directory.
pub fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("kreisel-cli-convert");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let path = dir.join(name);
    let _ = std::fs::remove_file(&path);
    path
}

/// A reference CSV file of `tests/data` (comment lines `#`, then a header).
pub struct Table {
    columns: HashMap<String, usize>,
    rows: Vec<Vec<String>>,
}

/// One row of a [`Table`].
#[derive(Clone, Copy)]
pub struct Row<'a> {
    table: &'a Table,
    fields: &'a [String],
}

impl Table {
    /// Loads `tests/data/{name}` of the workspace.
    pub fn load(name: &str) -> Table {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../tests/data")
            .join(name);
        let text =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let mut lines = text.lines().filter(|l| !l.starts_with('#'));
        let header = lines.next().expect("header line");
        let columns = header
            .split(',')
            .enumerate()
            .map(|(i, c)| (c.to_owned(), i))
            .collect();
        let rows = lines
            .filter(|l| !l.trim().is_empty())
            .map(|l| l.split(',').map(str::to_owned).collect())
            .collect();
        Table { columns, rows }
    }

    /// All rows.
    pub fn rows(&self) -> impl Iterator<Item = Row<'_>> {
        self.rows.iter().map(|fields| Row {
            table: self,
            fields,
        })
    }
}

impl<'a> Row<'a> {
    /// The text of a column.
    pub fn str(&self, column: &str) -> &'a str {
        let i = self.table.columns[column];
        &self.fields[i]
    }

    /// A column as a number.
    pub fn num(&self, column: &str) -> f64 {
        self.str(column).parse().expect("number in reference data")
    }

    /// Columns joined with commas, exactly as written in the file.
    pub fn line(&self, columns: &[&str]) -> String {
        columns
            .iter()
            .map(|c| self.str(c))
            .collect::<Vec<_>>()
            .join(",")
    }

    /// The quaternion of columns `qw, qx, qy, qz`.
    pub fn quat(&self) -> DQuat {
        DQuat::from_xyzw(
            self.num("qx"),
            self.num("qy"),
            self.num("qz"),
            self.num("qw"),
        )
    }

    /// Three columns as a vector.
    pub fn vec3(&self, a: &str, b: &str, c: &str) -> DVec3 {
        DVec3::new(self.num(a), self.num(b), self.num(c))
    }

    /// A short description for error messages.
    pub fn describe(&self) -> String {
        self.fields.join(",")
    }
}

/// Stdin text: one line per row, the given columns comma-separated.
pub fn stdin_of(rows: &[Row<'_>], columns: &[&str]) -> String {
    rows.iter().map(|r| r.line(columns) + "\n").collect()
}

/// `|a − b|` for angles, modulo 2π (the difference wrapped into `(−π, π]`).
pub fn angle_diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    if d > PI { TAU - d } else { d }
}

/// `|v|` without underflow (the `tiny` rows have components near 1e-200).
pub fn norm(v: DVec3) -> f64 {
    let m = v.abs().max_element();
    if m == 0.0 { 0.0 } else { m * (v / m).length() }
}

/// Quaternion from `w, x, y, z` numbers.
pub fn wxyz(n: &[f64]) -> DQuat {
    DQuat::from_xyzw(n[1], n[2], n[3], n[0])
}

/// The largest error of one kind, where it happened, and its bound.
pub struct MaxError {
    name: &'static str,
    bound: f64,
    value: f64,
    at: String,
    count: usize,
}

impl MaxError {
    /// Starts tracking errors of kind `name` that must stay `≤ bound`.
    pub fn new(name: &'static str, bound: f64) -> Self {
        Self {
            name,
            bound,
            value: 0.0,
            at: String::new(),
            count: 0,
        }
    }

    /// Records one error (NaN counts as a failure).
    pub fn record(&mut self, error: f64, at: impl FnOnce() -> String) {
        self.count += 1;
        if error > self.value || error.is_nan() {
            self.value = error;
            self.at = at();
        }
    }

    /// Prints the maximum (visible with `--nocapture`) and asserts the bound.
    pub fn check(&self) {
        println!(
            "max error {:<45} {:.3e}  (bound {:e}, {} values)",
            self.name, self.value, self.bound, self.count
        );
        assert!(self.count > 0, "{}: nothing checked", self.name);
        assert!(
            self.value <= self.bound,
            "{}: {:e} > {:e} at {}",
            self.name,
            self.value,
            self.bound,
            self.at
        );
    }
}
