//! Error-controlled stepping for a [`GroundTop`]: the embedded
//! Dormand–Prince 5(4) pair with the standard step-size controller.
//!
//! Why: a fixed step gives no warning when it is too large. With the
//! regularised Coulomb law at `ε = 0.1 mm/s` (a stiff vector field while
//! the contact nearly sticks), fixed-step RK4 put Leine & Glocker's
//! inversion at 9.14 s (`dt = 1e-4`) and 19.19 s (`dt = 5e-5`) against the
//! converged 19.478416 s (`dt ≤ 2.5e-5`). Hand-written rather than a crate:
//! the contact checks (lift-off located inside a step, Painlevé, a disk
//! lying flat) must see every stage and redo a step of any length, which
//! the ODE crates (`ode_solvers`, `diffsol`) do not expose.
//!
//! Coefficients: Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19,
//! Table 2 (RK5(4)7M), as printed in Hairer, Nørsett & Wanner, *Solving
//! ODEs I*, Table II.5.2. The unit tests check all 17 order conditions of
//! order 5 for the solution weights and all 8 of order 4 for the embedded
//! ones. The step is advanced with the fifth-order solution (local
//! extrapolation), and the last stage is the first of the next step (FSAL).

use glam::{DMat3, DVec3};

use super::ground_top::Rates;
use super::rk4::{Trial, check_start, weighted};
use super::{ContactShape, GroundTop, GroundTopState};
use crate::DynamicsError;

/// The method's name in errors.
const METHOD: &str = "ground-top dopri5";

/// Stage times `cᵢ` (where applied loads are read; the order conditions).
pub(crate) const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];

/// The Runge–Kutta matrix, row `i` the weights of stages `0..i`.
pub(crate) const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];

/// Fifth-order weights (the last row of `A`: FSAL).
pub(crate) const B: [f64; 7] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
    0.0,
];

/// Embedded fourth-order weights.
pub(crate) const B_HAT: [f64; 7] = [
    5179.0 / 57600.0,
    0.0,
    7571.0 / 16695.0,
    393.0 / 640.0,
    -92097.0 / 339200.0,
    187.0 / 2100.0,
    1.0 / 40.0,
];

/// The controller's safety factor on the predicted step.
pub(crate) const SAFETY: f64 = 0.9;
/// The most a step may grow after an accepted step.
pub(crate) const MAX_GROWTH: f64 = 5.0;
/// The most a step may shrink after a rejected one.
pub(crate) const MIN_SHRINK: f64 = 0.2;
/// The smallest step, relative to the larger of `|t0|`, `|t_end|` (and
/// 1 s): below it the controller gives up with
/// [`DynamicsError::StepTooSmall`].
const MIN_STEP_RELATIVE: f64 = 1e-12;

/// The accuracy asked of [`GroundTop::try_advance_adaptive`]: each step's
/// estimated local error `e` (fifth- minus fourth-order solution) must
/// satisfy, for every one of the 13 state components `y` (`r_G`, `v_G`,
/// `q`, `L`):
///
/// ```text
/// |e_i| ≤ atol · s_i + rtol · max(|y_i(t)|, |y_i(t + h)|)
/// s_i:  ℓ for r_G,  ℓ/τ for v_G,  1 for q,  I_max/τ for L
/// ℓ = the contact radius (sphere or rim; an ellipsoid's smallest
///     semi-axis), τ = √(ℓ/g), I_max = the largest diagonal entry of the
///     body inertia tensor
/// ```
///
/// so `atol` is dimensionless: an absolute floor in the body's own units
/// of length, speed, attitude and angular momentum (the error norm is the
/// maximum over components of `|e_i|` over its bound).
///
/// ```
/// use kreisel_dynamics::AdaptiveTolerance;
/// let tol = AdaptiveTolerance::try_new(1e-10, 1e-12)?;
/// assert_eq!((tol.rtol(), tol.atol()), (1e-10, 1e-12));
/// assert!(AdaptiveTolerance::try_new(0.0, 0.0).is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdaptiveTolerance {
    rtol: f64,
    atol: f64,
}

// Both are finite (checked by `try_new`): equality is an equivalence.
impl Eq for AdaptiveTolerance {}

