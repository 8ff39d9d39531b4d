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
use super::urdf_relocate::relocate;
use super::urdf_report::{Fields, UrdfReport, Value};
use super::urdf_table::{render, sig, sig3};
use super::{DEFAULT_DENSITY, Format, InertiaArgs, InertialForm, WeldChoice};
use crate::error::{CliError, Stream};
use kreisel_scene::error::one_line;

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

/// Whether the report is the table on standard error or JSON on standard
/// output (`--format text|json`; the others are refused with `--urdf`).
///
/// # Errors
/// [`CliError::Argument`] for `--format urdf|sdf|mjcf`, and for
/// `--format json` when filling without `--output` (the URDF and the report
/// cannot share standard output).
fn json_report(args: &InertiaArgs) -> Result<bool, CliError> {
    let refuse = |message: &str| {
        Err(CliError::Argument {
            argument: "--format".into(),
            message: message.into(),
        })
    };
    match args.format {
        Format::Text => Ok(false),
        Format::Json if args.robot.check || args.robot.output.is_some() => Ok(true),
        Format::Json => refuse(
            "json with --urdf needs --output FILE (or --check): the filled URDF and the report cannot share standard output",
        ),
        _ => refuse(
            "with --urdf only text (the table on standard error) or json (the report on standard output); the URDF itself is the output",
        ),
    }
}

/// Runs `inertia --urdf` (filling, or `--check`).
///
/// # Errors
/// [`CliError::ReadUrdf`], [`CliError::Urdf`] (malformed file, missing mesh
/// or package), [`CliError::Write`] for the output; after writing the
/// output, [`CliError::LinksKept`]; for `--check`, [`CliError::CheckFailed`]
/// and [`CliError::NotCompared`].
pub fn run(urdf: &Path, args: &InertiaArgs) -> Result<(), CliError> {
    let json = json_report(args)?;
    let text = kreisel_inertia::io::read_limited_text(urdf, "a URDF file").map_err(|source| {
        CliError::ReadUrdf {
            path: urdf.to_path_buf(),
            source,
        }
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
        let check = super::urdf_check::Check {
            urdf,
            doc: &doc,
            outcomes: &outcomes,
            source,
            density: args.density,
            hull: args.hull,
        };
        return check.run(json);
    }
    let density = args.density.unwrap_or(DEFAULT_DENSITY);
    let form = InertialForm {
        principal: args.principal,
        digits: args.digits,
    };
    let mut elements = Vec::new();
    let mut rows = Vec::new();
    let mut report_rows = Vec::new();
    let mut kept = Vec::new();
    for (k, (link, outcome)) in doc.links.iter().zip(&outcomes).enumerate() {
        let mut row = vec![link.name.clone()];
        let mut fields: Fields = vec![("name", Value::Text(link.name.clone()))];
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
                match link.inertial.as_ref().and_then(|i| i.mass) {
                    // pybullet (and others) read mass 0 as a static link.
                    Some(0.0) => {
                        notes.insert(0, "was mass 0 (static in pybullet), now has mass".into());
                    }
                    Some(m) if m < 0.0 => notes.insert(
                        0,
                        format!(
                            "was mass {} (negative, unphysical), now density x volume",
                            sig(m)
                        ),
                    ),
                    _ => {}
                }
                row.extend([
                    sig(props.mass),
                    sig(rho),
                    sig3(props.center_of_mass),
                    sig3(props.principal().moments),
                    solid.parts.join(" + "),
                    notes.join("; "),
                ]);
                fields.extend([
                    ("action", Value::Text("filled".into())),
                    ("mass", Value::Number(props.mass)),
                    ("density", Value::Number(rho)),
                    (
                        "mass_source",
                        Value::Text(match mass_source {
                            MassSource::Kept => "kept".into(),
                            MassSource::Density => "density".into(),
                        }),
                    ),
                    ("center_of_mass", Value::Vector(props.center_of_mass)),
                    ("inertia", Value::Matrix(props.inertia)),
                    (
                        "principal_moments",
                        Value::Vector(props.principal().moments),
                    ),
                    ("geometry", Value::Texts(solid.parts.clone())),
                    ("notes", Value::Texts(notes)),
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
                row.push(note.clone());
                let action = if failed { "kept" } else { "unchanged" };
                fields.push(("action", Value::Text(action.into())));
                for key in [
                    "mass",
                    "density",
                    "mass_source",
                    "center_of_mass",
                    "inertia",
                    "principal_moments",
                ] {
                    fields.push((key, Value::Null));
                }
                fields.push(("geometry", Value::Texts(Vec::new())));
                fields.push(("notes", Value::Texts(vec![note])));
            }
        }
        rows.push(row);
        report_rows.push(fields);
    }
    let moved = match &args.robot.output {
        Some(output) => relocate(&doc, urdf, output),
        None => Vec::new(),
    };
    let summary: Fields = vec![
        ("links", Value::Count(doc.links.len())),
        ("filled", Value::Count(elements.len())),
        ("kept", Value::Count(kept.len())),
        ("mesh_paths_rewritten", Value::Count(moved.len())),
        ("exit_status", Value::Count(usize::from(!kept.is_empty()))),
    ];
    let out = doc.splice_with(&elements, moved.clone());
    if !json {
        let header = [
            "link",
            "mass kg",
            "density kg/m^3",
            "COM m (link frame)",
            "principal moments kg m^2",
            source.element(),
            "notes",
        ];
        let mut table = render(&header, &rows);
        if !moved.is_empty() {
            table.push_str(&format!(
                "{} relative mesh path(s) rewritten to load from the output's folder\n",
                moved.len()
            ));
        }
        let _ = std::io::stderr().write_all(table.as_bytes());
    }
    match &args.robot.output {
        Some(path) => {
            crate::output::atomic_file::write_file(path, out.as_bytes()).map_err(|source| {
                CliError::Write {
                    output: Stream::File(path.clone()),
                    source,
                }
            })?;
        }
        None => crate::output::print_stdout(&out)?,
    }
    if json {
        let report = UrdfReport {
            urdf: urdf.display().to_string(),
            mode: "fill",
            links: report_rows,
            summary,
        };
        crate::output::print_stdout(&report.json())?;
    }
    if kept.is_empty() {
        Ok(())
    } else {
        Err(CliError::LinksKept { links: kept })
    }
}
