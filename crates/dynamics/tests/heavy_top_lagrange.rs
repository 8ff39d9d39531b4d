//! The two independent ways kreisel has to move a Lagrange top must agree:
//! the closed form (`LagrangeTop`, Jacobi sn and Π) and the 3-D heavy-top
//! integrators (`HeavyTop`, splitting into the free flow and the gravity
//! kick) to ≤ 1e-10 rad at every reference time, on every Lagrange-top
//! scenario of `tests/data/lagrange_top/` and on the symmetric tops of
//! `tests/data/heavy_top/` (which the closed form must also match against
//! the 60-digit references).

mod common;

use std::path::Path;

use glam::{DQuat, DVec3};
use kreisel_dynamics::{
    HeavyTop, HeavyTopClosedForm, HeavyTopIntegrator, HeavyTopMethod, LagrangeTop,
    LagrangeTopInitial, LagrangeTopMotion, PrincipalState,
};
use kreisel_kinematics::{EulerSequence, rotation_angle_between};

/// The largest angle between the closed form and `method` over `times`
/// (step h ≈ 1e-3 s, ending exactly on every time); the closed form's
/// body frame is `state`'s principal frame times `principal_from_top`.
fn compare(
    motion: &LagrangeTopMotion,
    top: &HeavyTop,
    start: PrincipalState,
    principal_from_top: DQuat,
    times: &[f64],
    method: &dyn HeavyTopIntegrator,
) -> f64 {
    let mut s = start;
    let mut worst: f64 = 0.0;
    let mut t = times[0];
    for &next in &times[1..] {
        let n = ((next - t) / 1e-3).round().max(1.0) as usize;
        for _ in 0..n {
            method.step(top, &mut s, (next - t) / n as f64);
        }
        t = next;
        let closed = motion.world_from_body_at(t) * principal_from_top.conjugate();
        worst = worst.max(rotation_angle_between(s.world_from_principal, closed));
    }
    worst
}

/// `# key = (a, b, …)` of a reference file.
fn numbers(text: &str, key: &str) -> Vec<f64> {
    let line = text
        .lines()
        .find_map(|l| l.strip_prefix(&format!("# {key} = ")))
        .unwrap_or_else(|| panic!("no `{key}`"));
    line.trim_matches(|c| c == '(' || c == ')')
        .split(',')
        .map(|x| x.trim().parse().unwrap())
        .collect()
}

#[test]
fn closed_form_and_splitting_agree_on_the_lagrange_scenarios() {
    let zxz: EulerSequence = "ZXZ".parse().unwrap();
    let auto = HeavyTopMethod::Auto.integrator();
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/lagrange_top");
    let mut names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        // fast_tops.csv and fast_top_angles.csv hold the fast tops' roots,
        // rates and a few angles, no trajectory.
        .filter(|p| {
            p.file_name()
                .is_some_and(|n| !n.to_string_lossy().starts_with("fast_top"))
        })
        .collect();
    names.sort();
    assert!(names.len() >= 9);
    for path in names {
        let text = std::fs::read_to_string(&path).unwrap();
        let [i1, i3, mgl] = numbers(&text, "top")[..] else {
            panic!()
        };
        let v = numbers(&text, "initial");
        let initial = LagrangeTopInitial {
            phi: v[0],
            theta: v[1],
            psi: v[2],
            phi_dot: v[3],
            theta_dot: v[4],
            psi_dot: v[5],
        };
        let motion = LagrangeTop::new(i1, i3, mgl).try_solve(initial).unwrap();
        // The same top in 3-D: J = (I₁, I₁, I₃), unit mass with the centre
        // of mass 1 m up the axis, and a "gravity" of Mgl.
        let top = HeavyTop::try_from_principal(
            DVec3::new(i1, i1, i3),
            DVec3::Z,
            1.0,
            DVec3::new(0.0, 0.0, -mgl),
        )
        .unwrap();
        let angles = DVec3::new(v[0], v[1], v[2]);
        let omega_body = zxz.rate_matrix_body(angles) * DVec3::new(v[3], v[4], v[5]);
        let start =
            PrincipalState::try_from_omega_body(top.body(), zxz.to_quat(angles), omega_body)
                .unwrap();
        let times: Vec<f64> = text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.starts_with('t'))
            .map(|l| l.split(',').next().unwrap().parse().unwrap())
            .collect();
        let err = compare(&motion, &top, start, DQuat::IDENTITY, &times, auto);
        let name = path.file_stem().unwrap().to_string_lossy();
        println!(
            "{name:>20}: closed form vs auto (dt ≈ 1e-3, {} s): {err:.2e} rad",
            times.last().unwrap()
        );
        assert!(err < 1e-10, "{name}: {err:e}");
    }
}

