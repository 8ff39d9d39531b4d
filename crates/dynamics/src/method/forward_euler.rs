//! Adding a free-body method is one file plus one line of the list: this
//! file is that file for forward Euler (a method kreisel does not ship),
//! and the list given one extra line, `Euler => &FORWARD_EULER`, makes an
//! enum that parses, lists, describes and runs it like any other.

use glam::{DQuat, DVec3};

use super::free_body_methods;
use crate::{ExactSolution, FreeBodyIntegrator, PrincipalState, integrate};

/// Forward Euler on `(q, L)` (Euler 1768), order 1: the simplest method,
/// and the least faithful.
///
/// ```text
/// Lₙ₊₁ = Lₙ + h Lₙ × ωₙ,   qₙ₊₁ = qₙ + h ½ qₙ ⊗ (0, ωₙ),   ωₙ = I⁻¹ Lₙ
/// ```
#[derive(Debug, Clone, Copy)]
struct ForwardEuler;

/// The method's integrator, as the list names it.
const FORWARD_EULER: ForwardEuler = ForwardEuler;

impl FreeBodyIntegrator for ForwardEuler {
    fn name(&self) -> &'static str {
        "euler"
    }

    fn order(&self) -> u32 {
        1
    }

    fn description(&self) -> &'static str {
        "forward Euler on L and q, order 1 (a test's method)"
    }

    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64) {
        let (q, l) = (state.world_from_principal, state.l_principal);
        let omega = l / moments;
        state.world_from_principal = q + kreisel_kinematics::quat_derivative(q, omega) * h;
        state.l_principal = l + l.cross(omega) * h;
    }
}

free_body_methods! {
    /// The free-body methods and forward Euler.
    enum WithEuler {
        /// `euler`: forward Euler ([`ForwardEuler`]), order 1.
        Euler => &FORWARD_EULER,
    }
}

/// The largest difference of `L` from the exact motion after `T = 2 s` of
/// steps `h` (`I` = (1, 2, 3) kg m², an asymmetric body tumbling near its
/// middle axis).
fn error_at(method: WithEuler, h: f64) -> f64 {
    let moments = DVec3::new(1.0, 2.0, 3.0);
    let s0 = PrincipalState {
        world_from_principal: DQuat::IDENTITY,
        l_principal: DVec3::new(0.2, 1.0, 0.3),
    };
    let steps = (2.0 / h).round() as usize;
    let mut s = s0;
    integrate(method.integrator(), moments, &mut s, h, steps).unwrap();
    let exact = ExactSolution::try_new(moments, s0).unwrap().state_at(2.0);
    (s.l_principal - exact.l_principal).length()
}

#[test]
fn the_new_method_is_parsed_listed_and_described_from_its_integrator() {
    let euler: WithEuler = "euler".parse().unwrap();
    assert_eq!(euler, WithEuler::Euler);
    assert_eq!(WithEuler::ALL.len(), crate::FreeBodyMethod::ALL.len() + 1);
    assert_eq!(WithEuler::ALL.last(), Some(&WithEuler::Euler));
    assert_eq!(
        (euler.name(), euler.order(), euler.description()),
        ("euler", Some(1), FORWARD_EULER.description())
    );
    assert_eq!(euler.to_string(), "euler");
    // What it does not say it has: no step limit, no heavy-top version.
    assert_eq!((euler.step_limit(), euler.heavy_top()), (None, None));
    assert_eq!(euler.resolve(), euler);
    // The methods of the list are all still there, with their facts.
    for (old, new) in crate::FreeBodyMethod::ALL.into_iter().zip(WithEuler::ALL) {
        assert_eq!(old.name(), new.name());
        assert_eq!(
            (
                old.order(),
                old.description(),
                old.step_limit(),
                old.heavy_top()
            ),
            (
                new.order(),
                new.description(),
                new.step_limit(),
                new.heavy_top()
            )
        );
    }
    assert_eq!(WithEuler::default(), WithEuler::Auto);
    let e = "eulr".parse::<WithEuler>().unwrap_err().to_string();
    assert!(e.ends_with("pdmv8, pdmv10, euler)"), "{e}");
}

#[test]
fn the_new_method_runs_and_converges_at_order_1() {
    // Halving h halves forward Euler's error: ratio 2 = 2¹.
    let (coarse, fine) = (
        error_at(WithEuler::Euler, 1e-3),
        error_at(WithEuler::Euler, 5e-4),
    );
    let ratio = coarse / fine;
    eprintln!("forward Euler: error {coarse:.3e} at h = 1e-3, {fine:.3e} at h/2: ratio {ratio:.4}");
    assert!(
        (ratio - 2.0).abs() < 0.05,
        "{coarse:e} / {fine:e} = {ratio}"
    );
    // And an order-2 method of the same list, for contrast: ratio 4.
    let strang = error_at(WithEuler::Strang, 1e-2) / error_at(WithEuler::Strang, 5e-3);
    eprintln!("strang: ratio {strang:.4}");
    assert!((strang - 4.0).abs() < 0.1, "{strang}");
}
