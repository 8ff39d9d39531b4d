//! Shared test problems: the committed reference data under `tests/data/`,
//! and meshes of primitive solids ([`shapes`]).
#![allow(dead_code)]

pub mod bounces;
pub mod bouncing_ball;
pub mod coin;
pub mod contact;
pub mod euler_disk;
pub mod free_body;
pub mod heavy_top;
pub mod shapes;
pub mod tippe_top;

use std::path::PathBuf;

use kreisel::kinematics::glam::{DQuat, DVec3};

/// One CSV file of reference data: the header's column names and the rows.
pub struct Table {
    columns: Vec<String>,
    /// Rows as raw fields.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// Loads `tests/data/NAME`, skipping `#` comment lines.
    pub fn load(name: &str) -> Table {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("tests/data")
            .join(name);
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

/// `a − b` wrapped into `(−π, π]`: the distance between two angles.
pub fn angle_difference(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(std::f64::consts::TAU);
    if d > std::f64::consts::PI {
        d - std::f64::consts::TAU
    } else {
        d
    }
}