#[test]
fn closed_form_matches_the_symmetric_heavy_top_references() {
    let zxz: EulerSequence = "ZXZ".parse().unwrap();
    let auto = HeavyTopMethod::Auto.integrator();
    for name in ["bruls", "lagrange_slow"] {
        let r = common::heavy_top::load(name);
        let k = r.top.symmetry_axis().expect("a Lagrange top");
        // Top axes (e₃ = symmetry axis) from principal axes by a cyclic permutation.
        let principal_from_top = match k {
            0 => DQuat::from_mat3(&glam::DMat3::from_cols(DVec3::Y, DVec3::Z, DVec3::X)),
            1 => DQuat::from_mat3(&glam::DMat3::from_cols(DVec3::Z, DVec3::X, DVec3::Y)),
            _ => DQuat::IDENTITY,
        };
        let moments = r.top.body().principal_moments();
        let c = r.top.com_principal()[k];
        let mgl = r.top.weight_world().length() * c;
        let lagrange = LagrangeTop::new(moments[(k + 1) % 3], moments[k], mgl);
        let world_from_top = r.start.world_from_principal * principal_from_top;
        let found = zxz.from_quat(world_from_top);
        let omega_top = principal_from_top.conjugate() * (r.start.l_principal / moments);
        let rates = zxz.rates_from_omega_body(found.angles, omega_top).unwrap();
        let a = found.angles;
        let motion = lagrange
            .try_solve(LagrangeTopInitial {
                phi: a.x,
                theta: a.y,
                psi: a.z,
                phi_dot: rates.x,
                theta_dot: rates.y,
                psi_dot: rates.z,
            })
            .unwrap();
        let times: Vec<f64> = r.samples.iter().map(|s| s.0).collect();
        let err = compare(&motion, &r.top, r.start, principal_from_top, &times, auto);
        let mut to_reference: f64 = 0.0;
        for (k, &(t, _, _)) in r.samples.iter().enumerate() {
            let closed = PrincipalState {
                world_from_principal: motion.world_from_body_at(t) * principal_from_top.conjugate(),
                l_principal: DVec3::ZERO,
            };
            to_reference = to_reference.max(r.attitude_error(&closed, k));
        }
        println!(
            "{name:>14}: closed form vs auto {err:.2e} rad, vs the 60-digit reference {to_reference:.2e} rad"
        );
        assert!(err < 1e-10, "{name}: {err:e}");
        assert!(to_reference < 1e-10, "{name}: {to_reference:e}");
    }
}

/// `HeavyTopClosedForm`, built from the 3-D top and state alone, against
/// the 60-digit references of the symmetric heavy tops: attitude and
/// angular momentum at every sample; and it refuses the asymmetric tops.
#[test]
fn heavy_top_closed_form_matches_the_references() {
    for name in ["bruls", "lagrange_slow"] {
        let r = common::heavy_top::load(name);
        let closed = HeavyTopClosedForm::try_new(&r.top, r.start).unwrap();
        let (mut attitude, mut momentum): (f64, f64) = (0.0, 0.0);
        let principal_from_body = r.top.body().body_from_principal().conjugate();
        for (k, &(t, _, l_body)) in r.samples.iter().enumerate() {
            let s = closed.state_at(t);
            attitude = attitude.max(r.attitude_error(&s, k));
            let l_ref = principal_from_body * l_body;
            momentum = momentum.max((s.l_principal - l_ref).length() / l_ref.length());
        }
        println!(
            "{name:>14}: HeavyTopClosedForm vs the 60-digit reference: {attitude:.2e} rad, L {momentum:.2e} (relative)"
        );
        assert!(attitude < 1e-12, "{name}: {attitude:e}");
        assert!(momentum < 1e-12, "{name}: {momentum:e}");
    }
    for name in ["asymmetric_fast", "tumbling"] {
        let r = common::heavy_top::load(name);
        let e = HeavyTopClosedForm::try_new(&r.top, r.start).unwrap_err();
        assert!(e.to_string().contains("Lagrange top"), "{name}: {e}");
    }
}

