//! The report of `inertia --urdf` as data: one row of named values per
//! link and a summary, written as the table on standard error or, with
//! `--format json`, as one JSON object on standard output:
//!
//! ```text
//! {"urdf": FILE, "mode": "fill" | "check", "links": [{"name": .., ..}, ..], "summary": {..}}
//! ```
//!
//! Numbers are in shortest round-trip form, `null` where there is none.

use glam::{DMat3, DVec3};

use super::json::{Object, matrix_rows, number, string, vector};

/// One value of a row or of the summary.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A number (`null` when not finite).
    Number(f64),
    /// A count.
    Count(usize),
    /// A vector, `[x, y, z]`.
    Vector(DVec3),
    /// A matrix, by rows.
    Matrix(DMat3),
    /// A string.
    Text(String),
    /// A list of strings.
    Texts(Vec<String>),
    /// No value (`null`).
    Null,
}

/// Named values, in order.
pub type Fields = Vec<(&'static str, Value)>;

/// The whole report.
#[derive(Debug, Clone, PartialEq)]
pub struct UrdfReport {
    /// The URDF as given.
    pub urdf: String,
    /// `fill` or `check`.
    pub mode: &'static str,
    /// One entry per link, in file order.
    pub links: Vec<Fields>,
    /// Counts and the exit status.
    pub summary: Fields,
}

/// Writes one value.
fn value(out: &mut String, v: &Value) {
    match v {
        Value::Number(x) => number(out, *x),
        Value::Count(n) => out.push_str(&n.to_string()),
        Value::Vector(v) => vector(out, *v),
        Value::Matrix(m) => matrix_rows(out, *m),
        Value::Text(t) => string(out, t),
        Value::Texts(list) => {
            out.push('[');
            for (i, t) in list.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                string(out, t);
            }
            out.push(']');
        }
        Value::Null => out.push_str("null"),
    }
}

/// The members of `fields`, one per line at `depth`.
fn members(out: &mut String, depth: usize, fields: &Fields) {
    let mut obj = Object::new(out, depth);
    for (key, v) in fields {
        obj.key(key);
        value(obj.out, v);
    }
}

impl UrdfReport {
    /// The JSON text, ending with a newline.
    pub fn json(&self) -> String {
        let mut out = String::from("{\n");
        members(
            &mut out,
            1,
            &vec![
                ("urdf", Value::Text(self.urdf.clone())),
                ("mode", Value::Text(self.mode.into())),
            ],
        );
        out.push_str(",\n  \"links\": [");
        for (i, link) in self.links.iter().enumerate() {
            out.push_str(if i == 0 { "\n    {\n" } else { ",\n    {\n" });
            members(&mut out, 3, link);
            out.push_str("\n    }");
        }
        out.push_str(if self.links.is_empty() {
            "],\n"
        } else {
            "\n  ],\n"
        });
        out.push_str("  \"summary\": {\n");
        members(&mut out, 2, &self.summary);
        out.push_str("\n  }\n}\n");
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_layout() {
        let report = UrdfReport {
            urdf: "r\"1.urdf".into(),
            mode: "check",
            links: vec![vec![
                ("name", Value::Text("a".into())),
                ("mass", Value::Number(f64::NAN)),
                ("com", Value::Vector(DVec3::new(1.0, -0.5, 1e-9))),
                ("notes", Value::Texts(vec!["x".into(), "y".into()])),
            ]],
            summary: vec![("links", Value::Count(1)), ("none", Value::Null)],
        };
        assert_eq!(
            report.json(),
            "{\n  \"urdf\": \"r\\\"1.urdf\",\n  \"mode\": \"check\",\n  \"links\": [\n    {\n      \"name\": \"a\",\n      \"mass\": null,\n      \"com\": [1, -0.5, 1e-9],\n      \"notes\": [\"x\", \"y\"]\n    }\n  ],\n  \"summary\": {\n    \"links\": 1,\n    \"none\": null\n  }\n}\n"
        );
    }
}
