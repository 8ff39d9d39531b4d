//! Identities and edge cases of the exact free-body solution: the flow
//! property over long horizons, conservation to rounding, steady spins,
//! the separatrix's asymptote, a body one ulp from the separatrix, and bad
//! input. (Accuracy against the 60-digit references: `tests/free_body_exact.rs`
//! at the workspace root.)

use glam::{DQuat, DVec3};
use kreisel_dynamics::{ExactSolution, FreeBodyMethod, PrincipalState, elliptic_motion, integrate};
use kreisel_kinematics::rotation_angle_between;

fn state(l: DVec3) -> PrincipalState {
    PrincipalState {
        world_from_principal: DQuat::from_xyzw(0.1, -0.3, 0.2, 0.9).normalize(),
        l_principal: l,
    }
}

fn energy(moments: DVec3, l: DVec3) -> f64 {
    0.5 * (l * l / moments).element_sum()
}

/// Φ(t₁ + t₂) = Φ(t₂) ∘ Φ(t₁) after 10⁴ s (≈ 240 periods), and E, |L|,
/// L_world stay at rounding level.
#[test]
fn flow_property_and_conservation_over_long_horizons() {
    let moments = DVec3::new(1.0, 2.0, 3.0);
    for l in [
        DVec3::new(0.01, 2.0, 0.0),
        DVec3::new(0.6, -0.2, 1.4),
        DVec3::new(-1.2, 0.5, 0.3),
    ] {
        let s0 = state(l);
        let exact = ExactSolution::try_new(moments, s0).unwrap();
        let (t1, t2) = (1.0e4, 37.25);
        let s1 = exact.state_at(t1);
        let direct = exact.state_at(t1 + t2);
        let restarted = ExactSolution::try_new(moments, s1).unwrap().state_at(t2);
        let dq =
            rotation_angle_between(direct.world_from_principal, restarted.world_from_principal);
        let dl = (direct.l_principal - restarted.l_principal).length() / l.length();
        // The phase at 10⁴ s carries the rounding of λ t (~10⁻¹² rad).
        assert!(dq < 1e-11 && dl < 1e-11, "{l}: {dq:e} {dl:e}");
        let de = (energy(moments, s1.l_principal) - energy(moments, l)).abs() / energy(moments, l);
        let dnorm = (s1.l_principal.length() - l.length()).abs() / l.length();
        let dworld = (s1.l_world() - s0.l_world()).length() / l.length();
        // One evaluation from the tables (≤ 5e-15 absolute in sn, cn, dn),
        // not an accumulation: the invariants hold to a few ulps.
        assert!(
            de < 5e-15 && dnorm < 5e-15 && dworld < 5e-15,
            "{l}: {de:e} {dnorm:e} {dworld:e}"
        );
    }
}

/// A spin exactly about a principal axis is uniform; a spin 1e-9 off the
/// major axis stays within 1e-9 of it, like the splitting integrator says.
#[test]
fn steady_and_nearly_steady_spins() {
    let moments = DVec3::new(1.0, 2.0, 3.0);
    for axis in 0..3 {
        let mut l = [0.0; 3];
        l[axis] = 1.5;
        let l = DVec3::from_array(l);
        let s = ExactSolution::try_new(moments, state(l))
            .unwrap()
            .state_at(4.0);
        let expected = state(l).world_from_principal
            * DQuat::from_axis_angle(l.normalize(), 4.0 * 1.5 / moments[axis]);
        assert!(rotation_angle_between(s.world_from_principal, expected) < 1e-15);
        assert_eq!(s.l_principal, l);
    }
    let l = DVec3::new(1e-9, -2e-9, 3.0);
    let s0 = state(l);
    let exact = ExactSolution::try_new(moments, s0).unwrap().state_at(10.0);
    let mut split = s0;
    integrate(
        FreeBodyMethod::Splitting8.integrator(),
        moments,
        &mut split,
        0.01,
        1000,
    )
    .unwrap();
    let dq = rotation_angle_between(exact.world_from_principal, split.world_from_principal);
    assert!(dq < 1e-12, "{dq:e}");
    assert!((exact.l_principal - split.l_principal).length() < 1e-13);
}

