//! Stepping one forced body through time, with the checks that stop a run
//! whose state has stopped being usable.

use super::{ForcedBody, ForcedSplitting, ForcedState};
use crate::error::Divergence;
use crate::{DIVERGENCE_FACTOR, DynamicsError, PrincipalState, Propagator};

/// One forced body advanced step after step from a time and a state.
///
/// With applied inputs the energy is not conserved, so the checks are the
/// ones that hold whatever is applied: every number finite — the state and
/// what a row reports from it, ω, `L_world` and the mechanical energy —
/// and `|q|` within a factor [`DIVERGENCE_FACTOR`] of its start (every
/// stage is a rotation, so `|q|` moves by rounding only).
///
/// No energy or `|L|` drift check as a free body has: with inputs both
/// change by the work and the impulse done, and every stage of the
/// splitting is an exact flow (the free flow, the kicks, damping's exact
/// decay), so no step amplifies an error the way an unstable method does —
/// a large error is inaccuracy of the composition, not instability. The
/// mechanical energy minus the work done ([`ForcedBody::power`]) is a
/// diagnostic of that accuracy (`tests/forced_reference.rs`), not a check.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{ForcedBody, ForcedPropagator, ForcedSplitting, ForcedState, Inputs, RigidBody};
/// let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0))?;
/// let forced = ForcedBody::try_new(body, 1.0, DVec3::new(0.0, 0.0, -9.81), Inputs::default().with_torque_body(DVec3::X))?;
/// let s0 = ForcedState::try_new(&body, DQuat::IDENTITY, DVec3::Y, DVec3::ZERO, DVec3::ZERO)?;
/// let mut p = ForcedPropagator::try_new(ForcedSplitting::DEFAULT, &forced, 0.0, s0)?;
/// for _ in 0..100 {
///     p.try_advance(0.01)?;
/// }
/// // Free fall: z = −g t²/2, exact.
/// assert!((p.time() - 1.0).abs() < 1e-14);
/// assert!((p.forced_state().position_world.z + 9.81 / 2.0).abs() < 1e-12);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone)]
pub struct ForcedPropagator<'a> {
    method: ForcedSplitting,
    body: &'a ForcedBody,
    time: f64,
    state: ForcedState,
    q_norm: f64,
}

impl<'a> ForcedPropagator<'a> {
    /// `body` at time `t0` in `state`, to be advanced by `method`.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidState`] for a state that
    /// [`PrincipalState::validate`] refuses;
    /// [`DynamicsError::InvalidBodyParameter`] for a non-finite position,
    /// velocity or `t0`.
    pub fn try_new(
        method: ForcedSplitting,
        body: &'a ForcedBody,
        t0: f64,
        state: ForcedState,
    ) -> Result<Self, DynamicsError> {
        state.rotation.validate(body.body().principal_moments())?;
        super::state::check_finite("position_world", state.position_world)?;
        super::state::check_finite("velocity_world", state.velocity_world)?;
        if !t0.is_finite() {
            return Err(DynamicsError::InvalidBodyParameter {
                parameter: "t0",
                value: t0,
                reason: "must be finite",
            });
        }
        Ok(Self {
            method,
            body,
            time: t0,
            q_norm: state.rotation.world_from_principal.length(),
            state,
        })
    }

    /// The current time, s.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The current state.
    pub fn forced_state(&self) -> ForcedState {
        self.state
    }

    /// Replaces the state between steps (a new angular velocity, an
    /// angular impulse); the time stays.
    pub fn set_state(&mut self, state: ForcedState) {
        self.q_norm = state.rotation.world_from_principal.length();
        self.state = state;
    }

    /// Advances by `h` seconds, or says why the run has stopped; on an
    /// error the state and time are those before the step.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidStep`] for `h` that is not positive and
    /// finite; [`DynamicsError::Diverged`] when the new state is not finite
    /// or `|q|` has left its band.
    pub fn try_advance(&mut self, h: f64) -> Result<(), DynamicsError> {
        if !(h.is_finite() && h > 0.0) {
            return Err(DynamicsError::InvalidStep { h });
        }
        self.state = checked_step(
            self.method,
            self.body,
            &self.state,
            self.time,
            h,
            self.q_norm,
        )?;
        self.time += h;
        Ok(())
    }
}

/// The first quantity a row reports that is not finite although `state`
/// is: `ω = I⁻¹L`, `L_world` or the mechanical energy (`½ L·I⁻¹L` or
/// `½ m|v|²` overflow long before `L` or `v` do).
fn overflowed(body: &ForcedBody, state: &ForcedState) -> Option<&'static str> {
    let rotation = &state.rotation;
    if !(rotation.l_principal / body.body().principal_moments()).is_finite() {
        Some("angular velocity")
    } else if !(rotation.world_from_principal.normalize() * rotation.l_principal).is_finite() {
        Some("angular momentum")
    } else if !body.mechanical_energy(state).is_finite() {
        Some("energy")
    } else {
        None
    }
}

/// One step of `method` from `(t, state)` by `h`, checked: every number
/// finite, and every quantity a row reports from it (ω, `L_world`, the
/// energy), and `|q|` within a factor [`DIVERGENCE_FACTOR`] of `q_norm`
/// (the checks of [`ForcedPropagator::try_advance`], shared with the
/// world).
///
/// # Errors
/// [`DynamicsError::Diverged`] (at `t + h`) for a state that fails them.
pub(crate) fn checked_step(
    method: ForcedSplitting,
    body: &ForcedBody,
    state: &ForcedState,
    t: f64,
    h: f64,
    q_norm: f64,
) -> Result<ForcedState, DynamicsError> {
    let mut next = *state;
    method.step(body, &mut next, t, h);
    let fail = |reason| DynamicsError::Diverged {
        method: method.name(),
        time: t + h,
        reason,
    };
    if !next.is_finite() {
        return Err(fail(Divergence::NonFinite));
    }
    if let Some(quantity) = overflowed(body, &next) {
        return Err(fail(Divergence::Overflow { quantity }));
    }
    let norm = next.rotation.world_from_principal.length();
    if !(norm <= q_norm * DIVERGENCE_FACTOR && norm >= q_norm / DIVERGENCE_FACTOR) {
        return Err(fail(Divergence::Drift {
            quantity: "|q|",
            initial: q_norm,
            current: norm,
        }));
    }
    Ok(next)
}
impl Propagator for ForcedPropagator<'_> {
    /// One step, unchecked: a step the method cannot take leaves a
    /// non-finite state (see [`ForcedPropagator::try_advance`] for the
    /// checked step).
    fn advance(&mut self, h: f64) {
        self.method.step(self.body, &mut self.state, self.time, h);
        self.time += h;
    }

    fn try_advance(&mut self, h: f64) -> Result<(), DynamicsError> {
        ForcedPropagator::try_advance(self, h)
    }

    fn state(&self) -> PrincipalState {
        self.state.rotation
    }
}
