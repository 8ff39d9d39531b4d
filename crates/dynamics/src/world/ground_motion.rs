//! [`GroundMotion`]: a body on the ground as the world moves it — its
//! [`GroundTop`], placed on the plane, stepped by error-controlled
//! Dormand–Prince steps under its [`GroundCheck`] (how the world adds,
//! retunes and replans such a body, and why: `ground`).

use glam::{DQuat, DVec2, DVec3};

use super::{Body, BodyState, Support};
use crate::contact::Controlled;
use crate::{
    AdaptiveTolerance, ContactShape, DynamicsError, Friction, GroundCheck, GroundTop,
    GroundTopState, PrincipalState,
};

/// A body on the ground as the world moves it: its contact model, its
/// state, and the rotation from principal to body axes (to report the
/// rotational state the other plans report).
#[derive(Debug)]
pub(crate) struct GroundMotion {
    pub(crate) top: GroundTop,
    pub(crate) state: GroundTopState,
    body_from_principal: DQuat,
    /// The guard, started where the body was last placed.
    check: GroundCheck,
    /// The accuracy of the error-controlled steps.
    pub(crate) tolerance: AdaptiveTolerance,
    /// The step the controller proposed last (the next step's first try).
    next_step: Option<f64>,
}

/// `g` of a world whose gravity is `(0, 0, −g)`, `g > 0`.
///
/// # Errors
/// [`DynamicsError::InvalidBody`] for any other gravity.
pub(super) fn gravity_down(gravity: DVec3) -> Result<f64, DynamicsError> {
    if gravity.x == 0.0 && gravity.y == 0.0 && gravity.z < 0.0 {
        Ok(-gravity.z)
    } else {
        Err(DynamicsError::InvalidBody {
            field: "gravity",
            reason: "must point along −z, (0, 0, −g) with g > 0, for a body on the ground",
        })
    }
}

/// The state of `top` touching the plane at attitude `q` spinning at
/// `omega_world`, its centre of mass above `position_xy` moving at
/// `velocity_xy` (rolling with `velocity_xy = 0`: as rolling needs).
pub(super) fn place(
    top: &GroundTop,
    q: DQuat,
    omega_world: DVec3,
    position_xy: DVec2,
    velocity_xy: DVec2,
) -> Result<GroundTopState, DynamicsError> {
    if !top.shape().contact_from_com_world(q).is_finite() {
        // Said here: the rolling state would first find ω × ρ not finite.
        return Err(DynamicsError::InvalidState {
            reason: "the disk lies flat (axis vertical): no single contact point",
        });
    }
    let mut state = if top.friction() == Friction::Rolling && velocity_xy == DVec2::ZERO {
        top.try_rolling_state_on_ground(q, omega_world)?
    } else {
        top.try_state_on_ground(q, omega_world, velocity_xy)?
    };
    state.com_world.x += position_xy.x;
    state.com_world.y += position_xy.y;
    if state.com_world.z < 0.0 {
        // Every part of a body on the table is above it, so is their mean.
        return Err(DynamicsError::InvalidBody {
            field: "contact",
            reason: "touching the plane puts the centre of mass below it: a body on the table \
                     has all its mass above the plane (is the contact shape's centre right?)",
        });
    }
    check_others_clear(top, &state)?;
    Ok(state)
}

/// [`DynamicsError::OtherContactTouching`] for the first further shape of
/// `top` at or below the plane in `state` (its gap not positive).
fn check_others_clear(top: &GroundTop, state: &GroundTopState) -> Result<(), DynamicsError> {
    for contact in 0..top.other_contacts().len() {
        let gap = top.other_gap(state, contact).unwrap_or(f64::NAN);
        if gap.is_nan() || gap <= 0.0 {
            return Err(DynamicsError::OtherContactTouching { contact, gap });
        }
    }
    Ok(())
}

impl GroundMotion {
    /// The contact model of `body` (on the ground, in a world of gravity
    /// `gravity`) and its state at attitude `q` spinning at `omega_world`.
    pub(super) fn try_new(
        body: &Body,
        (gravity, tolerance): (DVec3, AdaptiveTolerance),
        q: DQuat,
        omega_world: DVec3,
    ) -> Result<Self, DynamicsError> {
        let Support::Ground {
            shape,
            friction,
            position_xy,
            velocity_xy,
        } = body.support()
        else {
            return Err(DynamicsError::InvalidBody {
                field: "support",
                reason: "is not the ground",
            });
        };
        let top = ground_top(body, shape, friction, gravity)?
            .try_with_other_contacts(body.other_contacts())?;
        let state = place(&top, q, omega_world, position_xy, velocity_xy)?;
        Ok(Self {
            check: GroundCheck::new(&top, &state),
            top,
            state,
            body_from_principal: body.rigid_body().body_from_principal(),
            tolerance,
            next_step: None,
        })
    }

