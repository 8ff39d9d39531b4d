//! Fixed-step classical RK4 for a [`GroundTop`], with lift-off detection.

use glam::{DQuat, DVec3};

use super::ground_top::Rates;
use super::{GroundCheck, GroundTop, GroundTopState};
use crate::{Divergence, DynamicsError};

/// The method's name in [`DynamicsError::Diverged`].
const METHOD: &str = "ground-top rk4";

/// Bisection steps that locate a lift-off, a touchdown or a landing inside
/// its interval (2⁻⁶⁰ of it).
const BISECTIONS: usize = 60;

/// `Σ wᵢ kᵢ` over Runge–Kutta stages (the normal force and compliance
/// fields are left at zero: they are not rates).
pub(super) fn weighted(stages: &[Rates], weights: &[f64]) -> Rates {
    let mut sum = Rates {
        d_com: DVec3::ZERO,
        d_velocity: DVec3::ZERO,
        d_attitude: DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0),
        d_l: DVec3::ZERO,
        normal_force: 0.0,
        contact_force: DVec3::ZERO,
        compliance: 0.0,
    };
    for (k, &w) in stages.iter().zip(weights) {
        if w != 0.0 {
            sum.d_com += k.d_com * w;
            sum.d_velocity += k.d_velocity * w;
            sum.d_attitude += k.d_attitude * w;
            sum.d_l += k.d_l * w;
        }
    }
    sum
}

