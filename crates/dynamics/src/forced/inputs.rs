//! What is applied to a body: constant torques and forces, a force at a
//! body point, linear angular damping and a user law of time and state.

use std::fmt;
use std::sync::Arc;

use glam::DVec3;

use super::ForcedState;
use crate::DynamicsError;

/// A user law `(t, state) ↦ (torque_world, force_world)`: torque about the
/// centre of mass (N m) and force through it (N), both in world axes.
///
/// `Send + Sync` so that bodies can be stepped on several threads.
pub type LoadFn = dyn Fn(f64, &ForcedState) -> (DVec3, DVec3) + Send + Sync;

/// A user law and what it reads, which decides how its kick is integrated
/// (see [`crate::ForcedSplitting`]).
#[derive(Clone)]
pub struct Load {
    law: Arc<LoadFn>,
    reads_velocity: bool,
}

impl Load {
    /// Evaluates the law.
    #[inline]
    pub fn eval(&self, t: f64, state: &ForcedState) -> (DVec3, DVec3) {
        (self.law)(t, state)
    }

    /// Whether the law may read the angular momentum or the velocity (then
    /// its kick is an implicit midpoint step, not an exact one).
    pub fn reads_velocity(&self) -> bool {
        self.reads_velocity
    }
}

impl fmt::Debug for Load {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Load")
            .field("reads_velocity", &self.reads_velocity)
            .finish_non_exhaustive()
    }
}

/// A force (world axes, N) applied at a point fixed in the body (body
/// coordinates from the centre of mass, m). It pushes the centre of mass
/// and adds the torque `(R r) × F`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointForce {
    /// The point of application, body axes, from the centre of mass, m.
    pub point_body: DVec3,
    /// The force, world axes, N.
    pub force_world: DVec3,
}

/// Everything applied to one body besides gravity. All zero by default
/// (a free body).
///
/// ```text
/// τ_world total = τ_w + R τ_b + Σ (R rₖ) × Fₖ − c ω_world + τ_law(t, s)
/// F_world total = F_w + Σ Fₖ + F_law(t, s)            (gravity m g acts besides)
/// ```
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::{Inputs, PointForce};
/// let inputs = Inputs::default()
///     .with_torque_world(DVec3::new(0.0, 0.0, 0.1))
///     .with_point_force(PointForce { point_body: DVec3::X, force_world: DVec3::Y })
///     .with_angular_damping(0.05);
/// assert!(inputs.validate().is_ok());
/// assert!(Inputs::default().with_angular_damping(-1.0).validate().is_err());
/// assert!(Inputs::default().is_none());
/// ```
#[derive(Debug, Clone, Default)]
pub struct Inputs {
    /// Constant torque in world axes, N m.
    pub torque_world: DVec3,
    /// Constant torque in body axes (turns with the body), N m.
    pub torque_body: DVec3,
    /// Constant force in world axes through the centre of mass, N.
    pub force_world: DVec3,
    /// Constant world-axes forces at body points.
    pub point_forces: Vec<PointForce>,
    /// Linear angular damping `c` ≥ 0: the torque `−c ω`, N m s.
    pub angular_damping: f64,
    /// A user law of time and state, if any.
    pub load: Option<Load>,
}

impl Inputs {
    /// These inputs with a constant torque in world axes, N m.
    pub fn with_torque_world(self, torque_world: DVec3) -> Self {
        Self {
            torque_world,
            ..self
        }
    }

    /// These inputs with a constant torque in body axes, N m.
    pub fn with_torque_body(self, torque_body: DVec3) -> Self {
        Self {
            torque_body,
            ..self
        }
    }

    /// These inputs with a constant world-axes force through the centre of
    /// mass, N.
    pub fn with_force_world(self, force_world: DVec3) -> Self {
        Self {
            force_world,
            ..self
        }
    }

    /// These inputs with one more force at a body point.
    pub fn with_point_force(mut self, force: PointForce) -> Self {
        self.point_forces.push(force);
        self
    }

    /// These inputs with linear angular damping `c` (torque `−c ω`), N m s.
    pub fn with_angular_damping(self, angular_damping: f64) -> Self {
        Self {
            angular_damping,
            ..self
        }
    }

    /// These inputs with a user law that reads the time, the attitude and
    /// the position only (not `L` nor `v`): its kick is exact. A law that
    /// does read `L` or `v` must be given to
    /// [`Inputs::with_velocity_load`]; given here it is evaluated at the
    /// start of each kick (explicit Euler, and the compositions lose their
    /// order).
    pub fn with_load(
        self,
        law: impl Fn(f64, &ForcedState) -> (DVec3, DVec3) + Send + Sync + 'static,
    ) -> Self {
        self.with_law(Arc::new(law), false)
    }