impl AdaptiveTolerance {
    /// Relative tolerance `rtol` and scaled absolute tolerance `atol`.
    ///
    /// # Panics
    /// Where [`AdaptiveTolerance::try_new`] returns an error.
    ///
    /// ```
    /// let tol = kreisel_dynamics::AdaptiveTolerance::new(1e-8, 1e-10);
    /// assert_eq!(tol.rtol(), 1e-8);
    /// ```
    pub fn new(rtol: f64, atol: f64) -> Self {
        match Self::try_new(rtol, atol) {
            Ok(tol) => tol,
            // The documented panic of the `new` half of the `new`/`try_new`
            // pair, for tolerances written in code; no input path (CLI,
            // Python, World) calls `new`.
            Err(e) => panic!("{e}"),
        }
    }

    /// Relative tolerance `rtol` and scaled absolute tolerance `atol`.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidTolerance`] when either is negative, not
    /// finite or not below 1, or both are zero.
    ///
    /// ```
    /// use kreisel_dynamics::AdaptiveTolerance;
    /// let e = AdaptiveTolerance::try_new(-1e-8, 1e-10).unwrap_err();
    /// assert_eq!(e.to_string(), "adaptive tolerance: rtol = -0.00000001: must be finite, in [0, 1)");
    /// ```
    pub fn try_new(rtol: f64, atol: f64) -> Result<Self, DynamicsError> {
        for (parameter, value) in [("rtol", rtol), ("atol", atol)] {
            if !(value.is_finite() && (0.0..1.0).contains(&value)) {
                return Err(DynamicsError::InvalidTolerance {
                    parameter,
                    value,
                    reason: "must be finite, in [0, 1)",
                });
            }
        }
        if rtol == 0.0 && atol == 0.0 {
            return Err(DynamicsError::InvalidTolerance {
                parameter: "atol",
                value: atol,
                reason: "rtol and atol cannot both be zero",
            });
        }
        Ok(Self { rtol, atol })
    }

    /// The relative tolerance.
    pub fn rtol(&self) -> f64 {
        self.rtol
    }

    /// The absolute tolerance, in the body's units (see the type's docs).
    pub fn atol(&self) -> f64 {
        self.atol
    }
}

/// How [`GroundTop::advance_controlled`] runs: the accuracy and the first
/// step (`None`: chosen by the starting-step rule).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Controlled {
    /// The accuracy asked.
    pub(crate) tolerance: AdaptiveTolerance,
    /// The first step to try, s (a previous run's last proposal).
    pub(crate) first_step: Option<f64>,
}

/// What an adaptive run did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct AdaptiveStats {
    /// Steps accepted (the observer was called this many times).
    pub accepted: usize,
    /// Steps rejected by the error test (or by a stage that lost contact).
    pub rejected: usize,
    /// Evaluations of the vector field.
    pub evaluations: usize,
}

/// The 13 components of a state, in the order `r_G, v_G, q (w, x, y, z), L`.
fn flat(s: &GroundTopState) -> [f64; 13] {
    let (r, v, q, l) = (s.com_world, s.velocity_world, s.world_from_body, s.l_world);
    [
        r.x, r.y, r.z, v.x, v.y, v.z, q.w, q.x, q.y, q.z, l.x, l.y, l.z,
    ]
}

/// One Dormand–Prince step of `h` from `s` whose rates are `k1`: the
/// trial (fifth order, its end rates the FSAL stage) and the error
/// estimate's state difference.
fn dopri(top: &GroundTop, s: &GroundTopState, t: f64, k1: Rates, h: f64) -> (Trial, [f64; 13]) {
    let mut k = [k1; 7];
    for i in 1..7 {
        let inc = weighted(&k[..i], &A[i][..i]);
        k[i] = top.rates(t + C[i] * h, &s.plus(&inc, h));
    }
    let next = s.plus(&weighted(&k, &B), h);
    let err_weights: [f64; 7] = std::array::from_fn(|i| B[i] - B_HAT[i]);
    let diff = flat(&GroundTopState::default_zero().plus(&weighted(&k, &err_weights), h));
    (Trial::of(next, &k[..6], k[6]), diff)
}

impl GroundTopState {
    /// All zero (the origin of the state space; not a valid state).
    fn default_zero() -> Self {
        Self {
            com_world: DVec3::ZERO,
            velocity_world: DVec3::ZERO,
            world_from_body: glam::DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0),
            l_world: DVec3::ZERO,
        }
    }
}

