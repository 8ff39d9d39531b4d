//! Invalid input: one line on stderr naming the line, exit status 1, every
//! earlier line written; usage errors; files; a closed output pipe.

use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

use crate::support::{KREISEL, Run, convert, scratch};

/// A valid line (the identity) in each input representation.
fn identity(from: &str) -> &'static str {
    match from {
        "quat" => "1,0,0,0",
        "quat-xyzw" => "0,0,0,1",
        "matrix" => "1,0,0,0,1,0,0,0,1",
        "axis-angle" => "1,0,0,0",
        _ => "0,0,0",
    }
}

/// `(from, bad line, words the message must contain)`.
const CASES: &[(&str, &str, &[&str])] = &[
    ("quat", "0,0,0,0", &["zero norm"]),
    ("quat-xyzw", "0 0 0 -0", &["zero norm"]),
    ("quat", "nan,0,0,1", &["`nan`", "not finite"]),
    ("quat", "1,inf,0,0", &["`inf`", "not finite"]),
    ("euler:ZXZ", "1e999,0,0", &["`1e999`", "not finite"]),
    ("rotvec", "0,-infinity,0", &["`-infinity`", "not finite"]),
    ("axis-angle", "0,0,1,NaN", &["`NaN`", "not finite"]),
    ("matrix", "0,0,0,0,0,0,0,0,NaN", &["`NaN`", "not finite"]),
    (
        "matrix",
        "1,0,0,0,1,0,0,0,1.001",
        &["not orthonormal", "1e-6"],
    ),
    ("matrix", "2,0,0,0,2,0,0,0,2", &["not orthonormal"]),
    ("matrix", "1,0,0,0,1,0,0,0,-1", &["reflection"]),
    ("axis-angle", "0,0,0,1", &["axis is zero", "angle is 1"]),
    ("quat", "1,0,0", &["expected 4 numbers for quat, found 3"]),
    (
        "matrix",
        "1 0 0 0 1 0 0 0 1 0",
        &["expected 9 numbers for matrix, found 10"],
    ),
    (
        "euler:zyx",
        "1,2",
        &["expected 3 numbers for euler:zyx, found 2"],
    ),
    (
        "rotvec",
        "1 2 3 4 5 6 7 8 9 10 11 12",
        &["expected 3 numbers for rotvec, found 12"],
    ),
    ("quat", "1,0,abc,0", &["`abc`", "cannot parse"]),
    ("quat", "1;0;0;0", &["`1;0;0;0`", "cannot parse"]),
    ("quat", "1,0,0,0 # identity", &["`#`", "cannot parse"]),
    ("quat", "1,,0,0", &["empty number"]),
    ("quat", "1,0,0,0,", &["empty number"]),
    (
        "rotvec",
        "1.5e308,1.5e308,0",
        &["rotation vector", "overflow"],
    ),
];

/// Checks the common shape of a data error: status 1, no panic, exactly
/// one stderr line with the given prefix and words, and `stdout` as given.
fn assert_data_error(run: &Run, prefix: &str, words: &[&str], stdout: &str, case: &str) {
    assert_eq!(run.code, Some(1), "{case}: {}", run.stderr);
    assert!(!run.stderr.contains("panicked"), "{case}: {}", run.stderr);
    let lines = run.stderr_lines();
    assert_eq!(lines.len(), 1, "{case}: {:?}", run.stderr);
    assert!(lines[0].starts_with(prefix), "{case}: {:?}", lines[0]);
    for word in words {
        assert!(
            lines[0].contains(word),
            "{case}: {:?} lacks {word:?}",
            lines[0]
        );
    }
    assert_eq!(run.stdout, stdout, "{case}");
}

#[test]
fn each_invalid_line_stops_with_its_line_number_after_earlier_output() {
    for &(from, bad, words) in CASES {
        let good = identity(from);
        let input = format!("{good}\n# a comment\n{bad}\n{good}\n");
        let run = convert(from, "quat", &[], input);
        let prefix = "kreisel: error: line 3: ";
        assert_data_error(&run, prefix, words, "1,0,0,0\n", &format!("{from} {bad:?}"));
    }
}

#[test]
fn invalid_utf8_is_a_line_error() {
    let run = convert("quat", "quat", &[], b"\n1,0,0,0\n1,0,\xff,0\n".to_vec());
    assert_data_error(
        &run,
        "kreisel: error: line 3: ",
        &["UTF-8"],
        "1,0,0,0\n",
        "utf8",
    );
}

#[test]
fn errors_in_files_name_file_and_line_and_keep_earlier_output_on_stdout() {
    let input = scratch("errors-input.csv");
    let output = scratch("errors-output.csv");
    let _ = std::fs::remove_file(&output);
    std::fs::write(&input, "0,0,0\n\n0,0,1\n0,x,0\n0,0,2\n").unwrap();
    let (i, o) = (input.to_str().unwrap(), output.to_str().unwrap());
    let run = convert("rotvec", "rotvec", &["--input", i], "");
    let prefix = format!("kreisel: error: {i}:4: ");
    assert_data_error(&run, &prefix, &["`x`"], "0,0,0\n0,0,1\n", "file");
    let run = convert("rotvec", "rotvec", &["--input", i, "--output", o], "");
    assert_data_error(&run, &prefix, &["`x`"], "", "file to file");
    // An --output file is all or nothing: after the error it does not exist.
    assert!(!output.exists());
}

