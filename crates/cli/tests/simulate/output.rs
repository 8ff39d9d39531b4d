//! The shape of the CSV: header, first and last rows, row counts and times,
//! several bodies, `--output`, and `--list-methods`.

use glam::{DQuat, DVec3};
use kreisel_dynamics::{FreeBodyMethod, HeavyTopMethod};

use crate::support::{HEADER, body, kreisel, parse_csv, scratch, simulate, simulation};

#[test]
fn header_first_row_and_last_row() {
    let scene = simulation(1.0, 0.01, "output_interval = 0.1")
        + &body(
            [1.0, 2.0, 3.0],
            [0.01, 1.0, 0.0],
            "name = \"handle\"\norientation = [2.0, 0.0, 0.0, 0.0]",
        );
    let run = simulate("shape.toml", &scene, &[]);
    assert!(run.stdout.starts_with(&format!("{HEADER}\n")));
    let rows = run.rows();
    // t = 0, 0.1, …, 1.0.
    assert_eq!(rows.len(), 11);
    let first = &rows[0];
    assert_eq!(first.t, 0.0);
    assert_eq!(first.body, "handle");
    // The orientation is normalised on load.
    assert_eq!(first.q, DQuat::IDENTITY);
    assert_eq!(first.omega, DVec3::new(0.01, 1.0, 0.0));
    assert_eq!(first.energy, 0.5 * (0.01 * 0.01 + 2.0));
    assert_eq!(first.l, DVec3::new(0.01, 2.0, 0.0));
    assert_eq!(rows.last().unwrap().t, 1.0);
    for (k, row) in rows.iter().enumerate() {
        // The time of step 10 k is 10 k · dt.
        assert_eq!(row.t, (10 * k) as f64 * 0.01, "row {k}");
    }
}

#[test]
fn row_counts_with_and_without_interval() {
    let spin = body([1.0, 2.0, 3.0], [0.3, 0.2, 0.1], "");
    // Every step: 100 steps, 101 rows.
    let rows = simulate("every.toml", &(simulation(1.0, 0.01, "") + &spin), &[]).rows();
    assert_eq!(rows.len(), 101);
    // A partial last step: rows at 0, 0.2, …, 1.0 and at 1.05 exactly.
    let scene = simulation(1.05, 0.01, "output_interval = 0.2") + &spin;
    let rows = simulate("partial.toml", &scene, &[]).rows();
    let times: Vec<f64> = rows.iter().map(|r| r.t).collect();
    assert_eq!(times.len(), 7, "{times:?}");
    assert_eq!(*times.last().unwrap(), 1.05);
    assert!((times[5] - 1.0).abs() < 1e-15, "{times:?}");
    // An interval longer than the run: first and last state only.
    let scene = simulation(0.5, 0.01, "output_interval = 10.0") + &spin;
    let rows = simulate("long_interval.toml", &scene, &[]).rows();
    assert_eq!(rows.iter().map(|r| r.t).collect::<Vec<_>>(), [0.0, 0.5]);
    // dt longer than the duration: one step of the duration.
    let rows = simulate("one_step.toml", &(simulation(0.25, 1.0, "") + &spin), &[]).rows();
    assert_eq!(rows.iter().map(|r| r.t).collect::<Vec<_>>(), [0.0, 0.25]);
}

#[test]
fn bodies_in_scene_order_with_default_names() {
    let scene = simulation(0.1, 0.05, "")
        + &body([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], "")
        + &body([2.0, 2.0, 2.0], [1.0, 0.0, 0.0], "name = \"ball\"")
        + &body([1.0, 2.0, 2.5], [0.0, 1.0, 0.0], "");
    let rows = simulate("three.toml", &scene, &[]).rows();
    let names: Vec<&str> = rows.iter().map(|r| r.body.as_str()).collect();
    assert_eq!(names, ["body1", "ball", "body3"].repeat(3));
    for (n, row) in rows.iter().enumerate() {
        assert_eq!(row.t, [0.0, 0.05, 0.1][n / 3]);
    }
}

#[test]
fn quaternion_is_continuous() {
    // A fast spin turns q through w < 0; consecutive rows never flip sign.
    let scene = simulation(10.0, 0.01, "") + &body([1.0, 2.0, 3.0], [0.5, 6.0, 0.3], "");
    let rows = simulate("continuous.toml", &scene, &[]).rows();
    assert!(rows.iter().any(|r| r.q.w < -0.9));
    for pair in rows.windows(2) {
        assert!(pair[0].q.dot(pair[1].q) > 0.9, "{:?}", pair);
    }
}

#[test]
fn output_file_holds_the_same_csv() {
    let scene = simulation(1.0, 0.1, "") + &body([1.0, 2.0, 3.0], [0.1, 1.0, 0.1], "");
    let path = scratch("to_file.toml", &scene);
    let out = path.with_extension("csv");
    let to_file = crate::support::simulate_file(&path, &["--output", out.to_str().unwrap()]);
    assert_eq!(
        (
            to_file.code,
            to_file.stdout.as_str(),
            to_file.stderr.as_str()
        ),
        (Some(0), "", "")
    );
    let written = std::fs::read_to_string(&out).unwrap();
    let to_stdout = crate::support::simulate_file(&path, &[]);
    assert_eq!(written, to_stdout.stdout);
    assert_eq!(parse_csv(&written).len(), 11);
}

#[test]
fn list_methods_names_every_registry_method_and_the_default() {
    let run = kreisel(&["simulate", "--list-methods"]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    for method in FreeBodyMethod::ALL {
        let name = method.name();
        let line = lines
            .iter()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("{name} not listed:\n{}", run.stdout));
        let order = match method.integrator().order() {
            u32::MAX => "exact".to_owned(),
            p => p.to_string(),
        };
        assert_eq!(
            line.split_whitespace().nth(1),
            Some(order.as_str()),
            "{line}"
        );
    }
    assert!(
        run.stdout
            .contains("auto        exact  the default; runs exact"),
        "{}",
        run.stdout
    );
    // The first line is a header, then one line per method and `auto`;
    // then a blank line, a heading and one line per heavy-top method.
    let registry = FreeBodyMethod::ALL.len() - 1;
    let heavy = HeavyTopMethod::ALL.len();
    assert_eq!(lines.len(), 2 + registry + 2 + heavy, "{}", run.stdout);
    let tail = &lines[2 + registry + 2..];
    for (line, method) in tail.iter().zip(HeavyTopMethod::ALL) {
        let order = method.integrator().order().to_string();
        let fields: Vec<&str> = line.split_whitespace().collect();
        assert_eq!(&fields[..2], &[method.name(), order.as_str()], "{line}");
    }
}

#[test]
fn help_documents_the_format() {
    let run = kreisel(&["simulate", "--help"]);
    assert_eq!(run.code, Some(0));
    for needle in [
        HEADER,
        "- m g.x",
        "output_interval",
        "--list-methods",
        "t = duration",
    ] {
        assert!(run.stdout.contains(needle), "{needle}:\n{}", run.stdout);
    }
}
