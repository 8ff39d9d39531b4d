//! Accuracy as an input: a [`Tolerance`] on the attitude error over a run,
//! and the [`Choice`] it makes for a body — the cheapest method and
//! sub-step predicted to meet it.
//!
//! ```text
//! predicted error over the horizon T with steps h = dt/n:
//!     e(h) = SAFETY · (T / h) · ℓ(h),     SAFETY = 4
//! ℓ(h): the largest local attitude error of one step of h, measured at plan time
//!     free body:  |Φ_h(s_k) − exact(t_k + h)|   at s_k = exact(t_k), t_k = k T/4, k = 0..3
//!     forced:     |Φ_h(s) − Φ_{h/2}∘Φ_{h/2}(s)| · 2ᵖ/(2ᵖ − 1)   at 8 states spread over a
//!                 pilot run of the default plan (up to 64 steps of dt)
//! work per simulated second (measured costs, benches/work_precision.csv and
//! the forced stages):  steps/s × ns per step, exact: reads/s × ns per evaluation
//! ```
//!
//! Errors of the splittings accumulate at most linearly in the number of
//! steps (they are symplectic or close to it): on the eight references of
//! `tests/data/forced/` the actual worst error over 10 s was at most 1.9×
//! `(T/h) ℓ(h)` wherever it was above the rounding floor, for every order and
//! `h` from 0.1 to 0.01 s; `SAFETY = 4` covers that with a margin. Below
//! [`Tolerance::ROUNDING`] no truncation model is trusted: the default plan,
//! at rounding level, is kept. The measurement assumes that the start of the
//! run is representative: a load that switches on later (a closure of time)
//! is not probed.

use std::fmt;

use glam::DVec3;

use crate::{
    DynamicsError, ExactSolution, ForcedBody, ForcedSplitting, ForcedState, FreeBodyMethod,
    HeavyTop, HeavyTopIntegrator, PrincipalState,
};
use kreisel_kinematics::rotation_angle_between;

/// How far the predicted error is trusted: the factor between the measured
/// accumulation `(T/h) ℓ(h)` and the prediction.
pub const SAFETY: f64 = 4.0;

/// The most sub-steps per `dt` a tolerance may ask of a forced body.
pub const MAX_SUBSTEPS: u32 = 4096;

/// Measured cost of one RK4 step of a free body, ns (benches/work_precision.csv).
const RK4_NS: f64 = 80.0;
/// Measured cost of one PDMV6 step of a free body, ns (benches/work_precision.csv).
const PDMV6_NS: f64 = 126.0;
/// Measured cost of one evaluation of the exact solution, ns (benches/work_precision.csv).
const EXACT_NS: f64 = 160.0;
/// Measured cost of one stage (free flow and kick) of a forced splitting, ns:
/// PDMV10 for three distinct moments, the exact rotations otherwise
/// (BENCHMARKS.md, the heavy-top splittings: 3097/17 and 2386/17 ns).
const STAGE_NS: [f64; 2] = [182.0, 140.0];

/// The accuracy asked of a [`crate::World`]: the largest attitude error a
/// body may gather over a run of `horizon` seconds, read every
/// `read_interval` seconds (every `dt` unless said: a game loop).
///
/// ```text
/// |angle(q_world(t), q_true(t))| ≤ attitude   for 0 ≤ t ≤ horizon
/// ```
///
/// ```
/// use kreisel_dynamics::Tolerance;
/// let tol = Tolerance::try_new(1e-6, 10.0)?.try_reading_every(0.5)?;
/// assert_eq!((tol.attitude(), tol.horizon(), tol.read_interval()), (1e-6, 10.0, Some(0.5)));
/// assert!(Tolerance::try_new(0.0, 10.0).is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    attitude: f64,
    horizon: f64,
    read_interval: Option<f64>,
}

