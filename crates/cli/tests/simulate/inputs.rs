//! Applied inputs (`torque`, `torque_body`, `force`, `angular_damping`)
//! against closed forms, their one-line errors, and `--columns`.

use glam::{DQuat, DVec3};

use crate::support::{
    HEADER, body, quat_diff, scratch, simulate, simulate_file, simulation, workspace,
};

/// The rows of a `--columns` CSV: the header's names and the numbers.
fn columns(stdout: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = stdout.lines();
    let header = lines.next().expect("header");
    let names = header.split(',').map(str::to_owned).collect();
    let rows = lines
        .map(|line| {
            line.split(',')
                .map(|x| x.parse().expect("a number"))
                .collect()
        })
        .collect();
    (names, rows)
}

#[test]
fn a_sphere_spun_up_about_its_axis_follows_the_closed_form() {
    // I = 0.5, ω₀ = 1 about n, τ = 0.3 n (world axes = body axes at t = 0):
    // L(t) = (I ω₀ + τ t) n,  q(t) = exp(θ n),  θ = ω₀ t + τ t²/(2I),
    // energy ½|L|²/I, so ΔE = ω₀ τ t + τ² t²/(2I) = ∫ τ·ω dt.
    let (inertia, omega0, tau) = (0.5, 1.0, 0.3);
    let n = DVec3::new(1.0, 2.0, 2.0) / 3.0;
    let extra = format!("torque = {:?}", (tau * n).to_array());
    let scene = simulation(10.0, 0.01, "output_interval = 0.5")
        + &body([inertia; 3], (omega0 * n).to_array(), &extra);
    let run = simulate("sphere_torque.toml", &scene, &[]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let rows = run.rows();
    assert_eq!(rows.len(), 21);
    let (mut angle, mut l_error, mut energy_error) = (0.0f64, 0.0f64, 0.0f64);
    let e0 = 0.5 * inertia * omega0 * omega0;
    for row in &rows {
        let t = row.t;
        let theta = omega0 * t + tau * t * t / (2.0 * inertia);
        let l = (inertia * omega0 + tau * t) * n;
        angle = angle.max(quat_diff(row.q, DQuat::from_axis_angle(n, theta)));
        l_error = l_error.max((row.l - l).length() / l.length());
        let work = omega0 * tau * t + tau * tau * t * t / (2.0 * inertia);
        energy_error = energy_error.max(((row.energy - e0) - work).abs() / (e0 + work));
        assert!((row.omega - l / inertia).length() < 1e-12 * l.length() / inertia);
    }
    println!(
        "simulate, sphere under torque ∥ L over 10 s (θ = 40 rad): \
         attitude {angle:.1e} rad, |ΔL|/|L| {l_error:.1e}, ΔE − W {energy_error:.1e} (relative)"
    );
    assert!(angle < 1e-12, "attitude {angle:.2e} rad");
    assert!(l_error < 1e-12, "L {l_error:.2e}");
    assert!(energy_error < 1e-12, "energy {energy_error:.2e}");
}

#[test]
fn a_damped_wheel_spins_up_as_the_closed_form() {
    // examples/scenes/spin_up.toml: I₃ = 0.02, τ = 0.1 N m (body axes),
    // c = 0.01 N m s: ω_z = (τ/c)(1 − e^{−c t/I₃}), energy ½ I₃ ω_z².
    let path = workspace("examples/scenes/spin_up.toml");
    let run = simulate_file(&path, &["--columns", "t,wz,lz,energy,qz"]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let (names, rows) = columns(&run.stdout);
    assert_eq!(names, ["t", "wz", "lz", "energy", "qz"]);
    assert_eq!(rows.len(), 11);
    let (i3, tau, c) = (0.02, 0.1, 0.01);
    let mut worst = 0.0f64;
    for row in &rows[1..] {
        let t = row[0];
        let omega = tau / c * (1.0 - (-c * t / i3).exp());
        // θ = ∫ω dt = (τ/c)(t − (I₃/c)(1 − e^{−c t/I₃})), about z.
        let theta = tau / c * (t - i3 / c * (1.0 - (-c * t / i3).exp()));
        worst = worst.max((row[1] - omega).abs() / omega);
        assert!((row[2] - i3 * omega).abs() < 1e-12 * i3 * omega, "t = {t}");
        let energy = 0.5 * i3 * omega * omega;
        assert!((row[3] - energy).abs() < 1e-12 * energy, "t = {t}");
        // qz = ± sin(θ/2): the attitude is continuous, its sign not fixed.
        assert!(
            (row[4].abs() - (theta / 2.0).sin().abs()).abs() < 1e-12,
            "t = {t}: qz {} θ {theta}",
            row[4]
        );
    }
    println!("simulate, damped wheel: ω_z relative error {worst:.1e}");
    assert!(worst < 1e-12, "{worst:.2e}");
}

#[test]
fn a_force_moves_the_centre_of_mass() {
    // m = 1, F = (2, 0, 0) N, g = (0, 0, −9.81): x = x₀ + v₀ t + (g + F/m) t²/2.
    let scene = simulation(2.0, 0.01, "output_interval = 0.5\ngravity = [0, 0, -9.81]")
        + &body(
            [1.0, 2.0, 3.0],
            [0.01, 1.0, 0.0],
            "position = [1, 2, 3]\nvelocity = [0, 1, 5]\nforce = [2, 0, 0]",
        );
    let run = simulate(
        "force.toml",
        &scene,
        &["--columns", "t,x,y,z,vx,vy,vz,lx,ly,lz"],
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let (_, rows) = columns(&run.stdout);
    assert_eq!(rows.len(), 5);
    let l0 = DVec3::new(rows[0][7], rows[0][8], rows[0][9]);
    for row in &rows {
        let t = row[0];
        let a = DVec3::new(2.0, 0.0, -9.81);
        let x = DVec3::new(1.0, 2.0, 3.0) + DVec3::new(0.0, 1.0, 5.0) * t + a * (0.5 * t * t);
        let v = DVec3::new(0.0, 1.0, 5.0) + a * t;
        assert!((DVec3::new(row[1], row[2], row[3]) - x).length() < 1e-12 * x.length());
        assert!((DVec3::new(row[4], row[5], row[6]) - v).length() < 1e-12 * v.length());
        // A force through the centre of mass exerts no torque: L is kept.
        let l = DVec3::new(row[7], row[8], row[9]);
        assert!((l - l0).length() < 1e-13 * l0.length(), "t = {t}");
    }
}

#[test]
fn columns_choose_and_order_the_csv() {
    let scene = simulation(1.0, 0.1, "gravity = [0, 0, -10]")
        + &body([1.0, 2.0, 3.0], [0.01, 1.0, 0.0], "velocity = [1, 0, 0]");
    let plain = simulate("columns.toml", &scene, &[]);
    // The default columns, named: the same bytes.
    let named = simulate("columns.toml", &scene, &["--columns", HEADER]);
    assert_eq!(plain.stdout, named.stdout);
    assert!(plain.stdout.starts_with(&format!("{HEADER}\n")));
    let run = simulate("columns.toml", &scene, &["--columns", "z,body,t,vx"]);
    let mut lines = run.stdout.lines();
    assert_eq!(lines.next(), Some("z,body,t,vx"));
    assert_eq!(lines.last(), Some("-5,body1,1,1"));
    for (list, needle) in [
        (
            "t,speed",
            "unknown column `speed` (valid: t,body,qw,qx,qy,qz,wx,wy,wz,energy,lx,ly,lz,x,y,z,vx,vy,vz)",
        ),
        ("t,t", "column `t` is given twice"),
        ("", "unknown column ``"),
    ] {
        let run = simulate("columns.toml", &scene, &["--columns", list]);
        let line = run.error_line(1);
        assert!(
            line.starts_with(&format!("kreisel: error: --columns: {needle}")),
            "{line}"
        );
    }
}

#[test]
fn explain_names_the_torque_splitting() {
    let scene = simulation(1.0, 0.1, "")
        + &body(
            [1.0, 2.0, 3.0],
            [0.0, 1.0, 0.0],
            "name = \"driven\"\nangular_damping = 0.1",
        )
        + &body(
            [1.0, 2.0, 3.0],
            [0.0, 1.0, 0.0],
            "name = \"zero\"\ntorque = [0, 0, 0]",
        );
    let run = simulate(
        "explain_inputs.toml",
        &scene,
        &["--explain", "--method", "splitting8"],
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert!(
        lines[0].starts_with("driven: forced free body: splitting8 (order 8) every dt"),
        "{lines:?}"
    );
    // All-zero inputs: the torque-free plan of the method.
    assert!(
        lines[1].starts_with("zero: free body stepped by splitting8"),
        "{lines:?}"
    );
    let run = simulate("explain_inputs.toml", &scene, &["--explain"]);
    let zero = run.stdout.lines().nth(1).unwrap_or_default();
    assert!(
        zero.starts_with("zero: free spin about principal axis 2: exact"),
        "{zero}"
    );
}

/// A symmetric top on a pivot on its axis, spun up by a motor about that
/// axis against bearing friction while gravity makes it precess and nutate:
/// Euler's equation about the axis has no gyroscopic or gravity term, so
/// J₃ ω̇₃ = τ − c ω₃ and ω₃ = τ/c + (ω₃(0) − τ/c) e^(−c t/J₃) exactly.
#[test]
fn a_top_spun_up_by_a_motor_follows_the_closed_form() {
    let scene = simulation(4.0, 0.01, "output_interval = 0.5\ngravity = [0, 0, -9.81]")
        + &body(
            [0.02, 0.02, 0.035],
            [0.5, 0.0, 20.0],
            "name = \"top\"\npivot = [0, 0, -0.05]\norientation = [0.98, 0.15, 0.1, 0.0]\ntorque_body = [0, 0, 0.002]\nangular_damping = 0.0005",
        );
    let explain = simulate("top_motor.toml", &scene, &["--explain"]);
    assert!(
        explain
            .stdout
            .starts_with("top: driven heavy top on a pivot: splitting8 (order 8)"),
        "{}",
        explain.stdout
    );
    let run = simulate("top_motor.toml", &scene, &[]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let (tau, c, j3, w0): (f64, f64, f64, f64) = (0.002, 0.0005, 0.035, 20.0);
    let mut worst: f64 = 0.0;
    for row in run.rows() {
        let exact = tau / c + (w0 - tau / c) * (-c * row.t / j3).exp();
        worst = worst.max((row.omega.z - exact).abs() / exact);
    }
    println!("motor-driven top: omega_3 within {worst:.1e} relative");
    assert!(worst < 1e-12, "{worst:e}");
}

#[test]
fn bad_inputs_give_one_line_naming_line_and_key() {
    let sim = "[simulation]\nduration = 1.0\ndt = 0.01\n";
    let body =
        "[[body]]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\nangular_velocity = [0.01, 1.0, 0.0]\n";
    let cases: [(&str, &[&str], u32, &str); 6] = [
        (
            "torque = [0, 0, nan]\n",
            &[],
            8,
            "body `body1`: `torque` must be finite numbers",
        ),
        (
            "torque_body = [inf, 0, 0]\n",
            &[],
            8,
            "body `body1`: `torque_body` must be finite numbers",
        ),
        ("force = [1, 2]\n", &[], 8, "`body.force`: invalid length 2"),
        (
            "angular_damping = -0.5\n",
            &[],
            8,
            "body `body1`: `angular_damping` must be zero or positive and finite (N m s), got -0.5",
        ),
        (
            "pivot = [0, 0, -0.1]\nforce = [0, 0, 1]\n",
            &["--method", "rk4"],
            9,
            "body `body1`: `force`: heavy-top method `rk4` cannot move a body with applied inputs (methods that can: auto, strang, splitting4, splitting6, splitting8)",
        ),
        (
            "torque = [0, 0, 1]\n",
            &["--method", "pdmv6"],
            8,
            "body `body1`: `torque`: free-body method `pdmv6` cannot move a body with applied inputs (methods that can: auto, strang, splitting4, splitting6, splitting8)",
        ),
    ];
    for (k, (extra, args, line, message)) in cases.into_iter().enumerate() {
        let path = scratch(
            &format!("bad_input_{k}.toml"),
            format!("{sim}{body}{extra}"),
        );
        let run = simulate_file(&path, args);
        let got = run.error_line(1);
        let prefix = format!("kreisel: error: {}:{line}: {message}", path.display());
        assert!(got.starts_with(&prefix), "{got}\nexpected {prefix}");
    }
}
