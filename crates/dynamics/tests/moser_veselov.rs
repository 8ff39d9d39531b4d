//! DMV and the preprocessed DMV of Hairer & Vilmart (J. Phys. A 39 (2006)
//! 13225) against the mpmath reference trajectories of
//! `tests/data/free_body/` (workspace root): convergence orders, the
//! conserved quantities, and the errors at dt = 0.01 and 0.1 (printed with
//! `--nocapture`).

use glam::{DQuat, DVec3};
use kreisel_dynamics::{
    FreeBodyIntegrator, FreeBodyMethod, MoserVeselov, PreprocessedMoserVeselov, PrincipalState,
    integrate,
};
use kreisel_kinematics::rotation_angle_between;

#[path = "common/free_body.rs"]
mod free_body;

use free_body::{Reference, load};

/// Every method of this file, lowest order first.
fn methods() -> [&'static dyn FreeBodyIntegrator; 5] {
    [
        FreeBodyMethod::Dmv,
        FreeBodyMethod::Pdmv4,
        FreeBodyMethod::Pdmv6,
        FreeBodyMethod::Pdmv8,
        FreeBodyMethod::Pdmv10,
    ]
    .map(FreeBodyMethod::integrator)
}

/// Attitude error (rad) and relative L error at the sample nearest `t_end`.
fn error_at(m: &dyn FreeBodyIntegrator, r: &Reference, t_end: f64, h: f64) -> (f64, f64) {
    let (_, q0, l0) = r.samples[0];
    let (t, q, l) = *r
        .samples
        .iter()
        .min_by(|a, b| (a.0 - t_end).abs().total_cmp(&(b.0 - t_end).abs()))
        .unwrap();
    let steps = (t / h).round() as usize;
    assert!((steps as f64 * h - t).abs() < 1e-9, "t = {t}, h = {h}");
    let mut s = PrincipalState {
        world_from_principal: q0,
        l_principal: l0,
    };
    for _ in 0..steps {
        m.step(r.moments, &mut s, h);
    }
    (
        rotation_angle_between(s.world_from_principal, q),
        (s.l_principal - l).length() / l.length(),
    )
}

#[test]
fn registry_names_and_orders() {
    for (m, order) in methods().iter().zip([2, 4, 6, 8, 10]) {
        assert_eq!(m.order(), order, "{}", m.name());
    }
    assert_eq!(FreeBodyMethod::Pdmv10.integrator().name(), "pdmv10");
    assert_eq!(PreprocessedMoserVeselov::new(2).unwrap().name(), "dmv");
}

/// The error ratio between h and h/2 is 2^p (±0.4 in the exponent) on four
/// scenarios, with steps where the error stays far above rounding.
#[test]
fn measured_convergence_orders() {
    // (scenario, t_end, steps for dmv … pdmv10): the thin rod spins at
    // 3 rad/s, near the separatrix |ω| ≈ 0.5 rad/s.
    let table = [
        ("hlw", 10.0, [0.02, 0.05, 0.1, 0.4, 0.5]),
        ("rapier", 10.0, [0.02, 0.05, 0.1, 0.4, 0.5]),
        ("near_separatrix_7", 16.0, [0.04, 0.1, 0.2, 0.8, 1.6]),
        ("ratio_1000", 2.0, [0.01, 0.025, 0.05, 0.2, 0.25]),
    ];
    for (scenario, t_end, steps) in table {
        let r = load(scenario);
        for (m, h) in methods().into_iter().zip(steps) {
            let (e1, _) = error_at(m, &r, t_end, h);
            let (e2, _) = error_at(m, &r, t_end, h / 2.0);
            let order = (e1 / e2).log2();
            eprintln!(
                "{scenario:>18} {:>7}: error {e1:.2e} at h = {h}, {e2:.2e} at h/2: order {order:.2}",
                m.name()
            );
            assert!(e2 > 5e-12, "{scenario} {}: too close to rounding", m.name());
            assert!(
                (order - f64::from(m.order())).abs() < 0.4,
                "{scenario} {}: order {order}",
                m.name()
            );
        }
    }
}

