//! The errors of the `kreisel` binary: where a problem happened and what it was.
//!
//! [`CliError`] is what a subcommand returns; `main` prints it as one line,
//! `kreisel: error: {error}`, and exits with [`CliError::exit_code`]. Errors
//! caused by a line of input carry a [`Location`] (the file, or standard
//! input, and the 1-based line number) and a [`LineProblem`].

use std::fmt;
use std::io;
use std::path::PathBuf;

use kreisel_inertia::InertiaError;
use kreisel_kinematics::KinematicsError;

use crate::numbers::Shortest;
use crate::representation::Representation;

/// Exit status for errors in the data or in the files (clap uses 2 for usage errors).
pub const EXIT_DATA_ERROR: u8 = 1;

/// Where input comes from or output goes to: a named file or a standard stream.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Stream {
    /// Standard input or standard output.
    Standard,
    /// A file given on the command line.
    File(PathBuf),
}

/// The place of an offending input line.
///
/// Displays as `FILE:LINE` for a file and `line LINE` for standard input.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// The input the line was read from.
    pub input: Stream,
    /// 1-based line number, counting every line (comments and blank ones too).
    pub line: u64,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.input {
            Stream::Standard => write!(f, "line {}", self.line),
            Stream::File(path) => write!(f, "{}:{}", path.display(), self.line),
        }
    }
}

/// What is wrong with one line of input.
#[derive(Debug, thiserror::Error)]
pub enum LineProblem {
    /// The line is not valid UTF-8 text.
    #[error("line is not valid UTF-8 text")]
    NotUtf8,
    /// The line exceeds the length limit (protects memory from endless lines).
    #[error("line is longer than {limit} bytes")]
    TooLong {
        /// The limit in bytes.
        limit: usize,
    },
    /// Two commas with nothing between them, or a comma at the start or end.
    #[error(
        "empty number at position {position} (two commas in a row, or a leading or trailing comma)"
    )]
    EmptyNumber {
        /// 1-based position of the empty field among the numbers.
        position: usize,
    },
    /// A token that `f64::from_str` does not accept.
    #[error("cannot parse `{token}` as a number")]
    BadNumber {
        /// The token as written.
        token: String,
    },
    /// A number that parses but is NaN or infinite (also `1e999`, which overflows).
    #[error("number `{token}` is not finite")]
    NonFinite {
        /// The token as written.
        token: String,
    },
    /// The line holds the wrong count of numbers for the representation.
    #[error("expected {expected} numbers for {representation}, found {found}")]
    WrongCount {
        /// The input representation.
        representation: Representation,
        /// How many numbers it needs.
        expected: usize,
        /// How many the line holds.
        found: usize,
    },
    /// A rotation vector with finite components whose length overflows `f64`.
    #[error("rotation vector length is not a finite number (it overflows)")]
    RotationVectorLength,
    /// The numbers do not describe a rotation (zero quaternion, non-orthonormal
    /// or reflection matrix, zero axis with a non-zero angle).
    #[error("{source}")]
    NotARotation {
        /// The library's description of the problem.
        #[from]
        source: KinematicsError,
    },
    // `kreisel convert --skip-columns N --header` (issue 16).
    /// A line with fewer fields than `--skip-columns` passes through.
    #[error("line has {found} columns, fewer than --skip-columns {skip}")]
    TooFewColumns {
        /// `--skip-columns`.
        skip: usize,
        /// The fields the line holds.
        found: usize,
    },
    /// The `--header` line names the wrong number of columns.
    #[error(
        "header has {found} columns, expected {skip} passed through (--skip-columns) + {expected} for {representation}"
    )]
    HeaderCount {
        /// The names the header holds.
        found: usize,
        /// `--skip-columns`.
        skip: usize,
        /// The input representation.
        representation: Representation,
        /// How many numbers it needs.
        expected: usize,
    },
}

