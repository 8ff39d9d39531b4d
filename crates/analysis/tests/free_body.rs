//! The free body's steady rotations against the closed forms of the
//! notes' §3.7 (Landau & Lifshitz §37, problem), and against the engine's
//! exact motion started a small distance along each mode.

mod support;

use glam::DVec3;
use kreisel_analysis::{FreeBodyRotation, Linearisation, Verdict, ZeroModeKind};
use kreisel_dynamics::Body;

/// `(moments, rate)` cases: the issue's body, a T-handle-like one, and a
/// nearly symmetric one; rates of both signs.
fn cases() -> Vec<(DVec3, f64)> {
    let bodies = [
        DVec3::new(1.0, 2.0, 3.0),
        DVec3::new(2.7e-4, 6.1e-4, 7.9e-4),
        DVec3::new(1.0, 1.0 + 1e-3, 1.7),
    ];
    let rates = [-3.0, 0.5, 7.0];
    bodies
        .iter()
        .flat_map(|&b| rates.iter().map(move |&r| (b, r)))
        .collect()
}

/// Growth rate about the intermediate axis and the two wobble
/// frequencies, to 1e-12 relative; one zero eigenvalue, `|L|²`.
///
/// ```text
/// axis 2: σ = |ω| √((I₂−I₁)(I₃−I₂)/(I₁I₃))
/// axis 1: ν = |ω| √((I₂−I₁)(I₃−I₁)/(I₂I₃)),   axis 3: ν = |ω| √((I₃−I₁)(I₃−I₂)/(I₁I₂))
/// ```
#[test]
fn growth_rates_and_wobble_frequencies_match_the_closed_forms() {
    let mut worst: f64 = 0.0;
    for (moments, w) in cases() {
        let [i1, i2, i3] = moments.to_array();
        let family = FreeBodyRotation::try_new(moments).unwrap();
        let expected = [
            w.abs() * ((i2 - i1) * (i3 - i1) / (i2 * i3)).sqrt(),
            w.abs() * ((i2 - i1) * (i3 - i2) / (i1 * i3)).sqrt(),
            w.abs() * ((i3 - i1) * (i3 - i2) / (i1 * i2)).sqrt(),
        ];
        for (axis, &rate) in expected.iter().enumerate() {
            let lin =
                Linearisation::try_new(&family, &family.about_axis(axis, w).unwrap()).unwrap();
            assert_eq!(lin.zero_modes.len(), 1);
            assert_eq!(lin.zero_modes[0].kind, ZeroModeKind::Casimir);
            assert_eq!(lin.dependent.len(), 1, "the energy's gradient is parallel");
            assert_eq!(lin.modes.len(), 2);
            let found = match (&lin.verdict, axis) {
                (Verdict::Unstable { growth_rate }, 1) => {
                    // The pair ±σ, real.
                    assert!(lin.modes.iter().all(|m| m.eigenvalue.im == 0.0));
                    *growth_rate
                }
                (Verdict::Stable { asymptotic: false }, 0 | 2) => {
                    assert!(
                        lin.modes
                            .iter()
                            .all(|m| m.eigenvalue.re.abs() <= 1e-12 * rate)
                    );
                    lin.modes[0].eigenvalue.frequency()
                }
                (v, a) => panic!("axis {a}: {v:?}"),
            };
            let error = found / rate - 1.0;
            worst = worst.max(error.abs());
            assert!(
                error.abs() <= 1e-12,
                "{moments} ω {w} axis {axis}: {error:e}"
            );
        }
    }
    eprintln!("worst relative error against the closed forms: {worst:.1e}");
}

/// The engine's exact free body, started 1e-8 rad/s along the growing
/// mode of the T-handle's intermediate axis, grows at the linearised
/// rate; started along a wobble of the largest axis, it wobbles at the
/// linearised frequency (measured: relative −2.5e-11 and −1.6e-12).
#[test]
fn the_engine_grows_and_wobbles_at_the_linearised_rates() {
    let moments = DVec3::new(1.0, 2.0, 3.0);
    let family = FreeBodyRotation::try_new(moments).unwrap();
    let omega = 2.0;
    // Intermediate axis: ω₁ and ω₃ grow like e^{σt}.
    let lin = Linearisation::try_new(&family, &family.about_axis(1, omega).unwrap()).unwrap();
    let growing = &lin.modes[0];
    let sigma = growing.eigenvalue.re;
    assert!(sigma > 0.0);
    let amplitude = 1e-8;
    let start = |lin: &Linearisation, mode: usize| {
        let shape = &lin.modes[mode].shape;
        DVec3::from_array(std::array::from_fn(|k| {
            lin.state[k] + amplitude * shape[k].re
        }))
    };
    let body = |omega_body: DVec3| {
        Body::from_principal_moments(1.0, moments)
            .omega_body(omega_body)
            .try_build()
            .unwrap()
    };
    let h = 0.01;
    // From 1e-8 to 1e-4: the nonlinear terms stay below 1e-8 relative.
    let steps = ((1e4f64).ln() / sigma / h) as usize;
    let samples = support::run(
        DVec3::ZERO,
        body(start(&lin, 0)),
        h,
        steps,
        |_, w: DVec3| w.x.abs().ln(),
    );
    let measured = support::late_slope(&samples, h);
    let error = measured / sigma - 1.0;
    eprintln!("growth: linearised {sigma:.12} 1/s, measured {measured:.12} (relative {error:.1e})");
    assert!(error.abs() < 1e-6, "{error:e}");

    // Largest axis: ω₁ oscillates at ν.
    let lin = Linearisation::try_new(&family, &family.about_axis(2, omega).unwrap()).unwrap();
    let nu = lin.modes[0].eigenvalue.frequency();
    let h = 2e-3 / nu;
    let steps = (20.0 * std::f64::consts::TAU / nu / h) as usize;
    let samples = support::run(
        DVec3::ZERO,
        body(start(&lin, 0)),
        h,
        steps,
        |_, w: DVec3| w.x,
    );
    let measured = support::frequency_from_zeros(&samples, h);
    let error = measured / nu - 1.0;
    eprintln!("wobble: linearised {nu:.12} rad/s, measured {measured:.12} (relative {error:.1e})");
    assert!(error.abs() < 1e-8, "{error:e}");
}
