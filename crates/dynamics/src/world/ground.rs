//! Bodies on the ground plane in a [`World`]
//! ([`Support::Ground`](super::Support::Ground), [`crate::Plan::OnGround`]):
//! the world's gravity must point along −z; each body is a
//! [`GroundTop`](crate::GroundTop) moved by its error-controlled
//! Dormand–Prince 5(4) steps within every step the world takes.
//!
//! ```text
//! add:       GroundTop(mass, inertia about the centre of mass (body axes), shape, friction, g = −gravity_z)
//!            state touching the plane: z_G = −ρ_z, ż_G = −(ω × ρ)_z, (x_G, y_G), (ẋ_G, ẏ_G) given
//!            (rolling: v_G = −ω × ρ)
//! step h:    dopri5 steps from t to t + h, each chosen so that its local error meets
//!            rtol = atol = tol (GroundTop::try_advance_adaptive), the last one landing on
//!            t + h; the controller's next step carried over to the next world step
//!            tol = GROUND_TOLERANCE = 1e-11                     without a world Tolerance
//!                = clamp(1e-4 · attitude, 1e-13, 1e-8)           with Tolerance(attitude, horizon)
//! read:      q, ω_body = qᵀ ω, L about the centre of mass (world axes), r_G, v_G,
//!            E = ½ m |v_G|² + ½ L·ω + m g z_G           (GroundTop::energy)
//! setters:   attitude / ω / angular impulse re-place the body on the plane
//!            (horizontal position and velocity kept; rolling: v_G from ω)
//! watched:   further shapes (Body::other_contacts), gaps gᵢ = z_G + (ρᵢ)_z:
//!            gᵢ > 0 on every placing (else OtherContactTouching), checked
//!            after every step (gᵢ = 0: ContactTouchdown, located in the step)
//! ```
//!
//! The world's `dt` is only the grid the states are read on: the steps
//! inside it are the error control's (issue 26). At the default tolerance
//! the viscous tippe top passes the horizontal at the independent
//! generator's time to 1e-8 and the rattleback reverses at its time to
//! 1e-8 at `dt` = 1/60 s, 1e-3 s and 1e-5 s alike
//! (`tests/world_ground_adaptive.rs`). A lift-off
//! ([`DynamicsError::ContactLost`], with its time located inside the
//! step), a disk lying flat ([`DynamicsError::DiskFlat`]), Painlevé's
//! case ([`DynamicsError::ContactIndeterminate`]) or a step the controller
//! cannot make small enough ([`DynamicsError::StepTooSmall`]) is the
//! world's failure ([`DynamicsError::BodyFailed`]); the body holds the
//! state the model left (at lift-off: the state where the normal force
//! reached zero).
//!
//! Every accepted step is checked by the body's
//! [`GroundCheck`](crate::GroundCheck) (|q|, the
//! contact point on the plane, the centre of mass above it, the energy
//! not rising under friction nor drifting without it, beyond
//! [`crate::GROUND_CHECK_TOLERANCE`]), not only the state at the end of
//! the world's step: a drift that the error estimate missed is caught at
//! the step that made it, and a state that recovers by the frame's end
//! does not hide it. A failure is the world's, with the source
//! [`DynamicsError::GroundCheckFailed`] and the accepted step's time, the
//! body left at the last state that passed. A setter starts the checks
//! again from the new state; applied loads switch the energy check off.
//!
//! A body may carry further contact shapes that do not touch
//! ([`crate::BodyBuilder::other_contacts`], the stem's ball of a tippe
//! top): its [`GroundTop`](crate::GroundTop) watches them
//! ([`GroundTop::try_with_other_contacts`](crate::GroundTop::try_with_other_contacts)).
//! One reaching the plane is the
//! world's failure in the same way, its source
//! [`DynamicsError::ContactTouchdown`] (the time located inside the step,
//! which shape, its approach speed; the body holds the state at the
//! touchdown): the impact and the two-contact motion after it are not
//! modelled. Placing the body — when it is added, or by a setter — with a
//! further shape at or below the plane is
//! [`DynamicsError::OtherContactTouching`].

use glam::DVec2;

use super::ground_motion::{GroundMotion, place};
use super::motion::Motion;
use super::reads::Reading;
use super::{Body, BodyId, Entry, Plan, World};
use crate::{AdaptiveTolerance, DynamicsError, Friction, PrincipalState};

/// The accuracy of a ground body's steps in a world without a
/// [`crate::Tolerance`]: `rtol = atol` of [`AdaptiveTolerance`] (what a
/// tolerance of 1e-7 rad asks).
///
/// Measured (`tests/world_ground_adaptive.rs`): at this tolerance the
/// viscous tippe top passes the horizontal at the independent generator's
/// time to 8e-12 relative and the rattleback reverses at the generator's
/// time to 6e-10, whatever `dt` the world is stepped at (1/60 s, 1e-3 s,
/// 1e-5 s); at 1e-10 the rattleback was 6e-9 off, too close to the 1e-8
/// the tests ask.
pub(crate) const GROUND_TOLERANCE: f64 = 1e-11;

