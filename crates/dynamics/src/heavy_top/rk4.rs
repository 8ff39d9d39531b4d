//! The classical fourth-order Runge–Kutta method on the heavy top: the
//! baseline.

use glam::{DQuat, DVec3};

use super::HeavyTop;
use crate::PrincipalState;
use crate::stepping::HeavyTopIntegrator;

/// Classical RK4 (Kutta 1901) on `(q, L)` of the heavy top, with no
/// renormalisation of `q`.
///
/// ```text
/// L̇ = L × ω + c × (Rᵀ W),   q̇ = ½ q ⊗ (0, ω),   ω = J⁻¹ L
/// ```
///
/// Not geometric: the energy, `L_v` and `|q|` drift like `O(h⁴ t)`. Stable
/// for `h |ω|_max ≲ 2.8` (the RK4 stability interval on the imaginary axis,
/// `2√2`, for the rotation at the fastest rate); accurate far below that.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{HeavyTop, HeavyTopRk4, PrincipalState, integrate_heavy_top};
/// let top = HeavyTop::try_from_principal(DVec3::new(0.02, 0.02, 0.01), DVec3::new(0.0, 0.0, 0.1), 1.0, DVec3::new(0.0, 0.0, -9.81))?;
/// let mut s = PrincipalState { world_from_principal: DQuat::from_rotation_x(0.3), l_principal: DVec3::new(0.0, 0.0, 0.5) };
/// let e0 = top.energy(&s);
/// integrate_heavy_top(&HeavyTopRk4, &top, &mut s, 1e-3, 1000)?;
/// assert!((top.energy(&s) - e0).abs() < 1e-9 * e0);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct HeavyTopRk4;

/// The vector field at `(q, L)`.
#[inline]
fn field(top: &HeavyTop, q: DQuat, l: DVec3) -> (DQuat, DVec3) {
    let omega = l / top.body.principal_moments();
    (
        kreisel_kinematics::quat_derivative(q, omega),
        l.cross(omega) + top.torque_principal(q),
    )
}

impl HeavyTopIntegrator for HeavyTopRk4 {
    fn name(&self) -> &'static str {
        "rk4"
    }

    fn order(&self) -> u32 {
        4
    }

    fn description(&self) -> &'static str {
        "classical Runge-Kutta on L and q with the gravity torque, the baseline"
    }

    fn step(&self, top: &HeavyTop, state: &mut PrincipalState, h: f64) {
        let (q, l) = (state.world_from_principal, state.l_principal);
        let (k1q, k1l) = field(top, q, l);
        let (k2q, k2l) = field(top, q + k1q * (0.5 * h), l + k1l * (0.5 * h));
        let (k3q, k3l) = field(top, q + k2q * (0.5 * h), l + k2l * (0.5 * h));
        let (k4q, k4l) = field(top, q + k3q * h, l + k3l * h);
        state.world_from_principal = q + (k1q + k2q * 2.0 + k3q * 2.0 + k4q) * (h / 6.0);
        state.l_principal = l + (k1l + k2l * 2.0 + k3l * 2.0 + k4l) * (h / 6.0);
    }
}
