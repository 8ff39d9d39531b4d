//! Running the `kreisel` binary from a test, shared by the test targets
//! (`#[path]`-included, so each target gets its own copy of the module).

// Each test target uses its own subset of these helpers.
#![allow(dead_code)]

use std::io::Write;
use std::process::{Command, Stdio};

/// The binary under test.
pub const KREISEL: &str = env!("CARGO_BIN_EXE_kreisel");

/// The result of one run of the binary.
pub struct Run {
    /// Exit status (`None` when killed by a signal).
    pub code: Option<i32>,
    /// Standard output.
    pub stdout: String,
    /// Standard error.
    pub stderr: String,
}

impl Run {
    /// Asserts a failure with exit status `code` and one `kreisel: error:`
    /// line on standard error (and nothing on standard output); returns it.
    pub fn error_line(&self, code: i32) -> &str {
        assert_eq!(
            self.code,
            Some(code),
            "stdout: {}\nstderr: {}",
            self.stdout,
            self.stderr
        );
        assert!(!self.stderr.contains("panicked"), "{}", self.stderr);
        assert!(self.stdout.is_empty(), "stdout: {}", self.stdout);
        let lines: Vec<&str> = self.stderr.lines().collect();
        assert_eq!(lines.len(), 1, "stderr: {}", self.stderr);
        assert!(lines[0].starts_with("kreisel: error: "), "{}", lines[0]);
        lines[0]
    }
}

/// Runs `kreisel` with `args`, feeding `stdin` (from a thread, so large
/// inputs and outputs cannot deadlock).
pub fn kreisel(args: &[&str], stdin: impl Into<Vec<u8>>) -> Run {
    let stdin = stdin.into();
    let mut child = Command::new(KREISEL)
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn kreisel");
    let mut pipe = child.stdin.take().expect("stdin pipe");
    // The child may stop reading early (at an error): ignore write failures.
    let writer = std::thread::spawn(move || {
        let _ = pipe.write_all(&stdin);
    });
    let output = child.wait_with_output().expect("wait for kreisel");
    writer.join().expect("stdin writer thread");
    Run {
        code: output.status.code(),
        stdout: String::from_utf8(output.stdout).expect("stdout is UTF-8"),
        stderr: String::from_utf8(output.stderr).expect("stderr is UTF-8"),
    }
}
