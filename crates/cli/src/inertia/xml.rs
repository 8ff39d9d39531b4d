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

use core::fmt::Write;

use super::{Report, Summary};
use crate::numbers::Shortest;

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
    let [ixx, ixy, ixz, iyy, iyz, izz] = six(s);
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
        .zip(six(s))
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
    let [ixx, ixy, ixz, iyy, iyz, izz] = six(s);
    let mut out = comment(report, "mjcf");
    let _ = writeln!(
        out,
        "<inertial pos=\"{pos}\" mass=\"{mass}\" fullinertia=\"{ixx} {iyy} {izz} {ixy} {ixz} {iyz}\"/>"
    );
    let (q, m) = (s.principal.orientation, s.principal.moments);
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
fn six(s: &Summary) -> [Shortest; 6] {
    let i = s.properties.inertia;
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

/// Text that is safe inside an XML comment: one line, no `--`.
fn comment_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        let c = if c == '\n' || c == '\r' { ' ' } else { c };
        // "--" may not occur in a comment: separate consecutive hyphens.
        if c == '-' && out.ends_with('-') {
            out.push(' ');
        }
        out.push(c);
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
    }
}
