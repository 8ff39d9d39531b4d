//! Free flight of a [`GroundTop`] after a lift-off: the exact ballistic
//! motion (a parabola for the centre of mass, the torque-free rotation of
//! [`crate::ExactSolution`]) until one of its contact shapes reaches the
//! plane.

use glam::{DQuat, DVec3};

use super::{GroundTop, GroundTopState};
use crate::{DynamicsError, ExactSolution, PrincipalState, RigidBody};

/// Samples per radian of the fastest possible turn, `|L|/I_min`: the gaps
/// are checked at least every `1/16` rad of rotation.
const SAMPLES_PER_RADIAN: f64 = 16.0;

/// Where a flight ([`GroundTop::try_fly`]) ended on the plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Landing {
    /// The time the shape's gap reached zero, s.
    pub time: f64,
    /// Which shape: `None` for the main one ([`GroundTop::shape`]),
    /// `Some(i)` for [`GroundTop::other_contacts`]`[i]`.
    pub contact: Option<usize>,
    /// The speed of its lowest point towards the plane there, m/s (`−ġ`).
    pub approach_speed: f64,
}

/// The exact flight from one state: the centre of mass on its parabola,
/// the rotation torque-free ([`ExactSolution`]).
#[derive(Debug, Clone)]
pub(crate) struct Flight {
    start: GroundTopState,
    exact: ExactSolution,
    body_from_principal: DQuat,
    gravity: f64,
    /// The fastest possible turn, `|L|/I_min`, rad/s.
    pub(crate) fastest_turn: f64,
}

impl Flight {
    /// The flight of a body with inertia `inertia_body` (about its centre
    /// of mass, body axes) from `state` under gravity `g`.
    ///
    /// # Errors
    /// Those of [`RigidBody::try_from_inertia_tensor`] and
    /// [`ExactSolution::try_new`].
    pub(crate) fn try_new(
        inertia_body: glam::DMat3,
        state: &GroundTopState,
        gravity: f64,
    ) -> Result<Self, DynamicsError> {
        let body = RigidBody::try_from_inertia_tensor(inertia_body)?;
        let (moments, body_from_principal) = (body.principal_moments(), body.body_from_principal());
        let world_from_principal = state.world_from_body.normalize() * body_from_principal;
        let exact = ExactSolution::try_new(
            moments,
            PrincipalState {
                world_from_principal,
                l_principal: world_from_principal.conjugate() * state.l_world,
            },
        )?;
        Ok(Self {
            start: *state,
            exact,
            body_from_principal,
            gravity,
            fastest_turn: state.l_world.length() / moments.min_element(),
        })
    }

    /// The state `tau` seconds into the flight.
    pub(crate) fn at(&self, tau: f64) -> GroundTopState {
        let p = self.exact.state_at(tau);
        let s = &self.start;
        GroundTopState {
            com_world: s.com_world + s.velocity_world * tau
                - 0.5 * self.gravity * tau * tau * DVec3::Z,
            velocity_world: s.velocity_world - self.gravity * tau * DVec3::Z,
            world_from_body: p.world_from_principal * self.body_from_principal.conjugate(),
            // Torque-free: L about the centre of mass is constant in world axes.
            l_world: s.l_world,
        }
    }
}

impl GroundTop {
    /// The gap and its rate of every shape, main first, then
    /// [`GroundTop::other_contacts`].
    fn all_gaps(&self, state: &GroundTopState) -> Vec<(f64, f64)> {
        let main = (self.gap(state), self.gap_rate(state));
        std::iter::once(main)
            .chain((0..self.other_contacts().len()).map(|i| {
                (
                    self.other_gap(state, i).unwrap_or(f64::NAN),
                    self.other_gap_rate(state, i).unwrap_or(f64::NAN),
                )
            }))
            .collect()
    }

