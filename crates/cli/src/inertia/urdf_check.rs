//! `kreisel inertia --urdf ROBOT --check`: every link's inertial against its
//! geometry, and on its own physics.
//!
//! ```text
//! mass ratio   m_file / (ρ V)                       only with an explicit --density
//! COM offset   |c_file − c_mesh| / diag(bounding box of the geometry)
//! tensor diff  ‖I_file − I_mesh‖_F / ‖I_mesh‖_F      about each own COM, link axes,
//!                                                   the mesh at the file's mass
//! physical     m > 0, I₁ > 0, I₁ + I₂ ≥ I₃ (1e-6 relative),
//!              c_file inside the convex hull of the geometry (1e-6 of its diagonal)
//! ```
//!
//! Without `--density` the mesh gets the link's own mass, so a mass ratio
//! would be 1 by construction and is not shown. A link without an inertial,
//! or with mass 0, is massless (or static) in URDF: listed, not failed. A link whose geometry cannot be
//! integrated is listed as not compared (its physics still checked).

use std::io::Write;
use std::path::Path;

use glam::{DMat3, DVec3};
use kreisel_inertia::{PrincipalAxes, TriMesh, convex_hull};

use super::urdf_args::GeometrySource;
use super::urdf_document::{Inertial, UrdfDocument};
use super::urdf_links::{LinkOutcome, LinkSolid};
use super::urdf_report::{Fields, UrdfReport, Value};
use super::urdf_table::{render, sig};
use crate::error::CliError;

/// Largest accepted `|m_file / (ρ V) − 1|` (with an explicit density).
pub const MASS_TOLERANCE: f64 = 0.1;
/// Largest accepted COM offset, as a fraction of the geometry's bounding-box diagonal.
pub const COM_TOLERANCE: f64 = 0.05;
/// Largest accepted relative Frobenius difference of the tensors.
pub const TENSOR_TOLERANCE: f64 = 0.2;
/// Slack of the triangle inequality, relative to the largest moment.
pub const TRIANGLE_SLACK: f64 = 1e-6;
/// Slack of the inside-the-hull test, relative to the hull's diagonal.
pub const HULL_SLACK: f64 = 1e-6;

/// `x <= limit`, false for NaN (a measure that cannot be computed fails).
fn within(x: f64, limit: f64) -> bool {
    x <= limit
}

/// The Frobenius norm of a matrix.
fn frobenius(m: DMat3) -> f64 {
    m.to_cols_array().iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// Why the inertial on its own is unphysical (empty when it is physical).
fn physics(inertial: &Inertial, tensor: DMat3) -> Vec<String> {
    let mut problems = Vec::new();
    match inertial.mass {
        Some(m) if m.is_finite() && m > 0.0 => {}
        Some(m) => problems.push(format!("mass {m} is not positive")),
        None => problems.push("no <mass>".into()),
    }
    match PrincipalAxes::try_from_tensor(tensor) {
        Err(_) => problems.push("tensor is not finite".into()),
        Ok(p) => {
            let [a, b, c] = p.moments.to_array();
            if a <= 0.0 {
                problems.push(format!(
                    "not positive definite (smallest moment {})",
                    sig(a)
                ));
            }
            if a + b < c - TRIANGLE_SLACK * c.abs() {
                problems.push(format!(
                    "breaks I1 + I2 >= I3 ({} + {} < {})",
                    sig(a),
                    sig(b),
                    sig(c)
                ));
            }
        }
    }
    problems
}

/// The outward distance of `point` from the convex hull of `points`
/// (≤ 0 inside), or `None` for a flat or degenerate hull.
fn outside_hull(points: &[DVec3], point: DVec3) -> Option<f64> {
    let hull = convex_hull(&TriMesh::try_new(points.to_vec(), vec![[0, 1, 2]]).ok()?).ok()?;
    let mut distance = f64::NEG_INFINITY;
    for &t in hull.triangles() {
        let [a, b, c] = hull.corners(t);
        let n = (b - a).cross(c - a).normalize_or_zero();
        distance = distance.max(n.dot(point - a));
    }
    Some(distance)
}

/// The measures of one link's comparison.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Measures {
    /// `m_file / (ρ V)`, with an explicit density.
    ratio: Option<f64>,
    /// `|c_file − c_mesh|`, m.
    offset: f64,
    /// The offset over the geometry's bounding-box diagonal.
    fraction: f64,
    /// `‖I_file − I_mesh‖_F / ‖I_mesh‖_F`.
    diff: f64,
}

