//! One stepping interface for the heavy-top integrators: each carries its
//! method's facts (name, order, description), which [`HeavyTopMethod`]
//! reads.

use super::HeavyTop;
#[cfg(doc)]
use crate::HeavyTopMethod;
use crate::{DivergenceCheck, DynamicsError, PrincipalState, Propagator};

/// A one-step method for the heavy top.
pub trait HeavyTopIntegrator: Sync {
    /// The method's name (e.g. `"strang"`), which [`HeavyTopMethod`]
    /// parses and writes.
    fn name(&self) -> &'static str;
    /// The order of the method (global error `O(hᵖ)`).
    fn order(&self) -> u32;
    /// One line about the method, as `kreisel simulate --list-methods`
    /// shows it.
    fn description(&self) -> &'static str;
    /// Advances `state` by `h` seconds.
    ///
    /// Infallible (the inner loop of every run): a step the method cannot
    /// take leaves a non-finite state, which [`integrate_heavy_top`] and
    /// [`crate::DivergenceCheck`] report.
    fn step(&self, top: &HeavyTop, state: &mut PrincipalState, h: f64);

    /// Advances `state` by `h` seconds, or says why the method refuses the
    /// step (the sub-step cap of [`crate::HeavyTopAuto`]). By default one
    /// [`HeavyTopIntegrator::step`].
    ///
    /// # Errors
    /// The method's refusal, e.g. [`DynamicsError::TooManySubsteps`].
    fn try_step(
        &self,
        top: &HeavyTop,
        state: &mut PrincipalState,
        h: f64,
    ) -> Result<(), DynamicsError> {
        self.step(top, state, h);
        Ok(())
    }

    /// One top from `state`, to be advanced step after step (what
    /// `kreisel simulate` uses): each [`Propagator::advance`] is one
    /// [`HeavyTopIntegrator::step`].
    fn propagator<'a>(
        &'a self,
        top: &'a HeavyTop,
        state: PrincipalState,
    ) -> Box<dyn Propagator + 'a> {
        Box::new(Stepping {
            method: self,
            top,
            state,
        })
    }
}

/// Repeated steps of a heavy-top method.
struct Stepping<'a, M: ?Sized> {
    method: &'a M,
    top: &'a HeavyTop,
    state: PrincipalState,
}

impl<M: HeavyTopIntegrator + ?Sized> Propagator for Stepping<'_, M> {
    fn advance(&mut self, h: f64) {
        self.method.step(self.top, &mut self.state, h);
    }

    fn try_advance(&mut self, h: f64) -> Result<(), DynamicsError> {
        self.method.try_step(self.top, &mut self.state, h)
    }

    fn state(&self) -> PrincipalState {
        self.state
    }
}

/// Advances `state` by `steps` steps of size `h`.
///
/// ```text
/// x(t₀ + n h) ≈ Φₕⁿ x(t₀)
/// ```
///
/// Every state reached is checked ([`crate::DivergenceCheck`]).
///
/// # Errors
/// [`DynamicsError::InvalidStep`] for `h` that is not positive and finite;
/// [`DynamicsError::InvalidState`] for a state that
/// [`PrincipalState::validate`] refuses; the method's refusal of a step
/// ([`DynamicsError::TooManySubsteps`]); [`DynamicsError::Diverged`] when a
/// state becomes non-finite or its energy drifts beyond
/// [`crate::DIVERGENCE_FACTOR`] times its scale (`state` then holds the
/// last good state).
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{HeavyTop, HeavyTopMethod, PrincipalState, integrate_heavy_top};
/// let top = HeavyTop::try_from_principal(DVec3::new(0.02, 0.02, 0.01), DVec3::new(0.0, 0.0, 0.1), 1.0, DVec3::new(0.0, 0.0, -9.81))?;
/// let mut s = PrincipalState { world_from_principal: DQuat::from_rotation_x(0.3), l_principal: DVec3::new(0.0, 0.0, 0.5) };
/// let e0 = top.energy(&s);
/// integrate_heavy_top(HeavyTopMethod::Splitting8.integrator(), &top, &mut s, 1e-3, 1000)?;
/// assert!((top.energy(&s) - e0).abs() < 1e-13 * e0);
/// assert!(integrate_heavy_top(HeavyTopMethod::Rk4.integrator(), &top, &mut s, -1.0, 1).is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
pub fn integrate_heavy_top(
    method: &dyn HeavyTopIntegrator,
    top: &HeavyTop,
    state: &mut PrincipalState,
    h: f64,
    steps: usize,
) -> Result<(), DynamicsError> {
    if !(h.is_finite() && h > 0.0) {
        return Err(DynamicsError::InvalidStep { h });
    }
    state.validate(top.body().principal_moments())?;
    let check = DivergenceCheck::heavy_top(method.name(), top, state);
    for k in 1..=steps {
        let mut next = *state;
        method.try_step(top, &mut next, h)?;
        check.check(&next, k as f64 * h)?;
        *state = next;
    }
    Ok(())
}
