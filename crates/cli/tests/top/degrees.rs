//! `--degrees` (issue 25): θ₀ read in degrees, the angles written in
//! degrees under keys and columns that say so; everything agrees with the
//! radians run of the same top (angles × 180/π, the rest unchanged).

use crate::support::{CASES, json, kreisel, raw_members, run_case, scratch_dir};

/// The run of `case` with θ₀ given in degrees (`theta0_deg`) and `extra`.
fn run_degrees(case: &[f64; 7], theta0_deg: f64, extra: &[&str]) -> crate::support::Run {
    let mut c = *case;
    c[3] = theta0_deg;
    let mut args = vec!["--degrees"];
    args.extend_from_slice(extra);
    run_case(&c, &args)
}

const DEG: f64 = 180.0 / std::f64::consts::PI;

#[test]
fn report_in_degrees_agrees_with_radians() {
    for theta0_deg in [30.0, 0.0, 90.0, 135.0, 180.0] {
        let mut case = CASES[1];
        case[3] = f64::to_radians(theta0_deg);
        let rad = run_case(&case, &["--format", "json"]);
        let deg = run_degrees(&case, theta0_deg, &["--format", "json"]);
        json(&rad);
        json(&deg);
        let (r, d) = (raw_members(&rad.stdout), raw_members(&deg.stdout));
        assert_eq!(r.len(), d.len());
        for (key, value) in &r {
            let angle = ["theta0", "theta_min", "theta_max"].contains(&key.as_str());
            if angle {
                assert!(!d.contains_key(key), "{key} without its unit");
                let in_deg: f64 = d[&format!("{key}_deg")].parse().unwrap();
                let in_rad: f64 = value.parse().unwrap();
                assert!(
                    (in_deg - in_rad * DEG).abs() <= 1e-13 * in_deg.abs().max(1.0),
                    "{theta0_deg}: {key} {in_deg} vs {in_rad}"
                );
            } else {
                assert_eq!(&d[key], value, "{theta0_deg}: {key}");
            }
        }
        // θ₀ is echoed as given, not converted back and forth.
        assert_eq!(d["theta0_deg"].parse::<f64>().unwrap(), theta0_deg);
    }
    let text = run_degrees(&CASES[1], 57.0, &[]);
    assert!(
        text.stdout.contains("\ntheta0_deg: 57 deg\n"),
        "{}",
        text.stdout
    );
    assert!(text.stdout.contains("\ntheta_max_deg: "), "{}", text.stdout);
    assert!(
        text.stdout.contains("\npsi_dot0: 8 rad/s\n"),
        "rates stay rad/s"
    );
}

#[test]
fn csv_in_degrees_agrees_with_radians() {
    let dir = scratch_dir();
    for (k, case) in CASES.iter().enumerate() {
        let theta0_deg = case[3].to_degrees();
        let mut case = *case;
        case[3] = theta0_deg.to_radians();
        let (rad_path, deg_path) = (
            dir.join(format!("rad{k}.csv")),
            dir.join(format!("deg{k}.csv")),
        );
        let grid = ["--duration", "2", "--dt", "0.01"];
        let mut args = vec!["--csv", rad_path.to_str().unwrap()];
        args.extend_from_slice(&grid);
        assert_eq!(run_case(&case, &args).code, Some(0));
        let mut args = vec!["--csv", deg_path.to_str().unwrap()];
        args.extend_from_slice(&grid);
        let run = run_degrees(&case, theta0_deg, &args);
        assert_eq!(run.code, Some(0), "{}", run.stderr);
        let (rad, deg) = (
            std::fs::read_to_string(&rad_path).unwrap(),
            std::fs::read_to_string(&deg_path).unwrap(),
        );
        assert!(rad.starts_with("t,theta,phi,psi,theta_dot,"));
        assert!(deg.starts_with("t,theta_deg,phi_deg,psi_deg,theta_dot,phi_dot,psi_dot,qw,"));
        assert_eq!(rad.lines().count(), deg.lines().count());
        for (r, d) in rad.lines().zip(deg.lines()).skip(1) {
            let r: Vec<f64> = r.split(',').map(|x| x.parse().unwrap()).collect();
            let d: Vec<f64> = d.split(',').map(|x| x.parse().unwrap()).collect();
            for c in 0..r.len() {
                if (1..=3).contains(&c) {
                    let scale = d[c].abs().max(1.0);
                    assert!(
                        (d[c] - r[c] * DEG).abs() <= 1e-13 * scale,
                        "{k} col {c}: {} vs {}",
                        d[c],
                        r[c]
                    );
                } else {
                    assert_eq!(d[c], r[c], "{k} col {c}");
                }
            }
        }
    }
}

#[test]
fn degrees_out_of_range_is_refused_in_degrees() {
    for bad in ["200", "-1", "181"] {
        let run = kreisel(
            &[
                "top",
                "--i1",
                "1",
                "--i3",
                "0.5",
                "--mgl",
                "1",
                "--theta0",
                bad,
                "--degrees",
            ],
            "",
        );
        let line = run.error_line(1);
        assert!(
            line.contains(&format!("--theta0: {bad} deg: must lie in [0, 180]")),
            "{line}"
        );
    }
    // Without --degrees 3.2 is out of [0, pi] radians; with it, 3.2 degrees is fine.
    let case = [1.0, 0.5, 1.0, 3.2, 0.0, 0.0, 8.0];
    assert_eq!(run_case(&case, &[]).code, Some(1));
    assert_eq!(run_case(&case, &["--degrees"]).code, Some(0));
}
