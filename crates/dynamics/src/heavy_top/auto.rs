//! `auto` for the heavy top: the order-8 composition, with the step
//! subdivided where the stability limits ask for it, for the whole motion.

use super::HeavyTop;
use super::splitting::HeavyTopSplitting;
use crate::stepping::HeavyTopIntegrator;
use crate::{DynamicsError, PrincipalState};

/// The fraction of the small-swing stability limit `auto` stays below.
const SAFETY: f64 = 0.8;

/// The largest `h |ω|` at which `auto` lets the PDMV10 free flow take a
/// stage. PDMV10 itself breaks down at `h |ω| ≈ 1.6` (its modified moments
/// are power series in `h²`; measured on four bodies, error 10⁻⁴ at 1.5,
/// O(1) at 1.7); at 1.0 its error is ~10⁻⁶ per stage.
pub(crate) const PDMV_STAGE_LIMIT: f64 = 1.0;

/// The largest `h ω_swing` per sub-step: how far the body may turn under
/// gravity in one sub-step. The small-swing limit `h Ω_g < 3.096` holds
/// near the bottom of a swing only; a large swing (a pendulum let go near
/// the top, a top whose axis whirls) turns at up to `ω_swing`, and at
/// `h ω_swing ≈ 2` and beyond the kicks, evaluated at attitudes a
/// radian apart, pump energy in (measured in `tests/heavy_top_auto.rs`: a
/// pendulum let go 0.1 rad from the top gained 45× its energy at
/// `dt = 1 s` under the small-swing rule alone). At 1 the energy error
/// there stays below 5e-4 of `|W||c|` at every `dt` from 0.01 s to 100 s
/// (below 1e-6 for the swings over the top), bounded over 100 periods.
pub(crate) const SWING_LIMIT: f64 = 1.0;

/// The most sub-steps one step may take. Beyond it a step is refused
/// ([`DynamicsError::TooManySubsteps`]) rather than run for hours: at
/// ~1 µs per sub-step, 10⁵ sub-steps are 0.1 s per step.
pub const MAX_SUBSTEPS: usize = 100_000;

/// `auto`: [`HeavyTopSplitting::ORDER_8`], every step split into the fewest
/// equal sub-steps that keep it inside its stability limits over the whole
/// motion.
///
/// ```text
/// n = ⌈h · max(Ω_g / (0.8 x₈),  ω_swing / 1.0,  γ_max ω_max / 1.0 (PDMV free flow only))⌉
/// x₈ = 3.096,   γ_max = 0.6055,   n ≤ 10⁵
/// ω_max² = 2 (E + |W||c|) / J_min                        (any rotation, from the energy)
/// ω_swing² = 2 (E + |W||c| − L_k²/2J_k) / J⊥             (Lagrange top, symmetric about k)
/// ω_swing = ω_max                                       (any other top)
/// ```
///
/// The bounds come from the conserved energy `E` and the largest potential
/// `|W||c|`, so they hold at every point of the motion, not only where the
/// step starts: a pendulum-like top that swings through the bottom at its
/// highest speed is sub-stepped for that speed from the first step. For a
/// Lagrange top the spin about the symmetry axis (`L_k` conserved) is
/// taken exactly by the free flow and needs no sub-steps; `ω_swing` counts
/// only the motion of the axis.
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
/// assert_eq!(HeavyTopAuto.try_substeps(&top, &s, 0.01)?, 1);
/// // The axis can swing at up to ω_swing = √(2 · 0.981 (1 + cos 0.3) / 0.02) = 13.8 rad/s:
/// // a 1 s step is cut into 14.
/// assert_eq!(HeavyTopAuto.try_substeps(&top, &s, 1.0)?, 14);
/// // A step that would need more than 10⁵ sub-steps is refused.
/// assert!(HeavyTopAuto.try_substeps(&top, &s, 1e5).is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct HeavyTopAuto;

impl HeavyTopAuto {
    /// The number of equal sub-steps one step of `h` from `state` takes.
    ///
    /// ```text
    /// n = ⌈h r⌉,   r = max(Ω_g / (0.8 x₈), ω_swing, γ_max ω_max)   (see the type's docs)
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::TooManySubsteps`] when `n` exceeds [`MAX_SUBSTEPS`]
    /// or cannot be computed (an energy or a rate that overflows).
    pub fn try_substeps(
        &self,
        top: &HeavyTop,
        state: &PrincipalState,
        h: f64,
    ) -> Result<usize, DynamicsError> {
        substep_count("auto", h, h * substep_rate(top, state))
    }
}

/// The sub-steps a step of `h` takes when it needs `span` of them
/// (rounded up, at least 1), at most [`MAX_SUBSTEPS`].
///
/// # Errors
/// [`DynamicsError::TooManySubsteps`] naming `method` beyond the limit or
/// for a `span` that is NaN.
pub(crate) fn substep_count(
    method: &'static str,
    h: f64,
    span: f64,
) -> Result<usize, DynamicsError> {
    let needed = span.ceil().max(1.0);
    // NaN fails the comparison too.
    if needed <= MAX_SUBSTEPS as f64 {
        Ok(needed as usize)
    } else {
        Err(DynamicsError::TooManySubsteps {
            method,
            h,
            needed,
            limit: MAX_SUBSTEPS,
        })
    }
}

/// Sub-steps per second: the largest of the three rates of the type's docs
/// divided by their limits.
fn substep_rate(top: &HeavyTop, state: &PrincipalState) -> f64 {
    let method = HeavyTopSplitting::ORDER_8;
    let gravity = top.gravity_frequency() / (SAFETY * method.stability_limit());
    let swing = top.swing_rate_bound(state) / SWING_LIMIT;
    let free = if top.free_flow_is_exact() {
        0.0
    } else {
        method.largest_stage() * top.angular_speed_bound(state) / PDMV_STAGE_LIMIT
    };
    // NaN is kept (f64::max would drop it).
    [gravity, swing, free].into_iter().fold(0.0, |acc, r| {
        if r.is_nan() || acc.is_nan() {
            f64::NAN
        } else {
            acc.max(r)
        }
    })
}

impl HeavyTopIntegrator for HeavyTopAuto {
    fn name(&self) -> &'static str {
        "auto"
    }

    fn order(&self) -> u32 {
        8
    }

    fn description(&self) -> &'static str {
        "the default; splitting8, sub-stepped where dt exceeds its stability limit"
    }

    /// As [`HeavyTopIntegrator::try_step`]; a step it refuses leaves a NaN
    /// state (which [`crate::DivergenceCheck`] reports).
    fn step(&self, top: &HeavyTop, state: &mut PrincipalState, h: f64) {
        if self.try_step(top, state, h).is_err() {
            *state = PrincipalState {
                world_from_principal: glam::DQuat::NAN,
                l_principal: glam::DVec3::NAN,
            };
        }
    }

    fn try_step(
        &self,
        top: &HeavyTop,
        state: &mut PrincipalState,
        h: f64,
    ) -> Result<(), DynamicsError> {
        let n = self.try_substeps(top, state, h)?;
        let sub = h / n as f64;
        for _ in 0..n {
            HeavyTopSplitting::ORDER_8.step(top, state, sub);
        }
        Ok(())
    }
}