/// `HeavyTopClosedForm` against splitting8 at a small step (an
/// independent method) where the conversion has special cases: gravity
/// not along −z, the centre of mass below the pivot, the symmetry axis on
/// principal x, and a start exactly upright (θ = 0, a pole of the Euler
/// angles) with the axis thrown sideways.
#[test]
fn heavy_top_closed_form_special_starts() {
    let g = DVec3::new(1.0, -2.0, -9.5);
    let tops = [
        (DVec3::new(0.01, 0.02, 0.02), DVec3::new(0.1, 0.0, 0.0), g),
        (DVec3::new(0.02, 0.02, 0.01), DVec3::new(0.0, 0.0, -0.1), g),
        (
            DVec3::new(0.02, 0.02, 0.01),
            DVec3::new(0.0, 0.0, 0.1),
            DVec3::new(0.0, 0.0, -9.81),
        ),
    ];
    let starts = [
        (DQuat::from_rotation_y(0.7), DVec3::new(0.3, -0.2, 25.0)),
        (DQuat::IDENTITY, DVec3::new(1.5, -0.5, 40.0)),
        (DQuat::from_rotation_z(2.0), DVec3::new(0.0, 0.0, 40.0)),
    ];
    let splitting8 = HeavyTopMethod::Splitting8.integrator();
    for (moments, com, gravity) in tops {
        let top = HeavyTop::try_from_principal(moments, com, 1.0, gravity).unwrap();
        let k = top.symmetry_axis().unwrap();
        for (q, omega) in starts {
            // The spin of the start along the symmetry axis; the upright
            // starts put the axis along the vertical (θ = 0 or π).
            let spin_axis = DQuat::from_rotation_arc(DVec3::Z, DVec3::AXES[k]);
            let up = -gravity.normalize();
            let q = if q == DQuat::IDENTITY {
                DQuat::from_rotation_arc(DVec3::AXES[k], up)
            } else {
                q
            };
            let start =
                PrincipalState::try_from_omega_body(top.body(), q, spin_axis * omega).unwrap();
            let closed = HeavyTopClosedForm::try_new(&top, start).unwrap();
            let mut s = start;
            let mut worst: f64 = 0.0;
            for n in 1..=1000 {
                splitting8.step(&top, &mut s, 1e-3);
                if n % 100 == 0 {
                    let c = closed.state_at(n as f64 * 1e-3);
                    worst = worst.max(rotation_angle_between(
                        s.world_from_principal,
                        c.world_from_principal,
                    ));
                    worst = worst
                        .max((s.l_principal - c.l_principal).length() / s.l_principal.length());
                }
            }
            println!("k = {k}, q0 = {q:?}: closed form vs splitting8 over 1 s: {worst:.2e}");
            assert!(worst < 1e-10, "k = {k}, q0 = {q:?}: {worst:e}");
        }
    }
}

/// Through the World: under `auto` a Lagrange top is planned as its closed
/// form, evaluated at the times asked: within 2e-13 rad of the 60-digit
/// references at every sample, bit-identical on one and on two threads.
#[test]
fn the_world_moves_lagrange_tops_by_their_closed_form() {
    use kreisel_dynamics::{Plan, World};
    for name in ["bruls", "lagrange_slow"] {
        let r = common::heavy_top::load(name);
        let mut runs = Vec::new();
        for threads in [1, 2] {
            let mut world = World::try_new(r.gravity, 1e-3).unwrap();
            world.set_threads(std::num::NonZeroUsize::new(threads).unwrap());
            let ids: Vec<_> = (0..4).map(|_| world.add(r.world_body()).unwrap()).collect();
            assert_eq!(world.plan(ids[0]), Some(&Plan::LagrangeTop));
            let mut worst: f64 = 0.0;
            let mut states = Vec::new();
            for &(t, q, _) in &r.samples[1..] {
                world.advance_to(t).unwrap();
                for &id in &ids {
                    let s = world.state(id).unwrap();
                    worst = worst.max(kreisel_kinematics::rotation_angle_between(
                        s.world_from_body,
                        q,
                    ));
                    states.push(s);
                }
            }
            println!("{name}: World closed form {worst:.2e} rad on {threads} thread(s)");
            assert!(worst <= 2e-13, "{name}: {worst:e}");
            runs.push(states);
        }
        assert_eq!(runs[0], runs[1]);
    }
}
