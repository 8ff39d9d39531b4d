//! The adapter's one error type.

use kreisel_dynamics::DynamicsError;
use rapier3d::prelude::RigidBodyHandle;

/// What can go wrong when kreisel carries a rapier body's rotation.
///
/// ```
/// use kreisel_rapier::{ExactRotation, RapierAdapterError};
/// use rapier3d::prelude::*;
/// let mut bodies = RigidBodySet::new();
/// let wall = bodies.insert(RigidBodyBuilder::fixed());
/// let mut exact = ExactRotation::new();
/// let e = exact.manage(&mut bodies, &ColliderSet::new(), wall).unwrap_err();
/// assert!(matches!(e, RapierAdapterError::NotDynamic { .. }));
/// assert!(e.to_string().contains("not a dynamic body"));
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RapierAdapterError {
    /// The handle names no body of the set.
    #[error("rigid body {handle:?} is not in the body set")]
    UnknownBody {
        /// The handle given.
        handle: RigidBodyHandle,
    },
    /// Only dynamic bodies move under forces; fixed and kinematic ones are
    /// moved by the user.
    #[error(
        "rigid body {handle:?} is not a dynamic body (it is {kind}); only dynamic bodies can be managed"
    )]
    NotDynamic {
        /// The handle given.
        handle: RigidBodyHandle,
        /// Its body type, as rapier names it.
        kind: &'static str,
    },
    /// A body with a locked rotation axis does not rotate freely.
    #[error("rigid body {handle:?} has a locked rotation axis; its rotation is not free")]
    RotationLocked {
        /// The handle given.
        handle: RigidBodyHandle,
    },
    /// The body's mass properties cannot describe a rotating rigid body:
    /// zero mass or inertia (a body without colliders or mass), or
    /// moments that violate the triangle inequality.
    #[error(
        "rigid body {handle:?} has mass {mass} kg and principal moments {moments:?} kg·m²: {reason}"
    )]
    InvalidMassProperties {
        /// The handle given.
        handle: RigidBodyHandle,
        /// Its mass, kg.
        mass: f32,
        /// Its principal moments of inertia, kg·m².
        moments: [f32; 3],
        /// Why they were refused.
        reason: String,
    },
    /// The body's mass properties changed after it was managed (a collider
    /// added or removed): release it and manage it again.
    #[error(
        "rigid body {handle:?}'s mass properties changed since it was managed; release it and manage it again"
    )]
    MassPropertiesChanged {
        /// The body.
        handle: RigidBodyHandle,
    },
    /// The exact flow refused a state (a non-finite velocity from the
    /// engine, or a body that diverged).
    #[error("rigid body {handle:?}: {source}")]
    Dynamics {
        /// The body.
        handle: RigidBodyHandle,
        /// What kreisel-dynamics reported.
        source: DynamicsError,
    },
    /// The time step is not positive and finite.
    #[error("time step {dt} s is not positive and finite")]
    InvalidStep {
        /// The step given, s.
        dt: f32,
    },
}

impl RapierAdapterError {
    /// The [`RapierAdapterError::Dynamics`] of body `handle`, for `map_err`.
    pub(crate) fn dynamics(handle: RigidBodyHandle) -> impl Fn(DynamicsError) -> Self {
        move |source| Self::Dynamics { handle, source }
    }
}
