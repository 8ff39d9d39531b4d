//! Input syntax: separators, comments, blank lines, line endings, files.

use crate::support::{convert, scratch};

#[test]
fn commas_whitespace_tabs_and_mixtures_are_the_same() {
    let lines = [
        "0.5,0.5,0.5,0.5",
        "0.5 0.5 0.5 0.5",
        "0.5, 0.5 0.5,0.5",
        "0.5\t0.5\t0.5\t0.5",
        "  0.5 ,\t0.5 ,  0.5\t, 0.5   ",
        "\t0.5  0.5,0.5 \t 0.5",
        "5e-1,+0.5,.5,0.50",
    ];
    let input: String = lines.iter().map(|l| format!("{l}\n")).collect();
    let out = convert("quat", "quat", &[], input);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(out.stdout, "0.5,0.5,0.5,0.5\n".repeat(lines.len()));
}

#[test]
fn comments_and_blank_lines_produce_no_output() {
    let input = "# w, x, y, z\n\n1,0,0,0\n   \n\t\n   # indented comment\n0,0,0,2\n#\n0,1,0,0\n\n";
    let out = convert("quat", "rotvec", &[], input);
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(
        out.stdout,
        "0,0,0\n0,0,3.141592653589793\n3.141592653589793,0,0\n"
    );
    assert!(out.stderr.is_empty());
}

#[test]
fn crlf_missing_final_newline_and_empty_input() {
    let out = convert("quat", "quat", &[], "1,0,0,0\r\n0,0,0,-1\r\n0,0,1,0");
    assert_eq!(out.stdout, "1,0,0,0\n0,0,0,1\n0,0,1,0\n", "{}", out.stderr);
    for empty in ["", "\n\n", "# only a comment\n"] {
        let out = convert("matrix", "euler:ZXZ", &[], empty);
        assert_eq!((out.code, out.stdout.as_str()), (Some(0), ""), "{empty:?}");
    }
}

#[test]
fn quaternions_are_normalised_and_canonical() {
    let out = convert(
        "quat",
        "quat",
        &[],
        "2,0,0,0\n-1,0,0,0\n0,-3,0,0\n1e-300,0,0,1e-300\n",
    );
    let s = 1.0 / 2.0_f64.sqrt(); // the library divides by the norm
    assert_eq!(
        out.stdout,
        format!("1,0,0,0\n1,0,0,0\n0,1,0,0\n{s},0,0,{s}\n")
    );
}

#[test]
fn input_and_output_files() {
    let input = scratch("syntax-input.csv");
    let output = scratch("syntax-output.csv");
    std::fs::write(&input, "# rotvec\n0,0,0\n\n0 0 1.5707963267948966\n").unwrap();
    let (i, o) = (input.to_str().unwrap(), output.to_str().unwrap());
    let out = convert("rotvec", "axis-angle", &["--input", i, "--output", o], "");
    assert_eq!(out.code, Some(0), "{}", out.stderr);
    assert_eq!(out.stdout, "");
    let written = std::fs::read_to_string(&output).unwrap();
    assert_eq!(written, "1,0,0,0\n0,0,1,1.5707963267948966\n");
}

#[test]
fn output_numbers_are_shortest_round_trip() {
    // Tiny angles stay exact and are written in exponent form, not 300 zeros.
    let out = convert("rotvec", "rotvec", &[], "1e-300,0,-2.5e-310\n0.1,0.2,0.3\n");
    assert_eq!(
        out.stdout, "1e-300,0,-2.5e-310\n0.1,0.2,0.3\n",
        "{}",
        out.stderr
    );
}
