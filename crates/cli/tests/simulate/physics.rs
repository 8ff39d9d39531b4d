//! The physics against closed forms: uniform spin of a sphere and about a
//! principal axis, conserved energy and angular momentum, the Dzhanibekov
//! flips against the reference period, mesh bodies, and gravity.

use glam::{DQuat, DVec3};

use crate::support::{
    Row, body, max_relative_drift, quat_diff, scratch_dir, simulate, simulation, workspace,
};

/// The Dzhanibekov scene of the task: I = (1, 2, 3), ω = (0.01, 1, 0).
fn dzhanibekov(method: &str) -> Vec<Row> {
    let scene = simulation(100.0, 0.01, "") + &body([1.0, 2.0, 3.0], [0.01, 1.0, 0.0], "");
    simulate("dzhanibekov.toml", &scene, &["--method", method]).rows()
}

#[test]
fn sphere_spins_uniformly() {
    let omega = DVec3::new(0.3, -0.5, 1.1);
    let q0 = DQuat::from_xyzw(0.1, -0.2, 0.3, 0.9).normalize();
    let orientation = format!(
        "orientation = [{:?}, {:?}, {:?}, {:?}]",
        q0.w, q0.x, q0.y, q0.z
    );
    let scene = simulation(2.0, 0.01, "") + &body([2.0, 2.0, 2.0], omega.to_array(), &orientation);
    // The exact-rotation splittings are exact for a sphere (strang, rotating
    // about the three axes in turn, is not).
    for method in ["auto", "splitting", "splitting4"] {
        let rows = simulate("sphere.toml", &scene, &["--method", method]).rows();
        assert_eq!(rows.len(), 201);
        let mut worst: f64 = 0.0;
        for row in &rows {
            // q(t) = q0 ⊗ exp(ω t), ω fixed in the body.
            let exact = q0 * DQuat::from_scaled_axis(omega * row.t);
            worst = worst.max(quat_diff(row.q, exact));
            assert!((row.omega - omega).length() < 1e-15, "{method}: {row:?}");
        }
        eprintln!("sphere, {method}: max |q - q0 exp(w t)| = {worst:.2e}");
        assert!(worst < 1e-13, "{method}: {worst:e}");
    }
}

#[test]
fn spin_about_a_principal_axis_stays_on_it() {
    for axis in 0..3 {
        let mut omega = [0.0; 3];
        omega[axis] = 2.0;
        let scene = simulation(5.0, 0.01, "") + &body([1.0, 2.0, 3.0], omega, "");
        let rows = simulate("principal_axis.toml", &scene, &[]).rows();
        let mut worst: f64 = 0.0;
        for row in &rows {
            // Exactly on the axis (even the unstable middle one).
            assert_eq!(row.omega, DVec3::from_array(omega), "axis {axis}: {row:?}");
            let exact = DQuat::from_scaled_axis(DVec3::from_array(omega) * row.t);
            worst = worst.max(quat_diff(row.q, exact));
        }
        eprintln!("principal axis {axis}: max |q - exp(w t)| = {worst:.2e}");
        // Exact but for the rounding of 500 steps × 17 stages of rotations.
        assert!(worst < 1e-12, "axis {axis}: {worst:e}");
    }
}

#[test]
fn splittings_conserve_energy_and_angular_momentum() {
    // The compositions keep the energy to rounding; every splitting keeps
    // L_world (each piece is an exact rotation).
    for (method, energy_too) in [
        ("auto", true),
        ("splitting6", true),
        ("splitting", false),
        ("strang", false),
    ] {
        let rows = dzhanibekov(method);
        let l0 = rows[0].l;
        let drift_l = rows
            .iter()
            .map(|r| (r.l - l0).length() / l0.length())
            .fold(0.0, f64::max);
        let drift_norm = max_relative_drift(rows.iter().map(|r| r.l.length()));
        let drift_e = max_relative_drift(rows.iter().map(|r| r.energy));
        eprintln!(
            "{method:>10}: energy {drift_e:.2e}, |L_world| {drift_norm:.2e}, L_world {drift_l:.2e}"
        );
        assert!(drift_l < 1e-12 && drift_norm < 1e-12, "{method}");
        if energy_too {
            assert!(drift_e < 1e-12, "{method}: {drift_e:e}");
        }
    }
}

#[test]
fn rk4_works_and_differs_slightly() {
    let rk4 = dzhanibekov("rk4");
    let auto = dzhanibekov("auto");
    assert_eq!(rk4.len(), auto.len());
    let worst = rk4
        .iter()
        .zip(&auto)
        .map(|(a, b)| quat_diff(a.q, b.q))
        .fold(0.0, f64::max);
    eprintln!("rk4 vs auto over 100 s: max |dq| = {worst:.2e}");
    assert!(worst > 1e-12 && worst < 1e-5, "{worst:e}");
    // Not geometric: the energy drifts, but slightly.
    let drift = max_relative_drift(rk4.iter().map(|r| r.energy));
    assert!(drift > 1e-14 && drift < 1e-9, "{drift:e}");
}

