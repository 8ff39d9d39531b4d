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
    /// A heavy-top parameter or initial condition outside its domain
    /// (a moment of inertia that is not positive, a non-finite number, …).
    #[error("heavy top: {parameter} = {value}: {reason}")]
    InvalidTop {
        /// The parameter's name as the user wrote it (e.g. `"i1"`, `"theta0"`).
        parameter: &'static str,
        /// The value given.
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
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
