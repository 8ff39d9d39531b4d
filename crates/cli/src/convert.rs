//! `kreisel convert`: stream rotations from one representation to another,
//! one per line, in constant memory.

#![forbid(unsafe_code)]

pub mod columns;

use std::fs::File;
use std::io::{self, BufRead, BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};

pub use self::columns::Layout;
use crate::error::{CliError, Location, Stream};
use crate::output::{commit_output, open_output};
use kreisel_scene::escape::escape_invisible;
use kreisel_scene::line_problem::LineProblem;
use kreisel_scene::numbers::{Numbers, parse_numbers, write_numbers};
use kreisel_scene::representation::Representation;

/// Longest accepted input line in bytes (newline included); longer lines are
/// an error, so a file without newlines cannot exhaust memory.
pub const MAX_LINE_BYTES: usize = 1 << 20;

/// Size of the input and output buffers.
const BUFFER_BYTES: usize = 1 << 16;

/// The `--help` text of `kreisel convert` after the option list.
const AFTER_LONG_HELP: &str = "\
Representations (REPR):
  quat          w,x,y,z     quaternion, scalar first. Input of any non-zero
                            length is normalised; output is canonical (w >= 0).
  quat-xyzw     x,y,z,w     quaternion, scalar last (scipy, ROS).
  matrix        m00,m01,m02,m10,m11,m12,m20,m21,m22
                            active rotation matrix (v_world = M v_body),
                            row-major. Input must be orthonormal within
                            max|M^T M - I| <= 1e-6 and have det M > 0.
  rotvec        x,y,z       rotation vector axis*angle, always in radians
                            (--degrees does not apply). Output angle in [0, pi].
  axis-angle    x,y,z,angle axis of any non-zero length (zero only with angle
                            0). Output: unit axis, angle in [0, pi].
  euler:SEQ     a,b,c       Euler angles, SEQ named as in scipy: uppercase is
                            intrinsic (ZXZ: about the moving body axes),
                            lowercase extrinsic (zxz: about the fixed axes).
                            All 24: XYZ XZY YXZ YZX ZXY ZYX XYX XZX YXY YZY ZXZ
                            ZYZ and their lowercase forms. Output: first and
                            third angle in (-pi, pi], middle in [0, pi] (proper
                            Euler) or [-pi/2, pi/2] (Tait-Bryan); at exact
                            gimbal lock the third angle is 0.

Input: one rotation per line, numbers separated by commas and/or whitespace.
Blank lines and lines starting with '#' are skipped. Output: one line per
rotation, numbers comma-separated in shortest round-trip form.

Logs (--skip-columns N, --header):
  --skip-columns N passes the first N fields of every line (timestamps,
  ids; separated like the numbers, by commas and/or whitespace; no quoting)
  through unchanged before the converted rotation. --header reads the first
  line that is neither blank nor a comment as a header naming N + (numbers
  of --from) columns (comma-separated, or whitespace-separated when it has
  no comma) and writes the N passed-through names and the names of --to:
    quat qw,qx,qy,qz   quat-xyzw qx,qy,qz,qw   matrix m00,m01,...,m22
    rotvec rx,ry,rz    axis-angle ax,ay,az,angle
    euler:ZYX yaw,pitch,roll    euler:xyz roll,pitch,yaw
    other euler:SEQ the axis and position, e.g. euler:ZXZ Z1,X2,Z3
  With --degrees the angle names end in _deg (yaw_deg, angle_deg).

Errors: the first invalid line stops the conversion with a message naming its
line number (FILE:LINE: with --input) and exit status 1; every line before it
has been written to standard output. An --output file is written whole or not
at all: after an error it is not created, and an existing one is kept.

Examples:
  echo '0 0 1.5707963267948966' | kreisel convert --from rotvec --to quat
  kreisel convert --from matrix --to euler:ZXZ --degrees --input m.csv
  kreisel convert --from quat --to euler:ZYX --degrees --skip-columns 1 --header --input imu.csv";

/// Arguments of `kreisel convert`.
#[derive(Debug, Clone, clap::Args)]
#[command(after_long_help = AFTER_LONG_HELP)]
pub struct ConvertArgs {
    /// Representation of the input: quat, quat-xyzw, matrix, rotvec, axis-angle, euler:SEQ
    #[arg(long, value_name = "REPR")]
    pub from: Representation,

    /// Representation of the output: quat, quat-xyzw, matrix, rotvec, axis-angle, euler:SEQ
    #[arg(long, value_name = "REPR")]
    pub to: Representation,

