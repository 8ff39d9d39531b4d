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
