//! Where the subcommands' output goes, whole or not at all: standard
//! output, or a temporary file beside the target that is put in place
//! only when the run succeeds ([`atomic_file`]), so a failed run leaves no
//! partial file and keeps an existing one.

pub mod atomic_file;

use std::fs;
use std::io::{self, Write};
use std::path::Path;

use crate::error::{CliError, Stream};

/// Puts a finished `--output` file in place (see [`atomic_file`]);
/// nothing to do for standard output.
///
/// # Errors
/// [`CliError::Write`] if the file cannot be renamed onto its target.
pub fn commit_output(
    pending: Option<atomic_file::PendingFile>,
    output: Stream,
) -> Result<(), CliError> {
    match pending {
        None => Ok(()),
        Some(pending) => pending
            .commit()
            .map_err(|source| CliError::Write { output, source }),
    }
}

/// Writes `text` to standard output and flushes it.
///
/// # Errors
/// [`CliError::Write`] naming standard output.
pub fn print_stdout(text: &str) -> Result<(), CliError> {
    let mut stdout = io::stdout().lock();
    stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
        .map_err(|source| CliError::Write {
            output: Stream::Standard,
            source,
        })
}

/// An output stream: the writer, its name, and the file to put in place on
/// success (`None` for standard output).
pub type Output = (Box<dyn Write>, Stream, Option<atomic_file::PendingFile>);

/// Standard output, or a temporary file beside `path` that
/// [`commit_output`] puts in place when the run succeeds (so a failed run
/// leaves no partial file and keeps an existing one), unless `path` is the
/// input file (shared by the subcommands that write a stream).
pub fn open_output(path: Option<&Path>, input: Option<&Path>) -> Result<Output, CliError> {
    let Some(path) = path else {
        return Ok((Box::new(io::stdout().lock()), Stream::Standard, None));
    };
    if let Some(input) = input {
        // Both exist when this is the same file; then creating the output
        // would truncate the input before it is read.
        if let (Ok(a), Ok(b)) = (fs::canonicalize(input), fs::canonicalize(path))
            && a == b
        {
            return Err(CliError::OutputIsInput {
                path: path.to_owned(),
            });
        }
    }
    let (file, pending) = atomic_file::create(path).map_err(|source| CliError::CreateOutput {
        path: path.to_owned(),
        source,
    })?;
    Ok((Box::new(file), Stream::File(path.to_owned()), Some(pending)))
}

/// Renders `figure` as `format` and writes it to `path`, whole or not at
/// all (`--plot`).
///
/// # Errors
/// [`CliError::Plot`] when rendering fails or the file cannot be written.
pub fn write_figure(
    figure: &kreisel_plot::Figure,
    format: kreisel_plot::ImageFormat,
    path: &Path,
) -> Result<(), CliError> {
    let bytes = format.render(figure).map_err(|e| CliError::Plot {
        path: path.to_owned(),
        message: e.to_string(),
    })?;
    atomic_file::write_file(path, &bytes).map_err(|source| CliError::Plot {
        path: path.to_owned(),
        message: format!("cannot write the file: {source}"),
    })
}