/// How the world's [`crate::Tolerance`] (an attitude error over a horizon)
/// becomes the local accuracy of a ground body's steps:
/// `rtol = atol = TOLERANCE_TO_LOCAL · attitude`, clamped to
/// [[`MIN_LOCAL_TOLERANCE`], [`MAX_LOCAL_TOLERANCE`]].
///
/// Measured (`tests/world_ground_adaptive.rs`, the tippe top viscous over
/// 6 s and sliding over 3 s against the generator, at dt = 1/60 s): for
/// every tolerance from 1e-2 to 1e-9 rad the worst attitude error stayed
/// below half the tolerance (0.49 × at 1e-4 rad, sliding). At 1e-3 ×
/// attitude it was about 3 × the tolerance.
pub(crate) const TOLERANCE_TO_LOCAL: f64 = 1e-4;

/// The tightest local tolerance: below it the steps' rounding, not their
/// truncation, sets the error.
pub(crate) const MIN_LOCAL_TOLERANCE: f64 = 1e-13;

/// The loosest local tolerance: at 1e-6 the viscous tippe top's |q|
/// drifted by 1e-4 over 3.9 s (the guard's bound); at 1e-8 its attitude
/// error stays below 3e-5 rad.
pub(crate) const MAX_LOCAL_TOLERANCE: f64 = 1e-8;

/// The accuracy of a ground body's steps under the world's `tolerance`.
///
/// # Errors
/// None in practice: the clamp keeps it within (0, 1), which
/// [`AdaptiveTolerance::try_new`] accepts.
pub(crate) fn local_tolerance(
    tolerance: Option<crate::Tolerance>,
) -> Result<AdaptiveTolerance, DynamicsError> {
    let tol = tolerance.map_or(GROUND_TOLERANCE, |t| {
        (TOLERANCE_TO_LOCAL * t.attitude()).clamp(MIN_LOCAL_TOLERANCE, MAX_LOCAL_TOLERANCE)
    });
    AdaptiveTolerance::try_new(tol, tol)
}

/// The plan of a body on the ground moved by `ground`.
fn ground_plan(ground: &GroundMotion) -> Plan {
    Plan::OnGround {
        friction: ground.top.friction().model(),
        watched: ground.top.other_contacts().len(),
        tolerance: ground.tolerance,
    }
}

impl World {
    /// Adds `body`, on the ground, now (the part of [`World::add`] for
    /// [`Support::Ground`](super::Support::Ground)).
    pub(super) fn add_on_ground(&mut self, body: Body) -> Result<BodyId, DynamicsError> {
        let q = body.world_from_body();
        if !(q.is_finite() && q.length_squared() > 0.0) {
            return Err(DynamicsError::InvalidState {
                reason: "the attitude must be a finite, non-zero quaternion",
            });
        }
        let omega_world = q.normalize() * body.omega_body();
        let tolerance = local_tolerance(self.tolerance)?;
        let ground = GroundMotion::try_new(&body, (self.gravity, tolerance), q, omega_world)?;
        let plan = ground_plan(&ground);
        let baseline = ground.principal_state();
        let (position, velocity) = (ground.state.com_world, ground.state.velocity_world);
        let mass = body.mass();
        self.entries.push(Entry {
            rigid: *body.rigid_body(),
            body,
            top: None,
            plan,
            motion: Motion::Ground(Box::new(ground)),
            baseline,
            check: None,
            choice: None,
        });
        self.reads
            .push(Reading::new(mass, (position, velocity, self.time())));
        let index = self.entries.len() - 1;
        self.place(index);
        Ok(BodyId(index))
    }

    /// Gives body `index`, on the ground, the accuracy of the world's
    /// tolerance (its plan says it); nothing for another body.
    ///
    /// # Errors
    /// As [`local_tolerance`].
    pub(super) fn retune_ground(&mut self, index: usize) -> Result<(), DynamicsError> {
        let tolerance = local_tolerance(self.tolerance)?;
        let entry = &mut self.entries[index];
        if let Motion::Ground(ground) = &mut entry.motion {
            ground.set_tolerance(tolerance);
            entry.plan = ground_plan(ground);
        }
        Ok(())
    }

    /// Gives body `index`, on the ground, the rotational state `state` now:
    /// the body is placed on the plane again at the new attitude and
    /// angular velocity, its horizontal position and velocity kept (with
    /// [`Friction::Rolling`] the velocity follows from ω).
    pub(super) fn replan_ground(
        &mut self,
        index: usize,
        state: PrincipalState,
    ) -> Result<(), DynamicsError> {
        let entry = &mut self.entries[index];
        let moments = entry.rigid.principal_moments();
        state.validate(moments)?;
        let Motion::Ground(ground) = &mut entry.motion else {
            return Ok(());
        };
        let q = state.world_from_body(&entry.rigid);
        let omega_world = state.world_from_principal.normalize() * (state.l_principal / moments);
        let now = ground.state;
        let velocity_xy = if ground.top.friction() == Friction::Rolling {
            DVec2::ZERO
        } else {
            now.velocity_world.truncate()
        };
        ground.state = place(
            &ground.top,
            q,
            omega_world,
            now.com_world.truncate(),
            velocity_xy,
        )?;
        // A setter changes the energy: the guard starts again here.
        ground.restart_check();
        entry.baseline = ground.principal_state();
        self.refresh_reading(index);
        Ok(())
    }
}
