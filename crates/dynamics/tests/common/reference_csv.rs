//! Shared test helper: one CSV file of the committed reference data under
//! the workspace's `tests/data/` ([`Table`]), read by the tests of
//! kreisel-dynamics and (included by path) by the root package's reference
//! tests.
#![allow(dead_code)]

use std::path::PathBuf;

use glam::{DQuat, DVec3};

/// One CSV file of reference data: the header's column names and the rows.
pub struct Table {
    columns: Vec<String>,
    /// Rows as raw fields.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// Loads `tests/data/NAME`, skipping `#` comment lines.
    pub fn load(name: &str) -> Table {
        // The workspace root, also when included by the root package's tests.
        let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let root = manifest
            .ancestors()
            .find(|dir| dir.join("tests/data").is_dir())
            .expect("tests/data in an ancestor");
        let path = root.join("tests/data").join(name);
        let text = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
        let mut lines = text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.is_empty());
        let columns = lines
            .next()
            .expect("header line")
            .split(',')
            .map(str::to_owned)
            .collect();
        let rows = lines
            .map(|l| l.split(',').map(str::to_owned).collect())
            .collect();
        Table { columns, rows }
    }

    fn index(&self, column: &str) -> usize {
        self.columns
            .iter()
            .position(|c| c == column)
            .unwrap_or_else(|| panic!("no column {column}"))
    }

    /// The text of `column` in `row`.
    pub fn text<'a>(&self, row: &'a [String], column: &str) -> &'a str {
        &row[self.index(column)]
    }

    /// The number in `column` of `row`.
    pub fn num(&self, row: &[String], column: &str) -> f64 {
        self.text(row, column).parse().expect("a number")
    }

    /// Three numbers as a vector.
    pub fn vec3(&self, row: &[String], columns: [&str; 3]) -> DVec3 {
        DVec3::new(
            self.num(row, columns[0]),
            self.num(row, columns[1]),
            self.num(row, columns[2]),
        )
    }

    /// The quaternion in columns `qw, qx, qy, qz`.
    pub fn quat(&self, row: &[String]) -> DQuat {
        DQuat::from_xyzw(
            self.num(row, "qx"),
            self.num(row, "qy"),
            self.num(row, "qz"),
            self.num(row, "qw"),
        )
    }
}