/// |L| and L_world to rounding over 10⁵ steps; DMV's exact invariant, the
/// energy, too (its L moves on the exact orbit), and PDMV's since its
/// modified energy is a combination of |L|² and the energy.
#[test]
fn invariants_conserved_to_rounding() {
    let r = load("hlw");
    let (_, q0, l0) = r.samples[0];
    let energy = |l: DVec3| 0.5 * (l * l / r.moments).element_sum();
    let e0 = energy(l0);
    for m in methods() {
        let mut s = PrincipalState {
            world_from_principal: q0,
            l_principal: l0,
        };
        let lw0 = s.l_world();
        let (mut worst_l, mut worst_e): (f64, f64) = (0.0, 0.0);
        for _ in 0..100_000 {
            m.step(r.moments, &mut s, 0.1);
            worst_l = worst_l.max((s.l_principal.length() - l0.length()).abs());
            worst_e = worst_e.max((energy(s.l_principal) - e0).abs());
        }
        let dlw = (s.l_world() - lw0).length() / l0.length();
        eprintln!(
            "{:>7}: max |Δ|L|| {worst_l:.1e}, max |ΔE| {worst_e:.1e}, |ΔL_world| {dlw:.1e}",
            m.name()
        );
        assert!(worst_l < 1e-13, "{}: |L| {worst_l:e}", m.name());
        assert!(worst_e < 1e-13 * e0, "{}: E {worst_e:e}", m.name());
        assert!(dlw < 1e-13, "{}: L_world {dlw:e}", m.name());
    }
}

/// PDMV10 at h = 0.2 (Hairer & Vilmart report errors near 1e-12 there):
/// on HLW's body (Hairer, Lubich & Wanner's free rigid body, |ω| ≈ 1.3)
/// against the mpmath reference at t = 10 and 20, and on the body of
/// Hairer & Vilmart's DMV10 driver (I = (0.6, 0.8, 1), L₀ = (1.8, 0.4,
/// −0.9), |ω| ≈ 3.2, so hω three times larger) against PDMV10 at
/// h = 0.0125, itself checked against splitting8 at h = 0.005.
#[test]
fn pdmv10_at_h_0_2() {
    let pdmv10 = PreprocessedMoserVeselov::ORDER_10;
    let r = load("hlw");
    for t_end in [10.0, 20.0] {
        let (e, el) = error_at(&pdmv10, &r, t_end, 0.2);
        eprintln!("hlw, pdmv10, h = 0.2: attitude {e:.2e} rad, L {el:.2e} at t = {t_end}");
        assert!(e < 3e-12 && el < 3e-12, "{e:e} {el:e}");
    }
    let moments = DVec3::new(0.6, 0.8, 1.0);
    let s0 = PrincipalState {
        world_from_principal: DQuat::IDENTITY,
        l_principal: DVec3::new(1.8, 0.4, -0.9),
    };
    let run = |m: &dyn FreeBodyIntegrator, h: f64| {
        let mut s = s0;
        for _ in 0..(10.0 / h).round() as usize {
            m.step(moments, &mut s, h);
        }
        s
    };
    let fine = run(&pdmv10, 0.0125);
    let check = run(FreeBodyMethod::Splitting8.integrator(), 0.005);
    let agree = rotation_angle_between(fine.world_from_principal, check.world_from_principal);
    eprintln!(
        "driver problem reference: pdmv10 h = 0.0125 vs splitting8 h = 0.005: {agree:.1e} rad"
    );
    assert!(agree < 1e-12);
    let mut last = f64::NAN;
    for h in [0.4, 0.2, 0.1] {
        let s = run(&pdmv10, h);
        let e = rotation_angle_between(s.world_from_principal, fine.world_from_principal);
        let el = (s.l_principal - fine.l_principal).length() / fine.l_principal.length();
        eprintln!("driver problem, pdmv10, h = {h}: attitude {e:.2e} rad, L {el:.2e} at t = 10");
        if h == 0.1 {
            let order = (last / e).log2();
            assert!((order - 10.0).abs() < 0.6, "order {order}");
        }
        last = e;
    }
}

/// The errors at dt = 0.01 and 0.1 over 20 s on every scenario, printed
/// for the record; asserted only loosely (each method within its order's
/// reach at dt = 0.01).
#[test]
fn errors_at_dt_0_01_and_0_1() {
    for scenario in [
        "rapier",
        "hlw",
        "near_separatrix_7",
        "near_separatrix_12",
        "ratio_1000",
        "ratio_1000b",
    ] {
        let r = load(scenario);
        let t_end = r.samples.last().unwrap().0.min(20.0);
        for m in methods() {
            let (e1, l1) = error_at(m, &r, t_end, 0.01);
            let (e2, l2) = error_at(m, &r, t_end, 0.1);
            eprintln!(
                "{scenario:>18} {:>7}: dt 0.01: {e1:.2e} rad (L {l1:.1e}); dt 0.1: {e2:.2e} rad (L {l2:.1e}) at t = {t_end}",
                m.name()
            );
            assert!(e1.is_finite() && e2.is_finite());
            if m.order() >= 8 {
                assert!(e1 < 1e-10, "{scenario} {}: {e1:e}", m.name());
            }
        }
    }
}

