//! Moving a [`World`] forward: one step for a game loop, whole steps of
//! `dt`, or up to a time on the grid of `kreisel simulate`; every state
//! reached is checked. Forced bodies ([`crate::Plan::Forced`]) step like
//! the stepping methods: the step from grid time `t` by `h` is
//! [`crate::ForcedSplitting::step`] at `t` with the checks of
//! [`crate::ForcedPropagator::try_advance`].

use super::clock::{Clock, Route, elapsed};
use super::ground_motion::GroundMotion;
use super::motion::{ForcedMotion, Motion};
use super::table_run::TableRun;
use super::{Entry, World};
use crate::elliptic::dd::Dd;
use crate::{
    Divergence, DivergenceCheck, DynamicsError, ExactSolution, HeavyTop, HeavyTopClosedForm,
    HeavyTopIntegrator, PrincipalState,
};

/// The first failure of a run: step number, body, error.
type Failure = (u64, usize, DynamicsError);

impl World {
    /// One step of `h` seconds for every body (a game loop's frame): a
    /// stepping method takes one step of `h`, an exact solution is
    /// evaluated at the new time (accumulated in double-double, exactly as
    /// [`crate::ExactPropagator`] does), a resting body costs nothing, a
    /// body on the ground takes sub-steps of at most `dt`.
    ///
    /// `h` is how far to go now; `dt` ([`World::try_new`]) is the world's
    /// grid. With `h == dt` (a game loop whose frame time is the world's
    /// `dt`) the step is a whole step of the grid; any other `h` is taken
    /// as it is and the grid restarts from the new time.
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

    /// Moves every body along `route`, checking every state reached: the
    /// bodies that step every `dt` (heavy tops, forced bodies) on up to
    /// [`World::threads`] scoped threads, the others on the calling thread.
    /// Resting bodies are not touched (but for the first move after their
    /// plan was made); uniform rotations are evaluated in their batch; the
    /// loop over the other entries visits only them (`moving`).
    fn run(&mut self, route: Route) -> Result<(), DynamicsError> {
        if let Some(error) = &self.failed {
            return Err(error.clone());
        }
        if route.whole == 0 && route.last.is_none() {
            return Ok(());
        }
        let end = self.clock.end_of(&route);
        let walker = Walker {
            route,
            clock: self.clock,
            end,
        };
        let mut first: Option<Failure> = None;
        self.settle_fresh();
        for slot in self.uniform.evaluate(end) {
            let index = self.uniform.entry(slot);
            let entry = &self.entries[index];
            let state = entry.motion.state(&self.uniform);
            let failure = entry
                .check
                .as_ref()
                .and_then(|c| c.check(&state, route.end).err());
            first = earlier(first, failure.map(|e| (route.whole + 1, index, e)));
        }
        let mut jobs = Vec::with_capacity(self.moving.len());
        // The entries of `moving` (ascending), borrowed one by one.
        let mut rest: &mut [Entry] = &mut self.entries;
        let mut offset = 0;
        for &index in &self.moving {
            let Some((entry, tail)) = std::mem::take(&mut rest)
                .get_mut(index - offset..)
                .and_then(|s| s.split_first_mut())
            else {
                break;
            };
            (rest, offset) = (tail, index + 1);
            let Entry {
                motion,
                top,
                baseline,
                check,
                ..
            } = entry;
            let failure = match motion {
                // Not in `moving`: settled above (at rest the state is the
                // exact solution's value at its start, finite and checked
                // when the plan was made) or evaluated in the batch.
                Motion::Resting { .. } | Motion::Uniform { .. } => None,
                Motion::Exact {
                    solution,
                    start,
                    state,
                } => {
                    jobs.push((
                        index,
                        Job::Exact {
                            solution,
                            start: *start,
                            state,
                            check: check.as_ref(),
                        },
                    ));
                    None
                }
                Motion::LagrangeTop {
                    closed,
                    start,
                    state,
                } => {
                    let t = elapsed(end, *start);
                    jobs.push((
                        index,
                        Job::LagrangeTop {
                            closed,
                            t: t.hi + t.lo,
                            state,
                        },
                    ));
                    None
                }
                // Free-body propagators are not `Send`: stepped here.
                Motion::Stepping(propagator) => {
                    let check = check.as_ref();
                    let mut step = |k: u64, h: f64| {
                        propagator.try_advance(h)?;
                        match check {
                            Some(c) => c.check(&propagator.state(), walker.time_of(k)),
                            None => Ok(()),
                        }
                    };
                    walker.walk(&mut step)
                }
                Motion::Forced(forced) => {
                    jobs.push((index, Job::Forced(forced)));
                    None
                }
                Motion::Ground(ground) => {
                    jobs.push((index, Job::Ground(ground)));
                    None
                }
                Motion::Table(table) => {
                    jobs.push((index, Job::Table(table)));
                    None
                }
                Motion::HeavyTop { state, integrator } => {
                    if let Some(top) = top.as_ref() {
                        jobs.push((
                            index,
                            Job::HeavyTop {
                                top,
                                baseline,
                                state,
                                heavy: *integrator,
                            },
                        ));
                    }
                    None
                }
            };
            first = earlier(first, failure.map(|(k, e)| (k, index, e)));
        }
        let first = earlier(first, walker.run_jobs(&mut jobs, self.threads.get()));
        match first {
            None => {
                self.clock.follow(&route);
                Ok(())
            }
            Some((k, body, source)) => {
                let error = DynamicsError::BodyFailed {
                    body,
                    time: walker.time_of(k),
                    source: Box::new(source),
                };
                self.failed = Some(error.clone());
                Err(error)
            }
        }
    }
}