#[test]
fn unreadable_input_and_uncreatable_output_name_the_path() {
    let missing = scratch("no-such-input.csv");
    let m = missing.to_str().unwrap();
    let run = convert("quat", "quat", &["--input", m], "");
    assert_data_error(
        &run,
        "kreisel: error: cannot open input file",
        &[m],
        "",
        "missing",
    );

    let bad_output = scratch("no-such-dir").join("out.csv");
    let b = bad_output.to_str().unwrap();
    let run = convert("quat", "quat", &["--output", b], "1,0,0,0\n");
    assert_data_error(
        &run,
        "kreisel: error: cannot create output file",
        &[b],
        "",
        "output",
    );

    // --output naming the --input file would truncate it before reading.
    let same = scratch("same.csv");
    std::fs::write(&same, "1,0,0,0\n").unwrap();
    let s = same.to_str().unwrap();
    let run = convert("quat", "quat", &["--input", s, "--output", s], "");
    assert_data_error(
        &run,
        "kreisel: error: output file",
        &[s, "input"],
        "",
        "same",
    );
    assert_eq!(std::fs::read_to_string(&same).unwrap(), "1,0,0,0\n");
}

#[test]
fn unknown_representations_are_usage_errors_listing_the_valid_ones() {
    for (from, to) in [
        ("quaternion", "quat"),
        ("quat", "euler"),
        ("euler:ZZX", "quat"),
        ("quat", "euler:XyZ"),
        ("quat", "rotvec "),
    ] {
        let run = convert(from, to, &[], "1,0,0,0\n");
        assert_eq!(run.code, Some(2), "{from} {to}: {}", run.stderr);
        assert!(!run.stderr.contains("panicked"), "{}", run.stderr);
        for name in [
            "quat-xyzw",
            "matrix",
            "rotvec",
            "axis-angle",
            "euler:SEQ",
            "ZXZ",
        ] {
            assert!(run.stderr.contains(name), "{from} {to}: {}", run.stderr);
        }
        assert_eq!(run.stdout, "");
    }
    // Missing --to.
    let run = crate::support::kreisel(&["convert", "--from", "quat"], "");
    assert_eq!(run.code, Some(2), "{}", run.stderr);
}

#[test]
fn closed_output_pipe_ends_quietly() {
    let mut child = Command::new(KREISEL)
        .args(["convert", "--from", "quat", "--to", "matrix"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn kreisel");
    let mut stdin = child.stdin.take().expect("stdin");
    // Far more output than a pipe buffer holds, so the child must block on it.
    let writer = std::thread::spawn(move || {
        let chunk = "0.5,0.5,0.5,0.5\n".repeat(10_000);
        for _ in 0..50 {
            if stdin.write_all(chunk.as_bytes()).is_err() {
                break; // the child has exited
            }
        }
    });
    let mut stdout = BufReader::new(child.stdout.take().expect("stdout"));
    let mut first = String::new();
    stdout.read_line(&mut first).expect("first line");
    assert_eq!(first, "0,0,1,1,0,0,0,1,0\n");
    drop(stdout); // like `| head -1`
    let output = child.wait_with_output().expect("wait");
    writer.join().expect("writer thread");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(stderr.is_empty(), "{stderr}");
    assert_eq!(output.status.code(), Some(0), "{stderr}");
}

#[test]
fn a_failed_conversion_leaves_no_partial_output_file() {
    // Regression: an error at line 3 left a truncated --output file behind.
    let dir = scratch("atomic-output");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let output = dir.join("out.csv");
    let o = output.to_str().unwrap();
    std::fs::write(&output, "previous contents\n").unwrap();
    let run = convert(
        "quat",
        "quat",
        &["--output", o],
        "1,0,0,0\n0,1,0,0\n0,0,0,0\n",
    );
    assert_eq!(run.code, Some(1), "{}", run.stderr);
    assert_eq!(
        std::fs::read_to_string(&output).unwrap(),
        "previous contents\n"
    );
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["out.csv"], "a temporary file was left behind");
    // Writing to a full device fails cleanly with the device's reason.
    if std::path::Path::new("/dev/full").exists() {
        let run = convert("quat", "quat", &["--output", "/dev/full"], "1,0,0,0\n");
        assert_eq!(run.code, Some(1), "{}", run.stderr);
        assert!(run.stderr.contains("/dev/full"), "{}", run.stderr);
    }
    // A new file appears only on success.
    let fresh = dir.join("fresh.csv");
    let run = convert(
        "quat",
        "quat",
        &["--output", fresh.to_str().unwrap()],
        "0,0,0,0\n",
    );
    assert_eq!(run.code, Some(1));
    assert!(!fresh.exists());
}
