//! The `kreisel` command-line tool as a library: one module per subcommand,
//! their parsers and writers. The binary (`main.rs`) only calls [`main`];
//! the fuzz targets (`fuzz/`) call the parsers directly.
//!
//! [`main`] parses the command line, dispatches to one subcommand, and turns
//! its error into one line on standard error and an exit status: 0 on
//! success, 1 for bad data or files ([`error::EXIT_DATA_ERROR`]), 2 for usage
//! errors (clap).

#![forbid(unsafe_code)]

pub mod convert;
pub mod error;
pub mod inertia;
pub mod output;
pub mod simulate;
pub mod stability;
pub mod top;

use std::io::Write;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use crate::error::CliError;

/// The `--help` text after the subcommand list.
const AFTER_HELP: &str = "\
Examples:
  echo '0 0 1.5707963267948966' | kreisel convert --from rotvec --to quat
  kreisel inertia part.stl --units mm --density 2700
  kreisel inertia assets/t_handle.obj --format urdf
  kreisel simulate scene.toml --output run.csv
  kreisel top --i1 0.3 --i3 0.1 --mgl 2 --theta0 0.5 --psi-dot0 60 --plot top.svg
  kreisel stability examples/scenes/sleeping_top.toml --sweep spin=0:80:200";

/// Rigid-body rotations from the command line.
#[derive(Debug, Parser)]
#[command(
    name = "kreisel",
    version,
    propagate_version = true,
    after_help = AFTER_HELP
)]
struct Cli {
    /// What to do.
    #[command(subcommand)]
    command: Command,
}

/// The subcommands, one module each.
#[derive(Debug, Subcommand)]
enum Command {
    /// Convert rotations between representations (quaternion, matrix, rotation vector,
    /// axis-angle, Euler angles), one per line
    Convert(convert::ConvertArgs),
    /// Mass, centre of mass, inertia tensor and principal axes of a mesh file
    /// (STL, OBJ, PLY, glTF), as text, JSON, URDF, SDFormat or MJCF
    Inertia(inertia::InertiaArgs),
    /// Integrate the rotation of the bodies of a TOML scene (torque-free,
    /// driven by torques and forces, or on a pivot) and write their states as CSV;
    /// --plot draws omega(t), the energy and the polhode
    Simulate(simulate::SimulateArgs),
    /// The heavy symmetric top: constants of the motion, roots of f(u), nutation
    /// limits and period, precession, type of motion; --plot draws it, --csv samples it
    Top(top::TopCommand),
    /// Is it stable? Each body's steady motion near the scene's initial state,
    /// the eigenvalues and modes of its linearisation, the verdict; --sweep maps it
    Stability(stability::StabilityArgs),
}

/// Runs the chosen subcommand.
fn dispatch(command: &Command) -> Result<(), CliError> {
    match command {
        Command::Convert(args) => convert::run(args),
        Command::Inertia(args) => inertia::run(args),
        Command::Simulate(args) => simulate::run(args),
        Command::Top(args) => top::run(args),
        Command::Stability(args) => stability::run(args),
    }
}

/// Runs the command line of this process; the binary's `main`.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    match dispatch(&cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        // The reader of our output has gone (`| head -1`): nothing to report.
        Err(e) if e.is_broken_pipe() => ExitCode::SUCCESS,
        Err(e) => {
            // Unlike eprintln!, never panics if standard error is closed.
            let _ = writeln!(std::io::stderr(), "kreisel: error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn command_line_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn help_states_tolerance_and_radians() {
        // The help text spells out the library's tolerance; keep them in sync.
        assert_eq!(kreisel_kinematics::ORTHONORMALITY_TOLERANCE, 1e-6);
        let mut cli = Cli::command();
        let help = cli
            .find_subcommand_mut("convert")
            .expect("convert subcommand")
            .render_long_help()
            .to_string();
        assert!(help.contains("max|M^T M - I| <= 1e-6"), "{help}");
        assert!(help.contains("rotvec stays in radians"), "{help}");
    }

    #[test]
    fn parses_convert_arguments() {
        let cli = Cli::try_parse_from([
            "kreisel",
            "convert",
            "--from",
            "euler:zxz",
            "--to",
            "quat-xyzw",
            "--degrees",
        ])
        .unwrap();
        let Command::Convert(args) = cli.command else {
            panic!("not convert: {:?}", cli.command);
        };
        assert_eq!(args.from.to_string(), "euler:zxz");
        assert!(args.degrees && args.input.is_none());
        let e = Cli::try_parse_from(["kreisel", "convert", "--from", "quaternion", "--to", "quat"])
            .unwrap_err();
        assert_eq!(e.exit_code(), 2);
    }

    #[test]
    fn parses_inertia_arguments_and_conflicts() {
        let parse = |args: &[&str]| {
            let mut all = vec!["kreisel", "inertia"];
            all.extend_from_slice(args);
            Cli::try_parse_from(all)
        };
        let cli = parse(&["m.stl", "--units", "mm", "--shell", "--thickness", "2e-3"]).unwrap();
        let Command::Inertia(args) = cli.command else {
            panic!("not inertia");
        };
        let setup = args.setup();
        assert_eq!(
            (setup.scale, setup.units_text()),
            (0.001, "mm (scale 0.001)".into())
        );
        assert_eq!(setup.model_text(), "shell of thickness 0.002 m");
        for bad in [
            &["m.stl", "--density", "1", "--mass", "2"][..],
            &["m.stl", "--scale", "2", "--units", "cm"],
            &["m.stl", "--thickness", "0.1"],
            &["m.stl", "--shell", "--hull"],
            &["m.stl", "--density", "-1"],
            &["m.stl", "--scale", "0"],
            &["m.stl", "--format", "xml"],
            &["m.stl", "--units", "ft"],
        ] {
            let e = parse(bad).unwrap_err();
            assert_eq!(e.exit_code(), 2, "{bad:?}");
        }
        let help = Cli::command().render_help().to_string();
        assert!(help.contains("kreisel inertia"), "{help}");
    }

    #[test]
    fn parses_simulate_arguments() {
        let parse = |args: &[&str]| {
            let mut all = vec!["kreisel", "simulate"];
            all.extend_from_slice(args);
            Cli::try_parse_from(all)
        };
        let cli = parse(&["s.toml", "--method", "rk4", "--output", "o.csv"]).unwrap();
        let Command::Simulate(args) = cli.command else {
            panic!("not simulate");
        };
        assert_eq!(args.scene.as_deref(), Some(std::path::Path::new("s.toml")));
        assert_eq!(args.method.as_deref(), Some("rk4"));
        assert!(!args.list_methods);
        // --list-methods needs no scene; anything else does.
        assert!(parse(&["--list-methods"]).is_ok());
        assert_eq!(parse(&[]).unwrap_err().exit_code(), 2);
        assert_eq!(parse(&["--method", "rk4"]).unwrap_err().exit_code(), 2);
    }
}
