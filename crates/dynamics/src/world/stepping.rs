//! Moving a [`World`] forward: one step for a game loop, whole steps of
//! `dt`, or up to a time on the grid of `kreisel simulate`; every state
//! reached is checked. Forced bodies ([`crate::Plan::Forced`]) step like
//! the stepping methods: the step from grid time `t` by `h` is
//! [`crate::ForcedSplitting::step`] at `t` with the checks of
//! [`crate::ForcedPropagator::try_advance`].

use super::clock::Route;
use super::plan::Motion;
use super::{World, registry};
use crate::{DivergenceCheck, DynamicsError, forced};

/// The first failure of a run: step number, body, error.
type Failure = (u64, usize, DynamicsError);

impl World {
    /// One step of `h` seconds for every body (a game loop's frame): a
    /// stepping method takes one step of `h`, an exact solution is
    /// evaluated at the new time (accumulated in double-double, exactly as
    /// [`crate::ExactPropagator`] does), a resting body costs nothing.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidStep`] for an `h` that is not positive and
    /// finite; [`DynamicsError::BodyFailed`] naming the first body whose
    /// step failed or diverged, and when (see [`World::advance_to`]).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, World};
    /// let mut world = World::try_new(DVec3::ZERO, 1.0 / 60.0)?;
    /// world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::Y).try_build()?)?;
    /// for _ in 0..60 {
    ///     world.step(1.0 / 60.0)?;
    /// }
    /// assert!((world.time() - 1.0).abs() < 1e-15);
    /// assert!(world.step(-1.0).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn step(&mut self, h: f64) -> Result<(), DynamicsError> {
        if !(h.is_finite() && h > 0.0) {
            return Err(DynamicsError::InvalidStep { h });
        }
        let route = self.clock.step_route(h);
        self.run(route)
    }

    /// `n` whole steps of `dt`: exact solutions are evaluated once, at the
    /// end; stepping methods take the `n` steps.
    ///
    /// # Errors
    /// As [`World::advance_to`].
    ///
    /// ```
    /// # use kreisel_dynamics::{Body, World};
    /// let mut world = World::try_new(glam::DVec3::ZERO, 0.1)?;
    /// world.advance_steps(3)?;
    /// assert_eq!(world.time(), 3.0 * 0.1);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn advance_steps(&mut self, n: u64) -> Result<(), DynamicsError> {
        let route = Route {
            whole: n,
            last: None,
            end: self.clock.after_whole(n),
        };
        self.run(route)
    }

    /// Advances the world to time `t` (s): exact solutions are evaluated
    /// once, at `t`; stepping methods take steps of `dt` along the world's
    /// grid, the last one shortened to land on `t` exactly — the grid of
    /// `kreisel simulate`:
    ///
    /// ```text
    /// N = (t − t_grid)/dt rounded up (to the nearest whole number within 1e-6)
    /// steps of dt up to grid point N − 1, then one of t − (t_grid + (N − 1) dt)
    /// ```
    ///
    /// (`t_grid` is 0, or the time of the last step that was not a whole
    /// step of `dt`.)
    ///
    /// # Errors
    /// [`DynamicsError::InvalidTime`] for a `t` that is not finite or lies
    /// before the world's time; [`DynamicsError::BodyFailed`] naming the
    /// first body (earliest step, then lowest index) whose step was refused
    /// ([`DynamicsError::TooManySubsteps`]) or whose state became
    /// non-finite or drifted ([`DynamicsError::Diverged`]). After such an
    /// error each body holds the state it had reached and the world refuses
    /// to move on (it returns the same error).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{Body, World};
    /// let mut world = World::try_new(DVec3::ZERO, 0.01)?;
    /// world.set_free_body_method(kreisel_dynamics::FreeBodyMethod::Rk4)?;
    /// let fast = Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::new(1e4, 1e2, 0.0));
    /// world.add(fast.try_build()?)?;
    /// // h ω = 100: far beyond RK4's stability.
    /// let e = world.advance_to(1.0).unwrap_err();
    /// assert!(matches!(e, kreisel_dynamics::DynamicsError::BodyFailed { body: 0, .. }), "{e}");
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn advance_to(&mut self, t: f64) -> Result<(), DynamicsError> {
        let route = self.clock.route_to(t)?;
        self.run(route)
    }

    /// Moves every body along `route`, checking every state reached.
    fn run(&mut self, route: Route) -> Result<(), DynamicsError> {
        if let Some(error) = &self.failed {
            return Err(error.clone());
        }
        if route.whole == 0 && route.last.is_none() {
            return Ok(());
        }
        let end = self.clock.end_of(&route);
        let (clock, dt) = (self.clock, self.clock.dt());
        let heavy = registry::heavy_top(self.heavy_method);
        // The time of step k of the route (1-based; the last one ends at route.end).
        let time_of = |k: u64| {
            if k <= route.whole {
                clock.after_whole(k)
            } else {
                route.end
            }
        };
        let mut first: Option<Failure> = None;
        for (index, entry) in self.entries.iter_mut().enumerate() {
            let failure = match &mut entry.motion {
                // At rest the state is the exact solution's value at its
                // start, finite and checked when the plan was made.
                Motion::Resting { state, settled } => {
                    *state = *settled;
                    None
                }
                motion @ Motion::Exact { .. } => {
                    motion.evaluate_at(end);
                    let check = entry.check.as_ref();
                    check
                        .and_then(|c| c.check(&motion.state(), route.end).err())
                        .map(|e| (route.whole + 1, e))
                }
                Motion::Stepping(propagator) => {
                    let check = entry.check.as_ref();
                    let mut step = |k: u64, h: f64| {
                        propagator.try_advance(h)?;
                        match check {
                            Some(c) => c.check(&propagator.state(), time_of(k)),
                            None => Ok(()),
                        }
                    };
                    walk(&route, dt, &mut step)
                }
                Motion::Forced {
                    method,
                    body,
                    state,
                    q_norm,
                } => {
                    // Step k starts at the grid time of step k − 1 (loads
                    // that read the time see the world's clock).
                    let mut step = |k: u64, h: f64| {
                        let t = if k == 1 { clock.time() } else { time_of(k - 1) };
                        *state = forced::checked_step(*method, body, state, t, h, *q_norm)?;
                        Ok(())
                    };
                    walk(&route, dt, &mut step)
                }
                Motion::HeavyTop(state) => match &entry.top {
                    Some(top) => {
                        let check = DivergenceCheck::heavy_top(heavy.name(), top, &entry.baseline);
                        let mut step = |k: u64, h: f64| {
                            let mut next = *state;
                            heavy.try_step(top, &mut next, h)?;
                            check.check(&next, time_of(k))?;
                            *state = next;
                            Ok(())
                        };
                        walk(&route, dt, &mut step)
                    }
                    None => None,
                },
            };
            if let Some((k, error)) = failure
                && first.as_ref().is_none_or(|(k0, _, _)| k < *k0)
            {
                first = Some((k, index, error));
            }
        }
        match first {
            None => {
                self.clock.follow(&route);
                Ok(())
            }
            Some((k, body, source)) => {
                let error = DynamicsError::BodyFailed {
                    body,
                    time: time_of(k),
                    source: Box::new(source),
                };
                self.failed = Some(error.clone());
                Err(error)
            }
        }
    }
}

/// Takes the route's whole steps of `dt` and its last step through
/// `step(k, h)` (k from 1); the first failure and its step number.
fn walk(
    route: &Route,
    dt: f64,
    step: &mut dyn FnMut(u64, f64) -> Result<(), DynamicsError>,
) -> Option<(u64, DynamicsError)> {
    for k in 1..=route.whole {
        if let Err(e) = step(k, dt) {
            return Some((k, e));
        }
    }
    let h = route.last?;
    step(route.whole + 1, h).err().map(|e| (route.whole + 1, e))
}
