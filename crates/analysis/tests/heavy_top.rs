//! The heavy top on a pivot: the sleeping top against the notes' §3.11
//! criterion and precession frequencies, steady precession against the
//! small-nutation frequency from the effective potential, and both
//! against the engine's nonlinear motion started along a mode.

mod support;

use glam::{DMat3, DQuat, DVec3};
use kreisel_analysis::{
    Frame, HeavyTopPivot, Linearisation, PrecessingTop, Precession, Verdict, ZeroModeKind,
};
use kreisel_dynamics::{Body, HeavyTop};
use kreisel_inertia::MassProperties;

const M: f64 = 1.0;
const G: f64 = 9.81;
const L: f64 = 0.1;
const I_CM: DVec3 = DVec3::new(0.02, 0.02, 0.01);

/// The symmetric top: centre of mass `L` up the body's z axis from the
/// pivot; `J₁ = I₁ + M L²` about the pivot.
fn body(world_from_body: DQuat, omega_body: DVec3) -> Body {
    Body::from_principal_moments(M, I_CM)
        .world_from_body(world_from_body)
        .omega_body(omega_body)
        .pivot(DVec3::new(0.0, 0.0, -L), DVec3::ZERO)
        .try_build()
        .unwrap()
}

fn engine_top() -> HeavyTop {
    let props = MassProperties::try_new(M, DVec3::ZERO, DMat3::from_diagonal(I_CM)).unwrap();
    HeavyTop::try_new(&props, DVec3::new(0.0, 0.0, -L), DVec3::new(0.0, 0.0, -G)).unwrap()
}

const J1: f64 = 0.02 + M * L * L;
const J3: f64 = 0.01;
const MGL: f64 = M * G * L;

/// `Ω_c = √(4 J₁ M g l)/J₃`, the notes' threshold.
fn critical_spin() -> f64 {
    (4.0 * J1 * MGL).sqrt() / J3
}

/// Notes §3.11: stable iff `J₃²Ω² > 4 J₁ M g l`; below, growth rate
/// `√(4J₁Mgl − J₃²Ω²)/(2J₁)`; above, precession in space at
/// `p± = (J₃Ω ± √(J₃²Ω² − 4J₁Mgl))/(2J₁)` and in body axes at `Ω − p±`;
/// to 1e-12 relative, the top built by the engine from mass properties
/// and a pivot. Within 0.1 % of the threshold the pair is nearly double
/// and its split `2σ` (or `p₊ − p₋`) is ill-conditioned: a rounding `e`
/// of the matrix moves it by `≈ e |λ|/σ` (the 2×2 `[[a, b], [c, a]]` has
/// `a ± √(bc)`); there the bound is `8 ε |λ|²/σ²` (measured 2.8e-12 at
/// 0.999 Ω_c, where `|λ|/σ = 112`).
#[test]
fn the_sleeping_top_matches_the_notes() {
    // The engine orders the principal axes its own way: the same top.
    let top = HeavyTopPivot::of(&engine_top());
    let mut moments = top.moments_about_pivot().to_array();
    moments.sort_by(f64::total_cmp);
    assert!(
        (DVec3::from_array(moments) - DVec3::new(J3, J1, J1))
            .abs()
            .max_element()
            < 1e-15
    );
    assert!(
        (top.com_principal().length() - L).abs() < 1e-16 && (top.weight() - M * G).abs() < 1e-15
    );
    let critical = critical_spin();
    let mut worst: f64 = 0.0;
    for factor in [-3.0, -0.5, 0.3, 0.9, 0.999, 1.001, 1.1, 2.0, 10.0] {
        let spin = factor * critical;
        let lin = Linearisation::try_new(&top, &top.sleeping(spin).unwrap()).unwrap();
        let kinds: Vec<ZeroModeKind> = lin.zero_modes.iter().map(|z| z.kind).collect();
        assert_eq!(kinds, [ZeroModeKind::Casimir, ZeroModeKind::Momentum]);
        assert_eq!(lin.modes.len(), 4);
        assert_eq!(lin.frame, Frame::Body);
        let discriminant = (J3 * spin).powi(2) - 4.0 * J1 * MGL;
        // The pair's condition near the threshold, |λ|/split.
        let size = lin
            .modes
            .iter()
            .map(|m| m.eigenvalue.norm())
            .fold(0.0, f64::max);
        let split = discriminant.abs().sqrt() / J1;
        let bound = (8.0 * f64::EPSILON * (size / split).powi(2)).max(1e-12);
        let mut check = |found: f64, expected: f64| {
            let e = found / expected - 1.0;
            worst = worst.max(e.abs() / bound);
            assert!(
                e.abs() <= bound,
                "Ω/Ω_c = {factor}: {found} vs {expected} ({e:e}, bound {bound:e})"
            );
        };
        if factor.abs() < 1.0 {
            let Verdict::Unstable { growth_rate } = lin.verdict else {
                panic!("{factor}: {:?}", lin.verdict)
            };
            check(growth_rate, (-discriminant).sqrt() / (2.0 * J1));
        } else {
            assert!(
                matches!(lin.verdict, Verdict::Stable { asymptotic: false }),
                "{:?}",
                lin.verdict
            );
            let p = [
                (J3 * spin + discriminant.sqrt()) / (2.0 * J1),
                (J3 * spin - discriminant.sqrt()) / (2.0 * J1),
            ];
            for mode in &lin.modes {
                let space = mode.space_frequency.expect("circular modes");
                let k = if (space - p[0].abs()).abs() < (space - p[1].abs()).abs() {
                    0
                } else {
                    1
                };
                check(space, p[k].abs());
                check(mode.eigenvalue.frequency(), (spin - p[k]).abs());
            }
        }
    }
    eprintln!("sleeping top: worst relative error / its bound: {worst:.2}");
}

