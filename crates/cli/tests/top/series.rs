//! `kreisel top --csv`: the rows against the library called directly,
//! the quaternion column against the ZXZ closed form of the angle columns,
//! the attitude against a `kreisel simulate` run of the same top by a
//! stepping method (an independent integration), and the error paths.

use glam::DQuat;

use crate::support::{CASES, Case, kreisel, motion, run_case, scratch_dir};

/// The header `--csv` must write.
const HEADER: &str = "t,theta,phi,psi,theta_dot,phi_dot,psi_dot,qw,qx,qy,qz";

/// Runs a case with `--csv` into a fresh file and returns its rows.
fn csv_rows(c: &Case, name: &str, extra: &[&str]) -> Vec<[f64; 11]> {
    let path = scratch_dir().join(name);
    let _ = std::fs::remove_file(&path);
    let mut args = vec!["--csv", path.to_str().unwrap()];
    args.extend_from_slice(extra);
    let run = run_case(c, &args);
    assert_eq!(run.code, Some(0), "stderr: {}", run.stderr);
    // The report is still written.
    assert!(run.stdout.starts_with("i1: "), "{}", run.stdout);
    parse(&std::fs::read_to_string(&path).unwrap())
}

/// The rows of a `--csv` file (header checked).
fn parse(text: &str) -> Vec<[f64; 11]> {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(HEADER));
    lines
        .map(|line| {
            let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            v.try_into().unwrap_or_else(|v| panic!("row {v:?}"))
        })
        .collect()
}

/// ZXZ intrinsic angles to the quaternion w,x,y,z, in closed form:
/// Rz(φ) Rx(θ) Rz(ψ) = (cos θ/2 cos Σ, sin θ/2 cos Δ, sin θ/2 sin Δ, cos θ/2 sin Σ),
/// Σ = (φ + ψ)/2, Δ = (φ − ψ)/2.
fn zxz_quat(theta: f64, phi: f64, psi: f64) -> [f64; 4] {
    let (s, c) = (0.5 * theta).sin_cos();
    let (sum, diff) = (0.5 * (phi + psi), 0.5 * (phi - psi));
    [c * sum.cos(), s * diff.cos(), s * diff.sin(), c * sum.sin()]
}

#[test]
fn rows_are_the_library_motion_on_the_default_grid() {
    for (i, c) in CASES.iter().enumerate() {
        let rows = csv_rows(c, &format!("library{i}.csv"), &[]);
        let m = motion(c);
        let period = m.nutation_period().expect("every case nutates");
        // Three periods at period / 200: 600 steps, 601 rows.
        assert_eq!(rows.len(), 601, "case {i}");
        assert_eq!(rows[600][0], 3.0 * period, "case {i}");
        for (k, row) in rows.iter().enumerate() {
            let t = row[0];
            if k < 600 {
                assert_eq!(t, k as f64 * (period / 200.0));
            }
            let e = m.euler_at(t);
            let q = m.world_from_body_at(t);
            let expected = [
                t,
                e.theta,
                e.phi,
                e.psi,
                e.theta_dot,
                e.phi_dot,
                e.psi_dot,
                q.w,
                q.x,
                q.y,
                q.z,
            ];
            // Shortest round-trip text: the same bits (−0 is written as 0).
            for (a, b) in row.iter().zip(expected) {
                assert!(*a == b, "case {i} row {k}: {row:?} vs {expected:?}");
            }
        }
    }
}

#[test]
fn quaternion_column_is_the_zxz_rotation_of_the_angle_columns() {
    let mut worst: f64 = 0.0;
    for (i, c) in CASES.iter().enumerate() {
        for row in csv_rows(
            c,
            &format!("zxz{i}.csv"),
            &["--dt", "0.01", "--duration", "5"],
        ) {
            let z = zxz_quat(row[1], row[2], row[3]);
            let q = [row[7], row[8], row[9], row[10]];
            // q and −q are the same rotation (θ, φ, ψ jump by π where the
            // axis passes the vertical, the quaternion stays continuous).
            let err = |sign: f64| {
                q.iter()
                    .zip(z)
                    .map(|(a, b)| (a - sign * b).abs())
                    .fold(0.0, f64::max)
            };
            let err = err(1.0).min(err(-1.0));
            // The half angles of φ, ψ (tens of rad) lose ~ε |φ|.
            let scale = 1.0 + row[2].abs() + row[3].abs();
            assert!(err < 4e-16 * scale, "case {i} t {}: {err:e}", row[0]);
            worst = worst.max(err / scale);
        }
    }
    eprintln!("quaternion vs ZXZ closed form: max error / (1 + |phi| + |psi|) = {worst:.1e}");
}

/// The angle between two attitudes, rad (accurate for small angles).
fn angle(a: DQuat, b: DQuat) -> f64 {
    let chord = (a - b).length().min((a + b).length());
    4.0 * (0.5 * chord).asin()
}

