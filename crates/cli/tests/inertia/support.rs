//! Shared helpers: run `kreisel inertia`, parse its JSON and XML output,
//! write scratch meshes, read the exact reference table.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use glam::{DMat3, DQuat, DVec3};
use serde_json::Value;

#[path = "../common/run.rs"]
pub mod run;
pub use run::Run;

impl Run {
    /// Asserts exit status 0 and returns standard output parsed as JSON.
    pub fn json(&self) -> Value {
        assert_eq!(self.code, Some(0), "stderr: {}", self.stderr);
        match serde_json::from_str(&self.stdout) {
            Ok(v) => v,
            Err(e) => panic!("invalid JSON ({e}):\n{}", self.stdout),
        }
    }
}

/// Runs `kreisel inertia PATH ARGS...`.
pub fn inertia(path: &Path, args: &[&str]) -> Run {
    let path = path.to_str().expect("test paths are UTF-8");
    let mut all = vec!["inertia", path];
    all.extend_from_slice(args);
    run::kreisel(&all, Vec::new())
}

/// A path relative to the workspace root.
pub fn workspace(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(relative)
}

/// Writes `contents` to a fresh file in the test scratch directory.
pub fn scratch(name: &str, contents: impl AsRef<[u8]>) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("kreisel-cli-inertia");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let path = dir.join(name);
    std::fs::write(&path, contents).expect("write scratch file");
    path
}

/// The numbers of the first flat list `"key": [a, b, ...]` in JSON text,
/// parsed by Rust (correctly rounded; serde_json's default float parser may
/// be one ulp off, so exact comparisons use this).
pub fn raw_list(json: &str, key: &str) -> Vec<f64> {
    let start = json
        .find(&format!("\"{key}\": ["))
        .unwrap_or_else(|| panic!("no {key}"));
    let rest = &json[start + key.len() + 5..];
    let end = rest.find(']').expect("end of list");
    numbers(&rest[..end].replace(',', " "))
}

/// The first number member `"key": x` in JSON text, parsed by Rust.
pub fn raw_number(json: &str, key: &str) -> f64 {
    let start = json
        .find(&format!("\"{key}\": "))
        .unwrap_or_else(|| panic!("no {key}"));
    let rest = &json[start + key.len() + 4..];
    let end = rest.find([',', '\n']).unwrap_or(rest.len());
    numbers(&rest[..end])[0]
}

/// A JSON number.
pub fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// A JSON list of three numbers.
pub fn vec3(v: &Value) -> DVec3 {
    let a = v.as_array().unwrap_or_else(|| panic!("not a list: {v}"));
    assert_eq!(a.len(), 3, "{v}");
    DVec3::new(num(&a[0]), num(&a[1]), num(&a[2]))
}

/// A JSON list of three rows, as the matrix with those rows.
pub fn rows(v: &Value) -> DMat3 {
    let a = v.as_array().unwrap_or_else(|| panic!("not a list: {v}"));
    assert_eq!(a.len(), 3, "{v}");
    DMat3::from_cols(vec3(&a[0]), vec3(&a[1]), vec3(&a[2])).transpose()
}

/// `[w, x, y, z]` as a quaternion.
pub fn wxyz(v: &Value) -> DQuat {
    let a = v.as_array().unwrap_or_else(|| panic!("not a list: {v}"));
    assert_eq!(a.len(), 4, "{v}");
    DQuat::from_xyzw(num(&a[1]), num(&a[2]), num(&a[3]), num(&a[0]))
}

/// The largest absolute element.
pub fn max_abs(m: DMat3) -> f64 {
    m.to_cols_array()
        .iter()
        .fold(0.0_f64, |a, e| a.max(e.abs()))
}

/// The value of `name="..."` in an XML text (the first occurrence).
pub fn attribute<'a>(xml: &'a str, name: &str) -> &'a str {
    let key = format!(" {name}=\"");
    let start = xml
        .find(&key)
        .unwrap_or_else(|| panic!("no {name} in {xml}"))
        + key.len();
    let len = xml[start..].find('"').expect("closing quote");
    &xml[start..start + len]
}

/// The text of `<name>...</name>` in an XML text (the first occurrence).
pub fn element<'a>(xml: &'a str, name: &str) -> &'a str {
    let open = format!("<{name}>");
    let start = xml
        .find(&open)
        .unwrap_or_else(|| panic!("no <{name}> in {xml}"))
        + open.len();
    let len = xml[start..]
        .find(&format!("</{name}>"))
        .expect("closing tag");
    &xml[start..start + len]
}