impl Measures {
    /// The three table cells: mass ratio, COM offset (% size), tensor diff.
    fn cells(&self) -> [String; 3] {
        [
            self.ratio.map_or_else(|| "-".into(), sig),
            format!("{} ({}%)", sig(self.offset), sig(100.0 * self.fraction)),
            format!("{}%", sig(100.0 * self.diff)),
        ]
    }
}

/// One link's comparison: its measures and the reasons it fails.
fn compare(
    inertial: &Inertial,
    tensor: DMat3,
    solid: &LinkSolid,
    density: Option<f64>,
) -> (Measures, Vec<String>) {
    let mut fails = Vec::new();
    let volume = solid.unit.mass;
    let m_file = inertial.mass.unwrap_or(f64::NAN);
    let ratio = match density {
        Some(rho) => {
            let r = m_file / (rho * volume);
            if !within((r - 1.0).abs(), MASS_TOLERANCE) {
                fails.push(format!(
                    "mass {} kg is {}x density x volume",
                    sig(m_file),
                    sig(r)
                ));
            }
            Some(r)
        }
        None => None,
    };
    let mesh_mass = if m_file.is_finite() && m_file > 0.0 {
        m_file
    } else {
        volume
    };
    let mesh_inertia = solid.unit.inertia * (mesh_mass / volume);
    let size = solid.size();
    let offset = (inertial.origin.xyz - solid.unit.center_of_mass).length();
    if !within(offset, COM_TOLERANCE * size) {
        fails.push(format!(
            "centre of mass {} m ({}% of the size) from the geometry's",
            sig(offset),
            sig(100.0 * offset / size)
        ));
    }
    let diff = frobenius(tensor - mesh_inertia) / frobenius(mesh_inertia);
    if !within(diff, TENSOR_TOLERANCE) {
        fails.push(format!(
            "tensor differs by {}% from the geometry's",
            sig(100.0 * diff)
        ));
    }
    if let Some(out) = outside_hull(&solid.hull_points, inertial.origin.xyz)
        && out > HULL_SLACK * size
    {
        fails.push(format!(
            "centre of mass {} m outside the geometry's convex hull",
            sig(out)
        ));
    }
    let measures = Measures {
        ratio,
        offset,
        fraction: offset / size,
        diff,
    };
    (measures, fails)
}

/// `--check` on a parsed description and its integrated links.
pub struct Check<'a> {
    /// The URDF as given.
    pub urdf: &'a Path,
    /// Its links.
    pub doc: &'a UrdfDocument,
    /// What became of each link's geometry.
    pub outcomes: &'a [LinkOutcome],
    /// `--from`.
    pub source: GeometrySource,
    /// `--density`, when given.
    pub density: Option<f64>,
    /// `--hull`, to say whether it would help.
    pub hull: bool,
}

/// One link's verdict.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Verdict {
    Ok,
    Fail,
    /// The geometry cannot be integrated (its physics passed).
    NotCompared,
    /// No inertial, mass 0, or no geometry: nothing to compare.
    Listed,
}

impl Verdict {
    /// The word of the JSON report.
    fn json(self) -> &'static str {
        match self {
            Verdict::Ok => "ok",
            Verdict::Fail => "fail",
            Verdict::NotCompared => "not compared",
            Verdict::Listed => "not checked",
        }
    }

    /// The table cell.
    fn text(self) -> &'static str {
        match self {
            Verdict::Ok => "ok",
            Verdict::Fail => "FAIL",
            Verdict::NotCompared => "not compared",
            Verdict::Listed => "-",
        }
    }
}

