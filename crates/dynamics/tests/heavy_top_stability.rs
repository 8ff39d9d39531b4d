//! The stability limits stated in `HeavyTopSplitting`'s docs, checked two
//! independent ways: the linear theory (the composed Störmer–Verlet map of
//! the harmonic oscillator, scanned here) and the nonlinear integrators on
//! a small-amplitude pendulum just below and just above each limit.

use glam::{DQuat, DVec3};
use kreisel_dynamics::{
    HeavyTop, HeavyTopAuto, HeavyTopIntegrator, HeavyTopSplitting, PrincipalState,
};

/// The composed one-step map of the oscillator `x'' = −x` for step `x`
/// (kick–drift–kick per stage); returns |trace| / 2.
fn half_trace(gammas: &[f64], x: f64) -> f64 {
    let mut m = [[1.0, 0.0], [0.0, 1.0]];
    for &g in gammas {
        let y = g * x;
        let s = [
            [1.0 - y * y / 2.0, y],
            [-y * (1.0 - y * y / 4.0), 1.0 - y * y / 2.0],
        ];
        m = [
            [
                s[0][0] * m[0][0] + s[0][1] * m[1][0],
                s[0][0] * m[0][1] + s[0][1] * m[1][1],
            ],
            [
                s[1][0] * m[0][0] + s[1][1] * m[1][0],
                s[1][0] * m[0][1] + s[1][1] * m[1][1],
            ],
        ];
    }
    (m[0][0] + m[1][1]).abs() / 2.0
}

/// The stage coefficients of a composition, from the published tables.
fn gammas(method: &HeavyTopSplitting) -> Vec<f64> {
    use kreisel_dynamics::{KAHAN_LI_6, KAHAN_LI_8, SUZUKI_4};
    let c = match method.name() {
        "strang" => return vec![1.0],
        "splitting4" => SUZUKI_4,
        "splitting6" => KAHAN_LI_6,
        _ => KAHAN_LI_8,
    };
    let mut g: Vec<f64> = c.half.to_vec();
    g.push(c.middle);
    g.extend(c.half.iter().rev());
    g
}

#[test]
fn linear_theory_gives_the_documented_limits() {
    for method in HeavyTopSplitting::ALL {
        let g = gammas(&method);
        let mut x = 0.0;
        while half_trace(&g, x + 1e-5) <= 1.0 + 1e-12 {
            x += 1e-5;
        }
        println!("{}: first instability at h Ω = {x:.5}", method.name());
        assert!(
            (x - method.stability_limit()).abs() < 1e-3,
            "{}: {x}",
            method.name()
        );
        assert_eq!(g.len(), method.stages());
        let largest = g.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert_eq!(largest, method.largest_stage());
    }
}

/// A hanging pendulum (J₁ = J₂ = 0.02, centre of mass 0.1 m below the
/// pivot, 1 kg) released from a small angle; the largest angle from the
/// vertical over `steps` steps of `h`.
fn swing(method: &dyn HeavyTopIntegrator, h_omega: f64, steps: usize) -> f64 {
    let top = HeavyTop::try_from_principal(
        DVec3::new(0.02, 0.02, 0.01),
        DVec3::new(0.0, 0.0, -0.1),
        1.0,
        DVec3::new(0.0, 0.0, -9.81),
    )
    .unwrap();
    let omega_g = top.gravity_frequency();
    assert!((omega_g - (0.981f64 / 0.02).sqrt()).abs() < 1e-12);
    let theta0 = 1e-4;
    let mut s = PrincipalState {
        world_from_principal: DQuat::from_rotation_x(theta0),
        l_principal: DVec3::ZERO,
    };
    let mut widest: f64 = 0.0;
    for _ in 0..steps {
        method.step(&top, &mut s, h_omega / omega_g);
        let down = s.world_from_principal * DVec3::NEG_Z;
        widest = widest.max(down.angle_between(DVec3::NEG_Z) / theta0);
        if !widest.is_finite() || widest > 1e3 {
            break;
        }
    }
    widest
}

#[test]
fn pendulum_is_stable_below_the_limit_and_not_above() {
    for method in HeavyTopSplitting::ALL {
        let limit = method.stability_limit();
        let below = swing(&method, 0.97 * limit, 20_000);
        let above = swing(&method, 1.01 * limit, 20_000);
        println!(
            "{}: amplitude ×{below:.3} at 0.97 limit, ×{above:.3e} at 1.01 limit",
            method.name()
        );
        assert!(below < 3.0, "{}: {below}", method.name());
        assert!(above > 100.0, "{}: {above}", method.name());
        // auto sub-steps: stable at any step size.
        let auto = swing(&HeavyTopAuto, 10.0 * limit, 2_000);
        assert!(auto < 3.0, "auto: {auto}");
    }
}
