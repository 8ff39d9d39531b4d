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

/// One link's comparison: the table cells and the reasons it fails.
fn compare(
    inertial: &Inertial,
    tensor: DMat3,
    solid: &LinkSolid,
    density: Option<f64>,
) -> (Vec<String>, Vec<String>) {
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
            sig(r)
        }
        None => "-".into(),
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
    let cells = vec![
        ratio,
        format!("{} ({}%)", sig(offset), sig(100.0 * offset / size)),
        format!("{}%", sig(100.0 * diff)),
    ];
    (cells, fails)
}

/// Runs `--check` on the parsed description and its integrated links.
///
/// # Errors
/// [`CliError::CheckFailed`] naming the links that fail.
pub fn run(
    urdf: &Path,
    doc: &UrdfDocument,
    outcomes: &[LinkOutcome],
    source: GeometrySource,
    density: Option<f64>,
) -> Result<(), CliError> {
    let mut rows = Vec::new();
    let mut failed = Vec::new();
    for (link, outcome) in doc.links.iter().zip(outcomes) {
        let mut row = vec![link.name.clone()];
        let (cells, verdict, notes) = match &link.inertial {
            None => (vec![], "-", vec!["no inertial (massless)".to_owned()]),
            // URDF's (and pybullet's) convention for a static or massless link.
            Some(i) if i.mass == Some(0.0) => {
                (vec![], "-", vec!["mass 0 (massless or static)".to_owned()])
            }
            Some(inertial) => {
                let tensor = inertial.tensor_in_link().unwrap_or(DMat3::ZERO);
                let mut fails = physics(inertial, tensor);
                if inertial.tensor.is_none() {
                    fails.push("no <inertia>".into());
                }
                let cells = match outcome {
                    LinkOutcome::Solid(solid) => {
                        let (cells, more) = compare(inertial, tensor, solid, density);
                        fails.extend(more);
                        cells
                    }
                    LinkOutcome::NoGeometry => {
                        fails.push(format!(
                            "no <{}> geometry to compare with",
                            source.element()
                        ));
                        vec![]
                    }
                    LinkOutcome::Failed(reason) => {
                        fails.push(format!("not compared, cannot integrate: {reason}"));
                        vec![]
                    }
                };
                let unchecked = !matches!(outcome, LinkOutcome::Solid(_));
                let physical = physics(inertial, tensor).is_empty() && inertial.tensor.is_some();
                let verdict = if fails.is_empty() {
                    "ok"
                } else if unchecked && physical {
                    "-"
                } else {
                    "FAIL"
                };
                (cells, verdict, fails)
            }
        };
        if verdict == "FAIL" {
            failed.push(link.name.clone());
        }
        let mut notes = notes;
        if let LinkOutcome::Solid(solid) = outcome {
            notes.extend(solid.size_warning());
        }
        let mut cells = cells;
        cells.resize(3, "-".into());
        row.extend(cells);
        row.push(verdict.into());
        row.push(notes.join("; "));
        rows.push(row);
    }
    let header = [
        "link",
        "mass ratio",
        "COM offset m (% size)",
        "tensor diff",
        "check",
        "why",
    ];
    let mut out = render(&header, &rows);
    let uncompared = outcomes
        .iter()
        .filter(|o| matches!(o, LinkOutcome::Failed(_)))
        .count();
    let uncompared = if uncompared > 0 {
        format!(", {uncompared} not compared (geometry not integrable)")
    } else {
        String::new()
    };
    out.push_str(&format!(
        "{}: {} links, {} fail{uncompared}{}\n",
        urdf.display(),
        doc.links.len(),
        failed.len(),
        if density.is_none() {
            " (no --density: meshes at each link's own mass, no mass ratio)"
        } else {
            ""
        }
    ));
    let _ = std::io::stderr().write_all(out.as_bytes());
    if failed.is_empty() {
        Ok(())
    } else {
        Err(CliError::CheckFailed { links: failed })
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