impl Check<'_> {
    /// One link: its verdict, the measures of [`compare`] (empty when not
    /// compared) and the notes.
    fn link(
        &self,
        inertial: Option<&Inertial>,
        outcome: &LinkOutcome,
    ) -> (Verdict, Option<Measures>, Vec<String>) {
        let inertial = match inertial {
            None => {
                return (
                    Verdict::Listed,
                    None,
                    vec!["no inertial (massless)".to_owned()],
                );
            }
            // URDF's (and pybullet's) convention for a static or massless link.
            Some(i) if i.mass == Some(0.0) => {
                return (
                    Verdict::Listed,
                    None,
                    vec!["mass 0 (massless or static)".to_owned()],
                );
            }
            Some(i) => i,
        };
        let tensor = inertial.tensor_in_link().unwrap_or(DMat3::ZERO);
        let mut fails = physics(inertial, tensor);
        if inertial.tensor.is_none() {
            fails.push("no <inertia>".into());
        }
        let physical = fails.is_empty();
        let (cells, unchecked) = match outcome {
            LinkOutcome::Solid(solid) => {
                let (measures, more) = compare(inertial, tensor, solid, self.density);
                fails.extend(more);
                (Some(measures), None)
            }
            LinkOutcome::NoGeometry => (
                None,
                Some((
                    Verdict::Listed,
                    format!("no <{}> geometry to compare with", self.source.element()),
                )),
            ),
            LinkOutcome::Failed(reason) => (
                None,
                Some((
                    Verdict::NotCompared,
                    format!("not compared, cannot integrate: {reason}"),
                )),
            ),
        };
        let verdict = match unchecked {
            Some((verdict, why)) => {
                fails.push(why);
                if physical { verdict } else { Verdict::Fail }
            }
            None if fails.is_empty() => Verdict::Ok,
            None => Verdict::Fail,
        };
        (verdict, cells, fails)
    }

    /// Runs the check: the table on standard error, or with `json` the
    /// report on standard output.
    ///
    /// # Errors
    /// [`CliError::CheckFailed`] naming the links that fail; otherwise
    /// [`CliError::NotCompared`] naming those that could not be compared.
    pub fn run(&self, json: bool) -> Result<(), CliError> {
        let mut rows = Vec::new();
        let mut report_rows = Vec::new();
        let mut failed = Vec::new();
        let mut uncompared = Vec::new();
        for (link, outcome) in self.doc.links.iter().zip(self.outcomes) {
            let (verdict, cells, mut notes) = self.link(link.inertial.as_ref(), outcome);
            match verdict {
                Verdict::Fail => failed.push(link.name.clone()),
                Verdict::NotCompared => uncompared.push(link.name.clone()),
                Verdict::Ok | Verdict::Listed => {}
            }
            if let LinkOutcome::Solid(solid) = outcome {
                notes.extend(solid.size_warning());
            }
            let mut fields: Fields = vec![
                ("name", Value::Text(link.name.clone())),
                ("check", Value::Text(verdict.json().into())),
            ];
            let inertial = link.inertial.as_ref();
            fields.push((
                "mass",
                inertial
                    .and_then(|i| i.mass)
                    .map_or(Value::Null, Value::Number),
            ));
            fields.push((
                "center_of_mass",
                inertial.map_or(Value::Null, |i| Value::Vector(i.origin.xyz)),
            ));
            fields.push((
                "inertia",
                inertial
                    .and_then(Inertial::tensor_in_link)
                    .map_or(Value::Null, Value::Matrix),
            ));
            let measured = |f: fn(&Measures) -> Option<f64>| {
                cells
                    .as_ref()
                    .and_then(f)
                    .map_or(Value::Null, Value::Number)
            };
            fields.push(("mass_ratio", measured(|m| m.ratio)));
            fields.push(("com_offset", measured(|m| Some(m.offset))));
            fields.push(("com_offset_fraction", measured(|m| Some(m.fraction))));
            fields.push(("tensor_diff", measured(|m| Some(m.diff))));
            fields.push(("notes", Value::Texts(notes.clone())));
            report_rows.push(fields);
            let mut row = vec![link.name.clone()];
            match &cells {
                Some(m) => row.extend(m.cells()),
                None => row.extend(["-", "-", "-"].map(String::from)),
            }
            row.push(verdict.text().into());
            row.push(notes.join("; "));
            rows.push(row);
        }
        let uncompared_text = if uncompared.is_empty() {
            String::new()
        } else {
            format!(
                ", {} not compared (geometry not integrable)",
                uncompared.len()
            )
        };
        let status = usize::from(!failed.is_empty() || !uncompared.is_empty());
        if json {
            let report = UrdfReport {
                urdf: self.urdf.display().to_string(),
                mode: "check",
                links: report_rows,
                summary: vec![
                    ("links", Value::Count(self.doc.links.len())),
                    ("fail", Value::Count(failed.len())),
                    ("not_compared", Value::Count(uncompared.len())),
                    ("density", self.density.map_or(Value::Null, Value::Number)),
                    ("exit_status", Value::Count(status)),
                ],
            };
            crate::output::print_stdout(&report.json())?;
        } else {
            let header = [
                "link",
                "mass ratio",
                "COM offset m (% size)",
                "tensor diff",
                "check",
                "why",
            ];
            let mut out = render(&header, &rows);
            out.push_str(&format!(
                "{}: {} links, {} fail{uncompared_text}{}\n",
                self.urdf.display(),
                self.doc.links.len(),
                failed.len(),
                if self.density.is_none() {
                    " (no --density: meshes at each link's own mass, no mass ratio)"
                } else {
                    ""
                }
            ));
            let _ = std::io::stderr().write_all(out.as_bytes());
        }
        if !failed.is_empty() {
            Err(CliError::CheckFailed { links: failed })
        } else if !uncompared.is_empty() {
            Err(CliError::NotCompared {
                links: uncompared,
                hull: self.hull,
            })
        } else {
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unphysical_inertials_are_named() {
        let inertial = Inertial {
            range: 0..0,
            origin: Default::default(),
            mass: Some(1.0),
            tensor: None,
        };
        let ok = DMat3::from_diagonal(DVec3::new(1.0, 1.0, 2.0));
        assert!(physics(&inertial, ok).is_empty());
        let flat_plus = DMat3::from_diagonal(DVec3::new(1.0, 1.0, 2.0 + 1e-3));
        assert!(physics(&inertial, flat_plus)[0].starts_with("breaks I1 + I2 >= I3"));
        let negative = DMat3::from_diagonal(DVec3::new(-1.0, 2.0, 2.0));
        assert!(physics(&inertial, negative)[0].starts_with("not positive definite"));
    }

    #[test]
    fn help_states_the_tolerances() {
        let help = super::super::urdf_args::URDF_HELP.replace("\n", " ");
        let help = help.split_whitespace().collect::<Vec<_>>().join(" ");
        for text in [
            format!("more than {}%", MASS_TOLERANCE * 100.0),
            format!(
                "more than {}% of the geometry's bounding-box",
                COM_TOLERANCE * 100.0
            ),
            format!("|I_mesh|_F > {TENSOR_TOLERANCE}"),
            format!("beyond {TRIANGLE_SLACK:e} relative"),
            format!("beyond {HULL_SLACK:e} of its diagonal"),
        ] {
            assert!(help.contains(&text), "{text}");
        }
    }

    #[test]
    fn hull_distance() {
        let cube: Vec<DVec3> = (0..8)
            .map(|i| DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64))
            .collect();
        assert!(outside_hull(&cube, DVec3::splat(0.5)).unwrap() < 0.0);
        let d = outside_hull(&cube, DVec3::new(0.5, 0.5, 1.25)).unwrap();
        assert!((d - 0.25).abs() < 1e-15, "{d}");
    }
}
