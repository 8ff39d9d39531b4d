//! The stepping core: the one-step interfaces of the torque-free body
//! ([`FreeBodyIntegrator`]) and of the heavy top ([`HeavyTopIntegrator`]),
//! each carrying its method's facts (name, order, description, step
//! limit) that [`FreeBodyMethod`] and [`HeavyTopMethod`] read; one body
//! advanced step after step ([`Propagator`], which the World, the forced
//! splitting ([`crate::ForcedPropagator`]) and the exact solution
//! ([`crate::ExactPropagator`]) implement too); and the one checked loop
//! behind [`integrate`] and [`integrate_heavy_top`].
//!
//! A body on the ground or the table is not stepped through these: its
//! steps are error-controlled and event-driven
//! ([`crate::GroundTop::try_step`], [`crate::TableMotion`]).

use glam::DVec3;

use crate::{DivergenceCheck, DynamicsError, HeavyTop, PrincipalState, RigidBody};
#[cfg(doc)]
use crate::{FreeBodyMethod, HeavyTopMethod};

/// A one-step method for the torque-free rigid body in its principal frame
/// (`Sync`: a [`crate::World`] steps its bodies on threads and may be sent
/// between threads, e.g. by the Python package, which releases the GIL).
pub trait FreeBodyIntegrator: Sync {
    /// The method's name (e.g. `"rk4"`), which [`FreeBodyMethod`] parses
    /// and writes.
    fn name(&self) -> &'static str;
    /// The order of the method (global error `O(hᵖ)`); `u32::MAX` for the
    /// exact solution, which has no truncation error (where
    /// [`FreeBodyMethod::order`] says `None`).
    fn order(&self) -> u32;
    /// One line about the method, as `kreisel simulate --list-methods`
    /// shows it.
    fn description(&self) -> &'static str;
    /// The largest `h ω_max` at which the method still follows a
    /// torque-free body, measured as [`FreeBodyMethod::step_limit`] says;
    /// `None` (the default) for a method without one (the exact solution)
    /// or not measured.
    ///
    /// ```text
    /// h ω_max ≤ limit,   ω_max = |L| / min(I₁, I₂, I₃)
    /// ```
    fn step_limit(&self) -> Option<f64> {
        None
    }
    /// Advances `state` by `h` seconds for principal moments `moments`.
    ///
    /// Infallible by design (the inner loop of every run): a step that has
    /// no solution (an implicit method beyond its range) or bad moments
    /// leaves a non-finite state, which [`integrate`] and
    /// [`DivergenceCheck`] report as [`DynamicsError::Diverged`].
    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64);

    /// One body from `state`, to be advanced step after step: what
    /// [`integrate`] and `kreisel simulate` use. By default each
    /// [`Propagator::advance`] is one [`FreeBodyIntegrator::step`]; a method
    /// with per-body set-up (the exact solution) prepares it here once.
    fn propagator<'a>(&'a self, moments: DVec3, state: PrincipalState) -> Box<dyn Propagator + 'a> {
        Box::new(Stepping {
            method: self,
            moments,
            state,
        })
    }
}

/// One body advanced by an integrator, step after step (`Send + Sync`, so
/// that a [`crate::World`] holding it can move between threads).
///
/// ```text
/// xₙ₊₁ = Φₕ(xₙ)
/// ```
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{FreeBodyMethod, PrincipalState};
/// let s0 = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 0.0, 2.0) };
/// let strang = FreeBodyMethod::Strang.integrator();
/// let mut body = strang.propagator(DVec3::new(1.0, 1.0, 2.0), s0);
/// body.advance(0.5);
/// body.advance(0.5);
/// assert!(kreisel_kinematics::rotation_angle_between(body.state().world_from_principal, DQuat::from_rotation_z(1.0)) < 1e-15);
/// ```
pub trait Propagator: Send + Sync {
    /// Advances the body by `h` seconds (a step the method cannot take
    /// leaves a non-finite state: see [`DivergenceCheck`]).
    fn advance(&mut self, h: f64);
    /// Advances the body by `h` seconds, or says why the method refuses the
    /// step (e.g. the heavy-top `auto`'s sub-step cap). By default one
    /// [`Propagator::advance`].
    ///
    /// # Errors
    /// The method's refusal, e.g. [`DynamicsError::TooManySubsteps`].
    fn try_advance(&mut self, h: f64) -> Result<(), DynamicsError> {
        self.advance(h);
        Ok(())
    }
    /// The current state.
    fn state(&self) -> PrincipalState;
}

