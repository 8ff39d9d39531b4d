//! The world's clock and its time grid: whole steps of `dt` from an origin,
//! the time kept in double-double so that `n` steps land on `n·dt` to
//! ~10⁻³² relative, and the rule by which [`crate::World::advance_to`]
//! reaches a time (the grid of `kreisel simulate`).
//!
//! ```text
//! time after k whole steps:  origin + k·dt            (exact product, double-double sum)
//! advance_to(t):  N = (t − origin)/dt rounded up (to the nearest whole number within 1e-6)
//!                 whole steps up to N − 1, then one step of t − (origin + (N−1)·dt) landing on t
//! ```
//!
//! `origin + k·dt` is the same double-double as `k` steps of `dt` added
//! one by one (both are the exact sum, normalised): the exact solution is
//! evaluated at the same time whether the world stepped or jumped.

use crate::DynamicsError;
use crate::elliptic::dd::Dd;

/// `(t − origin)/dt` within this many steps of a whole number counts as
/// that number, so rounding never adds a needless tiny last step.
pub const WHOLE_STEPS_TOLERANCE: f64 = 1e-6;

/// The number of grid steps that reach `ratio` steps of `dt` (`ratio` =
/// span / dt, positive): the grid rule of [`crate::World::advance_to`] and
/// of every run's output grid (`kreisel simulate`, `kreisel top --csv`),
/// written once here.
///
/// ```text
/// N = round(ratio)          if |ratio − round(ratio)| ≤ WHOLE_STEPS_TOLERANCE and round(ratio) ≥ 1
///     max(1, ⌈ratio⌉)       otherwise
/// ```
///
/// The last of the `N` steps is shortened to land on the span exactly; a
/// ratio within 1e-6 of a whole number takes no needless tiny last step.
/// The result is a whole number (as `f64`, so a caller can check it
/// against its own limit before converting).
///
/// ```
/// use kreisel_dynamics::grid_steps;
/// assert_eq!(grid_steps(10.0), 10.0);
/// assert_eq!(grid_steps(10.0 + 1e-9), 10.0); // rounding in duration/dt
/// assert_eq!(grid_steps(10.2), 11.0); // a shortened last step
/// assert_eq!(grid_steps(0.3), 1.0); // one short step
/// ```
pub fn grid_steps(ratio: f64) -> f64 {
    let nearest = ratio.round();
    if nearest >= 1.0 && (ratio - nearest).abs() <= WHOLE_STEPS_TOLERANCE {
        nearest
    } else {
        ratio.ceil().max(1.0)
    }
}

/// The most whole steps one call may take: beyond 2⁵³ a step count is no
/// longer exact in a double.
const MAX_WHOLE_STEPS: f64 = 9_007_199_254_740_992.0;

/// The clock: an origin, whole steps of `dt` since it, and the time
/// reported (`t` exactly after `advance_to(t)`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Clock {
    dt: f64,
    origin: Dd,
    steps: u64,
    time: f64,
}

/// How to reach a time: whole steps of `dt`, then possibly one last step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Route {
    /// Whole steps of `dt` first.
    pub(crate) whole: u64,
    /// The last step, s (`None`: the time is on the grid).
    pub(crate) last: Option<f64>,
    /// The time reported at the end, s.
    pub(crate) end: f64,
}

impl Clock {
    /// The clock at time 0 with grid step `dt` (positive and finite).
    pub(crate) fn new(dt: f64) -> Self {
        Self {
            dt,
            origin: Dd::from_f64(0.0),
            steps: 0,
            time: 0.0,
        }
    }

    /// The grid step, s.
    pub(crate) fn dt(&self) -> f64 {
        self.dt
    }

    /// The time reported, s.
    pub(crate) fn time(&self) -> f64 {
        self.time
    }

    /// The grid point `k` whole steps past the origin, in double-double.
    fn grid(&self, k: u64) -> Dd {
        if k == 0 {
            self.origin
        } else {
            self.origin.add(Dd::from_f64(k as f64).mul_f64(self.dt))
        }
    }

    /// The exact time now, double-double.
    pub(crate) fn now(&self) -> Dd {
        self.grid(self.steps)
    }

    /// The time reported after `i` more whole steps.
    pub(crate) fn after_whole(&self, i: u64) -> f64 {
        self.grid(self.steps + i).hi
    }

