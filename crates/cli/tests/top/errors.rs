//! Bad arguments: exit status 1, one line naming the option, no panic, no file.

use crate::support::{Run, kreisel, scratch_dir};

/// `kreisel top` with a valid top, `option` set to `value`.
fn with(option: &str, value: &str) -> Run {
    let mut args = vec![
        "top", "--i1", "1", "--i3", "0.5", "--mgl", "1", "--theta0", "0.5",
    ];
    if let Some(i) = args.iter().position(|a| *a == option) {
        args[i + 1] = value;
    } else {
        args.extend([option, value]);
    }
    kreisel(&args, "")
}

#[test]
fn bad_numbers_name_the_option() {
    for (option, value) in [
        ("--i1", "0"),
        ("--i1", "-1"),
        ("--i1", "nan"),
        ("--i3", "0"),
        ("--i3", "inf"),
        ("--mgl", "-inf"),
        ("--theta0", "NaN"),
        ("--theta-dot0", "1e999"),
        ("--phi-dot0", "inf"),
        ("--psi-dot0", "-inf"),
    ] {
        let run = with(option, value);
        let line = run.error_line(1);
        assert!(
            line.starts_with(&format!("kreisel: error: {option}: ")),
            "{option} {value}: {line}"
        );
    }
}

#[test]
fn bad_plot_files_are_one_line_errors() {
    let dir = scratch_dir();
    let jpg = dir.join("top.jpg");
    let run = with("--plot", jpg.to_str().unwrap());
    let line = run.error_line(1);
    assert!(
        line.contains("--plot") && line.contains("top.jpg"),
        "{line}"
    );
    assert!(!jpg.exists());
    let missing = dir.join("no/such/dir/top.svg");
    let line = with("--plot", missing.to_str().unwrap())
        .error_line(1)
        .to_owned();
    assert!(
        line.contains("--plot") && line.contains("top.svg"),
        "{line}"
    );
    for bare in ["top", "top.", ".png.txt"] {
        let path = dir.join(bare);
        let run = with("--plot", path.to_str().unwrap());
        assert!(run.error_line(1).contains("--plot"));
    }
}

#[test]
fn usage_errors_come_from_clap() {
    let run = kreisel(&["top", "--i1", "1"], "");
    assert_eq!(run.code, Some(2));
    assert!(!run.stderr.contains("panicked"));
    let run = with("--i1", "one");
    assert_eq!(run.code, Some(2));
    assert!(run.stderr.contains("--i1"), "{}", run.stderr);
    let run = with("--format", "xml");
    assert_eq!(run.code, Some(2));
}
