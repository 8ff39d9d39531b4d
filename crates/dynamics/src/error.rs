//! The one error type of `kreisel-dynamics`.

/// Everything that can go wrong when setting up or advancing a rigid body.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DynamicsError {
    /// Principal moments that no physical body has.
    #[error("principal moments {moments:?} are not physical: {reason}")]
    UnphysicalInertia {
        /// The moments given, kg·m².
        moments: [f64; 3],
        /// Why (not positive and finite, or the triangle inequality broken).
        reason: &'static str,
    },
    /// The inertia tensor could not be used (see the inner message).
    #[error("inertia tensor: {reason}")]
    InertiaTensor {
        /// The inertia crate's description.
        reason: String,
    },
    /// A state with a non-finite or zero-length attitude quaternion, or a
    /// non-finite angular momentum.
    #[error("invalid state: {reason}")]
    InvalidState {
        /// What is wrong.
        reason: &'static str,
    },
    /// A step size that is not positive and finite.
    #[error("step size must be positive and finite, got {h}")]
    InvalidStep {
        /// The step size given, s.
        h: f64,
    },
    /// A method name that the registry does not know.
    #[error("unknown method `{name}` (known: {known})")]
    UnknownMethod {
        /// The name given.
        name: String,
        /// The known names, comma-separated.
        known: String,
    },
}