/// The growing mode below the threshold and each precession above it,
/// measured from the engine's heavy top started 1e-8 along the mode:
/// `|γ_⊥|` grows like `e^{σt}`, and the axis turns in space at `p±`
/// (measured: relative 7.4e-11; −1.3e-10 and −4.2e-9).
#[test]
fn the_engine_s_sleeping_top_grows_and_precesses_at_the_linearised_rates() {
    // Principal axes = the body's axes.
    let top =
        HeavyTopPivot::try_new(DVec3::new(J1, J1, J3), DVec3::new(0.0, 0.0, L), M * G).unwrap();
    let amplitude = 1e-8;
    // The mode's real part added to the steady state, as an attitude and a spin.
    let start = |lin: &Linearisation, mode: usize| {
        let x: Vec<f64> = (0..6)
            .map(|k| lin.state[k] + amplitude * lin.modes[mode].shape[k].re)
            .collect();
        // The rotation taking the body's up vector to ẑ (by its axis and
        // angle: glam's from_rotation_arc rounds a 1e-8 rad arc to none).
        let up_body = DVec3::new(x[0], x[1], x[2]).normalize();
        let across = up_body.cross(DVec3::Z);
        let angle = across.length().atan2(up_body.z);
        let world_from_body = DQuat::from_scaled_axis(across.normalize_or_zero() * angle);
        body(world_from_body, DVec3::new(x[3], x[4], x[5]))
    };
    let gravity = DVec3::new(0.0, 0.0, -G);
    let lin = Linearisation::try_new(&top, &top.sleeping(0.8 * critical_spin()).unwrap()).unwrap();
    let Verdict::Unstable { growth_rate } = lin.verdict else {
        panic!()
    };
    let h = 1e-3;
    let steps = ((1e4f64).ln() / growth_rate / h) as usize;
    let samples = support::run(gravity, start(&lin, 0), h, steps, |q, _| {
        let up = q.conjugate() * DVec3::Z;
        up.x.hypot(up.y).ln()
    });
    let measured = support::late_slope(&samples, h);
    let error = measured / growth_rate - 1.0;
    eprintln!("growth: linearised {growth_rate:.12} 1/s, measured {measured:.12} ({error:.1e})");
    assert!(error.abs() < 1e-6, "{error:e}");

    let lin = Linearisation::try_new(&top, &top.sleeping(2.0 * critical_spin()).unwrap()).unwrap();
    for (k, mode) in lin
        .modes
        .iter()
        .enumerate()
        .filter(|(_, m)| m.eigenvalue.im > 0.0)
    {
        let p = mode.space_frequency.unwrap();
        let h = 2e-3 / p.max(mode.eigenvalue.frequency());
        let steps = (3.0 * std::f64::consts::TAU / p / h) as usize;
        let mut unwrapped = Vec::new();
        let angles = support::run(gravity, start(&lin, k), h, steps, |q, _| {
            let axis = q * DVec3::Z;
            axis.y.atan2(axis.x)
        });
        let mut turns = 0.0;
        for (i, a) in angles.iter().enumerate() {
            if i > 0 {
                let jump = a - angles[i - 1];
                turns -= std::f64::consts::TAU * (jump / std::f64::consts::TAU).round();
            }
            unwrapped.push((i as f64 * h, a + turns));
        }
        let measured = support::slope(&unwrapped).abs();
        let error = measured / p - 1.0;
        eprintln!("precession: linearised {p:.12} rad/s, measured {measured:.12} ({error:.1e})");
        assert!(error.abs() < 1e-6, "{error:e}");
    }
}