/// Space-separated numbers.
pub fn numbers(text: &str) -> Vec<f64> {
    text.split_whitespace()
        .map(|t| {
            t.parse()
                .unwrap_or_else(|e| panic!("{t:?} in {text:?}: {e}"))
        })
        .collect()
}

/// `tests/data/polyhedra_expected.csv`: exact mass properties at density 1.
pub struct Expected {
    columns: HashMap<String, usize>,
    rows: Vec<Vec<String>>,
}

impl Expected {
    /// Loads the table.
    pub fn load() -> Self {
        let path = workspace("tests/data/polyhedra_expected.csv");
        let text =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let mut lines = text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.trim().is_empty());
        let header = lines.next().expect("header");
        let columns = header
            .split(',')
            .enumerate()
            .map(|(i, c)| (c.to_owned(), i))
            .collect();
        let rows = lines
            .map(|l| l.split(',').map(str::to_owned).collect())
            .collect();
        Self { columns, rows }
    }

    /// The names of all rows.
    pub fn names(&self) -> Vec<String> {
        self.rows.iter().map(|r| r[0].clone()).collect()
    }

    /// A column of a row as a number; `None` when empty.
    pub fn get(&self, name: &str, column: &str) -> Option<f64> {
        let row = self.rows.iter().find(|r| r[0] == name).expect("row");
        let text = &row[self.columns[column]];
        if text.is_empty() {
            None
        } else {
            Some(text.parse().expect("number"))
        }
    }

    /// A column that must be present.
    pub fn num(&self, name: &str, column: &str) -> f64 {
        self.get(name, column)
            .unwrap_or_else(|| panic!("{name}: {column} empty"))
    }

    /// The tensor of a row, from columns `{prefix}ixx` … `{prefix}iyz`.
    pub fn tensor(&self, name: &str, prefix: &str) -> DMat3 {
        let e = |c: &str| self.num(name, &format!("{prefix}{c}"));
        let (xy, xz, yz) = (e("ixy"), e("ixz"), e("iyz"));
        DMat3::from_cols(
            DVec3::new(e("ixx"), xy, xz),
            DVec3::new(xy, e("iyy"), yz),
            DVec3::new(xz, yz, e("izz")),
        )
    }

    /// The centre of mass of a row, from columns `{prefix}cx` … `{prefix}cz`.
    pub fn com(&self, name: &str, prefix: &str) -> DVec3 {
        let e = |c: &str| self.num(name, &format!("{prefix}{c}"));
        DVec3::new(e("cx"), e("cy"), e("cz"))
    }
}

/// `|a − b| / |b|` (absolute when `b` is 0).
pub fn rel(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        ((a - b) / b).abs()
    }
}

/// The 12 outward-wound triangles of the unit cube with corners 1..=8
/// (`(0,0,0) (1,0,0) (1,1,0) (0,1,0)` below, the same at z = 1 above),
/// two per face: bottom, top, front (y = 0), back, left (x = 0), right.
const CUBE_FACES: [[usize; 3]; 12] = [
    [1, 3, 2],
    [1, 4, 3],
    [5, 6, 7],
    [5, 7, 8],
    [1, 2, 6],
    [1, 6, 5],
    [4, 8, 7],
    [4, 7, 3],
    [1, 5, 8],
    [1, 8, 4],
    [2, 3, 7],
    [2, 7, 6],
];

/// OBJ text of a unit cube as object `name`, moved by `dx` along x, whose
/// vertex numbers start after `first - 1` earlier vertices. `inside_out`
/// reverses every triangle; `open` leaves out the two top triangles.
pub fn cube_obj(name: &str, dx: f64, first: usize, inside_out: bool, open: bool) -> String {
    let mut text = format!("o {name}\n");
    for z in [0.0, 1.0] {
        for (x, y) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            text.push_str(&format!("v {} {y} {z}\n", x + dx));
        }
    }
    for (k, [a, b, c]) in CUBE_FACES.iter().enumerate() {
        if open && (k == 2 || k == 3) {
            continue;
        }
        let [a, b, c] = [a, b, c].map(|i| i + first - 1);
        if inside_out {
            text.push_str(&format!("f {a} {c} {b}\n"));
        } else {
            text.push_str(&format!("f {a} {b} {c}\n"));
        }
    }
    text
}

/// The mass a URDF `text` gives link `name`.
pub fn mass_of(text: &str, name: &str) -> f64 {
    let doc = roxmltree::Document::parse(text).expect("XML");
    let link = doc
        .descendants()
        .find(|n| n.has_tag_name("link") && n.attribute("name") == Some(name))
        .expect("the link");
    let mass = link
        .descendants()
        .find(|n| n.has_tag_name("mass"))
        .expect("a mass");
    mass.attribute("value").unwrap().parse().unwrap()
}