/// The instant `τ ∈ (lo, hi]` where `holds(τ, at(τ))` first fails, found
/// by bisection (it holds at `lo`, fails at `hi`), and the state there: a
/// lift-off (`N > 0` fails), a touchdown or a landing (every gap positive
/// fails). Shared by the steppers and the exact flight.
pub(super) fn crossing(
    (mut lo, mut hi): (f64, f64),
    at: impl Fn(f64) -> GroundTopState,
    holds: impl Fn(f64, &GroundTopState) -> bool,
) -> (f64, GroundTopState) {
    for _ in 0..BISECTIONS {
        let mid = 0.5 * (lo + hi);
        if holds(mid, &at(mid)) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (hi, at(hi))
}

/// A trial step: the state it ends at, the smallest normal force and
/// compliance over its stages, and the rates at its end.
pub(super) struct Trial {
    pub(super) next: GroundTopState,
    pub(super) normal_min: f64,
    pub(super) compliance_min: f64,
    pub(super) end: Rates,
}

impl Trial {
    /// The trial of `stages` ending at `next`, whose rates are `end`.
    pub(super) fn of(next: GroundTopState, stages: &[Rates], end: Rates) -> Self {
        let min = |f: fn(&Rates) -> f64| stages.iter().map(f).fold(f64::INFINITY, f64::min);
        Self {
            next,
            normal_min: min(|k| k.normal_force),
            compliance_min: min(|k| k.compliance),
            end,
        }
    }
}

/// One classical RK4 step of `h` from `s` at time `t`.
fn rk4(top: &GroundTop, s: &GroundTopState, t: f64, h: f64) -> Trial {
    let mid = t + 0.5 * h;
    let k1 = top.rates(t, s);
    let k2 = top.rates(mid, &s.plus(&k1, 0.5 * h));
    let k3 = top.rates(mid, &s.plus(&k2, 0.5 * h));
    let k4 = top.rates(t + h, &s.plus(&k3, h));
    let stages = [k1, k2, k3, k4];
    let sum = weighted(&stages, &[1.0, 2.0, 2.0, 1.0]);
    let next = s.plus(&sum, h / 6.0);
    Trial::of(next, &stages, top.rates(t + h, &next))
}

/// `InvalidStep` / `InvalidState` for a step that cannot start.
pub(super) fn check_start(state: &GroundTopState, h: f64) -> Result<(), DynamicsError> {
    if !(h.is_finite() && h > 0.0) {
        return Err(DynamicsError::InvalidStep { h });
    }
    if !state.is_valid() {
        return Err(DynamicsError::InvalidState {
            reason: "the ground-top state is not finite",
        });
    }
    Ok(())
}

impl GroundTop {
    /// Advances `state`, at time `time`, by one classical RK4 step of `h`
    /// seconds (Kutta 1901; the attitude is not renormalised, the crate's
    /// rule for its Runge–Kutta methods, and the constraint is not
    /// projected: its drift is the method's error, measured by
    /// [`GroundTop::gap`]).
    ///
    /// ```text
    /// x(t + h) = x + h (k₁ + 2k₂ + 2k₃ + k₄)/6
    /// ```
    ///
    /// # Errors
    /// - [`DynamicsError::ContactLost`] when the normal force reaches zero
    ///   inside the step (lift-off; the body would leave the plane). The
    ///   instant is located by bisection on the step size, and `state` is
    ///   left there (`N ≈ 0`); when only an inner stage saw `N ≤ 0`, the
    ///   step is not taken and the time is the step's start.
    /// - [`DynamicsError::ContactTouchdown`] when one of the
    ///   [`GroundTop::other_contacts`] reaches the plane inside the step
    ///   (its gap's sign at the step's end, or a graze found from the gap's
    ///   values and rates at both ends: [`GroundTop::try_with_other_contacts`]).
    ///   The instant is located by bisection on the step size and `state`
    ///   is left there (the gap ≈ 0, not positive); the earlier of a
    ///   lift-off and a touchdown in the same step is reported. A `state`
    ///   that already has a further contact at or below the plane gives it
    ///   at `time`, the step not taken.
    /// - [`DynamicsError::DiskFlat`] when a disk rim's contact point, in
    ///   body axes, turns by more than 90° in the step (the disk passed
    ///   through lying flat, where its far side touches down, or the step
    ///   is far too large); `state` is left at the step's start.
    /// - [`DynamicsError::ContactIndeterminate`] when no normal force can
    ///   keep the contact (see [`GroundTop::normal_force`]).
    /// - [`DynamicsError::InvalidStep`] for `h` not positive and finite,
    ///   [`DynamicsError::InvalidState`] for a non-finite `state`,
    ///   [`DynamicsError::Diverged`] when the step leaves a non-finite state.
    ///   `state` is unchanged on these errors.
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec2, DVec3};
    /// use kreisel_dynamics::{Friction, GroundTop, SphereContact};
    /// let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
    /// let inertia = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
    /// let top = GroundTop::try_new(0.006, inertia, sphere, Friction::None, 9.81)?;
    /// let q = DQuat::from_rotation_x(0.1);
    /// let mut s = top.try_state_on_ground(q, q * DVec3::new(0.0, 0.0, 180.0), DVec2::ZERO)?;
    /// let e0 = top.energy(&s);
    /// for n in 0..1000 {
    ///     top.try_step(&mut s, n as f64 * 1e-4, 1e-4)?;
    /// }
    /// assert!((top.energy(&s) - e0).abs() < 1e-9 * e0);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_step(
        &self,
        state: &mut GroundTopState,
        time: f64,
        h: f64,
    ) -> Result<(), DynamicsError> {
        check_start(state, h)?;
        let trial = rk4(self, state, time, h);
        self.settle(state, time, h, METHOD, trial, |s, tau| {
            rk4(self, s, time, tau).next
        })
    }

    /// The contact checks after a trial step of `h` from `state` at `time`,
    /// shared by every ground-top integrator: takes the step (`*state =
    /// trial.next`) or returns the error [`GroundTop::try_step`] documents,
    /// leaving `state` as it says. `redo(s, τ)` is the same method's step
    /// of `τ ≤ h` from `s` (the step's start), for locating a lift-off or
    /// a touchdown. Without further contacts the common path adds one
    /// comparison; the touchdown checks live in `settle_events`.
    pub(super) fn settle(
        &self,
        state: &mut GroundTopState,
        time: f64,
        h: f64,
        method: &'static str,
        trial: Trial,
        redo: impl Fn(&GroundTopState, f64) -> GroundTopState,
    ) -> Result<(), DynamicsError> {
        let Trial {
            next,
            normal_min,
            compliance_min,
            end,
        } = trial;
        if compliance_min <= 0.0 {
            return Err(DynamicsError::ContactIndeterminate {
                time,
                compliance: compliance_min,
            });
        }
        if !next.is_valid() || !normal_min.is_finite() {
            return Err(DynamicsError::Diverged {
                method,
                time: time + h,
                reason: Divergence::NonFinite,
            });
        }
        if let Some(start) = self.rim_direction_body(state) {
            let end = self.rim_direction_body(&next).unwrap_or(DVec3::NAN);
            // NaN: exactly flat.
            let dot = start.dot(end);
            if dot.is_nan() || dot <= 0.0 {
                return Err(DynamicsError::DiskFlat { time });
            }
        }
        if end.normal_force > 0.0 && normal_min <= 0.0 {
            return Err(DynamicsError::ContactLost {
                time,
                normal_force: normal_min,
            });
        }
        if end.normal_force > 0.0 && self.others.is_empty() {
            *state = next;
            return Ok(());
        }
        self.settle_events(state, time, h, next, end.normal_force <= 0.0, redo)
    }

    /// The rest of [`GroundTop::settle`] where a lift-off is found at the
    /// step's end (`lost`) or further contacts are watched: takes the step,
    /// or locates the earlier of the lift-off and a touchdown and leaves
    /// `state` there (kept out of the common path, which it would slow).
    #[inline(never)]
    fn settle_events(
        &self,
        state: &mut GroundTopState,
        time: f64,
        h: f64,
        next: GroundTopState,
        lost: bool,
        redo: impl Fn(&GroundTopState, f64) -> GroundTopState,
    ) -> Result<(), DynamicsError> {
        let start = *state;
        let touch_by = if self.others.is_empty() {
            None
        } else {
            self.touchdown_bound(&start, &next, time, h, |tau| redo(&start, tau))?
        };
        if !lost && touch_by.is_none() {
            *state = next;
            return Ok(());
        }
        let lift = lost.then(|| {
            crossing(
                (0.0, h),
                |tau| redo(&start, tau),
                |tau, s| self.rates(time + tau, s).normal_force > 0.0,
            )
        });
        let touch = touch_by.map(|hi| {
            crossing(
                (0.0, hi),
                |tau| redo(&start, tau),
                |_, s| self.others_clear(s),
            )
        });
        match (lift, touch) {
            (Some((t_lift, _)), Some((tau, at))) if tau < t_lift => {
                *state = at;
                Err(self.touchdown_at(&at, time + tau))
            }
            (Some((tau, at)), _) => {
                *state = at;
                Err(DynamicsError::ContactLost {
                    time: time + tau,
                    normal_force: self.rates(time + tau, &at).normal_force,
                })
            }
            (None, Some((tau, at))) => {
                *state = at;
                Err(self.touchdown_at(&at, time + tau))
            }
            // Not reached (`lost` or `touch_by` holds here): the step stands.
            (None, None) => {
                *state = next;
                Ok(())
            }
        }
    }

    /// Takes `steps` steps of `h` from `time`, calling `observe(t, state)`
    /// after each, and returns the final time. Every step is checked by a
    /// [`GroundCheck`] started at `state`.
    ///
    /// # Errors
    /// As [`GroundTop::try_step`], at the first step that fails (`state`
    /// left as that function says);
    /// [`DynamicsError::GroundCheckFailed`] for a step whose state fails
    /// the guard ([`crate::GROUND_CHECK_TOLERANCE`]), `state` left at the
    /// step's start.
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec2, DVec3};
    /// use kreisel_dynamics::{Friction, GroundTop, SphereContact};
    /// let sphere = SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003))?;
    /// let inertia = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
    /// let top = GroundTop::try_new(0.006, inertia, sphere, Friction::try_viscous(0.3)?, 9.81)?;
    /// let q = DQuat::from_rotation_x(0.1);
    /// let mut s = top.try_state_on_ground(q, q * DVec3::new(0.0, 0.0, 180.0), DVec2::ZERO)?;
    /// let lambda0 = top.jellett(&s);
    /// let t = top.try_advance(&mut s, 0.0, 1e-4, 1000, |_, _| {})?;
    /// assert!((t - 0.1).abs() < 1e-12);
    /// assert!((top.jellett(&s) - lambda0).abs() < 1e-10 * lambda0.abs());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_advance(
        &self,
        state: &mut GroundTopState,
        time: f64,
        h: f64,
        steps: usize,
        mut observe: impl FnMut(f64, &GroundTopState),
    ) -> Result<f64, DynamicsError> {
        let mut check = GroundCheck::new(self, state);
        let mut t = time;
        for n in 0..steps {
            let start = *state;
            self.try_step(state, t, h)?;
            t = time + (n + 1) as f64 * h;
            if let Err(e) = check.check(self, state, t, h) {
                *state = start;
                return Err(e);
            }
            observe(t, state);
        }
        Ok(t)
    }
}