impl Tolerance {
    /// Tolerances below this many radians are at the rounding level of a
    /// run: the default plans (rounding level) are kept.
    pub const ROUNDING: f64 = 1e-10;

    /// At most `attitude` rad of attitude error over `horizon` s.
    ///
    /// # Panics
    /// Where [`Tolerance::try_new`] returns an error.
    ///
    /// ```
    /// let tol = kreisel_dynamics::Tolerance::new(1e-3, 60.0);
    /// assert_eq!(tol.read_interval(), None);
    /// ```
    pub fn new(attitude: f64, horizon: f64) -> Self {
        match Self::try_new(attitude, horizon) {
            Ok(tol) => tol,
            Err(e) => panic!("{e}"),
        }
    }

    /// At most `attitude` rad of attitude error over `horizon` s.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidBodyParameter`] naming `tolerance` or
    /// `horizon` when it is not positive and finite.
    ///
    /// ```
    /// use kreisel_dynamics::Tolerance;
    /// let e = Tolerance::try_new(1e-6, f64::INFINITY).unwrap_err();
    /// assert_eq!(e.to_string(), "free body: horizon = inf: must be positive and finite");
    /// ```
    pub fn try_new(attitude: f64, horizon: f64) -> Result<Self, DynamicsError> {
        positive("tolerance", attitude)?;
        positive("horizon", horizon)?;
        Ok(Self {
            attitude,
            horizon,
            read_interval: None,
        })
    }

    /// The same tolerance for a run whose states are read only every
    /// `interval` seconds (`kreisel simulate`'s `output_interval`): the
    /// exact solution is evaluated only there, which makes it cheaper.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidBodyParameter`] naming `read_interval` when
    /// it is not positive and finite.
    ///
    /// ```
    /// let tol = kreisel_dynamics::Tolerance::new(1e-6, 1.0);
    /// assert!(tol.try_reading_every(-1.0).is_err());
    /// ```
    pub fn try_reading_every(self, interval: f64) -> Result<Self, DynamicsError> {
        positive("read_interval", interval)?;
        Ok(Self {
            read_interval: Some(interval),
            ..self
        })
    }

    /// The largest attitude error allowed, rad.
    ///
    /// ```
    /// assert_eq!(kreisel_dynamics::Tolerance::new(1e-6, 1.0).attitude(), 1e-6);
    /// ```
    pub fn attitude(&self) -> f64 {
        self.attitude
    }

    /// The length of the run the error is allowed over, s.
    ///
    /// ```
    /// assert_eq!(kreisel_dynamics::Tolerance::new(1e-6, 3.0).horizon(), 3.0);
    /// ```
    pub fn horizon(&self) -> f64 {
        self.horizon
    }

    /// How often the states are read, s (`None`: every step).
    ///
    /// ```
    /// assert_eq!(kreisel_dynamics::Tolerance::new(1e-6, 3.0).read_interval(), None);
    /// ```
    pub fn read_interval(&self) -> Option<f64> {
        self.read_interval
    }

    /// The predicted error over the horizon of steps of `h` whose largest
    /// local error is `local`.
    fn predicted(&self, local: f64, h: f64) -> f64 {
        SAFETY * (self.horizon / h).ceil() * local
    }

    /// Whether the tolerance is above the rounding level (a model is trusted).
    fn above_rounding(&self) -> bool {
        self.attitude >= Self::ROUNDING
    }
}

fn positive(parameter: &'static str, value: f64) -> Result<(), DynamicsError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(DynamicsError::InvalidBodyParameter {
            parameter,
            value,
            reason: "must be positive and finite",
        })
    }
}