/// `(period of ω, time between flips)` of the `rapier` reference scenario
/// (the same I and ω₀), from `tests/data/free_body/periods.csv` when present.
fn reference_periods() -> Option<(f64, f64)> {
    let text = std::fs::read_to_string(workspace("tests/data/free_body/periods.csv")).ok()?;
    let line = text.lines().find(|l| l.starts_with("rapier,"))?;
    let fields: Vec<f64> = line
        .split(',')
        .skip(1)
        .map(|f| f.parse().unwrap())
        .collect();
    Some((fields[0], fields[1]))
}

#[test]
fn dzhanibekov_flips_at_the_reference_period() {
    let rows = dzhanibekov("auto");
    // Sign changes of ω_y, located by linear interpolation between steps.
    let flips: Vec<f64> = rows
        .windows(2)
        .filter(|p| (p[0].omega.y > 0.0) != (p[1].omega.y > 0.0))
        .map(|p| {
            let (a, b) = (p[0].omega.y, p[1].omega.y);
            p[0].t + (p[1].t - p[0].t) * a / (a - b)
        })
        .collect();
    let between: Vec<f64> = flips.windows(2).map(|w| w[1] - w[0]).collect();
    let period: Vec<f64> = flips.windows(3).map(|w| w[2] - w[0]).collect();
    eprintln!("flips at {flips:?}\n  intervals {between:?}\n  periods {period:?}");
    assert_eq!(flips.len(), 5, "{flips:?}");
    match reference_periods() {
        Some((period_omega, half)) => {
            for d in &between {
                assert!((d - half).abs() < 1e-6, "{d} vs {half}");
            }
            for p in &period {
                assert!((p - period_omega).abs() < 1e-6, "{p} vs {period_omega}");
            }
        }
        None => {
            for p in &period {
                assert!((p - 41.509).abs() < 0.01, "{p}");
            }
        }
    }
}

#[test]
fn mesh_body_conserves_energy() {
    // A copy of the T-handle next to the scene, named relative to it.
    let dir = scratch_dir().join("mesh_scene");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::copy(workspace("assets/t_handle.obj"), dir.join("t_handle.obj")).unwrap();
    let absolute = workspace("assets/t_handle.obj");
    let absolute = absolute.to_str().unwrap();
    // Spin near the mesh's z axis, the intermediate (unstable) one.
    let omega = [0.01, 0.0, 5.0];
    for (file, mesh) in [
        ("relative.toml", "t_handle.obj"),
        ("absolute.toml", absolute),
    ] {
        let scene = simulation(20.0, 0.001, "output_interval = 0.01")
            + &format!(
                "[[body]]\nmesh = {mesh:?}\ndensity = 1000.0\nangular_velocity = {omega:?}\n"
            );
        let path = dir.join(file);
        std::fs::write(&path, scene).unwrap();
        let rows = crate::support::simulate_file(&path, &[]).rows();
        assert_eq!(rows.len(), 2001);
        // Body axes are the mesh axes, which are principal: the README's moments.
        let moments = DVec3::new(4.71052e-06, 1.07163e-05, 6.36557e-06);
        let expect = 0.5 * (moments * DVec3::from_array(omega).powf(2.0)).element_sum();
        assert!((rows[0].energy - expect).abs() < 1e-5 * expect, "{rows:?}");
        assert!((rows[0].omega - DVec3::from_array(omega)).length() < 1e-12);
        let drift = max_relative_drift(rows.iter().map(|r| r.energy));
        let flips = rows
            .windows(2)
            .filter(|p| (p[0].omega.z > 0.0) != (p[1].omega.z > 0.0))
            .count();
        eprintln!("mesh ({file}): energy drift {drift:.2e}, {flips} flips of w_z");
        assert!(drift < 1e-12, "{drift:e}");
        assert!(flips >= 1, "the T-handle should flip about its middle axis");
    }
}

#[test]
fn gravity_moves_the_centre_of_mass_and_keeps_the_energy() {
    let motion = "position = [1.0, 2.0, 10.0]\nvelocity = [3.0, -1.0, 20.0]";
    let spin = body([1.0, 2.0, 3.0], [0.01, 1.0, 0.0], motion);
    let with = simulation(
        20.0,
        0.01,
        "gravity = [0.0, 0.0, -9.81]\noutput_interval = 0.5",
    );
    let rows = simulate("gravity.toml", &(with + &spin), &[]).rows();
    // E = rotational + m |v|²/2 − m g·x at t = 0.
    let expect = 1.00005 + 0.5 * (9.0 + 1.0 + 400.0) + 9.81 * 10.0;
    assert!(
        (rows[0].energy - expect).abs() < 1e-13 * expect,
        "{}",
        rows[0].energy
    );
    let drift = max_relative_drift(rows.iter().map(|r| r.energy));
    eprintln!("gravity: energy drift {drift:.2e} over 20 s");
    assert!(drift < 1e-12, "{drift:e}");
    // Gravity exerts no torque: the rotation is that of the free body.
    let without = simulation(20.0, 0.01, "output_interval = 0.5");
    let free = simulate("no_gravity.toml", &(without + &spin), &[]).rows();
    for (a, b) in rows.iter().zip(&free) {
        assert_eq!((a.q, a.omega, a.l), (b.q, b.omega, b.l));
    }
    // Without gravity the energy is rotational plus translational.
    let expect = 1.00005 + 0.5 * 410.0;
    assert!((free[0].energy - expect).abs() < 1e-13 * expect);
}
