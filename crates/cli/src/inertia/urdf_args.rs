//! The options of `kreisel inertia --urdf`: which robot description, which
//! geometry, where `package://` paths lead, and whether to fill or check.
//!
//! They are flattened into [`super::InertiaArgs`]; each requires `--urdf`,
//! and `--urdf` conflicts with the single-mesh options that have no meaning
//! for a robot (a URDF states each mesh's scale, and each link is solid).

use std::path::PathBuf;

/// The `--help` text of the URDF options (appended after the single-mesh help).
pub const URDF_HELP: &str = "\
Whole robots (--urdf):
  Every link with geometry (<collision> by default, --from visual) gets the
  inertial of all its geometries: meshes (with their scale attribute, per
  axis) and URDF box, cylinder and sphere primitives, each placed by its
  <origin xyz rpy> (R = Rz(yaw) Ry(pitch) Rx(roll)), summed as one rigid
  solid, in the link frame. The <inertial> is written with its origin at the
  centre of mass, rpy 0, and the full tensor. A link with a positive <mass>
  keeps it (the density follows and is reported); the others get --density
  (default 1000 kg/m^3). package://NAME/... is resolved by --package NAME=DIR
  or by searching upward from the URDF's folder for a folder named NAME;
  relative paths are relative to the URDF. Only the <inertial> elements
  change: the rest of the file is copied byte for byte, to --output (written
  whole or not at all) or standard output; a table goes to standard error.
  With --output in another folder, relative mesh paths are rewritten to lead
  from there to the same files (package:// and absolute ones are kept). A
  link's <mass> that is not positive is replaced by density x volume, said
  in the notes. Elements nested deeper than 1000, an XML version other than
  1.x and two links of one name are errors; a URDF or scene file larger
  than 64 MiB and a mesh file larger than 1 GiB are refused.
  --format json writes the report (per link: name, action or check, mass,
  centre of mass, inertia, notes; a summary with the exit status) to
  standard output instead of the table; filling then needs --output.
  With --hull every mesh is the solid convex hull of its vertices (for open
  meshes, common in published robots); --weld applies as for one mesh.
  Geometry: box, cylinder, sphere, capsule (radius, length of the cylinder
  along z) and mesh. A link whose geometry cannot be integrated (an open
  mesh, an unsupported format or element such as <plane>) keeps its old
  inertial: the file is still written, and the exit status is 1, naming the
  links. A missing mesh or package or a malformed URDF is an error: exit
  status 1 and no output.

  --check compares each link's inertial with its geometry instead (writes
  nothing on standard output). A link fails when
    its mass differs from density x volume by more than 10% (only with an
      explicit --density: otherwise the mesh gets the link's own mass),
    its centre of mass is more than 5% of the geometry's bounding-box
      diagonal from the geometry's,
    |I_file - I_mesh|_F / |I_mesh|_F > 0.2 (both about their own centre of
      mass, in the link frame, the mesh at the link's mass),
    or it is unphysical: mass not positive, a principal moment not positive,
      I1 + I2 < I3 (beyond 1e-6 relative), or the centre of mass outside the
      convex hull of the geometry (beyond 1e-6 of its diagonal).
  The exit status is 1 when a link fails, naming it, and when a link's
  geometry cannot be integrated, so it was not compared (its physics still
  checked; --hull compares open meshes as their convex hulls). A link
  without an inertial, with mass 0 (massless or static) or without geometry
  is listed but does not fail.

Examples (robots):
  kreisel inertia --urdf robot.urdf --output robot_filled.urdf
  kreisel inertia --urdf robot.urdf --package my_robot=src/my_robot --from visual
  kreisel inertia --urdf robot.urdf --check --density 2700
  kreisel inertia --urdf robot.urdf --check --hull --format json";

/// Which geometry of a link is integrated (`--from`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum GeometrySource {
    /// The `<collision>` elements.
    Collision,
    /// The `<visual>` elements.
    Visual,
}

impl GeometrySource {
    /// The URDF element name: `collision` or `visual`.
    pub const fn element(self) -> &'static str {
        match self {
            GeometrySource::Collision => "collision",
            GeometrySource::Visual => "visual",
        }
    }
}

/// `--package NAME=DIR`: where `package://NAME/` leads.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PackageDir {
    /// The package name.
    pub name: String,
    /// Its directory.
    pub dir: PathBuf,
}

/// Parses `NAME=DIR` (a non-empty name without `/`, a non-empty directory).
fn parse_package(text: &str) -> Result<PackageDir, String> {
    match text.split_once('=') {
        Some((name, dir)) if !name.is_empty() && !name.contains('/') && !dir.is_empty() => {
            Ok(PackageDir {
                name: name.to_owned(),
                dir: PathBuf::from(dir),
            })
        }
        _ => Err("expected NAME=DIR (a package name and its directory)".into()),
    }
}

/// The URDF options of `kreisel inertia`.
#[derive(Debug, Clone, clap::Args)]
pub struct UrdfArgs {
    /// Robot description: fill (or --check) the <inertial> of every link with geometry
    #[arg(
        long,
        value_name = "ROBOT.urdf",
        conflicts_with_all = ["mesh", "mass", "scale", "units", "shell", "thickness", "merge", "about", "transform"]
    )]
    pub urdf: Option<PathBuf>,

    /// With --urdf: write the filled URDF to FILE instead of standard output
    #[arg(long, value_name = "FILE", requires = "urdf", conflicts_with = "check")]
    pub output: Option<PathBuf>,

    /// With --urdf: the geometry to integrate
    #[arg(long = "from", value_name = "SOURCE", value_enum, requires = "urdf")]
    pub from: Option<GeometrySource>,

    /// With --urdf: the directory of package://NAME/ (repeatable) [default: a folder NAME above the URDF]
    #[arg(long, value_name = "NAME=DIR", value_parser = parse_package, requires = "urdf")]
    pub package: Vec<PackageDir>,

    /// With --urdf: compare every link's inertial with its geometry; exit status 1 when one fails or cannot be compared
    #[arg(long, requires = "urdf", conflicts_with_all = ["principal", "digits"])]
    pub check: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn package_is_name_equals_dir() {
        assert_eq!(
            parse_package("robot=/a/b"),
            Ok(PackageDir {
                name: "robot".into(),
                dir: PathBuf::from("/a/b")
            })
        );
        for bad in ["robot", "=dir", "robot=", "a/b=c"] {
            assert!(parse_package(bad).is_err(), "{bad}");
        }
        assert_eq!(GeometrySource::Visual.element(), "visual");
    }
}