/// What a [`Tolerance`] chose for one body ([`crate::World::choice`]): the
/// method, the sub-steps per `dt`, the predicted error over the horizon and
/// the work against the default plan's.
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::{Body, FreeBodyMethod, Plan, Tolerance, World};
/// let mut world = World::try_new(DVec3::ZERO, 1.0 / 60.0)?;
/// world.set_tolerance(Some(Tolerance::new(1e-4, 10.0)))?;
/// let id = world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::new(0.3, 1.0, 0.2)).try_build()?)?;
/// // Read every frame, RK4 meets 1e-4 rad for half the exact solution's work.
/// assert_eq!(world.plan(id), Some(&Plan::Stepping(FreeBodyMethod::Rk4)));
/// let choice = world.choice(id).unwrap();
/// assert!(choice.predicted <= 1e-4 && choice.work < choice.default_work);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Choice {
    /// The tolerance asked, rad.
    pub tolerance: f64,
    /// Its horizon, s.
    pub horizon: f64,
    /// The method's name.
    pub method: &'static str,
    /// Steps of the method per `dt` of the world.
    pub substeps: u32,
    /// The predicted attitude error over the horizon, rad (0 for the exact
    /// solution, which has no truncation error).
    pub predicted: f64,
    /// The predicted work, ns per simulated second (measured costs).
    pub work: f64,
    /// The default plan's work, ns per simulated second.
    pub default_work: f64,
}

impl fmt::Display for Choice {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "tolerance {:e} rad over {} s: {}",
            self.tolerance, self.horizon, self.method
        )?;
        if self.substeps > 1 {
            write!(f, " with {} sub-steps per dt", self.substeps)?;
        }
        if self.predicted > 0.0 {
            write!(f, ", predicted {:.1e} rad", self.predicted)?;
        } else {
            write!(f, ", no truncation error")?;
        }
        write!(
            f,
            ", about {:.2e} ns per simulated s (default: {:.2e})",
            self.work, self.default_work
        )
    }
}

/// The cheapest free-body method predicted to meet `tol` for an asymmetric
/// body whose exact solution is `exact`, stepped every `dt`: RK4 or PDMV6
/// every `dt`, or the exact solution evaluated at every read. `None` when
/// the tolerance is at the rounding level (the exact solution stays).
pub(crate) fn choose_free(
    tol: &Tolerance,
    exact: &ExactSolution,
    moments: DVec3,
    dt: f64,
) -> Option<(FreeBodyMethod, Choice)> {
    if !tol.above_rounding() {
        return None;
    }
    let reads_per_second = 1.0 / tol.read_interval.unwrap_or(dt).max(dt);
    let exact_work = EXACT_NS * reads_per_second;
    let mut best = (
        FreeBodyMethod::Exact,
        Choice {
            tolerance: tol.attitude,
            horizon: tol.horizon,
            method: FreeBodyMethod::Exact.name(),
            substeps: 1,
            predicted: 0.0,
            work: exact_work,
            default_work: exact_work,
        },
    );
    for (method, ns) in [
        (FreeBodyMethod::Rk4, RK4_NS),
        (FreeBodyMethod::Pdmv6, PDMV6_NS),
    ] {
        let work = ns / dt;
        if work >= best.1.work {
            continue;
        }
        let integrator = method.integrator();
        let local = (0..4)
            .map(|k| {
                let t = f64::from(k) * tol.horizon / 4.0;
                let mut state = exact.state_at(t);
                integrator.step(moments, &mut state, dt);
                attitude_gap(&state, &exact.state_at(t + dt))
            })
            .fold(0.0, f64::max);
        let predicted = tol.predicted(local, dt);
        if predicted <= tol.attitude {
            best = (
                method,
                Choice {
                    method: integrator.name(),
                    predicted,
                    work,
                    ..best.1
                },
            );
        }
    }
    Some(best)
}

