//! What can be wrong with one line of numbers read as a rotation: the
//! problem, without where it happened (the reader adds the place: a file
//! and line for the CLI, a row index for Python).

use kreisel_kinematics::KinematicsError;

use crate::representation::Representation;

/// What is wrong with one line of input.
#[derive(Debug, thiserror::Error)]
pub enum LineProblem {
    /// The line is not valid UTF-8 text.
    #[error("line is not valid UTF-8 text")]
    NotUtf8,
    /// The line exceeds the length limit (protects memory from endless lines).
    #[error("line is longer than {limit} bytes")]
    TooLong {
        /// The limit in bytes.
        limit: usize,
    },
    /// Two commas with nothing between them, or a comma at the start or end.
    #[error(
        "empty number at position {position} (two commas in a row, or a leading or trailing comma)"
    )]
    EmptyNumber {
        /// 1-based position of the empty field among the numbers.
        position: usize,
    },
    /// A token that `f64::from_str` does not accept.
    #[error("cannot parse `{token}` as a number")]
    BadNumber {
        /// The token as written.
        token: String,
    },
    /// A number that parses but is NaN or infinite (also `1e999`, which overflows).
    #[error("number `{token}` is not finite")]
    NonFinite {
        /// The token as written.
        token: String,
    },
    /// The line holds the wrong count of numbers for the representation.
    #[error("expected {expected} numbers for {representation}, found {found}")]
    WrongCount {
        /// The input representation.
        representation: Representation,
        /// How many numbers it needs.
        expected: usize,
        /// How many the line holds.
        found: usize,
    },
    /// A rotation vector with finite components whose length overflows `f64`.
    #[error("rotation vector length is not a finite number (it overflows)")]
    RotationVectorLength,
    /// The numbers do not describe a rotation (zero quaternion, non-orthonormal
    /// or reflection matrix, zero axis with a non-zero angle).
    #[error("{source}")]
    NotARotation {
        /// The library's description of the problem.
        #[from]
        source: KinematicsError,
    },
    // `kreisel convert --skip-columns N --header` (issue 16).
    /// A line with fewer fields than `--skip-columns` passes through.
    #[error("line has {found} columns, fewer than --skip-columns {skip}")]
    TooFewColumns {
        /// `--skip-columns`.
        skip: usize,
        /// The fields the line holds.
        found: usize,
    },
    /// The `--header` line names the wrong number of columns.
    #[error(
        "header has {found} columns, expected {skip} passed through (--skip-columns) + {expected} for {representation}"
    )]
    HeaderCount {
        /// The names the header holds.
        found: usize,
        /// `--skip-columns`.
        skip: usize,
        /// The input representation.
        representation: Representation,
        /// How many numbers it needs.
        expected: usize,
    },
}