    /// One step of `h` from time `t`: error-controlled Dormand–Prince
    /// steps ([`GroundTop::try_advance_adaptive`] at the body's tolerance)
    /// that land on `t + h`, the controller's last step carried over to
    /// the next call; every accepted step checked by the body's
    /// [`GroundCheck`].
    ///
    /// # Errors
    /// The errors of [`GroundTop::try_advance_adaptive`] (lift-off, a
    /// further shape's touchdown, a disk flat, Painlevé, divergence, a step
    /// below the smallest), with their time;
    /// [`DynamicsError::GroundCheckFailed`] for an accepted step whose
    /// state fails the guard (the state is left at the last one that
    /// passed).
    pub(crate) fn step(&mut self, t: f64, h: f64) -> Result<(), DynamicsError> {
        let run = Controlled {
            tolerance: self.tolerance,
            first_step: self.next_step,
        };
        let (top, check) = (&self.top, &mut self.check);
        let mut passed = self.state;
        let mut t_passed = t;
        let result = top.advance_controlled(&mut self.state, (t, t + h), run, |time, s| {
            check.check(top, s, time, time - t_passed)?;
            (passed, t_passed) = (*s, time);
            Ok(())
        });
        match result {
            Ok((_, next)) => {
                self.next_step = next;
                Ok(())
            }
            Err(e) => {
                if matches!(e, DynamicsError::GroundCheckFailed { .. }) {
                    self.state = passed;
                }
                self.next_step = None;
                Err(e)
            }
        }
    }

    /// Sets the accuracy of the steps (the world's tolerance changed).
    pub(crate) fn set_tolerance(&mut self, tolerance: AdaptiveTolerance) {
        self.tolerance = tolerance;
        self.next_step = None;
    }

    /// Starts the guard again from the current state (after a setter or
    /// new inputs: the energy it compares with has changed).
    pub(crate) fn restart_check(&mut self) {
        self.check = GroundCheck::new(&self.top, &self.state);
        self.next_step = None;
    }

    /// The rotational state as the other plans hold it: principal axes,
    /// `L` about the centre of mass.
    pub(crate) fn principal_state(&self) -> PrincipalState {
        let world_from_principal =
            self.state.world_from_body.normalize() * self.body_from_principal;
        PrincipalState {
            world_from_principal,
            l_principal: world_from_principal.conjugate() * self.state.l_world,
        }
    }

    /// The attitude as stepped (not renormalised).
    pub(crate) fn attitude(&self) -> DQuat {
        self.state.world_from_body
    }

    /// What the world reports at `time`.
    pub(crate) fn body_state(&self, time: f64) -> BodyState {
        let q = self.state.world_from_body;
        let omega_world = self.top.omega_world(&self.state);
        BodyState {
            time,
            world_from_body: q,
            omega_body: q.normalize().conjugate() * omega_world,
            l_world: self.state.l_world,
            energy: self.top.energy(&self.state),
            position: self.state.com_world,
            velocity: self.state.velocity_world,
        }
    }
}

/// The contact model of `body` with `shape` and `friction` under `gravity`,
/// with the body's inputs.
fn ground_top(
    body: &Body,
    shape: ContactShape,
    friction: Friction,
    gravity: DVec3,
) -> Result<GroundTop, DynamicsError> {
    let g = gravity_down(gravity)?;
    let props = body.mass_properties();
    GroundTop::try_with_shape(props.mass, props.inertia, shape, friction, g)?
        .try_with_inputs(body.inputs().clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gravity_must_point_down() {
        assert_eq!(gravity_down(DVec3::new(0.0, 0.0, -9.81)).unwrap(), 9.81);
        for g in [DVec3::ZERO, DVec3::Z, DVec3::new(0.1, 0.0, -9.81)] {
            assert!(matches!(
                gravity_down(g),
                Err(DynamicsError::InvalidBody {
                    field: "gravity",
                    ..
                })
            ));
        }
    }
}