    /// Read and write Euler angles and the axis-angle angle in degrees (rotvec stays in radians)
    #[arg(long)]
    pub degrees: bool,

    /// Read from FILE instead of standard input
    #[arg(long, value_name = "FILE")]
    pub input: Option<PathBuf>,

    /// Write to FILE (replaced only when the whole conversion succeeds) instead of standard output
    #[arg(long, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Pass the first N fields of every line (timestamps, ids) through unchanged
    #[arg(long, value_name = "N", default_value_t = 0)]
    pub skip_columns: usize,

    /// The first line that is not blank or a comment is a header: write a matching one
    #[arg(long)]
    pub header: bool,
}

/// What to convert: the representations and the angle unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Conversion {
    /// Representation of the input lines.
    pub from: Representation,
    /// Representation of the output lines.
    pub to: Representation,
    /// Euler and axis–angle angles in degrees.
    pub degrees: bool,
}

impl Conversion {
    /// Converts the text of one line: `None` for a blank or comment line.
    ///
    /// # Errors
    /// A [`LineProblem`] when the line is not a rotation in `self.from`.
    pub fn convert_line(&self, text: &str) -> Result<Option<Numbers>, LineProblem> {
        let text = text.trim();
        if text.is_empty() || text.starts_with('#') {
            return Ok(None);
        }
        self.convert_numbers(text).map(Some)
    }

    /// Converts the numbers of one rotation (the text holds nothing else).
    ///
    /// # Errors
    /// A [`LineProblem`] when the text is not a rotation in `self.from`.
    pub fn convert_numbers(&self, text: &str) -> Result<Numbers, LineProblem> {
        let numbers = parse_numbers(text).map_err(escape_problem)?;
        self.from.convert_numbers(&numbers, self.to, self.degrees)
    }
}

/// Runs `kreisel convert`: opens the input and output and streams the lines.
///
/// # Errors
/// A [`CliError`] for a file that cannot be opened or created, an I/O error,
/// or the first invalid line. Standard output is flushed in every case, so
/// all lines before an invalid one are written; an `--output` file is put in
/// place only on success.
pub fn run(args: &ConvertArgs) -> Result<(), CliError> {
    let conversion = Conversion {
        from: args.from,
        to: args.to,
        degrees: args.degrees,
    };
    let (reader, input) = open_input(args.input.as_deref())?;
    let (writer, output, pending) = open_output(args.output.as_deref(), args.input.as_deref())?;
    let mut writer = BufWriter::with_capacity(BUFFER_BYTES, writer);
    let layout = Layout {
        skip_columns: args.skip_columns,
        header: args.header,
    };
    let converted = convert_log(reader, &mut writer, (conversion, layout), &input, &output);
    let flushed = writer.flush().map_err(|source| CliError::Write {
        output: output.clone(),
        source,
    });
    converted.and(flushed)?;
    drop(writer);
    commit_output(pending, output)
}

/// Standard input, or the file at `path`.
fn open_input(path: Option<&Path>) -> Result<(Box<dyn BufRead>, Stream), CliError> {
    match path {
        None => Ok((Box::new(io::stdin().lock()), Stream::Standard)),
        Some(path) => {
            let file = File::open(path).map_err(|source| CliError::OpenInput {
                path: path.to_owned(),
                source,
            })?;
            let reader = BufReader::with_capacity(BUFFER_BYTES, file);
            Ok((Box::new(reader), Stream::File(path.to_owned())))
        }
    }
}

/// Converts every line of `reader` and writes the results to `writer`.
///
/// Reads one line at a time into a reused buffer (at most
/// [`MAX_LINE_BYTES`]), so memory stays constant however long the input.
/// Stops at the first invalid line. Does not flush `writer`.
///
/// # Errors
/// [`CliError::Line`] for an invalid line (with its 1-based number),
/// [`CliError::Read`] / [`CliError::Write`] for I/O errors.
pub fn convert_stream<R: BufRead, W: Write + ?Sized>(
    reader: R,
    writer: &mut W,
    conversion: Conversion,
    input: &Stream,
    output: &Stream,
) -> Result<(), CliError> {
    convert_log(
        reader,
        writer,
        (conversion, Layout::default()),
        input,
        output,
    )
}