/// Exactly on the separatrix L tends to the saddle ±|L| e₂ and stays
/// finite for ever; one ulp off it the period is finite and huge, and the
/// table stays small.
#[test]
fn on_and_next_to_the_separatrix() {
    // (I₂ − I₁)/I₁ = (I₃ − I₂)/I₃ = 1/3 and L₁ = L₃: exactly on it.
    let moments = DVec3::new(3.0, 4.0, 6.0);
    let l = DVec3::new(1.5, 0.8, 1.5);
    let on = ExactSolution::try_new(moments, state(l)).unwrap();
    assert_eq!(on.half_period(), Some(f64::INFINITY));
    // λ = 0.148/s: sech(λt) < 1e-60 from t = 10³ s on.
    for t in [1e3, 1e6, 1e300] {
        let s = on.state_at(t);
        assert!(
            (s.l_principal - DVec3::new(0.0, l.length(), 0.0)).length() < 1e-12,
            "{t}"
        );
        assert!(s.world_from_principal.is_finite(), "{t}");
    }
    let l_next = DVec3::new(1.5, 0.8, f64::from_bits(1.5f64.to_bits() + 1));
    let next = ExactSolution::try_new(moments, state(l_next)).unwrap();
    let half = next.half_period().unwrap();
    let expected = elliptic_motion(moments, l_next).unwrap().half_period;
    assert!(
        half > 30.0 && (half - expected).abs() < 1e-13 * half,
        "{half}"
    );
    assert!(next.table_pieces() < 64, "{}", next.table_pieces());
    // Over the first 10 s both follow the same heteroclinic path.
    let (a, b) = (on.state_at(10.0), next.state_at(10.0));
    assert!(rotation_angle_between(a.world_from_principal, b.world_from_principal) < 1e-12);
}

/// Bad input gives a typed error or a NaN step, never a panic.
#[test]
fn bad_input() {
    let good = state(DVec3::new(0.3, 0.2, 0.1));
    for moments in [
        DVec3::new(0.0, 1.0, 1.0),
        DVec3::new(1.0, f64::NAN, 1.0),
        DVec3::new(1.0, 1.0, 3.0),
    ] {
        assert!(ExactSolution::try_new(moments, good).is_err(), "{moments}");
    }
    let moments = DVec3::new(1.0, 2.0, 3.0);
    let zero_q = PrincipalState {
        world_from_principal: DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0),
        ..good
    };
    assert!(ExactSolution::try_new(moments, zero_q).is_err());
    let nan_l = state(DVec3::new(f64::NAN, 1.0, 0.0));
    assert!(ExactSolution::try_new(moments, nan_l).is_err());
    let mut s = nan_l;
    FreeBodyMethod::Exact
        .integrator()
        .step(moments, &mut s, 0.1);
    assert!(s.l_principal.is_nan());
    // L = 0: at rest for ever.
    let rest = ExactSolution::try_new(moments, state(DVec3::ZERO))
        .unwrap()
        .state_at(5.0);
    assert_eq!(
        rest.world_from_principal,
        state(DVec3::ZERO).world_from_principal
    );
}

/// `step` (which prepares the solution each call) and the propagator agree.
#[test]
fn step_and_propagator_agree() {
    let moments = DVec3::new(0.5, 0.85, 1.0);
    let s0 = state(DVec3::new(0.45, 0.0, 0.89));
    let m = FreeBodyMethod::Exact.integrator();
    let mut stepped = s0;
    for _ in 0..50 {
        m.step(moments, &mut stepped, 0.2);
    }
    let mut body = m.propagator(moments, s0);
    for _ in 0..50 {
        body.advance(0.2);
    }
    let d = rotation_angle_between(
        stepped.world_from_principal,
        body.state().world_from_principal,
    );
    assert!(d < 1e-13, "{d:e}");
}