    /// These inputs with a user law that may read the whole state (a
    /// controller's `−c ω` term, drag): its kick is an implicit midpoint
    /// step, symmetric and of order 2, so the compositions keep their order
    /// (see [`crate::ForcedSplitting`]).
    pub fn with_velocity_load(
        self,
        law: impl Fn(f64, &ForcedState) -> (DVec3, DVec3) + Send + Sync + 'static,
    ) -> Self {
        self.with_law(Arc::new(law), true)
    }

    /// These inputs with `law`, marked as reading the velocity or not.
    fn with_law(self, law: Arc<LoadFn>, reads_velocity: bool) -> Self {
        Self {
            load: Some(Load {
                law,
                reads_velocity,
            }),
            ..self
        }
    }

    /// Whether nothing is applied (all zero, no law): the body is free.
    pub fn is_none(&self) -> bool {
        self.torque_world == DVec3::ZERO
            && self.torque_body == DVec3::ZERO
            && self.force_world == DVec3::ZERO
            && self.point_forces.is_empty()
            && self.angular_damping == 0.0
            && self.load.is_none()
    }

    /// Whether anything can turn the body: a torque, a point force, damping
    /// or a law.
    pub fn has_rotational_part(&self) -> bool {
        self.torque_world != DVec3::ZERO
            || self.torque_body != DVec3::ZERO
            || !self.point_forces.is_empty()
            || self.angular_damping != 0.0
            || self.load.is_some()
    }

    /// Checks every number: finite components, `c ≥ 0`.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidInput`] naming the input (and the point
    /// force's index) and the bad value.
    pub fn validate(&self) -> Result<(), DynamicsError> {
        finite("torque_world", None, self.torque_world)?;
        finite("torque_body", None, self.torque_body)?;
        finite("force_world", None, self.force_world)?;
        for (k, p) in self.point_forces.iter().enumerate() {
            finite("point_force.point_body", Some(k), p.point_body)?;
            finite("point_force.force_world", Some(k), p.force_world)?;
        }
        let c = self.angular_damping;
        if !c.is_finite() {
            return Err(invalid("angular_damping", None, c, "must be finite"));
        }
        if c < 0.0 {
            return Err(invalid(
                "angular_damping",
                None,
                c,
                "must not be negative (it would feed energy in)",
            ));
        }
        Ok(())
    }
}

fn invalid(
    input: &'static str,
    index: Option<usize>,
    value: f64,
    reason: &'static str,
) -> DynamicsError {
    DynamicsError::InvalidInput {
        input,
        index,
        value,
        reason,
    }
}

fn finite(input: &'static str, index: Option<usize>, v: DVec3) -> Result<(), DynamicsError> {
    match v.to_array().into_iter().find(|x| !x.is_finite()) {
        Some(x) => Err(invalid(input, index, x, "must be finite")),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_name_the_input() {
        let e = Inputs::default()
            .with_point_force(PointForce {
                point_body: DVec3::ZERO,
                force_world: DVec3::X,
            })
            .with_point_force(PointForce {
                point_body: DVec3::new(0.0, f64::NAN, 0.0),
                force_world: DVec3::X,
            })
            .validate()
            .unwrap_err();
        assert!(matches!(
            e,
            DynamicsError::InvalidInput {
                input: "point_force.point_body",
                index: Some(1),
                ..
            }
        ));
        assert_eq!(
            e.to_string(),
            "applied input `point_force.point_body` #1: NaN: must be finite"
        );
        let e = Inputs::default()
            .with_torque_body(DVec3::new(0.0, 0.0, f64::INFINITY))
            .validate()
            .unwrap_err();
        assert!(e.to_string().contains("torque_body"), "{e}");
        assert!(
            Inputs::default()
                .with_angular_damping(f64::NAN)
                .validate()
                .is_err()
        );
    }

    #[test]
    fn what_is_applied() {
        assert!(Inputs::default().is_none());
        let pushed = Inputs::default().with_force_world(DVec3::X);
        assert!(!pushed.is_none() && !pushed.has_rotational_part());
        let law = Inputs::default().with_load(|_, _| (DVec3::ZERO, DVec3::ZERO));
        assert!(law.has_rotational_part());
        assert!(!law.load.unwrap().reads_velocity());
    }
}
