//! `kreisel inertia`: mass, centre of mass, inertia tensor and principal
//! axes of the bodies in a mesh file, as text, JSON, or a URDF, SDFormat or
//! MJCF `<inertial>` element.
//!
//! The options become a [`Setup`] (units, model, material), the library
//! loads and integrates each body ([`compute`]), and one of the writers
//! ([`text`], [`json`], [`xml`]) renders the [`Report`]. Mesh repairs are
//! warnings: written to standard error and into the report, exit status 0.

#![forbid(unsafe_code)]

mod frame_change;
mod inertial_form;
pub(crate) mod json;
mod rounding;
mod shown;
mod text;
mod xml;

// Whole robots: `--urdf` (issue 16).
mod urdf_args;
mod urdf_check;
mod urdf_document;
mod urdf_fill;
mod urdf_inertial;
mod urdf_links;
mod urdf_notes;
mod urdf_paths;
mod urdf_relocate;
mod urdf_report;
mod urdf_table;
mod urdf_wellformed;

use std::io::Write;
use std::path::PathBuf;

use kreisel_inertia::MassModel;

use crate::error::CliError;
use kreisel_scene::error::one_line;

pub use frame_change::{OutputFrame, Transform};
pub use inertial_form::{Inertial, InertialForm, MARGIN_ULPS, is_loadable, rpy_sequence};
use kreisel_scene::inertia_request::{DensityChoice, Report, Setup, Summary, compute};
use kreisel_scene::mesh_options::{DEFAULT_DENSITY, DEFAULT_THICKNESS, Units, WeldChoice};
pub use rounding::DIGITS;
pub use urdf_args::{GeometrySource, PackageDir, UrdfArgs};

/// The `--help` text of `kreisel inertia` after the option list.
const AFTER_LONG_HELP: &str = "\
Conventions:
  Everything is in SI units after scaling: coordinates in m, mass in kg,
  inertia in kg m^2. The tensor is about the centre of mass in the mesh axes,
  I_ab = sum m (r^2 delta_ab - r_a r_b), so its off-diagonal elements carry
  the minus sign (I_xy = -sum m x y), as URDF, SDFormat and MuJoCo expect.
  Principal moments ascend; the principal axes are unit vectors in mesh
  coordinates and form a right-handed frame; the principal orientation is the
  quaternion w,x,y,z that maps principal-frame coordinates to mesh coordinates.

Bodies:
  Every object/group of an OBJ file, solid of an ASCII STL file and mesh of a
  glTF scene is one body; all are in the mesh frame, and the assembly is their
  rigid sum. --mass is the mass of the assembly: one density, mass / total
  volume, is applied to every body. URDF, SDFormat and MJCF output is the
  assembly's inertial. With --merge all of them are one body (welded
  together), for files whose objects are closed only as a whole.

Meshes:
  Vertices within 1e-6 x the bounding-box diagonal are welded on loading
  (--weld TOL in metres, or --weld off for bit-identical ones only). A solid
  needs a closed surface: along every edge as many triangles run one way as
  the other (edges of more than two triangles are accepted when they
  cancel). Inconsistent winding, inside-out surfaces and degenerate
  triangles are repaired with a warning on standard error; an open mesh is
  an error naming where it is open and, when the gaps are tiny, the --weld
  that closes them. A surface that is open on purpose can be modelled with
  --shell (a thin wall of --thickness T) or, if convex, --hull (the solid
  convex hull of the vertices). A mesh larger than 10 m or smaller than
  1 mm after scaling gets a warning naming the likely --units.

Examples:
  kreisel inertia part.stl --units mm --density 2700
  kreisel inertia assets/t_handle.obj --format urdf
  kreisel inertia scan.ply --hull --mass 0.35 --format json