/// The cheapest forced splitting and sub-steps per `dt` predicted to meet
/// `tol` for `body` from `start` at world time and step `(t0, dt)`, with at
/// least the `default` plan's sub-steps (a heavy top's stability limit).
/// `None` when the tolerance is at the rounding level, or when no splitting
/// meets it within [`MAX_SUBSTEPS`] (the default stays).
pub(crate) fn choose_forced(
    tol: &Tolerance,
    body: &ForcedBody,
    start: &ForcedState,
    (t0, dt): (f64, f64),
    default: (ForcedSplitting, u32),
) -> Option<(ForcedSplitting, Choice)> {
    if !tol.above_rounding() {
        return None;
    }
    let min = default.1.clamp(1, MAX_SUBSTEPS);
    let pilot = pilot(tol, body, start, (t0, dt), min);
    let chooser = Chooser {
        tol,
        body,
        pilot: &pilot,
        dt,
        min,
    };
    let default_work = chooser.work(default.0, default.1);
    // Two passes over the splittings. First in order of cost per step, each
    // only up to the sub-steps that cost less than the default plan (a
    // loose tolerance is met cheaply). If none did, nothing cheaper than
    // the default meets the tolerance: the default's splitting first, with
    // as many sub-steps as it takes, then the others up to its cost. Each
    // is probed only up to the sub-steps that would cost less than the best
    // so far.
    let mut best: Option<(ForcedSplitting, Choice)> = None;
    let others = ForcedSplitting::ALL.into_iter().filter(|&m| m != default.0);
    let passes = [
        (Some(default_work), ForcedSplitting::ALL.to_vec()),
        (None, std::iter::once(default.0).chain(others).collect()),
    ];
    for (bound, methods) in passes {
        for method in methods {
            let limit = best.as_ref().map(|(_, c)| c.work).or(bound);
            if let Some((n, predicted)) = chooser.substeps(method, limit) {
                let work = chooser.work(method, n);
                if best.as_ref().is_none_or(|(_, c)| work < c.work) {
                    let choice = Choice {
                        tolerance: tol.attitude,
                        horizon: tol.horizon,
                        method: method.name(),
                        substeps: n,
                        predicted,
                        work,
                        default_work,
                    };
                    best = Some((method, choice));
                }
            }
        }
        if best.is_some() {
            break;
        }
    }
    best
}

/// What [`choose_forced`] measures and weighs for one body.
struct Chooser<'a> {
    tol: &'a Tolerance,
    body: &'a ForcedBody,
    pilot: &'a [(f64, ForcedState)],
    dt: f64,
    /// The fewest sub-steps per `dt` (a heavy top's stability limit).
    min: u32,
}

impl Chooser<'_> {
    /// The work of `n` sub-steps of `method` per `dt`, ns per simulated s.
    fn work(&self, method: ForcedSplitting, n: u32) -> f64 {
        splitting_work(self.body, method, n, self.dt)
    }

    /// The sub-steps with which `method` is predicted to meet the tolerance
    /// for less work than `limit` (`None`: any up to [`MAX_SUBSTEPS`]),
    /// and the prediction.
    fn substeps(&self, method: ForcedSplitting, limit: Option<f64>) -> Option<(u32, f64)> {
        let cap = limit.map_or(MAX_SUBSTEPS, |limit| {
            let n = (limit / self.work(method, 1)).ceil() - 1.0;
            n.clamp(0.0, f64::from(MAX_SUBSTEPS)) as u32
        });
        if cap < self.min {
            return None;
        }
        // A first guess from the local error at `min` sub-steps and the
        // order (e(h) ∝ hᵖ in the asymptotic range), then doublings until
        // the measured prediction meets the tolerance.
        let (min, attitude) = (self.min, self.tol.attitude);
        let first = self.predicted(method, min);
        if !first.is_finite() {
            return None;
        }
        if first <= attitude {
            return Some((min, first));
        }
        let guess = f64::from(min) * (first / attitude).powf(1.0 / f64::from(method.order()));
        let mut n = guess
            .ceil()
            .clamp(f64::from(min) + 1.0, f64::from(MAX_SUBSTEPS)) as u32;
        while n <= cap {
            let e = self.predicted(method, n);
            if e <= attitude {
                return Some((n, e));
            }
            if n >= MAX_SUBSTEPS {
                break;
            }
            n = n.saturating_mul(2).min(MAX_SUBSTEPS);
        }
        None
    }

    /// The predicted error over the horizon of `method` at `n` sub-steps
    /// per `dt`.
    fn predicted(&self, method: ForcedSplitting, n: u32) -> f64 {
        let h = self.dt / f64::from(n);
        self.tol.predicted(self.local(method, h), h)
    }

    /// The largest local attitude error of one step of `h` by `method` at
    /// the pilot's states, by step doubling.
    fn local(&self, method: ForcedSplitting, h: f64) -> f64 {
        let body = self.body;
        let richardson = {
            let p = 2f64.powi(method.order() as i32);
            p / (p - 1.0)
        };
        let mut worst: f64 = 0.0;
        for &(t, state) in self.pilot {
            let mut whole = state;
            method.step(body, &mut whole, t, h);
            let mut halves = state;
            method.step(body, &mut halves, t, 0.5 * h);
            method.step(body, &mut halves, t + 0.5 * h, 0.5 * h);
            let gap = attitude_gap(&whole.rotation, &halves.rotation) * richardson;
            if !gap.is_finite() {
                return f64::INFINITY;
            }
            worst = worst.max(gap);
        }
        worst
    }
}