/// Everything that makes a `kreisel` subcommand fail.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// The `--input` file cannot be opened.
    #[error("cannot open input file {}: {source}", path.display())]
    OpenInput {
        /// The path as given.
        path: PathBuf,
        /// The operating system's reason.
        source: io::Error,
    },
    /// The `--output` file cannot be created.
    #[error("cannot create output file {}: {source}", path.display())]
    CreateOutput {
        /// The path as given.
        path: PathBuf,
        /// The operating system's reason.
        source: io::Error,
    },
    /// `--input` and `--output` name the same file, which would be truncated
    /// before it is read.
    #[error("output file {} is the input file; refusing to overwrite it", path.display())]
    OutputIsInput {
        /// The output path as given.
        path: PathBuf,
    },
    /// Reading the input failed (an I/O error, not a problem with the text).
    #[error("cannot read {}: {source}", stream_name(input, "standard input"))]
    Read {
        /// The input being read.
        input: Stream,
        /// The operating system's reason.
        source: io::Error,
    },
    /// Writing the output failed (disk full, closed pipe, ...).
    #[error("cannot write {}: {source}", stream_name(output, "standard output"))]
    Write {
        /// The output being written.
        output: Stream,
        /// The operating system's reason.
        source: io::Error,
    },
    /// A line of input is not a valid rotation in the `--from` representation.
    #[error("{location}: {problem}")]
    Line {
        /// The file (or standard input) and line number.
        location: Location,
        /// What is wrong with it.
        problem: LineProblem,
    },
    /// A mesh file cannot be read or parsed (the library's message names the file).
    #[error("{}", one_line(&source.to_string()))]
    LoadMesh {
        /// The library's description of the problem.
        source: InertiaError,
    },
    /// A mesh file that parses but holds no body with triangles.
    #[error("{}: the file holds no mesh bodies", path.display())]
    NoBodies {
        /// The mesh file.
        path: PathBuf,
    },
    /// One body of a mesh file has no mass properties under the chosen model.
    #[error("{}: body '{}': {}", path.display(), one_line(body), problem)]
    Body {
        /// The mesh file.
        path: PathBuf,
        /// The body's name in the file.
        body: String,
        /// What went wrong.
        problem: BodyProblem,
    },
    /// `--mass` cannot be spread over the bodies: their total volume is too
    /// small (or too large) for a finite positive density.
    #[error(
        "{}: total volume {} m^3 gives no finite positive density for --mass {} kg",
        path.display(),
        Shortest(*volume),
        Shortest(*mass)
    )]
    DerivedDensity {
        /// The mesh file.
        path: PathBuf,
        /// The total mass asked for, kg.
        mass: f64,
        /// The total volume of the bodies, m³.
        volume: f64,
    },
    /// The scene file of `kreisel simulate` cannot be read.
    #[error("cannot read scene file {}: {source}", path.display())]
    ReadScene {
        /// The path as given.
        path: PathBuf,
        /// The operating system's reason.
        source: io::Error,
    },
    /// A problem in the scene file: `SCENE:LINE: message` (`SCENE: message`
    /// for a problem of the file as a whole).
    #[error("{}{}: {message}", path.display(), line.map(|l| format!(":{l}")).unwrap_or_default())]
    Scene {
        /// The scene file as given.
        path: PathBuf,
        /// The 1-based line of the offending key or table, when there is one.
        line: Option<u64>,
        /// What is wrong, naming the key (one line).
        message: String,
    },
    /// A command-line option with a value the subcommand cannot use.
    #[error("{argument}: {message}")]
    Argument {
        /// The option as written on the command line (`--i1`).
        argument: String,
        /// What is wrong with its value (one line).
        message: String,
    },
    /// The library cannot solve the heavy top for these parameters.
    #[error("heavy top: {message}")]
    Top {
        /// The library's description of the problem (one line).
        message: String,
    },
    /// A figure cannot be drawn.
    #[error("--plot {}: {message}", path.display())]
    Plot {
        /// The image file asked for.
        path: PathBuf,
        /// What went wrong.
        message: String,
    },
    /// `--method` names no known method.
    #[error("--method: {message}")]
    Method {
        /// What is wrong, listing the known methods.
        message: String,
    },
    /// The robot description of `inertia --urdf` cannot be read.
    #[error("cannot read URDF file {}: {source}", path.display())]
    ReadUrdf {
        /// The path as given.
        path: PathBuf,
        /// The operating system's reason.
        source: io::Error,
    },
    /// A problem in the robot description or a file it names:
    /// `ROBOT.urdf:LINE: message` (`ROBOT.urdf: message` without a line).
    #[error("{}{}: {message}", path.display(), line.map(|l| format!(":{l}")).unwrap_or_default())]
    Urdf {
        /// The URDF file as given.
        path: PathBuf,
        /// The 1-based line of the offending element, when there is one.
        line: Option<u32>,
        /// What is wrong, naming the link and the element (one line).
        message: String,
    },
    /// `inertia --urdf`: the output was written, but these links kept their
    /// old inertial because their geometry could not be integrated.
    #[error(
        "{} link(s) kept their old inertial, their geometry could not be integrated: {}",
        links.len(),
        links.join(", ")
    )]
    LinksKept {
        /// The links' names.
        links: Vec<String>,
    },
    /// `inertia --urdf --check`: these links' inertials fail the tolerances.
    #[error("{} link(s) fail the check: {}", links.len(), links.join(", "))]
    CheckFailed {
        /// The links' names.
        links: Vec<String>,
    },
    /// `inertia --urdf --check`: no link fails, but these links' inertials
    /// could not be compared with their geometry (it cannot be integrated).
    #[error(
        "{} link(s) not compared, their geometry could not be integrated: {}{}",
        links.len(),
        links.join(", "),
        if *hull { "" } else { " (--hull compares open meshes as their convex hulls)" }
    )]
    NotCompared {
        /// The links' names.
        links: Vec<String>,
        /// Whether `--hull` was given already.
        hull: bool,
    },
}

