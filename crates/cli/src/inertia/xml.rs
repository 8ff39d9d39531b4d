//! `--format urdf|sdf|mjcf`: the assembly's `<inertial>` element for a
//! robot description, after a comment stating file, units, density, model
//! and frame.
//!
//! All three formats take the inertia *tensor* about the centre of mass,
//! whose off-diagonal elements are `I_xy = −Σ m x y` (not the products of
//! inertia `+Σ m x y`):
//! - URDF `<inertia ixx ixy ixz iyy iyz izz>`: "the 3x3 rotational inertia
//!   matrix", six above-diagonal elements, in the frame of `<origin>`; with
//!   `rpy="0 0 0"` that frame has the mesh axes, at the centre of mass.
//! - SDFormat `<inertia><ixx>…`: the same matrix, in the frame of `<pose>`.
//! - MJCF `fullinertia="ixx iyy izz ixy ixz iyz"`: M(1,1), M(2,2), M(3,3),
//!   M(1,2), M(1,3), M(2,3) of the matrix, in the body frame at `pos`; the
//!   principal form `quat` (w x y z) rotates the inertial frame into the body
//!   frame, which is what the principal orientation does.
//!
//! Loadable by construction: MuJoCo (and Gazebo) refuse a tensor whose
//! principal moments break `A + B ≥ C`, and MuJoCo computes them itself from
//! `fullinertia`. A flat body (a sheet, a shell of a plane polygon) has
//! `A + B = C` exactly, so rounding alone puts it on either side: measured
//! on 40 tilted sheets, 10 were refused with `A + B − C ≈ −3e-16`. Before
//! printing, [`loadable`] raises the smallest principal moment until
//! `A + B − C` is at least [`MARGIN_ULPS`] ulps of `C` (never more than that
//! beyond the rounding it undoes: a relative change of ~1e-14), so that any
//! eigen-solver's own rounding keeps the inequality; other tensors are
//! printed unchanged. The numbers are printed in shortest round-trip form,
//! so the file holds exactly these values.
//!
//! Names from the mesh file (object names, the path) appear only inside
//! comments, with every character XML 1.0 forbids (control characters) and
//! `--` replaced, so the output always parses.

use core::fmt::Write;

use glam::{DMat3, DVec3};
use kreisel_inertia::PrincipalAxes;

use super::{Report, Summary};
use crate::numbers::Shortest;

/// How far (in ulps of the largest moment) `A + B` must exceed `C` in the
/// printed tensor: covers the rounding of rebuilding the tensor and of the
/// reader's eigen-decomposition (a few ulps each).
const MARGIN_ULPS: f64 = 64.0;

/// The tensor and its principal moments as they are printed: unchanged, or
/// with the smallest moment raised so that `A + B − C ≥ MARGIN_ULPS` ulps of C.
fn loadable(s: &Summary) -> (DMat3, PrincipalAxes) {
    let p = s.principal;
    let m = p.moments;
    let margin = MARGIN_ULPS * f64::EPSILON * m.z;
    let lift = (m.z - m.x - m.y + margin).max(-m.x + margin);
    if lift <= 0.0 {
        return (s.properties.inertia, p);
    }
    let moments = DVec3::new(m.x + lift, m.y, m.z);
    let r = p.axes;
    let t = r * DMat3::from_diagonal(moments) * r.transpose();
    let tensor = (t + t.transpose()) * 0.5;
    let principal = PrincipalAxes {
        moments,
        axes: r,
        orientation: p.orientation,
    };
    (tensor, principal)
}

/// The URDF `<inertial>` element.
pub fn urdf(report: &Report) -> String {
    let s = &report.assembly;
    let c = s.properties.center_of_mass;
    let mut out = comment(report, "urdf");
    let _ = writeln!(out, "<inertial>");
    let _ = writeln!(
        out,
        "  <origin xyz=\"{} {} {}\" rpy=\"0 0 0\"/>",
        Shortest(c.x),
        Shortest(c.y),
        Shortest(c.z)
    );
    let _ = writeln!(out, "  <mass value=\"{}\"/>", Shortest(s.properties.mass));
    let [ixx, ixy, ixz, iyy, iyz, izz] = six(loadable(s).0);
    let _ = writeln!(
        out,
        "  <inertia ixx=\"{ixx}\" ixy=\"{ixy}\" ixz=\"{ixz}\" iyy=\"{iyy}\" iyz=\"{iyz}\" izz=\"{izz}\"/>"
    );
    let _ = writeln!(out, "</inertial>");
    out
}