/// The work of `n` sub-steps of splitting `method` per `dt` on `body`, ns
/// per simulated second (measured stage costs).
pub(crate) fn splitting_work(body: &ForcedBody, method: ForcedSplitting, n: u32, dt: f64) -> f64 {
    let stage_ns = STAGE_NS[usize::from(body.free_flow_is_exact())];
    f64::from(n) * method.stages() as f64 * stage_ns / dt
}

/// Measured cost of one series step of [`crate::HeavyTopTaylor`] (order 18), ns:
/// 0.47 ms for the 400 series steps of the asymmetric fast top over 2 s
/// (BENCHMARKS.md, heavy top).
const TAYLOR_NS: f64 = 1200.0;

/// The Taylor series of the whole top ([`crate::HeavyTopTaylor`]) for a heavy top
/// without inputs from `state`, stepped every `dt`: its predicted error,
/// measured by step doubling at 8 states of its own pilot run of up to 8
/// steps, and its work, one series step per `0.8/ω_max` s. `None` at the
/// rounding level or when it is predicted to miss the tolerance.
pub(crate) fn choose_taylor(
    tol: &Tolerance,
    top: &HeavyTop,
    state: &PrincipalState,
    dt: f64,
    default_work: f64,
) -> Option<Choice> {
    if !tol.above_rounding() {
        return None;
    }
    let taylor = &crate::HeavyTopTaylor::DEFAULT;
    let steps = ((tol.horizon / dt).ceil() as usize).clamp(1, PROBES);
    let mut s = *state;
    let mut worst: f64 = 0.0;
    for _ in 0..steps {
        let mut whole = s;
        let mut halves = s;
        let stepped = taylor.try_step(top, &mut whole, dt).and_then(|()| {
            taylor.try_step(top, &mut halves, 0.5 * dt)?;
            taylor.try_step(top, &mut halves, 0.5 * dt)
        });
        let gap = attitude_gap(&whole, &halves);
        if stepped.is_err() || !gap.is_finite() {
            return None;
        }
        worst = worst.max(gap);
        s = whole;
    }
    let predicted = tol.predicted(worst, dt);
    let series = (dt * top.angular_speed_bound(state) / 0.8).ceil().max(1.0);
    let work = TAYLOR_NS * series / dt;
    (predicted <= tol.attitude && work.is_finite()).then(|| Choice {
        tolerance: tol.attitude,
        horizon: tol.horizon,
        method: "taylor",
        substeps: series.min(f64::from(u32::MAX)) as u32,
        predicted,
        work,
        default_work,
    })
}

