//! The exact solution (`ExactSolution`, method `exact`) against the
//! high-precision reference trajectories (`tests/data/free_body/*.csv`,
//! mpmath Taylor series at 60 digits, made by
//! `python3 tests/data/gen/free_body.py`): at every sample of every
//! scenario, at any step size, and over long horizons.

mod common;

use common::free_body::load;

use kreisel_dynamics::{ExactSolution, FreeBodyMethod, PrincipalState, integrate};
use kreisel_kinematics::rotation_angle_between;

const SCENARIOS: [&str; 9] = [
    "rapier",
    "separatrix",
    "hlw",
    "near_separatrix_7",
    "near_separatrix_12",
    "ratio_1000",
    "ratio_1000b",
    "symmetric",
    "sphere",
];

/// Evaluated directly at every reference sample (t up to 100 s): attitude
/// and L to ≤ 1e-13 (the goal for the exact solver).
#[test]
fn exact_solution_matches_every_reference_sample() {
    for name in SCENARIOS {
        let r = load(name);
        let (_, q0, l0) = r.samples[0];
        let exact = ExactSolution::try_new(
            r.moments,
            PrincipalState {
                world_from_principal: q0,
                l_principal: l0,
            },
        )
        .unwrap();
        let (mut worst_q, mut worst_l) = (0.0f64, 0.0f64);
        for &(t, q, l) in &r.samples {
            let s = exact.state_at(t);
            worst_q = worst_q.max(rotation_angle_between(s.world_from_principal, q));
            worst_l = worst_l.max((s.l_principal - l).length() / l.length());
        }
        eprintln!(
            "{name:>18}: t ≤ {:>5}: attitude {worst_q:.2e} rad, L {worst_l:.2e} (pieces {})",
            r.samples.last().unwrap().0,
            exact.table_pieces()
        );
        assert!(
            worst_q <= 1e-13 && worst_l <= 1e-13,
            "{name}: {worst_q:e} {worst_l:e}"
        );
    }
}

/// The `exact` method stepped with any step size lands on the reference.
#[test]
fn exact_method_at_any_step() {
    let exact = FreeBodyMethod::Exact.integrator();
    for name in SCENARIOS {
        let r = load(name);
        let (_, q0, l0) = r.samples[0];
        let (t, q, _) = *r.samples.iter().rfind(|s| s.0 <= 20.0).unwrap();
        for h in [1e-3, 0.01, 1.0 / 60.0, 0.1, 0.5, 2.0] {
            let steps = (t / h).round() as usize;
            if (steps as f64 * h - t).abs() > 1e-9 {
                continue;
            }
            let mut s = PrincipalState {
                world_from_principal: q0,
                l_principal: l0,
            };
            integrate(exact, r.moments, &mut s, h, steps).unwrap();
            let e = rotation_angle_between(s.world_from_principal, q);
            assert!(e <= 1e-13, "{name} h = {h}: {e:e}");
        }
    }
}

/// Relabelling the principal axes (a rotation `P` of the body frame, so the
/// moments come in another order) gives the same motion: the rapier
/// scenario with its moments in every order, cyclic and anticyclic,
/// against the reference transformed by `P`. This exercises the choice of
/// the circulation axis and the signs of the amplitudes.
#[test]
fn every_ordering_of_the_moments() {
    use kreisel_kinematics::glam::{DMat3, DQuat, DVec3};
    let r = load("rapier");
    let (_, q0, l0) = r.samples[0];
    // Columns: new principal axis k expressed in the old frame.
    let relabellings = [
        DMat3::from_cols(DVec3::Y, DVec3::Z, DVec3::X),
        DMat3::from_cols(DVec3::Z, DVec3::X, DVec3::Y),
        DMat3::from_cols(DVec3::Y, DVec3::X, DVec3::NEG_Z),
        DMat3::from_cols(DVec3::X, DVec3::NEG_Z, DVec3::Y),
        DMat3::from_cols(DVec3::NEG_Z, DVec3::Y, DVec3::X),
    ];
    for p in relabellings {
        let q_p = DQuat::from_mat3(&p);
        let moments = DVec3::new(
            p.x_axis.dot(r.moments * p.x_axis),
            p.y_axis.dot(r.moments * p.y_axis),
            p.z_axis.dot(r.moments * p.z_axis),
        );
        let exact = ExactSolution::try_new(
            moments,
            PrincipalState {
                world_from_principal: q0 * q_p,
                l_principal: p.transpose() * l0,
            },
        )
        .unwrap();
        let mut worst = 0.0f64;
        for &(t, q, l) in r.samples.iter().filter(|s| s.0 <= 50.0) {
            let s = exact.state_at(t);
            worst = worst.max(rotation_angle_between(s.world_from_principal, q * q_p));
            worst = worst.max((p * s.l_principal - l).length() / l.length());
        }
        eprintln!("moments {moments}: worst {worst:.2e}");
        assert!(worst < 1e-13, "moments {moments}: {worst:e}");
    }
}
