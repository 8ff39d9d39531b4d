//! `kreisel inertia --urdf`: reads the robot description, integrates every
//! link's geometry, and either writes the URDF with the links' inertials
//! filled in (only the `<inertial>` elements change) or hands over to
//! `--check`.
//!
//! Mass and density of a filled link:
//! ```text
//! link with <mass value=m>, m > 0:   m kept,      ρ = m / V  (reported)
//! otherwise:                         m = ρ V,     ρ = --density (1000 kg/m³)
//! ```
//! A link whose geometry cannot be integrated keeps its old inertial; the
//! file is still written whole, and the run ends with exit status 1 naming
//! those links ([`CliError::LinksKept`]).

use std::io::Write;
use std::path::Path;

use kreisel_inertia::{MassModel, MassProperties};

use super::urdf_args::GeometrySource;
use super::urdf_document::{Link, UrdfDocument};
use super::urdf_inertial::{Layout, inertial_element};
use super::urdf_links::{LinkOutcome, LinkSolid, MeshModel, integrate};
use super::urdf_paths::MeshPaths;
use super::urdf_table::{render, sig, sig3};
use super::{DEFAULT_DENSITY, InertiaArgs, InertialForm, WeldChoice};
use crate::error::{CliError, Stream, one_line};

/// Where a filled link's mass comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MassSource {
    /// The link's own positive `<mass>`: kept, the density derived.
    Kept,
    /// `--density` (or the default) times the volume.
    Density,
}

/// A link's mass properties from its geometry, at its mass or the density.
///
/// # Errors
/// The library's reason (one line) when the mass or tensor leave f64.
pub fn at_mass(
    link: &Link,
    solid: &LinkSolid,
    density: f64,
) -> Result<(MassProperties, f64, MassSource), String> {
    let volume = solid.unit.mass;
    let kept = link
        .inertial
        .as_ref()
        .and_then(|i| i.mass)
        .filter(|m| m.is_finite() && *m > 0.0);
    let (mass, source) = match kept {
        Some(m) => (m, MassSource::Kept),
        None => (density * volume, MassSource::Density),
    };
    let props = solid
        .unit
        .with_mass(mass)
        .map_err(|e| one_line(&e.to_string()))?;
    Ok((props, mass / volume, source))
}

/// Runs `inertia --urdf` (filling, or `--check`).
///
/// # Errors
/// [`CliError::ReadUrdf`], [`CliError::Urdf`] (malformed file, missing mesh
/// or package), [`CliError::Write`] for the output; after writing the
/// output, [`CliError::LinksKept`]; for `--check`, [`CliError::CheckFailed`].
pub fn run(urdf: &Path, args: &InertiaArgs) -> Result<(), CliError> {
    let text = super::read_text_file(urdf, "a URDF file").map_err(|source| CliError::ReadUrdf {
        path: urdf.to_path_buf(),
        source,
    })?;
    let doc = UrdfDocument::parse(urdf, text)?;
    let paths = MeshPaths::new(urdf, &args.robot.package);
    let source = args.robot.from.unwrap_or(GeometrySource::Collision);
    let how = MeshModel {
        weld: args.weld.unwrap_or(WeldChoice::Default),
        model: if args.hull {
            MassModel::ConvexHull
        } else {
            MassModel::Solid
        },
    };
    let outcomes = doc
        .links
        .iter()
        .map(|link| integrate(urdf, link, source, &paths, how))
        .collect::<Result<Vec<_>, _>>()?;
    if args.robot.check {
        return super::urdf_check::run(urdf, &doc, &outcomes, source, args.density);
    }
    let density = args.density.unwrap_or(DEFAULT_DENSITY);
    let form = InertialForm {
        principal: args.principal,
        digits: args.digits,
    };
    let mut elements = Vec::new();
    let mut rows = Vec::new();
    let mut kept = Vec::new();
    for (k, (link, outcome)) in doc.links.iter().zip(&outcomes).enumerate() {
        let mut row = vec![link.name.clone()];
        let result = match outcome {
            LinkOutcome::NoGeometry => Err(format!(
                "no <{}> geometry: inertial unchanged",
                source.element()
            )),
            LinkOutcome::Failed(reason) => Err(reason.clone()),
            LinkOutcome::Solid(solid) => at_mass(link, solid, density).map(|r| (solid, r)),
        };
        match result {
            Ok((solid, (props, rho, mass_source))) => {
                let layout = Layout {
                    indent: &link.child_indent,
                    step: &link.step,
                    newline: doc.newline,
                };
                elements.push((k, inertial_element(&props, form, layout)));
                let mut notes = solid.warnings.clone();
                if mass_source == MassSource::Kept {
                    notes.insert(0, "mass kept, density derived".into());
                }
                if link.inertial.as_ref().and_then(|i| i.mass) == Some(0.0) {
                    // pybullet (and others) read mass 0 as a static link.
                    notes.insert(0, "was mass 0 (static in pybullet), now has mass".into());
                }
                row.extend([
                    sig(props.mass),
                    sig(rho),
                    sig3(props.center_of_mass),
                    sig3(props.principal().moments),
                    solid.parts.join(" + "),
                    notes.join("; "),
                ]);
            }
            Err(note) => {
                let failed = !matches!(outcome, LinkOutcome::NoGeometry);
                if failed {
                    kept.push(link.name.clone());
                }
                let note = if failed {
                    format!("cannot integrate, old inertial kept: {note}")
                } else {
                    note
                };
                row.extend(["-", "-", "-", "-", "-"].map(String::from));
                row.push(note);
            }
        }
        rows.push(row);
    }
    let header = [
        "link",
        "mass kg",
        "density kg/m^3",
        "COM m (link frame)",
        "principal moments kg m^2",
        source.element(),
        "notes",
    ];
    let table = render(&header, &rows);
    let _ = std::io::stderr().write_all(table.as_bytes());
    let out = doc.splice(&elements);
    match &args.robot.output {
        Some(path) => {
            crate::atomic_file::write_file(path, out.as_bytes()).map_err(|source| {
                CliError::Write {
                    output: Stream::File(path.clone()),
                    source,
                }
            })?;
        }
        None => crate::convert::print_stdout(&out)?,
    }
    if kept.is_empty() {
        Ok(())
    } else {
        Err(CliError::LinksKept { links: kept })
    }
}