/// The small-nutation frequency of a steady precession, from the notes'
/// effective potential (derived in `PrecessingTop`'s docs, `k = I₃ω₃/I₁`):
/// `ω² = (k − 2φ̇ cos θ₀)² + φ̇² sin²θ₀`, slow and fast, above and below
/// the horizontal, to 1e-12 relative; `p_φ` and `p_ψ` account for the
/// zeros.
#[test]
fn steady_precession_nutates_at_the_effective_potential_s_frequency() {
    let top = PrecessingTop::of(&engine_top()).unwrap();
    let (i1, i3, mgl) = top.parameters();
    assert!((i1 - J1).abs() < 1e-16 && i3 == J3 && (mgl - MGL).abs() < 1e-15);
    let mut worst: f64 = 0.0;
    for theta in [0.05, 0.4, 1.2, 2.0, 3.0] {
        for spin in [1.5 * critical_spin(), 200.0, -80.0] {
            for which in [Precession::Slow, Precession::Fast] {
                let phi_dot = top.precession_rate(theta, spin, which).unwrap();
                let lin =
                    Linearisation::try_new(&top, &top.steady(theta, spin, which).unwrap()).unwrap();
                assert_eq!(lin.zero_modes.len(), 2);
                assert!(
                    lin.zero_modes
                        .iter()
                        .all(|z| z.kind == ZeroModeKind::Momentum)
                );
                assert!(
                    matches!(lin.verdict, Verdict::Stable { asymptotic: false }),
                    "{:?}",
                    lin.verdict
                );
                let k = i3 * spin / i1;
                let expected = ((k - 2.0 * phi_dot * theta.cos()).powi(2)
                    + (phi_dot * theta.sin()).powi(2))
                .sqrt();
                let e = lin.modes[0].eigenvalue.frequency() / expected - 1.0;
                worst = worst.max(e.abs());
                assert!(e.abs() <= 1e-12, "θ {theta} ω₃ {spin} {which:?}: {e:e}");
            }
        }
    }
    eprintln!("steady precession: worst relative error {worst:.1e}");
    // Too slow a spin for a steady precession above the horizontal.
    assert!(
        top.steady(0.4, 0.5 * critical_spin(), Precession::Slow)
            .is_err()
    );
}

/// The engine's top started at the steady precession's `φ̇` and `ω₃`,
/// tilted 1e-6 rad further: `θ(t)` oscillates at the linearised
/// nutation frequency, slow and fast precession (measured: relative
/// −8.2e-8 and 4.9e-7, the amplitude's own O(1e-6) shift).
#[test]
fn the_engine_s_precessing_top_nutates_at_the_linearised_frequency() {
    let top = PrecessingTop::of(&engine_top()).unwrap();
    let gravity = DVec3::new(0.0, 0.0, -G);
    let (theta, spin) = (0.6, 1.5 * critical_spin());
    for which in [Precession::Slow, Precession::Fast] {
        let phi_dot = top.precession_rate(theta, spin, which).unwrap();
        let lin = Linearisation::try_new(&top, &top.steady(theta, spin, which).unwrap()).unwrap();
        let nu = lin.modes[0].eigenvalue.frequency();
        let tilted = theta + 1e-6;
        // Euler angles ZXZ at φ = ψ = 0: ω_body = (θ̇, φ̇ sin θ, ω₃).
        let omega_body = DVec3::new(0.0, phi_dot * tilted.sin(), spin);
        let h = 2e-3 / nu.max(phi_dot.abs()).max(spin.abs());
        let steps = (10.0 * std::f64::consts::TAU / nu / h) as usize;
        let thetas = support::run(
            gravity,
            body(DQuat::from_rotation_x(tilted), omega_body),
            h,
            steps,
            |q, _| (q * DVec3::Z).z.acos(),
        );
        let mean = thetas.iter().sum::<f64>() / thetas.len() as f64;
        let centred: Vec<f64> = thetas.iter().map(|t| t - mean).collect();
        let measured = support::frequency_from_zeros(&centred, h);
        let error = measured / nu - 1.0;
        eprintln!(
            "{which:?}: nutation linearised {nu:.12} rad/s, measured {measured:.12} ({error:.1e})"
        );
        assert!(error.abs() < 1e-5, "{error:e}");
    }
}
