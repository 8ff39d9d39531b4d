//! `--format text`: a readable report, one section per body and one for the
//! assembly when there are several bodies. Numbers are in shortest
//! round-trip form, so nothing is lost by reading them back (unless
//! `--digits` rounds them).

use core::fmt::Write;

use glam::{DMat3, DVec3};

use super::shown::Shown;
use super::{Report, Summary, View};
use kreisel_scene::error::one_line;
use kreisel_scene::numbers::Shortest;

/// Width of the label column.
const LABEL: usize = 24;

/// The whole text report.
pub fn render(report: &Report, view: &View) -> String {
    let setup = &report.setup;
    let assembly = Shown::new(&report.assembly, &view.frame, setup.scale, view.form.digits);
    let mut out = String::new();
    let line = |out: &mut String, label: &str, value: &str| {
        let _ = writeln!(out, "{label:<LABEL$}{value}");
    };
    line(
        &mut out,
        "file",
        &one_line(&setup.file.display().to_string()),
    );
    line(&mut out, "mesh units", &setup.units_text());
    line(&mut out, "model", &setup.model_text());
    line(&mut out, "density", &setup.density_text(assembly.density));
    line(&mut out, "frame", &frame_text(view));
    if let (Some(mesh), Some((point, _))) = (view.frame.about, assembly.about) {
        line(
            &mut out,
            "about point",
            &format!(
                "{}  m, {} axes (mesh coordinates {})",
                vec3(point),
                view.frame.axes_name(),
                vec3(mesh)
            ),
        );
    }
    if let Some(n) = view.form.digits {
        line(
            &mut out,
            "digits",
            &format!("{n} significant; products of inertia below the last digit set to 0"),
        );
    }
    line(&mut out, "units", "SI: m, kg, kg m^2");
    let names: Vec<String> = report.bodies.iter().map(|b| one_line(&b.name)).collect();
    line(
        &mut out,
        "bodies",
        &format!("{} ({})", report.bodies.len(), names.join(", ")),
    );
    for w in &report.file_warnings {
        line(&mut out, "warning", &one_line(w));
    }
    for body in &report.bodies {
        out.push('\n');
        let title = format!("body '{}'", one_line(&body.name));
        section(&mut out, &title, body, view, setup.scale);
    }
    if report.bodies.len() > 1 {
        out.push('\n');
        let title = format!("assembly (sum of {} bodies)", report.bodies.len());
        section(&mut out, &title, &report.assembly, view, setup.scale);
    }
    out
}

/// `about the centre of mass, mesh axes`, or the link frame the mesh is placed in.
fn frame_text(view: &View) -> String {
    match view.frame.transform {
        None => "about the centre of mass, mesh axes".into(),
        Some(t) => format!("about the centre of mass, link axes (mesh placed at {t})"),
    }
}

/// Three numbers separated by two spaces.
fn vec3(v: DVec3) -> String {
    format!("{}  {}  {}", Shortest(v.x), Shortest(v.y), Shortest(v.z))
}

/// The rows of a matrix, each as [`vec3`].
fn rows(m: DMat3) -> [String; 3] {
    [vec3(m.row(0)), vec3(m.row(1)), vec3(m.row(2))]
}

/// One body's (or the assembly's) numbers.
fn section(out: &mut String, title: &str, s: &Summary, view: &View, scale: f64) {
    let shown = Shown::new(s, &view.frame, scale, view.form.digits);
    let _ = writeln!(out, "{title}");
    let mut line = |label: &str, value: &str| {
        let _ = writeln!(out, "  {label:<w$}{value}", w = LABEL - 2);
    };
    line("triangles", &s.triangles.to_string());
    line("volume", &format!("{} m^3", Shortest(shown.volume)));
    line("area", &format!("{} m^2", Shortest(shown.area)));
    line("mass", &format!("{} kg", Shortest(shown.mass)));
    line(
        "centre of mass",
        &format!("{}  m", vec3(shown.center_of_mass)),
    );
    let [r0, r1, r2] = rows(shown.inertia);
    line("inertia tensor", &format!("{r0}  kg m^2"));
    line("  (rows x, y, z)", &r1);
    line("", &r2);
    if let Some((_, tensor)) = shown.about {
        let [r0, r1, r2] = rows(tensor);
        line("inertia about point", &format!("{r0}  kg m^2"));
        line("  (rows x, y, z)", &r1);
        line("", &r2);
    }
    let p = &shown.principal;
    line("principal moments", &format!("{}  kg m^2", vec3(p.moments)));
    line("principal axis 1", &vec3(p.axes.x_axis));
    line("principal axis 2", &vec3(p.axes.y_axis));
    line("principal axis 3", &vec3(p.axes.z_axis));
    let q = p.orientation;
    line(
        "principal orientation",
        &format!(
            "{}  {}  {}  {}  (w x y z, principal -> {})",
            Shortest(q.w),
            Shortest(q.x),
            Shortest(q.y),
            Shortest(q.z),
            view.frame.axes_name()
        ),
    );
    if s.warnings.is_empty() {
        line("warnings", "none");
    }
    for w in &s.warnings {
        line("warning", &one_line(w));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vectors_and_rows_use_shortest_numbers() {
        assert_eq!(vec3(DVec3::new(1.0, -0.0, 1e-9)), "1  0  1e-9");
        let m = DMat3::from_cols(DVec3::X, DVec3::new(2.0, 1.0, 0.0), DVec3::Z);
        // Column 1 is (2, 1, 0): row 0 reads 1, 2, 0.
        assert_eq!(rows(m)[0], "1  2  0");
    }
}