/// The default propagator: repeated steps of a method.
struct Stepping<'a, M: ?Sized> {
    method: &'a M,
    moments: DVec3,
    state: PrincipalState,
}

impl<M: FreeBodyIntegrator + ?Sized> Propagator for Stepping<'_, M> {
    fn advance(&mut self, h: f64) {
        self.method.step(self.moments, &mut self.state, h);
    }

    fn state(&self) -> PrincipalState {
        self.state
    }
}

/// Advances `state` by `steps` steps of size `h`, checking every state
/// reached ([`DivergenceCheck`]).
///
/// ```text
/// x(t₀ + n h) ≈ Φₕⁿ x(t₀)
/// ```
///
/// The answer does not depend on the unit system: every method works in
/// the body's own unit of inertia ([`RigidBody`]'s checks keep it
/// representable), so moments scaled by `s` (and `L` with them) give the
/// same attitude, and `ω` scaled by `s` with `h` by `1/s` the same motion,
/// to rounding.
///
/// # Errors
/// [`DynamicsError::InvalidStep`] for `h` that is not positive and finite;
/// [`DynamicsError::UnphysicalInertia`] for moments that
/// [`RigidBody::try_from_principal_moments`] refuses;
/// [`DynamicsError::InvalidState`] for a state that
/// [`PrincipalState::validate`] refuses; [`DynamicsError::Diverged`] when a
/// state becomes non-finite or drifts beyond [`crate::DIVERGENCE_FACTOR`]
/// (`state` then holds the last good state).
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{integrate, FreeBodyMethod, PrincipalState};
/// let rk4 = FreeBodyMethod::Rk4.integrator();
/// let mut s = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 0.0, 2.0) };
/// integrate(rk4, DVec3::new(1.0, 1.0, 2.0), &mut s, 0.01, 100)?;
/// // Spin about a principal axis: uniform rotation by ω t = 1 rad
/// // (RK4's phase error here: 100 · (h ω/2)⁵/120 ≈ 3e-12 rad).
/// assert!(kreisel_kinematics::rotation_angle_between(s.world_from_principal, DQuat::from_rotation_z(1.0)) < 1e-10);
/// // h ω = 100: far beyond RK4's stability, an error rather than NaN.
/// let mut fast = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(1e4, 2e2, 0.0) };
/// let e = integrate(rk4, DVec3::new(1.0, 2.0, 3.0), &mut fast, 0.01, 100).unwrap_err();
/// assert!(matches!(e, kreisel_dynamics::DynamicsError::Diverged { method: "rk4", .. }), "{e}");
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
pub fn integrate(
    method: &dyn FreeBodyIntegrator,
    moments: DVec3,
    state: &mut PrincipalState,
    h: f64,
    steps: usize,
) -> Result<(), DynamicsError> {
    if !(h.is_finite() && h > 0.0) {
        return Err(DynamicsError::InvalidStep { h });
    }
    RigidBody::try_from_principal_moments(moments)?;
    state.validate(moments)?;
    let check = DivergenceCheck::free_body(method.name(), moments, state);
    checked_steps(method.propagator(moments, *state), &check, state, h, steps)
}

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
        Box::new(HeavyStepping {
            method: self,
            top,
            state,
        })
    }
}

/// Repeated steps of a heavy-top method.
struct HeavyStepping<'a, M: ?Sized> {
    method: &'a M,
    top: &'a HeavyTop,
    state: PrincipalState,
}

impl<M: HeavyTopIntegrator + ?Sized> Propagator for HeavyStepping<'_, M> {
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
    checked_steps(method.propagator(top, *state), &check, state, h, steps)
}

/// The one stepping loop: `steps` steps of `h` of `body` (from `state`),
/// each state reached checked, `state` left at the last good one.
///
/// ```text
/// for k = 1..n:  x ← Φₕ(x) (or the method's refusal);  check(x, k h);  state ← x
/// ```
fn checked_steps(
    mut body: Box<dyn Propagator + '_>,
    check: &DivergenceCheck,
    state: &mut PrincipalState,
    h: f64,
    steps: usize,
) -> Result<(), DynamicsError> {
    for k in 1..=steps {
        body.try_advance(h)?;
        let next = body.state();
        check.check(&next, k as f64 * h)?;
        *state = next;
    }
    Ok(())
}