/// Steps the solve cannot handle (zero moments, huge h) do not panic and
/// do not freeze the body: a step is either taken (finite state) or leaves
/// a NaN state, and `integrate` turns that into a typed error naming the
/// method (regression: DMV/PDMV used to leave the state unchanged, so a
/// body at |h ω| = 100 silently never turned).
#[test]
fn degenerate_inputs_do_not_panic() {
    let s0 = PrincipalState {
        world_from_principal: DQuat::IDENTITY,
        l_principal: DVec3::new(1.0, 2.0, 3.0),
    };
    for moments in [
        DVec3::ZERO,
        DVec3::new(1.0, 0.0, 2.0),
        DVec3::new(1.0, 2.0, 3.0),
    ] {
        for h in [0.0, -0.1, 1e3, 1e300] {
            for m in methods() {
                let mut s = s0;
                m.step(moments, &mut s, h);
                let finite = s.l_principal.is_finite() && s.world_from_principal.is_finite();
                let nan = s.l_principal.is_nan() && s.world_from_principal.is_nan();
                assert!(finite || nan, "{} {moments} {h}: {s:?}", m.name());
                if h > 0.0 {
                    let mut s = s0;
                    let result = integrate(m, moments, &mut s, h, 3);
                    let taken = result.is_ok() && s.l_principal.is_finite();
                    assert!(taken || result.is_err(), "{} {moments} {h}", m.name());
                    if h == 1e300 || moments != DVec3::new(1.0, 2.0, 3.0) {
                        let e = result.unwrap_err().to_string();
                        assert!(!e.is_empty() && s == s0, "{} {moments} {h}: {e}", m.name());
                    }
                }
            }
        }
    }
    // |h ω| = 100: no DMV rotation exists; an error, not a frozen body.
    for m in methods() {
        let mut s = PrincipalState {
            world_from_principal: DQuat::IDENTITY,
            l_principal: DVec3::new(1e4, 2e2, 0.0),
        };
        match integrate(m, DVec3::new(1.0, 2.0, 3.0), &mut s, 0.01, 10) {
            Err(kreisel_dynamics::DynamicsError::Diverged { method, time, .. }) => {
                assert_eq!((method, time), (m.name(), 0.01));
            }
            other => panic!("{}: {other:?}", m.name()),
        }
    }
    let mut s = PrincipalState {
        world_from_principal: DQuat::IDENTITY,
        l_principal: DVec3::ZERO,
    };
    MoserVeselov.step(DVec3::new(1.0, 2.0, 3.0), &mut s, 0.1);
    assert_eq!(s.world_from_principal, DQuat::IDENTITY);
}

/// `for_body` is a pure speed-up: bit-identical steps for its moments, and
/// for other moments the coefficients are computed as without it; and
/// `integrate`, which prepares them through the propagator, agrees too.
#[test]
fn prepared_coefficients_change_nothing() {
    let r = load("ratio_1000b");
    let (_, q0, l0) = r.samples[0];
    let s0 = PrincipalState {
        world_from_principal: q0,
        l_principal: l0,
    };
    for order in [4, 6, 8, 10] {
        let plain = PreprocessedMoserVeselov::new(order).unwrap();
        let prepared = plain.for_body(r.moments);
        let elsewhere = plain.for_body(DVec3::new(1.0, 2.0, 3.0));
        let (mut a, mut b, mut c) = (s0, s0, s0);
        for _ in 0..500 {
            plain.step(r.moments, &mut a, 0.01);
            prepared.step(r.moments, &mut b, 0.01);
            elsewhere.step(r.moments, &mut c, 0.01);
        }
        assert_eq!(a, b, "order {order}");
        assert_eq!(a, c, "order {order}");
        let mut d = s0;
        kreisel_dynamics::integrate(&plain, r.moments, &mut d, 0.01, 500).unwrap();
        assert_eq!(a, d, "order {order}: integrate (prepared propagator)");
    }
}
