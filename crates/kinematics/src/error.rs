//! The one error type of `kreisel-kinematics`.

use crate::EulerSequence;

/// Everything that can go wrong when building or converting a rotation.
///
/// Each variant carries the values a caller needs to explain the problem to a
/// person (the offending number, the limit it broke).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum KinematicsError {
    /// A quaternion of zero norm cannot be normalised into a rotation.
    #[error("quaternion has zero norm")]
    ZeroQuaternion,
    /// An input contained NaN or an infinity.
    #[error("{what} contains a non-finite number")]
    NonFinite {
        /// What kind of input it was (e.g. `"quaternion"`).
        what: &'static str,
    },
    /// A matrix is too far from orthonormal to be a rotation.
    #[error(
        "matrix is not orthonormal: max |MᵀM − I| = {deviation:e} exceeds the tolerance {tolerance:e}"
    )]
    NotOrthonormal {
        /// The largest element of `|MᵀM − I|`.
        deviation: f64,
        /// The tolerance it was checked against.
        tolerance: f64,
    },
    /// An orthonormal matrix with determinant −1 is a reflection, not a rotation.
    #[error("matrix is a reflection, not a rotation (determinant {determinant})")]
    Reflection {
        /// The determinant of the matrix.
        determinant: f64,
    },
    /// An axis–angle pair with a zero axis and a non-zero angle has no meaning.
    #[error("rotation axis is zero but the angle is {angle}")]
    ZeroAxis {
        /// The angle that came with the zero axis.
        angle: f64,
    },
    /// Text that does not name one of the 24 Euler conventions.
    #[error("invalid Euler sequence `{text}`: {reason}")]
    InvalidSequence {
        /// The text as given.
        text: String,
        /// Why it was rejected.
        reason: &'static str,
    },
    /// The Euler-rate matrix is (nearly) singular: the angles are at or next
    /// to gimbal lock, where Euler-angle rates are undefined.
    #[error(
        "Euler rates are singular for {sequence} at middle angle {middle_angle}: |det| = {determinant:e} is below {tolerance:e} (gimbal lock)"
    )]
    RateSingularity {
        /// The Euler convention.
        sequence: EulerSequence,
        /// The middle angle, radians.
        middle_angle: f64,
        /// The determinant of the rate matrix (`∓sin θ` or `±cos θ`).
        determinant: f64,
        /// The threshold below which `|det|` is refused.
        tolerance: f64,
    },
}