/// The fewest stepping bodies a thread is given: fewer are not worth a
/// thread (a spawn costs about as much as a few heavy-top steps).
pub(crate) const MIN_BODIES_PER_THREAD: usize = 2;

/// The fewest body-steps a thread is given (a single `step` of a small
/// world stays on the calling thread).
pub(crate) const MIN_BODY_STEPS_PER_THREAD: u64 = 64;

/// The number of threads for `bodies` bodies taking `body_steps` steps in
/// all (an exact evaluation counts as one), at most `threads`:
///
/// ```text
/// min(threads, bodies / MIN_BODIES_PER_THREAD, body_steps / MIN_BODY_STEPS_PER_THREAD), at least 1
/// ```
pub(crate) fn threads_for(threads: usize, bodies: usize, body_steps: u64) -> usize {
    let by_work = body_steps / MIN_BODY_STEPS_PER_THREAD;
    let by_work = usize::try_from(by_work).unwrap_or(usize::MAX);
    threads
        .min(bodies / MIN_BODIES_PER_THREAD)
        .min(by_work)
        .max(1)
}

/// The earlier of two failures: the smaller step number, then the smaller
/// body index (the failure a single thread reports first).
fn earlier(a: Option<Failure>, b: Option<Failure>) -> Option<Failure> {
    match (a, b) {
        (Some(a), Some(b)) => Some(if (b.0, b.1) < (a.0, a.1) { b } else { a }),
        (a, b) => a.or(b),
    }
}