    /// How to reach time `t` from now (see the module docs).
    ///
    /// # Errors
    /// [`DynamicsError::InvalidTime`] for a `t` that is not finite, lies
    /// before now, or is more than 2⁵³ steps away.
    pub(crate) fn route_to(&self, t: f64) -> Result<Route, DynamicsError> {
        let invalid = |reason| DynamicsError::InvalidTime {
            t,
            now: self.time,
            reason,
        };
        if !t.is_finite() {
            return Err(invalid("not finite"));
        }
        if t < self.time {
            return Err(invalid("before the world's time: it only moves forward"));
        }
        if t == self.time {
            return Ok(Route {
                whole: 0,
                last: None,
                end: t,
            });
        }
        let ratio = Dd::from_f64(t).add(self.origin.neg()).to_f64() / self.dt;
        if ratio.is_nan() || ratio >= MAX_WHOLE_STEPS {
            return Err(invalid("more than 2^53 steps of dt away"));
        }
        let n = grid_steps(ratio);
        // Exact: a whole number below 2⁵³.
        let before_last = n as u64 - 1;
        let (whole, from) = if before_last >= self.steps {
            (before_last - self.steps, self.grid(before_last).hi)
        } else {
            // t lies within the current step: one step from now.
            (0, self.time)
        };
        Ok(Route {
            whole,
            last: Some(t - from),
            end: t,
        })
    }

    /// Moves the clock along `route` (from [`Clock::route_to`]).
    pub(crate) fn follow(&mut self, route: &Route) {
        self.steps += route.whole;
        self.time = self.grid(self.steps).hi;
        if let Some(h) = route.last {
            self.origin = self.now().add(Dd::from_f64(h));
            self.steps = 0;
            self.time = route.end;
        }
    }

    /// The time after one step of `h` (a whole step when `h == dt`).
    pub(crate) fn step_route(&self, h: f64) -> Route {
        if h == self.dt {
            Route {
                whole: 1,
                last: None,
                end: self.after_whole(1),
            }
        } else {
            Route {
                whole: 0,
                last: Some(h),
                end: self.now().add(Dd::from_f64(h)).hi,
            }
        }
    }

    /// The exact time at the end of `route`, double-double.
    pub(crate) fn end_of(&self, route: &Route) -> Dd {
        let grid = self.grid(self.steps + route.whole);
        match route.last {
            Some(h) => grid.add(Dd::from_f64(h)),
            None => grid,
        }
    }
}

/// The time since world time `start`, double-double (`now` itself for a
/// start at 0).
#[inline]
pub(crate) fn elapsed(now: Dd, start: Dd) -> Dd {
    if start.hi == 0.0 && start.lo == 0.0 {
        now
    } else {
        now.add(start.neg())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn whole_steps_equal_steps_added_one_by_one() {
        for dt in [0.1, 1.0 / 60.0, 0.01, 3e-7] {
            let mut clock = Clock::new(dt);
            let mut sum = Dd::from_f64(0.0);
            for _ in 0..1000 {
                let route = clock.step_route(dt);
                clock.follow(&route);
                sum = sum.add(Dd::from_f64(dt));
                let now = clock.now();
                assert_eq!((now.hi, now.lo), (sum.hi, sum.lo), "dt = {dt}");
            }
        }
    }

    #[test]
    fn the_grid_of_kreisel_simulate() {
        // 0.3 / 0.1 = 2.9999999999999996: three steps, the last shortened.
        let clock = Clock::new(0.1);
        let route = clock.route_to(0.3).unwrap();
        assert_eq!(route.whole, 2);
        assert_eq!(route.last, Some(0.3 - 2.0 * 0.1));
        // 1.05 / 0.1: ten whole steps and 0.05.
        let route = clock.route_to(1.05).unwrap();
        assert_eq!((route.whole, route.last), (10, Some(1.05 - 10.0 * 0.1)));
        let mut clock = Clock::new(0.1);
        clock.follow(&route);
        assert_eq!(clock.time(), 1.05);
        assert!((clock.now().hi - 1.05).abs() < 1e-15);
        // Behind the clock: refused; the same time: nothing.
        assert!(clock.route_to(1.0).is_err());
        assert_eq!(clock.route_to(1.05).unwrap().last, None);
        assert!(clock.route_to(f64::NAN).is_err());
    }

    #[test]
    fn a_time_inside_the_current_step() {
        let mut clock = Clock::new(1.0);
        clock.follow(&clock.route_to(3.0).unwrap());
        let route = clock.route_to(3.25).unwrap();
        assert_eq!((route.whole, route.last), (0, Some(0.25)));
    }
}
