//! `auto` for the heavy top: the order-8 composition, with the step
//! subdivided where the stability limits ask for it.

use super::HeavyTop;
use super::integrator::HeavyTopIntegrator;
use super::splitting::HeavyTopSplitting;
use crate::PrincipalState;

/// The fraction of a stability limit `auto` stays below.
const SAFETY: f64 = 0.8;

/// The largest `h |ω|` at which `auto` lets the PDMV10 free flow take a
/// stage. PDMV10 itself breaks down at `h |ω| ≈ 1.6` (its modified moments
/// are power series in `h²`; measured on four bodies, error 10⁻⁴ at 1.5,
/// O(1) at 1.7); at 1.0 its error is ~10⁻⁶ per stage.
pub(crate) const PDMV_STAGE_LIMIT: f64 = 1.0;

/// `auto`: [`HeavyTopSplitting::ORDER_8`], every step split into the fewest
/// equal sub-steps that keep it inside its stability limits.
///
/// ```text
/// n = max(⌈h Ω_g / (0.8 x₈)⌉,  ⌈γ_max h ω_max / 1.0⌉ (PDMV free flow only)),   x₈ = 3.096,  γ_max = 0.6055
/// ```
///
/// Why order 8: on the reference tops it is the most accurate at every
/// step size and also the most stable per step (its largest stage is only
/// 0.61 h, and its limit for gravity swings, `h Ω_g < 3.096`, is the
/// widest of the four compositions; see [`HeavyTopSplitting`]); it is the
/// least stable per unit of work, which `auto` pays for by sub-stepping
/// only where needed. At `dt = 10⁻³` s it keeps the Bruls–Cardona–Arnold
/// fast top (150 rad/s) to ~10⁻¹² rad after 2 s (`tests/heavy_top_reference.rs`).
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{HeavyTop, HeavyTopAuto, HeavyTopIntegrator, PrincipalState};
/// let top = HeavyTop::try_from_principal(DVec3::new(0.02, 0.02, 0.01), DVec3::new(0.0, 0.0, 0.1), 1.0, DVec3::new(0.0, 0.0, -9.81))?;
/// let s = PrincipalState { world_from_principal: DQuat::from_rotation_x(0.3), l_principal: DVec3::new(0.0, 0.0, 0.5) };
/// assert_eq!(HeavyTopAuto.substeps(&top, &s, 0.01), 1);
/// // Ω_g = √(0.981 / 0.02) = 7.0 rad/s: a 1 s step is cut into ⌈7.0 / (0.8 · 3.096)⌉ = 3.
/// assert!((top.gravity_frequency() - 49.05f64.sqrt()).abs() < 1e-12);
/// assert_eq!(HeavyTopAuto.substeps(&top, &s, 1.0), 3);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct HeavyTopAuto;

impl HeavyTopAuto {
    /// The number of equal sub-steps one step of `h` from `state` takes.
    pub fn substeps(&self, top: &HeavyTop, state: &PrincipalState, h: f64) -> usize {
        let method = HeavyTopSplitting::ORDER_8;
        let gravity = h * top.gravity_frequency() / (SAFETY * method.stability_limit());
        let free = if top.free_flow_is_exact() {
            0.0
        } else {
            method.largest_stage() * h * top.angular_speed_bound(state) / PDMV_STAGE_LIMIT
        };
        // A saturating cast: NaN → 0, then at least one step.
        (gravity.max(free).ceil() as usize).max(1)
    }
}

impl HeavyTopIntegrator for HeavyTopAuto {
    fn name(&self) -> &'static str {
        "auto"
    }

    fn order(&self) -> u32 {
        8
    }

    fn step(&self, top: &HeavyTop, state: &mut PrincipalState, h: f64) {
        let n = self.substeps(top, state, h);
        let sub = h / n as f64;
        for _ in 0..n {
            HeavyTopSplitting::ORDER_8.step(top, state, sub);
        }
    }
}
