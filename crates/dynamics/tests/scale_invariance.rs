//! The answer does not depend on the unit system: every method of the
//! registry, run on the same body with its moments scaled by 1e-100 …
//! 1e100 (a 1 µm sphere has I ≈ 4e-28 kg m²) and its angular velocity
//! scaled by σ with the step and the time by 1/σ, gives the attitude of the
//! unscaled run to rounding, and stays as close to the mpmath reference
//! trajectories of `tests/data/free_body/` (an independent reference) as
//! the unscaled run. Regression: DMV and PDMV froze (the body never
//! turned) for moments ≤ 1e-26 or ≥ 1e36 kg m², and the exact solution went
//! wrong beyond 1e±104.
//!
//! Also the input checks that keep the scale representable: a subnormal
//! moment, an I ω² that overflows.

use glam::{DQuat, DVec3};
use kreisel_dynamics::{DynamicsError, FreeBodyMethod, PrincipalState, RigidBody, integrate};
use kreisel_kinematics::rotation_angle_between;

#[path = "common/free_body.rs"]
mod free_body;

/// Moment scales: SI for a 1 µm grain up to planets, and the extremes the
/// checks allow for ω of order 1.
const MOMENT_SCALES: [f64; 9] = [1e-100, 1e-30, 4e-28, 1e-26, 1e-10, 1e10, 1e30, 1e36, 1e100];

/// Rate scales σ: ω → σω, h → h/σ, t → t/σ.
const RATE_SCALES: [f64; 3] = [1e-3, 1.0, 1e4];

/// The step and the end time of the runs, unscaled.
const H: f64 = 0.05;
const T_END: f64 = 5.0;

/// How far a rescaled run may stray from the unscaled one: the inputs
/// differ by one rounding (1e-16 relative) and the runs by the rounding of
/// every step after that; measured ≤ 5e-14 rad (printed with --nocapture).
const SCALE_TOLERANCE: f64 = 1e-12;

/// The attitude after `T_END/σ` seconds of steps `H/σ`, for moments and L
/// scaled by `s` and `s σ`.
fn run(
    name: FreeBodyMethod,
    r: &free_body::Reference,
    s: f64,
    sigma: f64,
) -> Result<DQuat, DynamicsError> {
    let (_, q0, l0) = r.samples[0];
    let mut state = PrincipalState {
        world_from_principal: q0,
        l_principal: l0 * (s * sigma),
    };
    let steps = (T_END / H).round() as usize;
    integrate(
        name.integrator(),
        r.moments * s,
        &mut state,
        H / sigma,
        steps,
    )?;
    Ok(state.world_from_principal)
}

#[test]
fn every_method_gives_the_same_motion_in_every_unit_system() {
    let mut worst: f64 = 0.0;
    for scenario in ["hlw", "symmetric", "sphere"] {
        let r = free_body::load(scenario);
        let (t_ref, q_ref, _) = *r
            .samples
            .iter()
            .min_by(|a, b| (a.0 - T_END).abs().total_cmp(&(b.0 - T_END).abs()))
            .unwrap();
        assert!(
            (t_ref - T_END).abs() < 1e-12,
            "{scenario}: no sample at {T_END}"
        );
        for name in FreeBodyMethod::ALL {
            let unscaled = run(name, &r, 1.0, 1.0).unwrap();
            let accuracy = rotation_angle_between(unscaled, q_ref);
            // The unscaled body turns (a frozen one would not), so every
            // rescaled run that stays within rounding of it turns too.
            let moved = rotation_angle_between(unscaled, r.samples[0].1);
            assert!(moved > 0.05, "{scenario} {name}: turned {moved} rad");
            for s in MOMENT_SCALES {
                for sigma in RATE_SCALES {
                    let q = run(name, &r, s, sigma)
                        .unwrap_or_else(|e| panic!("{scenario} {name} I×{s:e} ω×{sigma:e}: {e}"));
                    let apart = rotation_angle_between(q, unscaled);
                    let error = rotation_angle_between(q, q_ref);
                    worst = worst.max(apart);
                    assert!(
                        apart <= SCALE_TOLERANCE,
                        "{scenario} {name} I×{s:e} ω×{sigma:e}: {apart:e} rad from the unscaled run"
                    );
                    assert!(
                        error <= accuracy + SCALE_TOLERANCE,
                        "{scenario} {name} I×{s:e} ω×{sigma:e}: {error:e} rad from the reference, \
                         unscaled {accuracy:e}"
                    );
                }
            }
            println!(
                "{scenario:>10} {name:>10}: {accuracy:.2e} rad from the reference at every scale"
            );
        }
    }
    println!("largest distance between a rescaled and the unscaled run: {worst:.2e} rad");
}

/// Scales that cannot be represented are refused with a typed error, at
/// the constructors and at `integrate`, never NaN rows.
#[test]
fn unrepresentable_scales_are_typed_errors() {
    let s0 = PrincipalState {
        world_from_principal: DQuat::IDENTITY,
        l_principal: DVec3::new(0.1, 1.0, 0.0),
    };
    // A subnormal moment (1e-320 kg m²) has lost its digits.
    for bad in [
        DVec3::splat(1e-320),
        DVec3::new(1e-320, 1.0, 1.0),
        DVec3::new(1.0, 1e-101, 1.0),
    ] {
        assert!(matches!(
            RigidBody::try_from_principal_moments(bad),
            Err(DynamicsError::UnphysicalInertia { .. })
        ));
        for name in FreeBodyMethod::ALL {
            let mut s = s0;
            let e = integrate(name.integrator(), bad, &mut s, 0.01, 10).unwrap_err();
            assert!(
                matches!(e, DynamicsError::UnphysicalInertia { .. }),
                "{name}: {e}"
            );
            assert_eq!(s, s0);
        }
    }
    // I ω² overflows: refused, not a state holding inf.
    let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0)).unwrap();
    for omega in [DVec3::splat(1e308), DVec3::new(0.0, 1e160, 0.0)] {
        assert!(matches!(
            PrincipalState::try_from_omega_body(&body, DQuat::IDENTITY, omega),
            Err(DynamicsError::InvalidState { .. })
        ));
    }
    let huge = PrincipalState {
        world_from_principal: DQuat::IDENTITY,
        l_principal: DVec3::new(0.0, 1e200, 0.0),
    };
    let mut s = huge;
    let e = integrate(
        FreeBodyMethod::Exact.integrator(),
        DVec3::new(1.0, 2.0, 3.0),
        &mut s,
        0.01,
        1,
    );
    assert!(
        matches!(e, Err(DynamicsError::InvalidState { .. })),
        "{e:?}"
    );
    // The same L on a body of moments 1e200 is ω = 1 rad/s: fine.
    assert!(
        integrate(
            FreeBodyMethod::Exact.integrator(),
            DVec3::new(1e200, 2e200, 2.5e200),
            &mut s,
            0.01,
            1
        )
        .is_ok()
    );
}