/// The SDFormat `<inertial>` element.
pub fn sdf(report: &Report) -> String {
    let s = &report.assembly;
    let c = s.properties.center_of_mass;
    let mut out = comment(report, "sdf");
    let _ = writeln!(out, "<inertial>");
    let _ = writeln!(
        out,
        "  <pose>{} {} {} 0 0 0</pose>",
        Shortest(c.x),
        Shortest(c.y),
        Shortest(c.z)
    );
    let _ = writeln!(out, "  <mass>{}</mass>", Shortest(s.properties.mass));
    let _ = writeln!(out, "  <inertia>");
    for (name, value) in ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]
        .iter()
        .zip(six(loadable(s).0))
    {
        let _ = writeln!(out, "    <{name}>{value}</{name}>");
    }
    let _ = writeln!(out, "  </inertia>");
    let _ = writeln!(out, "</inertial>");
    out
}

/// The MJCF `<inertial>` element, with the principal form in a comment.
pub fn mjcf(report: &Report) -> String {
    let s = &report.assembly;
    let c = s.properties.center_of_mass;
    let pos = format!("{} {} {}", Shortest(c.x), Shortest(c.y), Shortest(c.z));
    let mass = Shortest(s.properties.mass);
    let (tensor, principal) = loadable(s);
    let [ixx, ixy, ixz, iyy, iyz, izz] = six(tensor);
    let mut out = comment(report, "mjcf");
    let _ = writeln!(
        out,
        "<inertial pos=\"{pos}\" mass=\"{mass}\" fullinertia=\"{ixx} {iyy} {izz} {ixy} {ixz} {iyz}\"/>"
    );
    let (q, m) = (principal.orientation, principal.moments);
    let _ = writeln!(
        out,
        "<!-- principal form: <inertial pos=\"{pos}\" quat=\"{} {} {} {}\" mass=\"{mass}\" diaginertia=\"{} {} {}\"/> -->",
        Shortest(q.w),
        Shortest(q.x),
        Shortest(q.y),
        Shortest(q.z),
        Shortest(m.x),
        Shortest(m.y),
        Shortest(m.z)
    );
    out
}

/// The six tensor elements `ixx ixy ixz iyy iyz izz`, formatted.
fn six(i: DMat3) -> [Shortest; 6] {
    // Symmetric: the upper triangle, row by row (m.col(c)[r] = I_rc).
    let e = |r: usize, c: usize| Shortest(i.col(c)[r]);
    [e(0, 0), e(0, 1), e(0, 2), e(1, 1), e(1, 2), e(2, 2)]
}

/// The comment lines before the element: what was assumed, and which bodies
/// the assembly sums.
fn comment(report: &Report, format: &str) -> String {
    let setup = &report.setup;
    let mut text = format!(
        "kreisel inertia {}: mesh units {}, density {}, {}; inertia about the centre of mass in mesh axes",
        setup.file.display(),
        setup.units_text(),
        setup.density_text(report.assembly.density),
        setup.model_text(),
    );
    if format == "mjcf" {
        text.push_str(" (fullinertia order: ixx iyy izz ixy ixz iyz)");
    }
    let mut out = format!("<!-- {} -->\n", comment_text(&text));
    if report.bodies.len() > 1 {
        let parts: Vec<String> = report
            .bodies
            .iter()
            .map(|b| format!("'{}' (mass {} kg)", b.name, Shortest(b.properties.mass)))
            .collect();
        let text = format!(
            "assembly of {} bodies, one rigid inertial: {}",
            report.bodies.len(),
            parts.join(", ")
        );
        let _ = writeln!(out, "<!-- {} -->", comment_text(&text));
    }
    for w in &report.assembly.warnings {
        let _ = writeln!(out, "<!-- warning: {} -->", comment_text(w));
    }
    out
}

/// Text that is safe inside an XML comment: one line, no `--`, no character
/// XML 1.0 forbids (control characters other than tab become `\u{…}`; so do
/// the noncharacters U+FFFE and U+FFFF), not ending in `-`.
fn comment_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        let c = if c == '\n' || c == '\r' { ' ' } else { c };
        if (c.is_control() && c != '\t') || c == '\u{fffe}' || c == '\u{ffff}' {
            out.extend(c.escape_unicode());
            continue;
        }
        // "--" may not occur in a comment: separate consecutive hyphens.
        if c == '-' && out.ends_with('-') {
            out.push(' ');
        }
        out.push(c);
    }
    // "--->" would close the comment with a forbidden "--".
    if out.ends_with('-') {
        out.push(' ');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comment_text_has_no_double_hyphen() {
        assert_eq!(comment_text("a--b---c\nd"), "a- -b- - -c d");
        assert!(!comment_text("--->").contains("--"));
        assert!(!comment_text("a-").ends_with('-'));
    }

    #[test]
    fn comment_text_escapes_characters_xml_forbids() {
        // Regression: control characters in an OBJ object name made invalid XML.
        let text = comment_text("body\u{1}\u{1b}[0m\u{7f}\u{fffe}\tend");
        assert_eq!(text, "body\\u{1}\\u{1b}[0m\\u{7f}\\u{fffe}\tend");
    }
}
