//! The errors of the `kreisel` binary: where a problem happened and what it was.
//!
//! [`CliError`] is what a subcommand returns; `main` prints it as one line,
//! `kreisel: error: {error}`, and exits with [`CliError::exit_code`]. Errors
//! caused by a line of input carry a [`Location`] (the file, or standard
//! input, and the 1-based line number) and a [`LineProblem`].

use std::fmt;
use std::io;
use std::path::PathBuf;

use kreisel_scene::error::SceneError;
use kreisel_scene::line_problem::LineProblem;

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
    /// A command-line option with a value the subcommand cannot use.
    #[error("{argument}: {message}")]
    Argument {
        /// The option as written on the command line (`--i1`).
        argument: String,
        /// What is wrong with its value (one line).
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
    /// A scene, mesh or heavy-top request the scene layer rejects.
    #[error(transparent)]
    Library(#[from] SceneError),
    /// A body of a scene whose stability cannot be decided as asked.
    #[error("{}: body {body:?}: {error}", path.display())]
    Analysis {
        /// The scene.
        path: PathBuf,
        /// The body's name.
        body: String,
        /// What the analysis says.
        error: kreisel_analysis::AnalysisError,
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

/// `path` for a file, `standard` for a standard stream.
fn stream_name(stream: &Stream, standard: &str) -> String {
    match stream {
        Stream::Standard => standard.to_owned(),
        Stream::File(path) => path.display().to_string(),
    }
}

impl CliError {
    /// An error about the value of one command-line option (`--dt`).
    pub fn argument(option: &str, message: String) -> Self {
        CliError::Argument {
            argument: option.to_owned(),
            message,
        }
    }

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
    use kreisel_scene::representation::Representation;

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
}
