//! Identities of the closed form: f at the poles and at the start, the
//! effective-potential energy relation, the initial conditions at t = 0.

use super::{LagrangeTop, LagrangeTopInitial};

fn cases() -> Vec<(LagrangeTop, LagrangeTopInitial)> {
    let init = |theta, phi_dot, theta_dot, psi_dot| LagrangeTopInitial {
        phi: 0.3,
        theta,
        psi: -1.1,
        phi_dot,
        theta_dot,
        psi_dot,
    };
    vec![
        (LagrangeTop::new(1.0, 0.5, 1.0), init(0.5, 0.3, 0.2, 20.0)),
        (LagrangeTop::new(1.0, 0.5, 1.0), init(2.5, -0.3, -0.7, 3.0)),
        (LagrangeTop::new(2.0, 0.3, 0.0), init(1.0, 0.4, 0.1, -2.0)),
        (LagrangeTop::new(2.0, 0.3, -1.5), init(2.0, 0.4, 0.1, 5.0)),
        (LagrangeTop::new(2.0, 0.3, 1.5), init(1.0, 0.0, 0.0, 5.0)),
    ]
}

/// f(±1) = −(b ∓ a)² (ERRATA to notes §3.11) and f(u₀) = u̇₀².
#[test]
fn f_at_the_poles_and_at_the_start() {
    for (top, init) in cases() {
        let m = top.try_solve(init).unwrap();
        let scale = m.a().powi(2) + m.b().powi(2) + m.alpha().abs() + m.beta().abs();
        assert!((m.f(1.0) + (m.b() - m.a()).powi(2)).abs() <= 1e-14 * scale);
        assert!((m.f(-1.0) + (m.b() + m.a()).powi(2)).abs() <= 1e-14 * scale);
        let udot = init.theta.sin() * init.theta_dot;
        assert!((m.f(init.theta.cos()) - udot * udot).abs() <= 1e-14 * scale);
        for r in m.roots() {
            assert!(
                m.f(r).abs() <= 1e-13 * scale * r.abs().max(1.0).powi(3),
                "{r}"
            );
        }
    }
}

/// E' = ½I₁θ̇² + V_eff(θ) = ½I₁α along the motion, and t = 0 reproduces
/// the initial conditions.
#[test]
fn energy_in_the_effective_potential() {
    for (top, init) in cases() {
        let m = top.try_solve(init).unwrap();
        let e0 = m.euler_at(0.0);
        assert!((e0.theta - init.theta).abs() < 1e-15);
        assert!((e0.phi - init.phi).abs() < 1e-15 && (e0.psi - init.psi).abs() < 1e-15);
        assert!((e0.theta_dot - init.theta_dot).abs() < 1e-13);
        assert!((e0.phi_dot - init.phi_dot).abs() < 1e-13);
        assert!((e0.psi_dot - init.psi_dot).abs() < 1e-13);
        let e_prime = 0.5 * top.i1() * m.alpha();
        for k in 0..40 {
            let e = m.euler_at(0.31 * k as f64);
            let v = 0.5 * top.i1() * e.theta_dot * e.theta_dot + m.effective_potential(e.theta);
            assert!((v - e_prime).abs() <= 1e-12 * e_prime.abs().max(1.0), "{k}");
        }
    }
}

/// The upright top tilted by θ₀ ≪ 1 and released (θ̇₀ = φ̇₀ = 0) nutates
/// like the linearised top: the axis is the sum of two circular modes
/// turning at ω± = (a ± √(a² − 4Mgl/I₁))/2, so θ_max/θ₀ = a/√(a² − 4Mgl/I₁),
/// the period is 2π/√(a² − 4Mgl/I₁) and the mean precession ω₋ (the slow
/// mode dominates), up to relative O(θ₀²). Issue 25: θ₀ = 10⁻¹⁵ was put on
/// the pole (a sleeping top), unlike 10⁻¹⁴.
#[test]
fn a_tiny_tilt_nutates_like_the_linearised_top() {
    let (i1, i3, mgl, psi_dot) = (0.3, 0.1, 2.0, 60.0);
    let top = LagrangeTop::new(i1, i3, mgl);
    let a = i3 * psi_dot / i1;
    let root = (a * a - 4.0 * mgl / i1).sqrt();
    for theta in [1e-8, 1e-13, 1e-15, 1e-30, 1e-60] {
        let init = LagrangeTopInitial {
            theta,
            psi_dot,
            ..LagrangeTopInitial::default()
        };
        let m = top.try_solve(init).unwrap();
        assert!(!m.is_sleeping(), "{theta}");
        let rel = |got: f64, want: f64| (got / want - 1.0).abs();
        assert!(
            rel(m.theta_min(), theta) < 1e-15,
            "{theta}: {}",
            m.theta_min()
        );
        assert!(
            rel(m.theta_max() / theta, a / root) < 1e-12,
            "{theta}: {}",
            m.theta_max()
        );
        let period = m.nutation_period().unwrap();
        assert!(
            rel(period, std::f64::consts::TAU / root) < 1e-12,
            "{theta}: {period}"
        );
        let mean = m.mean_precession_rate().unwrap();
        assert!(rel(mean, 0.5 * (a - root)) < 1e-9, "{theta}: {mean}");
        assert!(rel(m.euler_at(0.0).theta, theta) < 1e-15);
        assert!(rel(m.euler_at(0.5 * period).theta, m.theta_max()) < 1e-9);
    }
    // Below ~1e-80 rad 1 − cos θ no longer resolves the band: refused by
    // name, not "too large".
    let init = LagrangeTopInitial {
        theta: 1e-90,
        psi_dot,
        ..LagrangeTopInitial::default()
    };
    let e = top.try_solve(init).unwrap_err().to_string();
    assert!(e.contains("theta") && e.contains("too small"), "{e}");
}