/// Why the mass properties of one body of a mesh file cannot be computed.
#[derive(Debug, thiserror::Error)]
pub enum BodyProblem {
    /// Scaling made a coordinate overflow to infinity.
    #[error("coordinates overflow when scaled by {}", Shortest(*scale))]
    ScaleOverflow {
        /// The scale factor.
        scale: f64,
    },
    /// The library rejected the body; for surfaces that enclose no well-defined
    /// volume the message says what gives the right answer, if anything.
    #[error("{}{}", one_line(&source.to_string()), solid_hint(source))]
    Inertia {
        /// The library's description of the problem.
        #[from]
        source: InertiaError,
    },
    /// The body is open along cracks that welding within `weld` metres
    /// closes (checked).
    #[error("{}; rerun with --weld {} to close them", one_line(&source.to_string()), Shortest(*weld))]
    Cracks {
        /// The library's description of the body's problem.
        source: InertiaError,
        /// A weld tolerance that closes the body, m.
        weld: f64,
    },
    /// The body is open, but all bodies of the file together are closed.
    #[error(
        "{}; the file's bodies together form a closed surface: rerun with --merge to treat them as one solid",
        one_line(&source.to_string())
    )]
    ClosedOnlyMerged {
        /// The library's description of the body's problem.
        source: InertiaError,
    },
}

/// What gives the right answer when a mesh is no closed, orientable surface
/// and neither welding nor merging closes it: the models that hold only for
/// some shapes, said so (never advice that silently gives a wrong mass).
fn solid_hint(error: &InertiaError) -> String {
    const OPEN_ON_PURPOSE: &str = "; if the surface is open on purpose, --shell models a thin-walled part (see --thickness) and --hull a convex one";
    match error {
        InertiaError::OpenMesh { .. } | InertiaError::NonManifold { .. } => OPEN_ON_PURPOSE.into(),
        InertiaError::MeshOutOfRange { .. } => {
            " (set with --units or --scale S, metres per mesh unit)".into()
        }
        InertiaError::NonOrientable { .. } => {
            "; it bounds no volume, but --shell models it as a thin wall (see --thickness)".into()
        }
        _ => String::new(),
    }
}

/// The text with line breaks replaced by spaces, so an error stays one line.
pub fn one_line(text: &str) -> String {
    text.replace(['\r', '\n'], " ")
}

/// `path` for a file, `standard` for a standard stream.
fn stream_name(stream: &Stream, standard: &str) -> String {
    match stream {
        Stream::Standard => standard.to_owned(),
        Stream::File(path) => path.display().to_string(),
    }
}

impl CliError {
    /// The process exit status for this error.
    pub fn exit_code(&self) -> u8 {
        EXIT_DATA_ERROR
    }

    /// `true` when the reader of standard output went away (e.g. `| head -1`):
    /// not a failure of `kreisel`, so it ends quietly with status 0.
    pub fn is_broken_pipe(&self) -> bool {
        matches!(
            self,
            CliError::Write { output: Stream::Standard, source }
                if source.kind() == io::ErrorKind::BrokenPipe
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn locations_name_file_or_line() {
        let stdin = Location {
            input: Stream::Standard,
            line: 7,
        };
        assert_eq!(stdin.to_string(), "line 7");
        let file = Location {
            input: Stream::File(PathBuf::from("data/q.csv")),
            line: 12,
        };
        assert_eq!(file.to_string(), "data/q.csv:12");
    }

    #[test]
    fn line_error_is_one_line() {
        let e = CliError::Line {
            location: Location {
                input: Stream::Standard,
                line: 3,
            },
            problem: LineProblem::WrongCount {
                representation: Representation::Quat,
                expected: 4,
                found: 3,
            },
        };
        assert_eq!(
            e.to_string(),
            "line 3: expected 4 numbers for quat, found 3"
        );
        assert!(!e.is_broken_pipe());
    }

    #[test]
    fn only_stdout_broken_pipe_is_quiet() {
        let pipe = |output| CliError::Write {
            output,
            source: io::Error::from(io::ErrorKind::BrokenPipe),
        };
        assert!(pipe(Stream::Standard).is_broken_pipe());
        assert!(!pipe(Stream::File(PathBuf::from("x"))).is_broken_pipe());
    }

    #[test]
    fn open_mesh_error_names_file_body_and_options() {
        let e = CliError::Body {
            path: PathBuf::from("part.obj"),
            body: "lid\nx".into(),
            problem: BodyProblem::from(InertiaError::OpenMesh {
                boundary_edges: 4,
                at: glam::DVec3::new(1.0, 0.5, 0.0),
                weld_gap: None,
            }),
        };
        let text = e.to_string();
        assert!(
            text.starts_with("part.obj: body 'lid x': mesh is open: 4 boundary edges"),
            "{text}"
        );
        assert!(
            text.contains("--shell") && text.contains("--hull"),
            "{text}"
        );
        assert!(!text.contains('\n'));
        let e = BodyProblem::from(InertiaError::ZeroVolume);
        assert!(!e.to_string().contains("--hull"));
    }
}
