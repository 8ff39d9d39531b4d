//! When the steps happen and which of them are written: the time grid of a
//! run, from `duration`, `dt` and `output_interval`.
//!
//! ```text
//! steps N = duration / dt rounded up (to the nearest whole number when within 1e-6 of it:
//!           kreisel_dynamics::grid_steps, the World's own grid rule)
//! step k (1 ≤ k < N) has size dt and ends at t = k·dt
//! step N has size duration − (N − 1)·dt and ends at t = duration exactly
//! rows after steps 0, every, 2·every, …, and N   (every = output_interval / dt)
//! ```

#![forbid(unsafe_code)]

/// The most steps a run may take (at ~1 µs a step, a quarter of an hour per body).
pub const MAX_STEPS: u64 = 1_000_000_000;

/// `output_interval` must be a whole multiple of `dt` within this relative tolerance.
pub const INTERVAL_TOLERANCE: f64 = 1e-9;

/// Why `duration`, `dt` and `output_interval` make no schedule.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ScheduleProblem {
    /// `duration / dt` exceeds [`MAX_STEPS`].
    TooManySteps {
        /// `duration / dt`.
        ratio: f64,
    },
    /// `output_interval` is no whole multiple of `dt` (or is less than `dt`).
    IntervalNotMultiple {
        /// `output_interval / dt`.
        ratio: f64,
    },
}

/// The steps of a run and the rows written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Schedule {
    duration: f64,
    dt: f64,
    steps: u64,
    every: u64,
}

impl Schedule {
    /// The schedule for positive, finite `duration`, `dt` and `interval`
    /// (`None`: a row after every step).
    ///
    /// # Errors
    /// [`ScheduleProblem::TooManySteps`] beyond [`MAX_STEPS`] steps,
    /// [`ScheduleProblem::IntervalNotMultiple`] when `interval / dt` is not a
    /// whole number ≥ 1 within [`INTERVAL_TOLERANCE`] relative.
    pub fn new(duration: f64, dt: f64, interval: Option<f64>) -> Result<Self, ScheduleProblem> {
        let ratio = duration / dt;
        // Also catches an infinite ratio (dt tiny against duration).
        if ratio > MAX_STEPS as f64 + 1.0 {
            return Err(ScheduleProblem::TooManySteps { ratio });
        }
        // Exact: a whole number below 2⁵³.
        let steps = kreisel_dynamics::grid_steps(ratio) as u64;
        if steps > MAX_STEPS {
            return Err(ScheduleProblem::TooManySteps { ratio });
        }
        let every = match interval {
            None => 1,
            Some(interval) => {
                let ratio = interval / dt;
                let n = ratio.round();
                if !(n >= 1.0 && (n * dt - interval).abs() <= INTERVAL_TOLERANCE * interval) {
                    return Err(ScheduleProblem::IntervalNotMultiple { ratio });
                }
                // Saturates for huge intervals: then only the first and last rows.
                n as u64
            }
        };
        Ok(Self {
            duration,
            dt,
            steps,
            every,
        })
    }

    /// The number of steps `N`.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The size of step `k` (1-based): `dt`, and for the last step whatever
    /// is left up to `duration`.
    pub fn step_size(&self, k: u64) -> f64 {
        if k < self.steps {
            self.dt
        } else {
            self.duration - (self.steps - 1) as f64 * self.dt
        }
    }

    /// The time at the end of step `k` (`0` for `k = 0`): `k·dt`, and exactly
    /// `duration` after the last step.
    pub fn time(&self, k: u64) -> f64 {
        if k < self.steps {
            k as f64 * self.dt
        } else {
            self.duration
        }
    }

    /// Whether the state after step `k` is written: the initial state, every
    /// `output_interval / dt` steps, and the final state.
    pub fn writes_row(&self, k: u64) -> bool {
        k == 0 || k == self.steps || k.is_multiple_of(self.every)
    }

    /// The first step after `k` whose state is written (`N` at the latest).
    pub fn next_row(&self, k: u64) -> u64 {
        (k / self.every + 1)
            .saturating_mul(self.every)
            .min(self.steps)
    }

    /// How many times rows are written (one row per body each time).
    ///
    /// ```text
    /// 1 + ⌊N / every⌋ + (1 if every does not divide N)
    /// ```
    #[cfg(test)]
    pub fn row_times(&self) -> u64 {
        1 + self.steps / self.every + u64::from(!self.steps.is_multiple_of(self.every))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn schedule(duration: f64, dt: f64, interval: Option<f64>) -> Schedule {
        Schedule::new(duration, dt, interval).unwrap()
    }

    /// Counts the written steps by walking the whole schedule.
    fn count_rows(s: &Schedule) -> u64 {
        (0..=s.steps()).filter(|&k| s.writes_row(k)).count() as u64
    }

    #[test]
    fn whole_number_of_steps_despite_rounding() {
        // 0.3 / 0.1 = 2.9999999999999996 and 100 / 0.01 = 10000.
        let s = schedule(0.3, 0.1, None);
        assert_eq!(s.steps(), 3);
        assert_eq!(s.time(3), 0.3);
        assert!((s.step_size(3) - 0.1).abs() < 1e-16);
        let s = schedule(100.0, 0.01, Some(0.1));
        assert_eq!((s.steps(), s.row_times()), (10_000, 1001));
        assert_eq!(s.time(10), 0.1);
        assert_eq!(count_rows(&s), s.row_times());
    }

    #[test]
    fn partial_last_step_ends_at_duration() {
        let s = schedule(1.05, 0.1, Some(0.2));
        assert_eq!(s.steps(), 11);
        assert!((s.step_size(11) - 0.05).abs() < 1e-15);
        assert_eq!(s.step_size(10), 0.1);
        assert_eq!(s.time(11), 1.05);
        // Rows after steps 0, 2, 4, 6, 8, 10 and 11.
        assert_eq!(s.row_times(), 7);
        assert_eq!(count_rows(&s), 7);
        assert_eq!((s.next_row(0), s.next_row(3), s.next_row(10)), (2, 4, 11));
        // dt longer than the duration: one short step.
        let s = schedule(0.5, 2.0, None);
        assert_eq!((s.steps(), s.step_size(1), s.time(1)), (1, 0.5, 0.5));
    }

    #[test]
    fn interval_must_be_a_multiple_of_dt() {
        for bad in [0.015, 0.005, 0.10001] {
            match Schedule::new(1.0, 0.01, Some(bad)) {
                Err(ScheduleProblem::IntervalNotMultiple { .. }) => {}
                other => panic!("{bad}: {other:?}"),
            }
        }
        assert_eq!(schedule(1.0, 0.01, Some(0.03)).row_times(), 35);
        // Longer than the run: only the first and last states.
        assert_eq!(schedule(1.0, 0.01, Some(1e300)).row_times(), 2);
    }

    #[test]
    fn refuses_too_many_steps() {
        assert!(Schedule::new(1e9, 0.5, None).is_err());
        assert!(Schedule::new(1.0, 1e-300, None).is_err());
        assert!(Schedule::new(f64::MAX, f64::MIN_POSITIVE, None).is_err());
        assert_eq!(schedule(1e9, 1.0, None).steps(), MAX_STEPS);
    }
}