impl GroundTop {
    /// The absolute scales `s_i` of the error norm ([`AdaptiveTolerance`]).
    fn error_scales(&self) -> [f64; 13] {
        let length = match self.shape() {
            ContactShape::Sphere(s) => s.radius(),
            ContactShape::Disk(d) => d.radius(),
            ContactShape::Ellipsoid(e) => e.semi_axes().min_element(),
        };
        let time = (length / self.gravity()).sqrt();
        let i: DMat3 = self.inertia_body();
        let l = i.x_axis.x.max(i.y_axis.y).max(i.z_axis.z) / time;
        let v = length / time;
        [length, length, length, v, v, v, 1.0, 1.0, 1.0, 1.0, l, l, l]
    }

    /// Advances `state` from `t0` to `t_end` with the embedded
    /// Dormand–Prince 5(4) pair, choosing each step so that its estimated
    /// local error meets `tolerance`, and calls `observe(t, state)` after
    /// every accepted step (the last at `t_end`).
    ///
    /// ```text
    /// err = max_i |e_i| / (atol s_i + rtol max(|y_i|, |y_i'|))   (AdaptiveTolerance)
    /// err ≤ 1: accept;   h ← h · min(5, max(0.2, 0.9 err^(−1/5)))
    ///                    (no growth right after a rejection)
    /// ```
    ///
    /// The first step follows Hairer, Nørsett & Wanner (*Solving ODEs I*,
    /// II.4, "starting step size"). A step whose inner stage sees `N ≤ 0`
    /// while `N > 0` at its end is rejected and halved (a step too large
    /// for the contact), not reported. The contact checks after an
    /// accepted step are those of [`GroundTop::try_step`] (lift-off and the
    /// touchdown of a further contact located by bisection on this method's
    /// step, Painlevé, a disk lying flat);
    /// no renormalisation, no projection.
    ///
    /// # Errors
    /// - [`DynamicsError::InvalidInterval`] for `t_end < t0` or a time not
    ///   finite; `state` is unchanged.
    /// - [`DynamicsError::StepTooSmall`] when the controller asks for a
    ///   step below `10⁻¹² max(|t0|, |t_end|, 1 s)`; `state` is left at the
    ///   last accepted step. A trial step that leaves a non-finite state is
    ///   rejected and shrunk like any other, so a field that blows up ends
    ///   here too.
    /// - As [`GroundTop::try_step`] (`ContactLost` and `ContactTouchdown`
    ///   with their times, `DiskFlat`, `ContactIndeterminate`,
    ///   `InvalidState`, `Diverged`), `state` left as that function says;
    ///   the observer is not called for the step that ends in an error.
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec2, DVec3};
    /// use kreisel_dynamics::{AdaptiveTolerance, Friction, GroundTop, SphereContact};
    /// let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
    /// let inertia = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
    /// let top = GroundTop::try_new(0.006, inertia, sphere, Friction::try_viscous(0.3)?, 9.81)?;
    /// let q = DQuat::from_rotation_x(0.1);
    /// let mut s = top.try_state_on_ground(q, q * DVec3::new(0.0, 0.0, 180.0), DVec2::ZERO)?;
    /// let lambda0 = top.jellett(&s);
    /// let tol = AdaptiveTolerance::try_new(1e-10, 1e-12)?;
    /// let mut last = 0.0;
    /// let stats = top.try_advance_adaptive(&mut s, 0.0, 0.1, tol, |t, _| last = t)?;
    /// assert_eq!(last, 0.1);
    /// assert!(stats.accepted > 0);
    /// assert!((top.jellett(&s) - lambda0).abs() < 1e-10 * lambda0.abs());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_advance_adaptive(
        &self,
        state: &mut GroundTopState,
        t0: f64,
        t_end: f64,
        tolerance: AdaptiveTolerance,
        mut observe: impl FnMut(f64, &GroundTopState),
    ) -> Result<AdaptiveStats, DynamicsError> {
        let run = Controlled {
            tolerance,
            first_step: None,
        };
        self.advance_controlled(state, (t0, t_end), run, |t, s| {
            observe(t, s);
            Ok(())
        })
        .map(|(stats, _)| stats)
    }

    /// [`GroundTop::try_advance_adaptive`] with the first step `run.first_step`
    /// (`None`: Hairer's starting step) and an observer that may stop the
    /// run with an error (returned as it is, `state` at the step it saw).
    /// Also returns the step the controller would take next (the one before
    /// the last step was shortened to land on `t_end`; `None` when nothing
    /// was stepped): a caller that goes on from `t_end` starts there.
    pub(crate) fn advance_controlled(
        &self,
        state: &mut GroundTopState,
        (t0, t_end): (f64, f64),
        run: Controlled,
        mut observe: impl FnMut(f64, &GroundTopState) -> Result<(), DynamicsError>,
    ) -> Result<(AdaptiveStats, Option<f64>), DynamicsError> {
        let tolerance = run.tolerance;
        if !(t0.is_finite() && t_end.is_finite() && t_end >= t0) {
            return Err(DynamicsError::InvalidInterval { t0, t_end });
        }
        let mut stats = AdaptiveStats::default();
        if t_end == t0 {
            return Ok((stats, run.first_step));
        }
        check_start(state, t_end - t0)?;
        let h_min = MIN_STEP_RELATIVE * t0.abs().max(t_end.abs()).max(1.0);
        let scales = self.error_scales();
        let bound = |y: &[f64; 13], z: &[f64; 13], i: usize| {
            tolerance.atol * scales[i] + tolerance.rtol * y[i].abs().max(z[i].abs())
        };
        let norm = |e: &[f64; 13], y: &[f64; 13], z: &[f64; 13]| {
            (0..13)
                .map(|i| e[i].abs() / bound(y, z, i))
                .fold(0.0, f64::max)
        };

        let mut k1 = self.rates(t0, state);
        stats.evaluations += 1;
        let mut h = match run.first_step {
            Some(h) if h.is_finite() && h > 0.0 => h,
            _ => {
                stats.evaluations += 1;
                self.starting_step(state, t0, &k1, t_end - t0, &norm)
            }
        };
        let mut t = t0;
        let mut rejected_last = false;
        loop {
            // The controller's step, before it is shortened to land on t_end.
            let planned = h;
            let last = h >= t_end - t;
            if last {
                h = t_end - t;
            }
            if h < h_min && !last {
                return Err(DynamicsError::StepTooSmall {
                    method: METHOD,
                    time: t,
                    h,
                    min: h_min,
                });
            }
            let (trial, diff) = dopri(self, state, t, k1, h);
            stats.evaluations += 6;
            let y = flat(state);
            let z = flat(&trial.next);
            let err = norm(&diff, &y, &z);
            let stage_lost = trial.normal_min <= 0.0 && trial.end.normal_force > 0.0;
            if !err.is_finite() || err > 1.0 || (stage_lost && h > h_min) {
                stats.rejected += 1;
                let factor = if err.is_finite() && !stage_lost {
                    (SAFETY * err.powf(-0.2)).max(MIN_SHRINK)
                } else {
                    0.5
                };
                h *= factor;
                rejected_last = true;
                continue;
            }
            let end = trial.end;
            self.settle(state, t, h, METHOD, trial, |s, tau| {
                dopri(self, s, t, k1, tau).0.next
            })?;
            t = if last { t_end } else { t + h };
            k1 = end;
            stats.accepted += 1;
            observe(t, state)?;
            let growth = (SAFETY * err.max(1e-10).powf(-0.2)).clamp(MIN_SHRINK, MAX_GROWTH);
            if last {
                // A shortened last step says little about the next: the
                // planned one carries on (grown as the error allows).
                let next = planned.max(h * growth);
                return Ok((stats, Some(next)));
            }
            h *= if rejected_last {
                growth.min(1.0)
            } else {
                growth
            };
            rejected_last = false;
        }
    }

    /// The first step (Hairer, Nørsett & Wanner, *Solving ODEs I*, II.4):
    /// `h₀ = 0.01 ‖y‖/‖f‖`, one Euler step to estimate the second
    /// derivative, `h₁ = (0.01 / max(‖f‖, ‖f'‖))^(1/5)`, the smaller of
    /// `100 h₀`, `h₁` and the interval.
    fn starting_step(
        &self,
        state: &GroundTopState,
        t0: f64,
        k1: &Rates,
        span: f64,
        norm: &impl Fn(&[f64; 13], &[f64; 13], &[f64; 13]) -> f64,
    ) -> f64 {
        let y = flat(state);
        let f = flat(&GroundTopState::default_zero().plus(k1, 1.0));
        let d0 = norm(&y, &y, &y);
        let d1 = norm(&f, &y, &y);
        let h0 = if d0 < 1e-5 || d1 < 1e-5 {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        let h0 = h0.min(span);
        let k2 = self.rates(t0 + h0, &state.plus(k1, h0));
        let f2 = flat(&GroundTopState::default_zero().plus(&k2, 1.0));
        let df: [f64; 13] = std::array::from_fn(|i| (f2[i] - f[i]) / h0);
        let d2 = norm(&df, &y, &y);
        let h1 = if d1.max(d2) <= 1e-15 {
            (h0 * 1e-3).max(1e-6)
        } else {
            (0.01 / d1.max(d2)).powf(0.2)
        };
        (100.0 * h0).min(h1).min(span)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `A c⃗` for a vector over the stages.
    fn a_times(v: &[f64; 7]) -> [f64; 7] {
        std::array::from_fn(|i| (0..i.min(6)).map(|j| A[i][j] * v[j]).sum())
    }

    fn dot(b: &[f64; 7], v: &[f64; 7]) -> f64 {
        b.iter().zip(v).map(|(x, y)| x * y).sum()
    }

    fn mul(u: &[f64; 7], v: &[f64; 7]) -> [f64; 7] {
        std::array::from_fn(|i| u[i] * v[i])
    }

    /// The order conditions up to order `p` (Butcher trees), as
    /// `(b·Φ(tree), 1/γ(tree))` pairs.
    fn conditions(b: &[f64; 7], p: usize) -> Vec<(f64, f64)> {
        let one = [1.0; 7];
        let c = C;
        let c2 = mul(&c, &c);
        let c3 = mul(&c2, &c);
        let ac = a_times(&c);
        let ac2 = a_times(&c2);
        let aac = a_times(&ac);
        let mut v = vec![
            (dot(b, &one), 1.0),
            (dot(b, &c), 1.0 / 2.0),
            (dot(b, &c2), 1.0 / 3.0),
            (dot(b, &ac), 1.0 / 6.0),
            (dot(b, &c3), 1.0 / 4.0),
            (dot(b, &mul(&c, &ac)), 1.0 / 8.0),
            (dot(b, &ac2), 1.0 / 12.0),
            (dot(b, &aac), 1.0 / 24.0),
        ];
        if p >= 5 {
            v.extend([
                (dot(b, &mul(&c3, &c)), 1.0 / 5.0),
                (dot(b, &mul(&c2, &ac)), 1.0 / 10.0),
                (dot(b, &mul(&ac, &ac)), 1.0 / 20.0),
                (dot(b, &mul(&c, &ac2)), 1.0 / 15.0),
                (dot(b, &a_times(&c3)), 1.0 / 20.0),
                (dot(b, &mul(&c, &aac)), 1.0 / 30.0),
                (dot(b, &a_times(&mul(&c, &ac))), 1.0 / 40.0),
                (dot(b, &a_times(&ac2)), 1.0 / 60.0),
                (dot(b, &a_times(&aac)), 1.0 / 120.0),
            ]);
        }
        v
    }

    #[test]
    fn rows_sum_to_the_stage_times() {
        for i in 0..7 {
            let row: f64 = A[i].iter().sum();
            assert!((row - C[i]).abs() < 1e-15, "row {i}: {row} vs {}", C[i]);
        }
    }

    #[test]
    fn fifth_order_weights_meet_all_17_conditions() {
        let conds = conditions(&B, 5);
        assert_eq!(conds.len(), 17);
        for (n, (got, want)) in conds.into_iter().enumerate() {
            assert!((got - want).abs() < 1e-14, "tree {n}: {got} vs {want}");
        }
    }

    #[test]
    fn embedded_weights_have_order_four_not_five() {
        for (n, (got, want)) in conditions(&B_HAT, 4).into_iter().enumerate() {
            assert!((got - want).abs() < 1e-14, "tree {n}: {got} vs {want}");
        }
        let worst = conditions(&B_HAT, 5)[8..]
            .iter()
            .map(|(g, w)| (g - w).abs())
            .fold(0.0, f64::max);
        assert!(worst > 1e-6, "the error estimate would vanish: {worst}");
    }

    #[test]
    fn fsal_last_row_is_the_fifth_order_weights() {
        for j in 0..6 {
            assert_eq!(A[6][j], B[j]);
        }
    }
}
