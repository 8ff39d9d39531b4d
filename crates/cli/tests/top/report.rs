//! The report: every field equals what the library returns for the same top.

use kreisel_dynamics::TopMotionKind;
use serde_json::Value;

use crate::support::{CASES, case_args, json, kreisel, motion, raw_members, run_case};

/// A JSON number (parsed exactly from its text) or null, as an `Option<f64>`.
fn number(raw: &std::collections::BTreeMap<String, String>, key: &str) -> Option<f64> {
    let text = raw.get(key).unwrap_or_else(|| panic!("{key} missing"));
    if text == "null" {
        None
    } else {
        Some(
            text.parse()
                .unwrap_or_else(|e| panic!("{key}: {text}: {e}")),
        )
    }
}

/// `a` and `b` agree to 1e-10 relative (they are printed in shortest
/// round-trip form, so in fact exactly).
fn close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-10 * a.abs().max(b.abs()) || a == b,
        "{what}: {a} vs {b}"
    );
    assert_eq!(a, b, "{what}: round trip");
}

#[test]
fn json_fields_equal_the_library() {
    for case in CASES {
        let run = run_case(&case, &["--format", "json"]);
        let v = json(&run);
        let raw = raw_members(&run.stdout);
        let m = motion(&case);
        let num = |key| number(&raw, key).unwrap_or_else(|| panic!("{key} is null"));
        for (key, expect) in [
            ("a", m.a()),
            ("b", m.b()),
            ("alpha", m.alpha()),
            ("beta", m.beta()),
            ("omega3", m.omega3()),
            ("theta_min", m.theta_min()),
            ("theta_max", m.theta_max()),
        ] {
            close(num(key), expect, &format!("{case:?} {key}"));
        }
        for (key, expect) in [
            ("nutation_period", m.nutation_period()),
            ("mean_precession_rate", m.mean_precession_rate()),
        ] {
            match (number(&raw, key), expect) {
                (Some(got), Some(expect)) => close(got, expect, &format!("{case:?} {key}")),
                (got, expect) => assert_eq!(got, expect, "{case:?} {key}"),
            }
        }
        assert!(v["roots"].is_array());
        let roots: Vec<f64> = raw["roots"]
            .trim_matches(['[', ']'])
            .split(", ")
            .map(|r| r.parse().expect("root"))
            .collect();
        assert_eq!(roots, m.roots(), "{case:?}");
        assert!(roots.windows(2).all(|w| w[0] <= w[1]), "ascending");
        let kind = match m.motion() {
            Some(TopMotionKind::NoLoops) => Value::from("no_loops"),
            Some(TopMotionKind::Loops) => Value::from("loops"),
            Some(TopMotionKind::Cusps) => Value::from("cusps"),
            None => Value::Null,
        };
        assert_eq!(v["motion"], kind, "{case:?}");
        assert_eq!(v["sleeping_stable"], Value::Bool(m.sleeping_stable()));
        assert_eq!(v["sleeping"], Value::Bool(false));
        for (key, input) in [
            "i1",
            "i3",
            "mgl",
            "theta0",
            "theta_dot0",
            "phi_dot0",
            "psi_dot0",
        ]
        .iter()
        .zip(case)
        {
            assert_eq!(num(key), input, "{key}");
        }
    }
}

#[test]
fn the_examples_cover_every_kind_of_motion() {
    let kinds: Vec<Option<TopMotionKind>> = CASES.iter().map(|c| motion(c).motion()).collect();
    for kind in [
        TopMotionKind::NoLoops,
        TopMotionKind::Loops,
        TopMotionKind::Cusps,
    ] {
        assert!(kinds.contains(&Some(kind)), "{kind:?} missing: {kinds:?}");
    }
}