/// The same top as a `kreisel simulate` scene: mass 1 kg, g = 9.81 m/s²,
/// the pivot l = Mgl / (m g) below the centre of mass on the symmetry axis,
/// I₁ about the centre of mass = I₁(pivot) − m l²; attitude ZXZ (0, θ₀, 0);
/// ω in body axes from the Euler rates at ψ = 0.
fn scene(c: &Case, duration: f64, dt: f64) -> String {
    let [i1, i3, mgl, theta, theta_dot, phi_dot, psi_dot] = *c;
    let l = mgl / 9.81;
    let omega = [
        theta_dot,
        phi_dot * theta.sin(),
        phi_dot * theta.cos() + psi_dot,
    ];
    format!(
        "[simulation]\nduration = {duration:?}\ndt = {dt:?}\ngravity = [0.0, 0.0, -9.81]\n\
         [[body]]\nname = \"top\"\nmass = 1.0\ninertia = [{:?}, {:?}, {i3:?}]\n\
         euler = {{ sequence = \"ZXZ\", angles = [0.0, {theta:?}, 0.0] }}\n\
         angular_velocity = {omega:?}\npivot = [0.0, 0.0, {:?}]\n",
        i1 - l * l,
        i1 - l * l,
        -l
    )
}

/// Attitudes of a `kreisel simulate` run: `(t, q)` per row.
fn simulated(c: &Case, name: &str, duration: f64, dt: f64, method: &str) -> Vec<(f64, DQuat)> {
    let path = scratch_dir().join(name);
    std::fs::write(&path, scene(c, duration, dt)).unwrap();
    let run = kreisel(
        &["simulate", path.to_str().unwrap(), "--method", method],
        "",
    );
    assert_eq!(run.code, Some(0), "stderr: {}", run.stderr);
    run.stdout
        .lines()
        .skip(1)
        .map(|line| {
            let v: Vec<f64> = line
                .split(',')
                .enumerate()
                .filter(|(k, _)| *k != 1)
                .map(|(_, x)| x.parse().unwrap())
                .collect();
            (v[0], DQuat::from_xyzw(v[2], v[3], v[4], v[1]))
        })
        .collect()
}

/// The largest attitude difference between `--csv` and a simulate run.
fn max_difference(rows: &[[f64; 11]], sim: &[(f64, DQuat)]) -> f64 {
    assert_eq!(rows.len(), sim.len());
    rows.iter()
        .zip(sim)
        .map(|(row, (t, q))| {
            assert_eq!(row[0], *t, "the same time grid");
            let ours = DQuat::from_xyzw(row[8], row[9], row[10], row[7]);
            angle(ours, q.normalize())
        })
        .fold(0.0, f64::max)
}

#[test]
fn agrees_with_a_simulate_run_of_the_same_top() {
    // A slow top with loops and a tilted one (not through the vertical:
    // simulate's rows then hold the same rotation as ours).
    for (i, c) in [CASES[1], CASES[3]].iter().enumerate() {
        let (duration, dt) = (2.0, 1e-3);
        let rows = csv_rows(
            c,
            &format!("vs_sim{i}.csv"),
            &["--duration", "2", "--dt", "0.001"],
        );
        // rk4 and splitting8 are independent integrations of the rigid body.
        let coarse = max_difference(&rows, &simulated(c, "rk4.toml", duration, dt, "rk4"));
        let fine = max_difference(
            &rows,
            &simulated(c, "fine.toml", duration, dt, "splitting8"),
        );
        eprintln!(
            "case {i}: top --csv vs simulate over 2 s at dt 1e-3: rk4 {coarse:.2e} rad, splitting8 {fine:.2e} rad"
        );
        assert!(coarse < 1e-9, "rk4 {coarse:e}");
        assert!(fine < 1e-12, "splitting8 {fine:e}");
        // The default method (the library's closed form) agrees to rounding.
        let exact = max_difference(&rows, &simulated(c, "auto.toml", duration, dt, "auto"));
        assert!(exact < 1e-12, "auto {exact:e}");
    }
}

/// A failed run: one line naming `needle`, exit 1, no file.
fn fails(extra: &[&str], needle: &str) {
    let path = scratch_dir().join("failed.csv");
    let _ = std::fs::remove_file(&path);
    let mut args = vec!["--csv", path.to_str().unwrap()];
    args.extend_from_slice(extra);
    let run = run_case(&CASES[0], &args);
    let line = run.error_line(1);
    assert!(line.contains(needle), "{line}");
    assert!(!path.exists(), "{line}");
}

