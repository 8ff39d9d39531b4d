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

/// θ₀ outside [0, π] (once folded silently), I₃ > 2 I₁ (no real body), a
/// subnormal moment and overflowing products are one-line errors naming
/// the option, never a report with NaN.
#[test]
fn unphysical_and_unrepresentable_tops_name_the_option() {
    for (option, value) in [
        ("--theta0", "4"),
        ("--theta0", "-0.1"),
        ("--theta0", "3.1415926535897936"),
        ("--i3", "2.5"),
        ("--i1", "1e-320"),
        ("--psi-dot0", "1e300"),
        ("--theta-dot0", "1e200"),
        ("--mgl", "1e308"),
    ] {
        let run = with(option, value);
        let line = run.error_line(1);
        assert!(
            line.starts_with(&format!("kreisel: error: {option}: {value}: "))
                || line.starts_with(&format!("kreisel: error: {option}: ")),
            "{option} {value}: {line}"
        );
        assert!(line.len() < 200, "{line}");
    }
    let line = with("--theta0", "4").error_line(1).to_owned();
    assert!(line.contains("[0, pi]"), "{line}");
    let line = with("--i3", "2.5").error_line(1).to_owned();
    assert!(line.contains("2 i1"), "{line}");
    // The edges are tops: θ₀ = 0 and π (as f64), a disc pivoted at its centre.
    for (option, value) in [
        ("--theta0", "0"),
        ("--theta0", "3.141592653589793"),
        ("--i3", "2"),
    ] {
        let run = with(option, value);
        assert_eq!(run.code, Some(0), "{option} {value}: {}", run.stderr);
        assert!(!run.stdout.contains("NaN") && !run.stdout.contains("inf"));
    }
}
