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
//! The numbers come from [`InertialForm`](super::InertialForm): loadable by construction (the
//! smallest moment of a flat body raised by a few ulps), in full or
//! principal form (`--principal`), rounded by `--digits`; they are printed
//! in shortest round-trip form, so the file holds exactly these values.
//! With `--transform` everything is in the link frame.
//!
//! Names from the mesh file (object names, the path) appear only inside
//! comments, with every character XML 1.0 forbids (control characters) and
//! `--` replaced, so the output always parses.

use core::fmt::Write;

use glam::DMat3;

use super::inertial_form::Inertial;
use super::rounding::significant;
use super::{Report, View};
use kreisel_scene::numbers::Shortest;

/// The assembly's inertial as written.
fn written(report: &Report, view: &View) -> Inertial {
    let p = &report.assembly.properties;
    view.form.inertial(p.mass, p.center_of_mass, p.inertia)
}

/// `x` rounded as `--digits` asks (unchanged without it).
fn rounded(x: f64, view: &View) -> f64 {
    view.form.digits.map_or(x, |n| significant(x, n))
}

/// Three numbers separated by spaces.
fn three(v: glam::DVec3) -> String {
    format!("{} {} {}", Shortest(v.x), Shortest(v.y), Shortest(v.z))
}

/// The URDF `<inertial>` element.
pub fn urdf(report: &Report, view: &View) -> String {
    let w = written(report, view);
    let mut out = comment(report, view, "urdf");
    let _ = writeln!(out, "<inertial>");
    let _ = writeln!(
        out,
        "  <origin xyz=\"{}\" rpy=\"{}\"/>",
        three(w.xyz),
        three(w.rpy)
    );
    let _ = writeln!(out, "  <mass value=\"{}\"/>", Shortest(w.mass));
    let [ixx, ixy, ixz, iyy, iyz, izz] = six(w.inertia);
    let _ = writeln!(
        out,
        "  <inertia ixx=\"{ixx}\" ixy=\"{ixy}\" ixz=\"{ixz}\" iyy=\"{iyy}\" iyz=\"{iyz}\" izz=\"{izz}\"/>"
    );
    let _ = writeln!(out, "</inertial>");
    out
}

/// The SDFormat `<inertial>` element.
pub fn sdf(report: &Report, view: &View) -> String {
    let w = written(report, view);
    let mut out = comment(report, view, "sdf");
    let _ = writeln!(out, "<inertial>");
    let _ = writeln!(out, "  <pose>{} {}</pose>", three(w.xyz), three(w.rpy));
    let _ = writeln!(out, "  <mass>{}</mass>", Shortest(w.mass));
    let _ = writeln!(out, "  <inertia>");
    for (name, value) in ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]
        .iter()
        .zip(six(w.inertia))
    {
        let _ = writeln!(out, "    <{name}>{value}</{name}>");
    }
    let _ = writeln!(out, "  </inertia>");
    let _ = writeln!(out, "</inertial>");
    out
}

/// The MJCF `<inertial>` element: `fullinertia` with the principal form in
/// a comment, or with `--principal` the principal form (`quat`, `diaginertia`).
pub fn mjcf(report: &Report, view: &View) -> String {
    let principal_form = super::InertialForm {
        principal: true,
        ..view.form
    };
    let p = &report.assembly.properties;
    let d = principal_form.inertial(p.mass, p.center_of_mass, p.inertia);
    let (q, m) = (d.quat, d.inertia);
    let principal = format!(
        "<inertial pos=\"{}\" quat=\"{} {} {} {}\" mass=\"{}\" diaginertia=\"{} {} {}\"/>",
        three(d.xyz),
        Shortest(q.w),
        Shortest(q.x),
        Shortest(q.y),
        Shortest(q.z),
        Shortest(d.mass),
        Shortest(m.x_axis.x),
        Shortest(m.y_axis.y),
        Shortest(m.z_axis.z)
    );
    let mut out = comment(report, view, "mjcf");
    if view.form.principal {
        let _ = writeln!(out, "{principal}");
        return out;
    }
    let w = written(report, view);
    let [ixx, ixy, ixz, iyy, iyz, izz] = six(w.inertia);
    let _ = writeln!(
        out,
        "<inertial pos=\"{}\" mass=\"{}\" fullinertia=\"{ixx} {iyy} {izz} {ixy} {ixz} {iyz}\"/>",
        three(w.xyz),
        Shortest(w.mass)
    );
    let _ = writeln!(out, "<!-- principal form: {principal} -->");
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
fn comment(report: &Report, view: &View, format: &str) -> String {
    let setup = &report.setup;
    let axes = match (view.form.principal, view.frame.transform) {
        (true, None) => "principal axes (the origin's orientation, in mesh axes)".to_owned(),
        (true, Some(t)) => {
            format!("principal axes (the origin's orientation, in link axes; mesh placed at {t})")
        }
        (false, None) => "mesh axes".to_owned(),
        (false, Some(t)) => format!("link axes (mesh placed at {t})"),
    };
    let mut text = format!(
        "kreisel inertia {}: mesh units {}, density {}, {}; inertia about the centre of mass in {axes}",
        setup.file.display(),
        setup.units_text(),
        setup.density_text(rounded(report.assembly.density, view)),
        setup.model_text(),
    );
    if let Some(n) = view.form.digits {
        text.push_str(&format!(
            "; {n} significant digits, products of inertia below the last digit set to 0"
        ));
    }
    if format == "mjcf" && !view.form.principal {
        text.push_str(" (fullinertia order: ixx iyy izz ixy ixz iyz)");
    }
    let mut out = format!("<!-- {} -->\n", comment_text(&text));
    if report.bodies.len() > 1 {
        let parts: Vec<String> = report
            .bodies
            .iter()
            .map(|b| {
                let mass = Shortest(rounded(b.properties.mass, view));
                format!("'{}' (mass {mass} kg)", b.name)
            })
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