/// [`convert_stream`] for lines laid out as `layout` says: leading fields
/// passed through, a header line (see [`columns`]).
///
/// # Errors
/// As [`convert_stream`]; also [`LineProblem::TooFewColumns`] and
/// [`LineProblem::HeaderCount`] with the line number.
pub fn convert_log<R: BufRead, W: Write + ?Sized>(
    mut reader: R,
    writer: &mut W,
    (conversion, layout): (Conversion, Layout),
    input: &Stream,
    output: &Stream,
) -> Result<(), CliError> {
    let mut header_pending = layout.header;
    let mut buffer = Vec::with_capacity(256);
    let mut line: u64 = 0;
    loop {
        buffer.clear();
        let read = read_line(&mut reader, &mut buffer).map_err(|source| CliError::Read {
            input: input.clone(),
            source,
        })?;
        if read == 0 {
            return Ok(());
        }
        line += 1;
        let at_line = |problem| CliError::Line {
            location: Location {
                input: input.clone(),
                line,
            },
            problem,
        };
        if buffer.len() > MAX_LINE_BYTES {
            return Err(at_line(LineProblem::TooLong {
                limit: MAX_LINE_BYTES,
            }));
        }
        let text = std::str::from_utf8(&buffer).map_err(|_| at_line(LineProblem::NotUtf8))?;
        // A UTF-8 byte-order mark (Windows editors write one) is no content.
        let text = if line == 1 {
            text.strip_prefix('\u{feff}').unwrap_or(text)
        } else {
            text
        };
        let write_error = |source| CliError::Write {
            output: output.clone(),
            source,
        };
        let text = text.trim();
        if text.is_empty() || text.starts_with('#') {
            continue;
        }
        if header_pending {
            header_pending = false;
            let names = columns::header(
                text,
                layout.skip_columns,
                conversion.from,
                conversion.to,
                conversion.degrees,
            )
            .map_err(at_line)?;
            writeln!(writer, "{names}").map_err(write_error)?;
            continue;
        }
        let (fields, rest) = columns::split_leading(text, layout.skip_columns).map_err(at_line)?;
        if rest.is_empty() {
            // Only the passed-through fields: no rotation at all.
            return Err(at_line(LineProblem::WrongCount {
                representation: conversion.from,
                expected: conversion.from.count(),
                found: 0,
            }));
        }
        let numbers = conversion.convert_numbers(rest).map_err(at_line)?;
        for field in fields {
            writer
                .write_all(field.as_bytes())
                .and_then(|()| writer.write_all(b","))
                .map_err(write_error)?;
        }
        write_numbers(writer, numbers.as_slice()).map_err(write_error)?;
    }
}

