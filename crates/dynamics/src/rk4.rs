//! The classical fourth-order Runge–Kutta method on Euler's equations and
//! the quaternion kinematics: the honest baseline.

use glam::{DQuat, DVec3};

use crate::{FreeBodyIntegrator, PrincipalState};

/// Classical RK4 (Kutta 1901) on `(q, L)`, with no renormalisation of `q`.
///
/// ```text
/// L̇ = L × ω,   q̇ = ½ q ⊗ (0, ω),   ω = I⁻¹ L
/// ```
///
/// Not geometric: `|q|`, `|L|` and the energy drift like `O(h⁴ t)`. The
/// quaternion is not renormalised (that would be a stabiliser, not the
/// method); attitudes are compared scale-invariantly.
#[derive(Debug, Clone, Copy, Default)]
pub struct Rk4;

/// The vector field at `(q, L)`.
#[inline]
fn field(moments: DVec3, q: DQuat, l: DVec3) -> (DQuat, DVec3) {
    let omega = l / moments;
    (
        kreisel_kinematics::quat_derivative(q, omega),
        l.cross(omega),
    )
}

impl FreeBodyIntegrator for Rk4 {
    fn name(&self) -> &'static str {
        "rk4"
    }

    fn order(&self) -> u32 {
        4
    }

    fn description(&self) -> &'static str {
        "classical Runge-Kutta on L and q, the baseline; energy, |L| and |q| drift"
    }

    /// 1.0: beyond it the energy drifts (decays) beyond 10 %, and the run
    /// blows up past `2√2`; the error grows with the run's length too (not
    /// geometric).
    fn step_limit(&self) -> Option<f64> {
        Some(1.0)
    }

    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64) {
        let (q, l) = (state.world_from_principal, state.l_principal);
        let (k1q, k1l) = field(moments, q, l);
        let (k2q, k2l) = field(moments, q + k1q * (0.5 * h), l + k1l * (0.5 * h));
        let (k3q, k3l) = field(moments, q + k2q * (0.5 * h), l + k2l * (0.5 * h));
        let (k4q, k4l) = field(moments, q + k3q * h, l + k3l * h);
        state.world_from_principal = q + (k1q + k2q * 2.0 + k3q * 2.0 + k4q) * (h / 6.0);
        state.l_principal = l + (k1l + k2l * 2.0 + k3l * 2.0 + k4l) * (h / 6.0);
    }
}