#[test]
fn text_has_the_same_fields_with_units() {
    let case = CASES[1];
    let run = run_case(&case, &["--format", "json"]);
    let v = json(&run);
    let raw = raw_members(&run.stdout);
    let text = run_case(&case, &[]);
    assert_eq!(text.code, Some(0), "{}", text.stderr);
    let lines: Vec<&str> = text.stdout.lines().collect();
    let keys: Vec<&str> = lines
        .iter()
        .map(|l| l.split_once(": ").expect("name: value").0)
        .collect();
    let json_keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    let mut sorted = keys.clone();
    sorted.sort_unstable();
    assert_eq!(sorted, json_keys, "same fields");
    for line in &lines {
        let (key, rest) = line.split_once(": ").unwrap();
        match &v[key] {
            Value::Number(_) => {
                let value: f64 = rest.split(' ').next().unwrap().parse().unwrap();
                assert_eq!(value, raw[key].parse::<f64>().unwrap(), "{line}");
            }
            Value::Array(_) => {
                let shown: Vec<f64> = rest
                    .split(" (")
                    .next()
                    .unwrap()
                    .split(", ")
                    .map(|t| t.parse().unwrap())
                    .collect();
                let expect: Vec<f64> = raw[key]
                    .trim_matches(['[', ']'])
                    .split(", ")
                    .map(|r| r.parse().unwrap())
                    .collect();
                assert_eq!(shown, expect, "{line}");
            }
            Value::String(s) => assert_eq!(rest, s),
            Value::Bool(b) => assert_eq!(rest, b.to_string()),
            other => panic!("{key}: {other}"),
        }
    }
    assert!(
        text.stdout.contains("\nomega3: 7.45969769413186 rad/s\n"),
        "{}",
        text.stdout
    );
    assert!(text.stdout.contains("\nnutation_period: "));
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("theta_max: ") && l.ends_with(" rad"))
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("alpha: ") && l.ends_with(" 1/s^2"))
    );
}

#[test]
fn a_sleeping_top_has_no_nutation() {
    for (psi_dot, stable) in [(5.0, true), (4.5, true), (3.0, false), (0.0, false)] {
        // ω₃² > 4 I₁ Mgl / I₃² = 16: stable from ω₃ = 4 on.
        let case = [1.0, 0.5, 1.0, 0.0, 0.0, 0.0, psi_dot];
        let v = json(&run_case(&case, &["--format", "json"]));
        for key in ["nutation_period", "mean_precession_rate", "motion"] {
            assert_eq!(v[key], Value::Null, "{key}: {v}");
        }
        assert_eq!(v["sleeping"], Value::Bool(true));
        assert_eq!(v["sleeping_stable"], Value::Bool(stable), "ψ̇ = {psi_dot}");
        assert_eq!(
            v["sleeping_stable"],
            Value::Bool(motion(&case).sleeping_stable())
        );
        let text = run_case(&case, &[]);
        assert!(
            text.stdout.contains("\nnutation_period: none\n"),
            "{}",
            text.stdout
        );
        assert!(text.stdout.contains("\nmotion: none\n"), "{}", text.stdout);
    }
}

#[test]
fn defaults_are_zero_rates() {
    let full = run_case(&[1.0, 0.5, 1.0, 0.5, 0.0, 0.0, 0.0], &["--format", "json"]);
    let short = kreisel(
        &[
            "top", "--i1", "1", "--i3", "0.5", "--mgl", "1", "--theta0", "0.5", "--format", "json",
        ],
        "",
    );
    assert_eq!(full.stdout, short.stdout);
    assert_eq!(case_args(&CASES[0])[1], "--i1");
}

/// A fast top keeps full precision through the CLI: the mean precession
/// rate at ψ̇₀ = 1e10 against mpmath (tests/data/lagrange_top/fast_tops.csv,
/// 120 digits); it was reported as 0 (true 2e-9 rad/s).
#[test]
fn fast_top_mean_precession_is_exact() {
    let manifest = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let csv = manifest
        .ancestors()
        .map(|d| d.join("tests/data/lagrange_top/fast_tops.csv"))
        .find(|p| p.is_file())
        .expect("fast_tops.csv");
    let text = std::fs::read_to_string(csv).unwrap();
    let mut checked = 0;
    for line in text.lines().filter(|l| l.starts_with("released,")) {
        let f: Vec<&str> = line.split(',').collect();
        let x: Vec<f64> = f[1..16].iter().map(|v| v.parse().unwrap()).collect();
        let case = [x[0], x[1], x[2], x[3], x[4], x[5], x[6]];
        let run = run_case(&case, &["--format", "json"]);
        let raw = raw_members(&run.stdout);
        for (key, want) in [
            ("mean_precession_rate", x[14]),
            ("nutation_period", x[13]),
            ("theta_max", x[12]),
        ] {
            let got = number(&raw, key).unwrap();
            assert!(
                (got - want).abs() <= 1e-12 * want.abs(),
                "psi_dot0 {}: {key} {got} vs {want}",
                x[6]
            );
        }
        checked += 1;
    }
    assert_eq!(checked, 5);
}