Frames and rounding:
  --transform \"xyz=X Y Z rpy=R P Y\" gives everything in the frame of a link in
  which the mesh is placed as by a URDF <origin>: p_link = R p_mesh + xyz,
  R = Rz(yaw) Ry(pitch) Rx(roll), xyz in metres (after --scale/--units),
  angles in radians (a URDF origin's quoted xyz=\"...\" rpy=\"...\" is accepted
  as pasted). --about X,Y,Z adds the tensor about that point (text and
  JSON); the point is in the mesh file's own coordinates and units (the
  numbers of its vertices, before --scale/--units), shown in metres in the
  output frame. --principal writes the URDF/SDFormat/MJCF inertial in its
  principal axes: the origin's rpy (pose, quat) is the principal frame and
  the tensor is diagonal. --digits N rounds every computed number to N
  significant digits; products of inertia below the last digit of the
  largest moment become 0, and the smallest moment is raised where rounding
  would break A + B >= C, so the rounded tensor still loads.

  kreisel inertia wheel.stl --units mm --transform \"xyz=0 0.1 0 rpy=1.5708 0 0\" --format urdf
  kreisel inertia part.obj --about 0,0,0 --digits 6
  kreisel inertia part.obj --principal --digits 8 --format sdf";

/// Arguments of `kreisel inertia`.
#[derive(Debug, Clone, clap::Args)]
#[command(after_long_help = format!("{AFTER_LONG_HELP}\n\n{}", urdf_args::URDF_HELP))]
pub struct InertiaArgs {
    /// Mesh file: .stl (binary or ASCII), .obj, .ply, .gltf or .glb
    #[arg(value_name = "MESH", required_unless_present = "urdf")]
    pub mesh: Option<PathBuf>,

    /// Uniform density in kg/m^3 [default: 1000, water]
    #[arg(long, value_name = "RHO", value_parser = parse_density, allow_hyphen_values = true)]
    pub density: Option<f64>,

    /// Total mass of the whole file in kg; the density follows from the total volume
    #[arg(
        long,
        value_name = "M",
        value_parser = parse_mass,
        allow_hyphen_values = true,
        conflicts_with = "density"
    )]
    pub mass: Option<f64>,

    /// Multiply every coordinate by S to get metres [default: 1]
    #[arg(long, value_name = "S", value_parser = parse_scale, allow_hyphen_values = true)]
    pub scale: Option<f64>,

    /// Length unit of the mesh coordinates (the same as --scale 0.001, 0.01, 1, 0.0254) [default: m]
    #[arg(long, value_name = "UNIT", value_parser = units_parser(), conflicts_with = "scale")]
    pub units: Option<Units>,

    /// Model the surface as a thin shell of uniform thickness (open meshes allowed)
    #[arg(long, conflicts_with = "hull")]
    pub shell: bool,

    /// Shell wall thickness in metres, after scaling [default: 0.001]
    #[arg(
        long,
        value_name = "T",
        value_parser = parse_thickness,
        allow_hyphen_values = true,
        requires = "shell"
    )]
    pub thickness: Option<f64>,

    /// Model each body as the solid convex hull of its vertices
    #[arg(long)]
    pub hull: bool,

    /// Weld vertices within TOL metres (after scaling), or 'off' for bit-identical ones only [default: 1e-6 x the bounding-box diagonal]
    #[arg(long, value_name = "TOL|off", value_parser = parse_weld, allow_hyphen_values = true)]
    pub weld: Option<WeldChoice>,

    /// Treat all objects/bodies of the file as one solid
    #[arg(long)]
    pub merge: bool,

    /// Output format
    #[arg(long, value_name = "FORMAT", value_enum, default_value_t = Format::Text)]
    pub format: Format,

    // ---- Frames and rounding (issue 16: single meshes in any frame) ----
    /// Also give the tensor about the point X,Y,Z, in the mesh file's coordinates and units (text and json)
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_point, allow_hyphen_values = true)]
    pub about: Option<glam::DVec3>,

    /// Give everything in a link frame the mesh is placed in: p_link = R p_mesh + xyz, R = Rz(yaw) Ry(pitch) Rx(roll); metres, radians
    #[arg(
        long,
        value_name = "xyz=X Y Z rpy=R P Y",
        value_parser = parse_transform,
        allow_hyphen_values = true
    )]
    pub transform: Option<Transform>,

    /// Write the URDF/SDFormat/MJCF inertial in principal form: origin rotated onto the principal axes, diagonal tensor
    #[arg(long)]
    pub principal: bool,

    /// Round every computed number to N significant digits (1-17); tiny products of inertia become 0
    #[arg(long, value_name = "N", value_parser = parse_digits, allow_hyphen_values = true)]
    pub digits: Option<u32>,

    // Whole robots: --urdf, --output, --from, --package, --check (urdf_args.rs).
    #[command(flatten)]
    pub robot: UrdfArgs,
}