/// Reads one line into `buffer`, without its terminator: `\n`, `\r\n` or a
/// lone `\r` (classic Mac OS) ends a line. Stops after
/// [`MAX_LINE_BYTES`]` + 1` bytes so an endless line cannot exhaust memory.
/// Returns the number of bytes consumed (0 at the end of the input).
fn read_line<R: BufRead>(reader: &mut R, buffer: &mut Vec<u8>) -> io::Result<usize> {
    let mut consumed = 0;
    loop {
        let available = match reader.fill_buf() {
            Ok(bytes) => bytes,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if available.is_empty() {
            return Ok(consumed);
        }
        let room = MAX_LINE_BYTES + 1 - buffer.len();
        let window = &available[..available.len().min(room)];
        match window.iter().position(|&b| b == b'\n' || b == b'\r') {
            Some(end) => {
                let cr = window[end] == b'\r';
                buffer.extend_from_slice(&window[..end]);
                reader.consume(end + 1);
                consumed += end + 1;
                if cr {
                    // `\r\n` is one terminator.
                    let next = loop {
                        match reader.fill_buf() {
                            Ok(bytes) => break bytes.first().copied(),
                            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
                            Err(e) => return Err(e),
                        }
                    };
                    if next == Some(b'\n') {
                        reader.consume(1);
                        consumed += 1;
                    }
                }
                return Ok(consumed);
            }
            None => {
                let n = window.len();
                buffer.extend_from_slice(window);
                reader.consume(n);
                consumed += n;
                if buffer.len() > MAX_LINE_BYTES {
                    return Ok(consumed);
                }
            }
        }
    }
}

/// The problem with its quoted tokens escaped (see [`escape_invisible`]).
fn escape_problem(problem: LineProblem) -> LineProblem {
    match problem {
        LineProblem::BadNumber { token } => LineProblem::BadNumber {
            token: escape_invisible(&token),
        },
        LineProblem::NonFinite { token } => LineProblem::NonFinite {
            token: escape_invisible(&token),
        },
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn convert(from: &str, to: &str, text: &str) -> (Result<(), CliError>, String) {
        let conversion = Conversion {
            from: from.parse().unwrap(),
            to: to.parse().unwrap(),
            degrees: false,
        };
        let mut out = Vec::new();
        let result = convert_stream(
            text.as_bytes(),
            &mut out,
            conversion,
            &Stream::Standard,
            &Stream::Standard,
        );
        (result, String::from_utf8(out).unwrap())
    }

    #[test]
    fn skips_blank_and_comment_lines_and_keeps_order() {
        let text = "# header\n\n2,0,0,0\n   \t\n  # note\n0,0,0,-3\r\n0 1 0 0";
        let (result, out) = convert("quat", "quat", text);
        assert!(result.is_ok());
        assert_eq!(out, "1,0,0,0\n0,0,0,1\n0,1,0,0\n");
    }

    #[test]
    fn stops_at_first_error_with_line_number() {
        let (result, out) = convert("quat", "rotvec", "1,0,0,0\n# c\n0,0,0,0\n1,0,0,0\n");
        assert_eq!(out, "0,0,0\n");
        let e = result.unwrap_err();
        assert_eq!(e.to_string(), "line 3: quaternion has zero norm");
    }

    #[test]
    fn rejects_invalid_utf8_and_endless_lines() {
        let conversion = Conversion {
            from: Representation::Quat,
            to: Representation::Quat,
            degrees: false,
        };
        let mut out = Vec::new();
        let bad = b"1,0,0,0\n1,0,\xff,0\n";
        let e = convert_stream(
            &bad[..],
            &mut out,
            conversion,
            &Stream::Standard,
            &Stream::Standard,
        )
        .unwrap_err();
        assert_eq!(e.to_string(), "line 2: line is not valid UTF-8 text");
        let long = vec![b' '; MAX_LINE_BYTES + 10];
        let e = convert_stream(
            &long[..],
            &mut out,
            conversion,
            &Stream::Standard,
            &Stream::Standard,
        )
        .unwrap_err();
        assert!(
            e.to_string().starts_with("line 1: line is longer than"),
            "{e}"
        );
    }

    #[test]
    fn skips_a_byte_order_mark_and_reads_every_line_ending() {
        // Regression: a BOM was an invisible "cannot parse" error; a lone CR
        // (classic Mac OS) made the whole file one line.
        let text = "\u{feff}1,0,0,0\r0,0,0,2\r\n0,1,0,0\n0,0,1,0\r";
        let (result, out) = convert("quat", "quat", text);
        assert!(result.is_ok(), "{result:?}");
        assert_eq!(out, "1,0,0,0\n0,0,0,1\n0,1,0,0\n0,0,1,0\n");
        // Line numbers count CR-only lines too.
        let (result, _) = convert("quat", "quat", "1,0,0,0\r\r0,0,0,0\r");
        assert_eq!(
            result.unwrap_err().to_string(),
            "line 3: quaternion has zero norm"
        );
        // A BOM later than the start is content, and shown escaped.
        let (result, _) = convert("quat", "quat", "1,0,0,0\n\u{feff}1,0,0,0\n");
        let e = result.unwrap_err().to_string();
        assert!(e.contains("\\u{feff}"), "{e}");
    }

    #[test]
    fn error_messages_show_control_characters_escaped() {
        let (result, _) = convert("quat", "quat", "1,0,\u{7}x,0\u{1b}[31m\n");
        let e = result.unwrap_err().to_string();
        assert!(!e.chars().any(char::is_control), "{e:?}");
        assert!(e.contains("\\u{7}x"), "{e}");
    }

    #[test]
    fn crlf_split_across_reads_is_one_line_end() {
        // A reader that returns one byte at a time puts the LF of a CRLF in
        // the next read: still one line end, so the error is on line 2.
        let text = b"1 0 0 0\r\n1 2 3\r\n";
        let reader = io::BufReader::with_capacity(1, &text[..]);
        let conversion = Conversion {
            from: Representation::Quat,
            to: Representation::Quat,
            degrees: false,
        };
        let mut out = Vec::new();
        let e = convert_stream(
            reader,
            &mut out,
            conversion,
            &Stream::Standard,
            &Stream::Standard,
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "line 2: expected 4 numbers for quat, found 3"
        );
        assert_eq!(out, b"1,0,0,0\n");
    }

    #[test]
    fn long_lines_are_refused_whatever_their_end() {
        let mut long = vec![b'1'; MAX_LINE_BYTES + 1];
        long.push(b'\r');
        let (result, _) = convert("quat", "quat", std::str::from_utf8(&long).unwrap());
        assert!(
            result
                .unwrap_err()
                .to_string()
                .starts_with("line 1: line is longer than"),
        );
    }
}