    /// Flies `state` from `t0` without any contact force — the centre of
    /// mass on a parabola, the rotation torque-free and exact — until the
    /// main shape or one of the [`GroundTop::other_contacts`] reaches the
    /// plane, or `t_end`; returns the [`Landing`] (`None`: still in the air
    /// at `t_end`), `state` left at the landing (that gap ≈ 0, not
    /// positive) or at `t_end`.
    ///
    /// ```text
    /// r_G(t) = r_G + v_G τ − ½ g τ² ẑ,   v_G(t) = v_G − g τ ẑ,   L(t) = L,   τ = t − t0
    /// q(t) = ExactSolution(I, q, L)(τ)   (about the centre of mass)
    /// ```
    ///
    /// The continuation after [`DynamicsError::ContactLost`]: from the
    /// state it leaves (the main gap ≈ 0, `N ≈ 0`), the body leaves the
    /// plane. A shape at or below the plane at the start (the one that
    /// just lifted off) is watched from when its gap turns positive; one
    /// still at or below it at the first check is reported as landed at
    /// `t0`. The gaps are checked at least every 1/16 rad of the fastest
    /// possible turn (`|L|/I_min`) and between checks by their cubic
    /// Hermite interpolant (as [`GroundTop::try_step`] does for a graze);
    /// a landing is located by bisection on the exact flight to
    /// round-off. The impact is not modelled.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidInterval`] for `t_end < t0` or a time not
    /// finite; [`DynamicsError::InvalidState`] for a non-finite state;
    /// the errors of [`ExactSolution::try_new`]. `state` is unchanged.
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec3};
    /// use kreisel_dynamics::{Friction, GroundTop, GroundTopState, SphereContact};
    /// // A spinning ball dropped from 1 m lands after √(2 (1 − R)/g).
    /// let (m, r) = (0.1, 0.02);
    /// let ball = SphereContact::try_new(r, DVec3::ZERO)?;
    /// let top = GroundTop::try_new(m, DMat3::from_diagonal(DVec3::splat(0.4 * m * r * r)), ball, Friction::None, 9.81)?;
    /// let mut s = GroundTopState {
    ///     com_world: DVec3::new(0.0, 0.0, 1.0),
    ///     velocity_world: DVec3::ZERO,
    ///     world_from_body: DQuat::IDENTITY,
    ///     l_world: DVec3::new(0.0, 1e-4, 3e-4),
    /// };
    /// let landing = top.try_fly(&mut s, 0.0, 2.0)?.expect("it lands");
    /// assert!((landing.time - (2.0 * (1.0 - r) / 9.81f64).sqrt()).abs() < 1e-14);
    /// assert_eq!(landing.contact, None);
    /// assert!(top.gap(&s).abs() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_fly(
        &self,
        state: &mut GroundTopState,
        t0: f64,
        t_end: f64,
    ) -> Result<Option<Landing>, DynamicsError> {
        if !(t0.is_finite() && t_end.is_finite() && t_end >= t0) {
            return Err(DynamicsError::InvalidInterval { t0, t_end });
        }
        if !state.is_valid() {
            return Err(DynamicsError::InvalidState {
                reason: "the ground-top state is not finite",
            });
        }
        if self.inputs().is_some() {
            return Err(DynamicsError::InvalidInput {
                input: "inputs",
                index: None,
                value: f64::NAN,
                reason: "the flight is the exact torque-free motion: not with applied inputs",
            });
        }
        let flight = Flight::try_new(self.inertia_body(), state, self.gravity())?;
        let span = t_end - t0;
        let fastest = flight.fastest_turn;
        let dt = if fastest > 0.0 {
            (1.0 / (SAMPLES_PER_RADIAN * fastest)).min(span)
        } else {
            span
        };
        let mut before = self.all_gaps(state);
        let mut armed: Vec<bool> = before.iter().map(|&(g, _)| g > 0.0).collect();
        let (mut tau_a, mut n) = (0.0, 0usize);
        while tau_a < span {
            n += 1;
            let tau_b = (n as f64 * dt).min(span);
            let s_b = flight.at(tau_b);
            let after = self.all_gaps(&s_b);
            if n == 1
                && let Some(j) = (0..after.len()).find(|&j| !armed[j] && after[j].0 <= 0.0)
            {
                return Ok(Some(self.landed(state, *state, t0, j, &before)));
            }
            let h = tau_b - tau_a;
            let mut hi: Option<f64> = None;
            for j in (0..after.len()).filter(|&j| armed[j]) {
                let bound = if after[j].0 <= 0.0 {
                    Some(tau_b)
                } else {
                    super::touchdown::hermite_dip(
                        (before[j].0, before[j].1 * h),
                        (after[j].0, after[j].1 * h),
                    )
                    .map(|s| tau_a + s * h)
                    .filter(|&tau| self.all_gaps(&flight.at(tau))[j].0 <= 0.0)
                };
                if let Some(b) = bound {
                    hi = Some(hi.map_or(b, |x: f64| x.min(b)));
                }
            }
            if let Some(hi) = hi {
                let clear = |_: f64, s: &GroundTopState| {
                    let g = self.all_gaps(s);
                    (0..g.len()).all(|j| !armed[j] || g[j].0 > 0.0)
                };
                let (hi, at) = super::rk4::crossing((tau_a, hi), |tau| flight.at(tau), clear);
                let gaps = self.all_gaps(&at);
                let j = (0..gaps.len())
                    .filter(|&j| armed[j])
                    .min_by(|&a, &b| gaps[a].0.total_cmp(&gaps[b].0))
                    .unwrap_or(0);
                return Ok(Some(self.landed(state, at, t0 + hi, j, &gaps)));
            }
            for (j, &(g, _)) in after.iter().enumerate() {
                armed[j] |= g > 0.0;
            }
            before = after;
            tau_a = tau_b;
            if tau_b >= span {
                *state = s_b;
            }
        }
        Ok(None)
    }

    /// Leaves `state` at `at` and describes the landing of shape `j`
    /// (0 the main one) at `time`, its gaps and rates there `gaps`.
    fn landed(
        &self,
        state: &mut GroundTopState,
        at: GroundTopState,
        time: f64,
        j: usize,
        gaps: &[(f64, f64)],
    ) -> Landing {
        *state = at;
        Landing {
            time,
            contact: j.checked_sub(1),
            approach_speed: -gaps[j].1,
        }
    }
}