/// A body moved by a job, borrowed from its entry so that it can be sent
/// to another thread (every field is `Send`): one that steps every `dt`,
/// or an exact solution or a Lagrange top's closed form evaluated once at
/// the route's end.
enum Job<'a> {
    /// A Lagrange top: its closed form evaluated `t` after its start.
    LagrangeTop {
        closed: &'a HeavyTopClosedForm,
        t: f64,
        state: &'a mut PrincipalState,
    },
    /// A symmetric or asymmetric free body: its exact solution from world
    /// time `start`, evaluated at the end and checked.
    Exact {
        solution: &'a ExactSolution,
        start: Dd,
        state: &'a mut PrincipalState,
        check: Option<&'a DivergenceCheck<'static>>,
    },
    /// A heavy top: stepped by the world's heavy-top method.
    HeavyTop {
        top: &'a HeavyTop,
        baseline: &'a PrincipalState,
        state: &'a mut PrincipalState,
        heavy: &'static (dyn HeavyTopIntegrator + Sync),
    },
    /// A body under inputs (or a heavy top under a tolerance): stepped by
    /// its splitting.
    Forced(&'a mut ForcedMotion),
    /// A body on the ground: stepped by its contact model's RK4.
    Ground(&'a mut GroundMotion),
    /// A body on the table: its run advanced to the route's end in its
    /// own steps.
    Table(&'a mut TableRun),
}

/// What every body's walk along a route needs (`Copy`, `Send`).
#[derive(Clone, Copy)]
struct Walker {
    route: Route,
    clock: Clock,
    /// The exact time at the end of the route.
    end: Dd,
}

impl Walker {
    /// The time of step `k` of the route (1-based; the last one ends at `route.end`).
    fn time_of(&self, k: u64) -> f64 {
        if k <= self.route.whole {
            self.clock.after_whole(k)
        } else {
            self.route.end
        }
    }

    /// The first step of the route (1-based) that ends at or after `t`
    /// (the last one for a `t` beyond the route).
    fn step_at(&self, t: f64) -> u64 {
        let last = self.route.whole + u64::from(self.route.last.is_some());
        // time_of is increasing in k: the first k with time_of(k) ≥ t.
        let (mut lo, mut hi) = (1, last.max(1));
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if self.time_of(mid) >= t {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        lo
    }

    /// Takes the route's whole steps of `dt` and its last step through
    /// `step(k, h)` (k from 1); the first failure and its step number.
    fn walk(
        &self,
        step: &mut dyn FnMut(u64, f64) -> Result<(), DynamicsError>,
    ) -> Option<(u64, DynamicsError)> {
        let route = &self.route;
        for k in 1..=route.whole {
            if let Err(e) = step(k, self.clock.dt()) {
                return Some((k, e));
            }
        }
        let h = route.last?;
        step(route.whole + 1, h).err().map(|e| (route.whole + 1, e))
    }

    /// Moves one stepping body along the route.
    fn job(&self, job: &mut Job<'_>) -> Option<(u64, DynamicsError)> {
        match job {
            Job::LagrangeTop { closed, t, state } => {
                **state = closed.state_at(*t);
                let finite =
                    state.world_from_principal.is_finite() && state.l_principal.is_finite();
                (!finite).then(|| {
                    let error = DynamicsError::Diverged {
                        method: "closed form",
                        time: self.route.end,
                        reason: Divergence::NonFinite,
                    };
                    (self.route.whole + 1, error)
                })
            }
            Job::Exact {
                solution,
                start,
                state,
                check,
            } => {
                let t = elapsed(self.end, *start);
                **state = solution.state_at_split(t.hi, t.lo);
                check
                    .and_then(|c| c.check(state, self.route.end).err())
                    .map(|e| (self.route.whole + 1, e))
            }
            Job::HeavyTop {
                top,
                baseline,
                state,
                heavy,
            } => {
                let check = DivergenceCheck::heavy_top(heavy.name(), top, baseline);
                let mut step = |k: u64, h: f64| {
                    let mut next = **state;
                    heavy.try_step(top, &mut next, h)?;
                    check.check(&next, self.time_of(k))?;
                    **state = next;
                    Ok(())
                };
                self.walk(&mut step)
            }
            Job::Forced(forced) => {
                // Step k starts at the grid time of step k − 1 (loads
                // that read the time see the world's clock).
                let mut step = |k: u64, h: f64| {
                    let t = if k == 1 {
                        self.clock.time()
                    } else {
                        self.time_of(k - 1)
                    };
                    forced.step(t, h)
                };
                self.walk(&mut step)
            }
            Job::Ground(ground) => {
                let mut step = |k: u64, h: f64| {
                    let t = if k == 1 {
                        self.clock.time()
                    } else {
                        self.time_of(k - 1)
                    };
                    ground.step(t, h)
                };
                self.walk(&mut step)
            }
            Job::Table(table) => {
                // The grid is for reading only: one advance to the end.
                let advanced = table.advance_to(self.route.end);
                advanced.err().map(|e| (self.step_at(table.time()), e))
            }
        }
    }

    /// Moves the bodies `(index, job)` along the route one after the
    /// other; the earliest failure.
    fn chunk(&self, jobs: &mut [(usize, Job<'_>)]) -> Option<Failure> {
        jobs.iter_mut().fold(None, |first, (index, job)| {
            earlier(first, self.job(job).map(|(k, e)| (k, *index, e)))
        })
    }

    /// Moves the stepping bodies `(index, job)` along the route in
    /// contiguous chunks on up to `threads` scoped threads
    /// ([`threads_for`]); the earliest failure. Each body's arithmetic is
    /// the same on any thread, so the states and the failure reported do
    /// not depend on `threads`. A panic in a user load is resumed here.
    fn run_jobs(&self, jobs: &mut [(usize, Job<'_>)], threads: usize) -> Option<Failure> {
        let steps = self.route.whole + u64::from(self.route.last.is_some());
        // An exact evaluation costs about one step.
        let work = jobs
            .iter()
            .map(|(_, job)| match job {
                Job::Exact { .. } => 1,
                _ => steps,
            })
            .fold(0u64, u64::saturating_add);
        let threads = threads_for(threads, jobs.len(), work);
        if threads <= 1 {
            return self.chunk(jobs);
        }
        let size = jobs.len().div_ceil(threads);
        std::thread::scope(|scope| {
            let mut chunks = jobs.chunks_mut(size);
            // The calling thread takes the first chunk itself.
            let own = chunks.next();
            let handles: Vec<_> = chunks.map(|c| scope.spawn(move || self.chunk(c))).collect();
            let mut first = own.and_then(|c| self.chunk(c));
            for handle in handles {
                match handle.join() {
                    Ok(failure) => first = earlier(first, failure),
                    Err(panic) => std::panic::resume_unwind(panic),
                }
            }
            first
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn threads_only_where_the_work_is_worth_them() {
        // One body or one thread: the calling thread.
        assert_eq!(threads_for(8, 1, 1000), 1);
        assert_eq!(threads_for(1, 1000, 1_000_000), 1);
        // Two bodies per thread at least.
        assert_eq!(threads_for(8, 5, 5000), 2);
        // A single step (or one exact evaluation) of a small world is not
        // worth a thread.
        assert_eq!(threads_for(2, 100, 100), 1);
        assert_eq!(threads_for(2, 1000, 1000), 2);
        assert_eq!(threads_for(2, 1000, u64::MAX), 2);
    }

    #[test]
    fn a_failure_inside_a_move_is_given_the_step_that_contains_it() {
        let clock = Clock::new(0.1);
        let walker = |whole, last: Option<f64>, end| Walker {
            route: Route { whole, last, end },
            clock,
            end: Dd::from_f64(end),
        };
        let grid = walker(10, None, 1.0);
        assert_eq!(grid.step_at(0.0), 1);
        assert_eq!(grid.step_at(0.25), 3);
        assert_eq!(grid.step_at(grid.time_of(3)), 3);
        assert_eq!(grid.step_at(0.95), 10);
        assert_eq!(grid.step_at(5.0), 10);
        let shortened = walker(10, Some(0.05), 1.05);
        assert_eq!(shortened.step_at(1.02), 11);
        assert_eq!(walker(0, Some(0.05), 0.05).step_at(0.01), 1);
    }

    #[test]
    fn the_earlier_failure_is_the_earlier_step_then_the_lower_index() {
        let e = || DynamicsError::InvalidStep { h: 0.0 };
        let pick = |a: (u64, usize), b: (u64, usize)| {
            earlier(Some((a.0, a.1, e())), Some((b.0, b.1, e()))).map(|(k, i, _)| (k, i))
        };
        assert_eq!(pick((3, 9), (2, 40)), Some((2, 40)));
        assert_eq!(pick((2, 9), (2, 4)), Some((2, 4)));
        assert_eq!(pick((2, 4), (2, 9)), Some((2, 4)));
        assert_eq!(earlier(None, None).map(|f| f.0), None);
    }
}
