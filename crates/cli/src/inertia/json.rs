//! `--format json`: one object, the assembly, with every body under `bodies`.
//!
//! Written by hand: numbers in shortest round-trip form (exponent notation
//! below 1e-4 and from 1e16 on, which JSON allows; `null` for a non-finite
//! value, which JSON cannot spell), strings escaped per RFC 8259.

use core::fmt::Write;

use glam::{DMat3, DVec3};

use super::shown::Shown;
use super::{Report, Setup, Summary, View};
use kreisel_scene::inertia_request::FRAME;
use kreisel_scene::numbers::Shortest;

/// The frame with `--transform`.
pub const LINK_FRAME: &str = "center of mass, link axes";

/// The JSON report, ending with a newline.
pub fn render(report: &Report, view: &View) -> String {
    let mut out = String::from("{\n");
    let mut top = Object::new(&mut out, 1);
    fields(&mut top, &report.setup, &report.assembly, view);
    top.key("bodies");
    top.out.push('[');
    for (i, body) in report.bodies.iter().enumerate() {
        top.out.push_str(if i == 0 { "\n" } else { ",\n" });
        top.out.push_str(&"  ".repeat(2));
        top.out.push_str("{\n");
        let mut obj = Object::new(top.out, 3);
        obj.key("name");
        string(obj.out, &body.name);
        fields(&mut obj, &report.setup, body, view);
        top.out.push('\n');
        top.out.push_str(&"  ".repeat(2));
        top.out.push('}');
    }
    top.out.push_str("\n  ]\n}\n");
    out
}

/// The fields of one body or of the assembly; those of `--transform`,
/// `--about` and `--digits` only when given.
fn fields(obj: &mut Object<'_>, setup: &Setup, s: &Summary, view: &View) {
    let shown = Shown::new(s, &view.frame, setup.scale, view.form.digits);
    obj.key("file");
    string(obj.out, &setup.file.display().to_string());
    obj.key("units");
    string(obj.out, setup.units_name());
    obj.number("scale", setup.scale);
    obj.key("model");
    string(obj.out, setup.model_name());
    if let Some(t) = setup.thickness() {
        obj.number("thickness", t);
    }
    obj.number("density", shown.density);
    obj.key("density_source");
    string(obj.out, setup.density_source());
    obj.key("frame");
    string(
        obj.out,
        if view.frame.transform.is_some() {
            LINK_FRAME
        } else {
            FRAME
        },
    );
    obj.number("mass", shown.mass);
    obj.number("volume", shown.volume);
    obj.number("area", shown.area);
    obj.key("triangles");
    let _ = write!(obj.out, "{}", s.triangles);
    obj.key("center_of_mass");
    vector(obj.out, shown.center_of_mass);
    obj.key("inertia");
    matrix_rows(obj.out, shown.inertia);
    obj.key("principal_moments");
    vector(obj.out, shown.principal.moments);
    obj.key("principal_axes");
    // Rows of the output = columns of the rotation matrix = the axes.
    matrix_rows(obj.out, shown.principal.axes.transpose());
    let q = shown.principal.orientation;
    obj.key("principal_orientation");
    list(obj.out, &[q.w, q.x, q.y, q.z]);
    obj.key("warnings");
    obj.out.push('[');
    for (i, w) in s.warnings.iter().enumerate() {
        if i > 0 {
            obj.out.push_str(", ");
        }
        string(obj.out, w);
    }
    obj.out.push(']');
    if let Some(t) = view.frame.transform {
        obj.key("transform_xyz");
        vector(obj.out, t.xyz);
        obj.key("transform_rpy");
        vector(obj.out, t.rpy);
    }
    if let Some((point, tensor)) = shown.about {
        obj.key("about_point_mesh");
        vector(obj.out, view.frame.about.unwrap_or(point));
        obj.key("about_point");
        vector(obj.out, point);
        obj.key("inertia_about_point");
        matrix_rows(obj.out, tensor);
    }
    if let Some(n) = view.form.digits {
        obj.key("digits");
        let _ = write!(obj.out, "{n}");
    }
}

/// Writes the members of an object, one per line, with commas between.
pub(super) struct Object<'a> {
    pub(super) out: &'a mut String,
    depth: usize,
    first: bool,
}

impl<'a> Object<'a> {
    /// An object whose members are indented by `depth` levels; the caller
    /// writes the braces.
    pub(super) fn new(out: &'a mut String, depth: usize) -> Self {
        Self {
            out,
            depth,
            first: true,
        }
    }

    /// Starts a member: separator, indentation, `"key": `.
    pub(super) fn key(&mut self, key: &str) {
        if !self.first {
            self.out.push_str(",\n");
        }
        self.first = false;
        self.out.push_str(&"  ".repeat(self.depth));
        string(self.out, key);
        self.out.push_str(": ");
    }

    /// A member whose value is a number.
    pub(super) fn number(&mut self, key: &str, value: f64) {
        self.key(key);
        number(self.out, value);
    }
}

/// A JSON number, or `null` for NaN and infinities.
pub(crate) fn number(out: &mut String, value: f64) {
    if value.is_finite() {
        let _ = write!(out, "{}", Shortest(value));
    } else {
        out.push_str("null");
    }
}

/// `[a, b, c]`.
fn list(out: &mut String, values: &[f64]) {
    out.push('[');
    for (i, &v) in values.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        number(out, v);
    }
    out.push(']');
}

/// `[x, y, z]`.
pub(super) fn vector(out: &mut String, v: DVec3) {
    list(out, &v.to_array());
}

/// `[[row 0], [row 1], [row 2]]`.
pub(super) fn matrix_rows(out: &mut String, m: DMat3) {
    out.push('[');
    for r in 0..3 {
        if r > 0 {
            out.push_str(", ");
        }
        vector(out, m.row(r));
    }
    out.push(']');
}

/// A JSON string: quotes, backslashes and control characters escaped.
pub(crate) fn string(out: &mut String, text: &str) {
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '\u{8}' => out.push_str("\\b"),
            '\u{c}' => out.push_str("\\f"),
            c if u32::from(c) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quoted(text: &str) -> String {
        let mut out = String::new();
        string(&mut out, text);
        out
    }

    #[test]
    fn strings_are_escaped() {
        assert_eq!(quoted("a\"b\\c"), r#""a\"b\\c""#);
        assert_eq!(quoted("x\ny\t\u{1}\u{7f}é"), "\"x\\ny\\t\\u0001\u{7f}é\"");
    }

    #[test]
    fn numbers_are_json() {
        let mut out = String::new();
        list(
            &mut out,
            &[1e-300, -0.0, f64::NAN, 2.5, 1e16, f64::INFINITY],
        );
        assert_eq!(out, "[1e-300, 0, null, 2.5, 1e16, null]");
    }

    #[test]
    fn matrices_are_written_by_rows() {
        let mut out = String::new();
        let m = DMat3::from_cols(DVec3::X, DVec3::new(2.0, 1.0, 0.0), DVec3::Z);
        matrix_rows(&mut out, m);
        assert_eq!(out, "[[1, 2, 0], [0, 1, 0], [0, 0, 1]]");
    }
}