/// How the results are presented: their frame, the `--about` point, and
/// the form and rounding of the numbers.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct View {
    /// `--transform` and `--about`.
    pub frame: OutputFrame,
    /// `--principal` and `--digits`.
    pub form: InertialForm,
}

/// `--about`: three finite numbers.
fn parse_point(text: &str) -> Result<glam::DVec3, String> {
    frame_change::three(text).map_err(|e| format!("point X,Y,Z: {e}"))
}

/// `--transform`: `xyz=X Y Z rpy=R P Y`.
fn parse_transform(text: &str) -> Result<Transform, String> {
    text.parse()
}

/// `--digits`: an integer from 1 to 17.
fn parse_digits(text: &str) -> Result<u32, String> {
    match text.trim().parse::<u32>() {
        Ok(n) if DIGITS.contains(&n) => Ok(n),
        _ => Err(format!(
            "digits must be an integer from {} to {} (17 keep every f64)",
            DIGITS.start(),
            DIGITS.end()
        )),
    }
}

/// `--units`: the library's units by their symbols, each listed with its
/// name in `--help`.
fn units_parser() -> impl clap::builder::TypedValueParser<Value = Units> {
    use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
    let value = |u: Units| {
        let name = u.name();
        let help = format!("{}{}", name[..1].to_uppercase(), &name[1..]);
        PossibleValue::new(u.symbol()).help(help)
    };
    PossibleValuesParser::new(Units::ALL.map(value)).try_map(|symbol| symbol.parse::<Units>())
}

/// What `kreisel inertia` writes (`--format`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// A readable report of every body and the assembly.
    Text,
    /// One JSON object: the assembly, with every body under `bodies`.
    Json,
    /// A URDF `<inertial>` element of the assembly.
    Urdf,
    /// An SDFormat `<inertial>` element of the assembly.
    Sdf,
    /// A MuJoCo MJCF `<inertial>` element of the assembly.
    Mjcf,
}

/// A positive finite number, or a message saying what `quantity` must be.
fn parse_positive(text: &str, quantity: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        Ok(_) => Err(format!("{quantity} must be a positive finite number")),
        Err(e) => Err(format!("{quantity} must be a positive finite number ({e})")),
    }
}

/// `--density`: kg/m³, positive and finite.
fn parse_density(text: &str) -> Result<f64, String> {
    parse_positive(text, "density (kg/m^3)")
}

/// `--mass`: kg, positive and finite.
fn parse_mass(text: &str) -> Result<f64, String> {
    parse_positive(text, "mass (kg)")
}

/// `--scale`: metres per mesh unit, positive and finite.
fn parse_scale(text: &str) -> Result<f64, String> {
    parse_positive(text, "scale (metres per mesh unit)")
}

/// `--thickness`: m, positive and finite.
fn parse_thickness(text: &str) -> Result<f64, String> {
    parse_positive(text, "thickness (m)")
}

/// `--weld`: `off`, or a tolerance in metres, non-negative and finite.
fn parse_weld(text: &str) -> Result<WeldChoice, String> {
    let text = text.trim();
    if text.eq_ignore_ascii_case("off") {
        return Ok(WeldChoice::Off);
    }
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(WeldChoice::Metres(v)),
        _ => Err("weld tolerance must be 'off' or a non-negative finite number of metres".into()),
    }
}

impl InertiaArgs {
    /// The frame and form these options choose.
    ///
    /// # Errors
    /// [`CliError::Argument`] for `--about` with an `<inertial>` format
    /// (always about the centre of mass) and `--principal` with text or JSON
    /// (which always give the principal axes).
    pub fn view(&self) -> Result<View, CliError> {
        let xml = matches!(self.format, Format::Urdf | Format::Sdf | Format::Mjcf);
        if self.about.is_some() && xml {
            return Err(CliError::Argument {
                argument: "--about".into(),
                message: "applies to --format text and json; a URDF, SDFormat or MJCF inertial is always about the centre of mass".into(),
            });
        }
        if self.principal && !xml {
            return Err(CliError::Argument {
                argument: "--principal".into(),
                message: "applies to --format urdf, sdf and mjcf; text and json always give the principal moments and axes".into(),
            });
        }
        Ok(View {
            frame: OutputFrame {
                transform: self.transform,
                about: self.about,
            },
            form: InertialForm {
                principal: self.principal,
                digits: self.digits,
            },
        })
    }