/// How many steps of `dt` the pilot run takes at most.
const PILOT_STEPS: usize = 64;

/// How many of the pilot's states are probed.
const PROBES: usize = 8;

/// The states the local errors are measured at: [`PROBES`] states, evenly
/// spaced over a pilot run of up to [`PILOT_STEPS`] steps of `dt` (within
/// the horizon) from `start` at `t0`, with their times. The pilot is
/// Strang's splitting at `n` sub-steps per `dt` (the stable number): the
/// states only need to lie near the motion, and it is the cheapest. A
/// pilot that stops being finite ends there.
fn pilot(
    tol: &Tolerance,
    body: &ForcedBody,
    start: &ForcedState,
    (t0, dt): (f64, f64),
    n: u32,
) -> Vec<(f64, ForcedState)> {
    let method = ForcedSplitting::STRANG;
    let steps = ((tol.horizon / dt).ceil() as usize).clamp(1, PILOT_STEPS);
    let stride = (steps / PROBES).max(1);
    let h = dt / f64::from(n.max(1));
    let mut states = vec![(t0, *start)];
    let mut state = *start;
    for k in 1..steps {
        let t = t0 + (k - 1) as f64 * dt;
        for j in 0..n.max(1) {
            method.step(body, &mut state, t + f64::from(j) * h, h);
        }
        if !state.is_finite() {
            break;
        }
        if k % stride == 0 && states.len() < PROBES {
            states.push((t0 + k as f64 * dt, state));
        }
    }
    states
}

/// The angle between two states' attitudes, rad.
fn attitude_gap(a: &PrincipalState, b: &PrincipalState) -> f64 {
    rotation_angle_between(a.world_from_principal, b.world_from_principal)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Inputs, RigidBody};
    use glam::DQuat;

    #[test]
    fn below_the_rounding_level_nothing_is_chosen() {
        let moments = DVec3::new(1.0, 2.0, 3.0);
        let state = PrincipalState {
            world_from_principal: DQuat::IDENTITY,
            l_principal: DVec3::new(0.3, 2.0, 0.1),
        };
        let exact = ExactSolution::try_new(moments, state).unwrap();
        let tol = Tolerance::new(1e-12, 10.0);
        assert!(choose_free(&tol, &exact, moments, 0.01).is_none());
        let loose = Tolerance::new(1e-3, 10.0);
        let (method, choice) = choose_free(&loose, &exact, moments, 0.01).unwrap();
        assert_eq!((method, choice.method), (FreeBodyMethod::Rk4, "rk4"));
        // Read once a second, the exact solution is cheaper than any stepping.
        let sparse = loose.try_reading_every(1.0).unwrap();
        let (method, choice) = choose_free(&sparse, &exact, moments, 0.01).unwrap();
        assert_eq!((method, choice.predicted), (FreeBodyMethod::Exact, 0.0));
    }

    #[test]
    fn tighter_tolerances_cost_more_sub_steps_or_a_higher_order() {
        let body = RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        let forced = ForcedBody::try_new(
            body,
            1.0,
            DVec3::ZERO,
            Inputs::default().with_torque_body(DVec3::new(0.5, 0.0, 0.2)),
        )
        .unwrap();
        let start = ForcedState::at_origin(PrincipalState {
            world_from_principal: DQuat::IDENTITY,
            l_principal: DVec3::new(0.2, 2.0, 0.3),
        });
        let mut last = 0.0;
        for tol in [1e-2, 1e-4, 1e-6, 1e-8] {
            let tol = Tolerance::new(tol, 10.0);
            let default = (ForcedSplitting::DEFAULT, 1);
            let (_, choice) = choose_forced(&tol, &forced, &start, (0.0, 0.1), default).unwrap();
            assert!(choice.predicted <= tol.attitude(), "{choice}");
            assert!(choice.work >= last, "{choice}");
            last = choice.work;
        }
    }
}