/// Released off the vertical with a spin → 0⁺ the top is the plane
/// pendulum that swings almost through the bottom: u's period is
/// 2K(m)/√(Mgl/I₁), m = cos²(θ₀/2), half the pendulum's, and φ turns by π
/// at each close pass of the bottom (⟨φ̇⟩ = π/T). K by the AGM,
/// K(m) = π/(2 AGM(1, √(1 − m))). Issue 25: ψ̇₀ = 10⁻³⁰⁰ was refused as
/// "too large" (1 + u₁ ≈ (b + a)²/(2(α + β)) underflowed to 0 and the
/// third-kind integral became infinite).
#[test]
fn a_vanishing_spin_is_the_pendulum_limit() {
    let (i1, i3, mgl, theta) = (0.3, 0.1, 2.0, 0.5_f64);
    let top = LagrangeTop::new(i1, i3, mgl);
    let m = (0.5 * theta).cos().powi(2);
    let (mut x, mut y) = (1.0_f64, (1.0 - m).sqrt());
    for _ in 0..10 {
        (x, y) = (0.5 * (x + y), (x * y).sqrt());
    }
    let k = std::f64::consts::PI / (2.0 * x);
    let period = 2.0 * k / (mgl / i1).sqrt();
    for psi_dot in [1e-10, 1e-50, 1e-100, 1e-140, 1e-160, 1e-300] {
        let init = LagrangeTopInitial {
            theta,
            psi_dot,
            ..LagrangeTopInitial::default()
        };
        let motion = top.try_solve(init).unwrap();
        let t = motion.nutation_period().unwrap();
        assert!(
            (t / period - 1.0).abs() < 1e-13,
            "{psi_dot}: {t} vs {period}"
        );
        let mean = motion.mean_precession_rate().unwrap();
        let want = std::f64::consts::PI / period;
        assert!(
            (mean / want - 1.0).abs() < 1e-11,
            "{psi_dot}: {mean} vs {want}"
        );
        assert!(
            std::f64::consts::PI - motion.theta_max() < 1e-9,
            "{psi_dot}"
        );
    }
    // ψ̇₀ = 1e-300 passes the bottom within ~1e-301 rad, unresolved: the
    // motion is 1e-10's up to ~1e-10 away from the passes; φ and ψ step by
    // +π at each (the sign of the spin), 3 passes over 3 periods.
    let at = |psi_dot: f64, t: f64| {
        let init = LagrangeTopInitial {
            theta,
            psi_dot,
            ..LagrangeTopInitial::default()
        };
        top.try_solve(init).unwrap().euler_at(t)
    };
    for k in 0..=60 {
        let t = 3.0 * period * (f64::from(k) + 0.37) / 60.0;
        let (small, tiny) = (at(1e-10, t), at(1e-300, t));
        assert!((small.theta - tiny.theta).abs() < 1e-12, "{t}");
        assert!(
            (small.phi - tiny.phi).abs() < 1e-8,
            "{t}: φ {} vs {}",
            small.phi,
            tiny.phi
        );
        assert!(
            (small.psi - tiny.psi).abs() < 1e-8,
            "{t}: ψ {} vs {}",
            small.psi,
            tiny.psi
        );
    }
    let end = at(1e-300, 3.0 * period - 1e-3);
    assert!(
        (end.phi - 3.0 * std::f64::consts::PI).abs() < 1e-9,
        "{}",
        end.phi
    );
    assert!((at(-1e-300, 3.0 * period - 1e-3).phi + 3.0 * std::f64::consts::PI).abs() < 1e-9);
    // A spin whose I₃ω₃/I₁ underflows is refused, not taken as 0.
    let init = LagrangeTopInitial {
        theta,
        psi_dot: 5e-324,
        ..LagrangeTopInitial::default()
    };
    let e = top.try_solve(init).unwrap_err().to_string();
    assert!(e.contains("psi_dot") && e.contains("too small"), "{e}");
}
