//! The tippe top's growth and wobble measured from the engine's
//! nonlinear runs started along the library's modes.

mod support;
use glam::{DQuat, DVec2, DVec3};
use kreisel_analysis::{LEINE_GLOCKER, Linearisation, TippeTop, Verdict};
use kreisel_dynamics::{Friction, GroundTop, GroundTopState, SphereContact};

fn viscous() -> Friction {
    Friction::try_viscous(0.3).unwrap()
}

fn sliding() -> Friction {
    Friction::try_sliding(0.3, 1e-3).unwrap()
}

/// The engine's tippe top with `friction`.
fn engine(friction: Friction) -> GroundTop {
    let p = LEINE_GLOCKER;
    let sphere = SphereContact::try_new(p.radius, DVec3::new(0.0, 0.0, p.offset)).unwrap();
    let i = glam::DMat3::from_diagonal(DVec3::new(
        p.transverse_moment,
        p.transverse_moment,
        p.axial_moment,
    ));
    GroundTop::try_new(p.mass, i, sphere, friction, p.gravity).unwrap()
}

/// The engine's state for the body-axes state `x` (`γ, ω` and, with a
/// friction law, `v`; any heading).
fn start(top: &GroundTop, x: &[f64]) -> GroundTopState {
    // The turn taking `up` to `ẑ` about `up × ẑ` (glam's
    // `from_rotation_arc` returns the identity for angles below ~1e-8).
    let up = DVec3::new(x[0], x[1], x[2]).normalize();
    let axis = up.cross(DVec3::Z);
    let q = if axis.length() > 0.0 {
        DQuat::from_axis_angle(axis.normalize(), axis.length().atan2(up.z))
    } else if up.z > 0.0 {
        DQuat::IDENTITY
    } else {
        DQuat::from_rotation_x(std::f64::consts::PI)
    };
    let omega = q * DVec3::new(x[3], x[4], x[5]);
    if x.len() == 6 {
        top.try_rolling_state_on_ground(q, omega).unwrap()
    } else {
        let v = q * DVec3::new(x[6], x[7], x[8]);
        top.try_state_on_ground(q, omega, DVec2::new(v.x, v.y))
            .unwrap()
    }
}

/// The growth rate and frequency (body axes) of `γ_x` from the engine
/// started at `amplitude` along the real part of the library's mode `k`
/// (the rattleback test's method: zeros `π/ω` apart, extrema on
/// `ln|y| = const + σ t`), RK4 at `ω h = 2e-3`.
fn measured(
    top: &GroundTop,
    lin: &Linearisation,
    k: usize,
    amplitude: f64,
    duration: f64,
) -> (f64, f64) {
    let mode = &lin.modes[k];
    let x: Vec<f64> = lin
        .state
        .iter()
        .zip(&mode.shape)
        .map(|(v, c)| v + amplitude * c.re)
        .collect();
    let mut s = start(top, &x);
    let observe = |s: &GroundTopState| (s.world_from_body.normalize().conjugate() * DVec3::Z).x;
    let fastest = lin.state[3..6]
        .iter()
        .fold(mode.eigenvalue.im.abs(), |a, b| a.max(b.abs()));
    let h = 2e-3 / fastest;
    let mut samples = vec![observe(&s)];
    top.try_advance(&mut s, 0.0, h, (duration / h).round() as usize, |_, s| {
        samples.push(observe(s))
    })
    .unwrap();
    support::growth_and_frequency(&samples, h)
}

/// Viscous and regularised Coulomb friction, upright at 180 rad/s: the
/// engine started `1e-7` along the library's growing wobble grows at its
/// rate and turns at its frequency (body axes). Frictionless and rolling,
/// inverted at 180 rad/s: the engine's slow wobble (started `1e-5` along
/// it: smaller starts drown in rounding, 1e-7 measured 2.2e-9 without
/// friction) turns at the library's frequency and neither grows nor
/// decays. Measured (debug build, RK4 at `h = 2e-3/180` s, 2 s of CPU in
/// all):
///
/// ```text
/// law           state     σ library (1/s)  ω library (rad/s)  σ rel. error  ω rel. error
/// viscous       upright   1.3077015080     21.0500235677      1.0e-11       5.2e-12
/// sliding       upright   1.0820731404     13.0573178201      −1.7e-11      1.7e-12
/// frictionless  inverted  0 (|σ| 1.5e-10)  23.9141254009      —             2.1e-11
/// rolling       inverted  0 (|σ| 1.2e-12)  28.2374373394      —             9.0e-13
/// ```
#[test]
fn the_engine_grows_and_wobbles_at_the_librarys_rates() {
    // Viscous and regularised Coulomb friction, upright: unstable.
    for friction in [viscous(), sliding()] {
        let top = TippeTop::try_new(LEINE_GLOCKER, friction).unwrap();
        let lin = Linearisation::try_new(&top, &top.spinning_upright(180.0).unwrap()).unwrap();
        let Verdict::Unstable { growth_rate } = lin.verdict else {
            panic!("{}", lin.verdict)
        };
        let k = lin
            .modes
            .iter()
            .position(|m| m.eigenvalue.re == growth_rate)
            .unwrap();
        let omega = lin.modes[k].eigenvalue.im.abs();
        let (sigma, w) = measured(&engine(friction), &lin, k, 1e-7, 4.0 / growth_rate);
        let (e_sigma, e_omega) = (sigma / growth_rate - 1.0, w / omega - 1.0);
        eprintln!(
            "{friction:?} upright: library σ = {growth_rate:.10}, ω = {omega:.10}; engine σ = {sigma:.10} ({e_sigma:.1e}), ω = {w:.10} ({e_omega:.1e})"
        );
        assert!(
            e_sigma.abs() <= 1e-9 && e_omega.abs() <= 1e-10,
            "{e_sigma:e} {e_omega:e}"
        );
    }

    // Frictionless and rolling, inverted: neutral wobbles.
    for friction in [Friction::None, Friction::Rolling] {
        slow_wobble(friction);
    }
}

/// The engine's slow wobble (body axes) inverted at 180 rad/s, started
/// `1e-5` along the library's mode, against its frequency; it neither
/// grows nor decays.
fn slow_wobble(friction: Friction) {
    let top = TippeTop::try_new(LEINE_GLOCKER, friction).unwrap();
    let lin = Linearisation::try_new(&top, &top.spinning_inverted(180.0).unwrap()).unwrap();
    assert!(
        matches!(lin.verdict, Verdict::Stable { .. }),
        "{}",
        lin.verdict
    );
    let k = lin
        .modes
        .iter()
        .enumerate()
        .filter(|(_, m)| m.eigenvalue.im > 0.0)
        .min_by(|a, b| a.1.eigenvalue.im.total_cmp(&b.1.eigenvalue.im))
        .unwrap()
        .0;
    let omega = lin.modes[k].eigenvalue.im;
    let (sigma, w) = measured(
        &engine(friction),
        &lin,
        k,
        1e-5,
        20.0 * std::f64::consts::TAU / omega,
    );
    let e_omega = w / omega - 1.0;
    eprintln!(
        "{friction:?} inverted: library ω = {omega:.10}; engine ω = {w:.10} ({e_omega:.1e}), σ = {sigma:.1e}"
    );
    assert!(e_omega.abs() <= 1e-10, "{e_omega:e}");
    assert!(sigma.abs() <= 1e-9, "{sigma:e}");
}