#[test]
fn bad_grids_and_paths_are_one_line_and_leave_no_file() {
    fails(&["--dt", "0"], "--dt: 0 s: must be a positive finite time");
    fails(
        &["--dt", "-0.1"],
        "--dt: -0.1 s: must be a positive finite time",
    );
    fails(&["--dt", "nan"], "--dt: NaN s");
    fails(&["--duration", "0"], "--duration: 0 s: must be a positive");
    fails(&["--duration", "-inf"], "--duration: -inf s");
    fails(
        &["--duration", "10", "--dt", "1e-6"],
        "--dt: 1e-6 s over --duration 10 s makes 10000001 rows; at most 1000000",
    );
    // A directory that does not exist.
    let missing = scratch_dir().join("no/such/dir/top.csv");
    let run = run_case(&CASES[0], &["--csv", missing.to_str().unwrap()]);
    let line = run.error_line(1);
    assert!(line.contains("cannot create output file"), "{line}");
    assert!(line.contains("no/such/dir/top.csv"), "{line}");
    // The same file for both outputs.
    let run = run_case(&CASES[0], &["--csv", "x.svg", "--plot", "x.svg"]);
    assert!(run.error_line(1).starts_with("kreisel: error: --csv: "));
    // --dt without --csv is a usage error.
    let run = run_case(&CASES[0], &["--dt", "0.1"]);
    assert_eq!(run.code, Some(2), "{}", run.stderr);
}

#[test]
fn an_existing_file_is_kept_after_an_error() {
    let path = scratch_dir().join("kept.csv");
    std::fs::write(&path, "old\n").unwrap();
    let run = run_case(&CASES[0], &["--csv", path.to_str().unwrap(), "--dt", "-1"]);
    run.error_line(1);
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "old\n");
}

#[test]
fn a_steady_precession_covers_one_precession_turn() {
    // The slow steady precession at θ = 0.5 with spin ω₃ = 20 (the
    // library's rates; ψ̇ = ω₃ − φ̇ cos θ).
    let top = kreisel_dynamics::LagrangeTop::new(1.0, 0.5, 1.0);
    let slow = top.steady_precession_rates(20.0, 0.5).unwrap().slow;
    let c = [1.0, 0.5, 1.0, 0.5, 0.0, slow, 20.0 - slow * 0.5f64.cos()];
    let rows = csv_rows(&c, "steady.csv", &[]);
    assert_eq!(rows.len(), 601);
    let turn = std::f64::consts::TAU / slow;
    assert_eq!(rows[600][0], turn);
    for row in &rows {
        // θ stays, φ turns uniformly.
        assert!((row[1] - 0.5).abs() < 1e-12, "{row:?}");
        assert!((row[2] - slow * row[0]).abs() < 1e-12, "{row:?}");
    }
    assert!((rows[600][2] - std::f64::consts::TAU).abs() < 1e-12);
}

#[test]
fn a_sleeping_top_covers_one_turn_of_its_spin() {
    let c = [1.0, 0.5, 1.0, 0.0, 0.0, 0.0, 10.0];
    let rows = csv_rows(&c, "sleeping.csv", &[]);
    let turn = std::f64::consts::TAU / 10.0;
    assert_eq!(rows.len(), 601);
    assert_eq!(rows[600][0], turn);
    for row in &rows {
        // Upright, spinning uniformly: q = (cos ψ/2, 0, 0, sin ψ/2), ψ = 10 t.
        assert_eq!(row[1], 0.0);
        let psi = 10.0 * row[0];
        let expected = [(0.5 * psi).cos(), 0.0, 0.0, (0.5 * psi).sin()];
        for (a, b) in row[7..].iter().zip(expected) {
            assert!((a - b).abs() < 1e-14, "{row:?}");
        }
    }
}

/// The 60-digit reference of `tests/data/heavy_top/lagrange_slow.csv`
/// (mpmath Taylor series, `tests/data/gen/heavy_top.py`): a slow top with
/// loops, mass 0.5 kg, I about the centre of mass (0.002, 0.002, 0.003), the
/// centre of mass 0.08 m above the pivot on the symmetry axis z, released
/// at q₀ = Rx(π/4) with ω₀ = (1.5, 0, 40) rad/s in body axes, i.e.
/// θ₀ = π/4, θ̇₀ = 1.5, φ̇₀ = 0, ψ̇₀ = 40; I₁ about the pivot
/// 0.002 + 0.5 · 0.08² = 0.0052, Mgl = 0.5 · 9.81 · 0.08 = 0.3924.
#[test]
fn agrees_with_the_60_digit_reference_of_a_slow_top() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/data/heavy_top/lagrange_slow.csv");
    let text = std::fs::read_to_string(&path).unwrap();
    let reference: Vec<(f64, DQuat)> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with('t'))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            (v[0], DQuat::from_xyzw(v[2], v[3], v[4], v[1]))
        })
        .collect();
    let c = [
        0.0052,
        0.003,
        0.3924,
        std::f64::consts::FRAC_PI_4,
        1.5,
        0.0,
        40.0,
    ];
    let rows = csv_rows(&c, "reference.csv", &["--duration", "10", "--dt", "0.05"]);
    assert_eq!(rows.len(), reference.len());
    let mut worst: f64 = 0.0;
    for (row, (t, q)) in rows.iter().zip(&reference) {
        assert!((row[0] - t).abs() < 1e-12, "{} vs {t}", row[0]);
        let ours = DQuat::from_xyzw(row[8], row[9], row[10], row[7]);
        worst = worst.max(angle(ours, *q));
    }
    eprintln!("top --csv vs the 60-digit reference over 10 s: {worst:.2e} rad");
    assert!(worst < 1e-12, "{worst:e}");
}