    /// The units, model and material these options choose.
    pub fn setup(&self) -> Setup {
        let (units, scale) = match (self.units, self.scale) {
            (_, Some(s)) => (None, s),
            (Some(u), None) => (Some(u), u.scale()),
            (None, None) => (Some(Units::M), 1.0),
        };
        let model = if self.shell {
            MassModel::Shell {
                thickness: self.thickness.unwrap_or(DEFAULT_THICKNESS),
            }
        } else if self.hull {
            MassModel::ConvexHull
        } else {
            MassModel::Solid
        };
        let density = match (self.mass, self.density) {
            (Some(m), _) => DensityChoice::TotalMass(m),
            (None, Some(d)) => DensityChoice::Given(d),
            (None, None) => DensityChoice::Default,
        };
        Setup {
            file: self.mesh.clone().unwrap_or_default(),
            units,
            scale,
            model,
            density,
            weld: self.weld.unwrap_or(WeldChoice::Default),
            merge: self.merge,
        }
    }
}

/// Runs `kreisel inertia`: loads, integrates, warns, and writes the report.
///
/// # Errors
/// [`CliError::LoadMesh`] for a file that cannot be read or parsed,
/// [`CliError::Body`] for a body without mass properties (an open mesh
/// without `--shell` or `--hull`, …), [`CliError::DerivedDensity`],
/// [`CliError::Argument`] for options that do not go together,
/// [`CliError::Write`] when standard output fails.
pub fn run(args: &InertiaArgs) -> Result<(), CliError> {
    if let Some(urdf) = &args.robot.urdf {
        return urdf_fill::run(urdf, args);
    }
    let view = args.view()?;
    let report = view.frame.place(compute(args.setup())?);
    let mut stderr = std::io::stderr();
    for warning in &report.file_warnings {
        let _ = writeln!(
            stderr,
            "kreisel: warning: {}: {}",
            report.setup.file.display(),
            one_line(warning)
        );
    }
    for body in &report.bodies {
        for warning in &body.warnings {
            // Like main's error line: never fail because stderr is closed.
            let _ = writeln!(
                stderr,
                "kreisel: warning: {}: body '{}': {}",
                report.setup.file.display(),
                one_line(&body.name),
                warning
            );
        }
    }
    let output = match args.format {
        Format::Text => text::render(&report, &view),
        Format::Json => json::render(&report, &view),
        Format::Urdf => xml::urdf(&report, &view),
        Format::Sdf => xml::sdf(&report, &view),
        Format::Mjcf => xml::mjcf(&report, &view),
    };
    crate::output::print_stdout(&output)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positive_values_only() {
        assert_eq!(parse_density("1000"), Ok(1000.0));
        assert_eq!(parse_scale(" 1e-3 "), Ok(0.001));
        for bad in ["0", "-1", "nan", "inf", "-0", "1e999", "x"] {
            let e = parse_mass(bad).unwrap_err();
            assert!(
                e.starts_with("mass (kg) must be a positive finite number"),
                "{bad}: {e}"
            );
        }
    }

    #[test]
    fn weld_is_off_or_metres() {
        assert_eq!(parse_weld("OFF"), Ok(WeldChoice::Off));
        assert_eq!(parse_weld("1e-5"), Ok(WeldChoice::Metres(1e-5)));
        assert_eq!(parse_weld("0"), Ok(WeldChoice::Metres(0.0)));
        for bad in ["-1", "nan", "inf", "x"] {
            assert!(parse_weld(bad).is_err(), "{bad}");
        }
        assert_eq!(
            WeldChoice::Metres(1e-6).weld(1e-3),
            kreisel_inertia::Weld::Absolute(1e-6 / 1e-3)
        );
    }

    #[test]
    fn units_are_scales() {
        assert_eq!(Units::Mm.scale(), 0.001);
        assert_eq!(Units::In.scale(), 0.0254);
        assert_eq!(Units::Cm.symbol(), "cm");
    }
}
