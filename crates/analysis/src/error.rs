//! [`AnalysisError`]: what can go wrong finding a steady motion or
//! deciding its stability, with the numbers a person needs.

use kreisel_dynamics::DynamicsError;

/// The error type of kreisel-analysis.
///
/// ```
/// use kreisel_analysis::AnalysisError;
/// let e = AnalysisError::NotSteady { residual: 0.3, limit: 1e-10 };
/// assert!(e.to_string().contains("residual 3.000e-1"));
/// ```
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AnalysisError {
    /// The state is not a steady motion.
    #[error(
        "not a steady motion: relative residual {residual:.3e} (at most {limit:.0e} is steady)"
    )]
    NotSteady {
        /// `|f(x)| / (‖A‖ |x|)`.
        residual: f64,
        /// [`crate::STEADY_RESIDUAL`].
        limit: f64,
    },
    /// The search from a state found no steady motion near it: Newton did
    /// not converge, or converged farther than [`crate::NEARBY`] of the
    /// state's size.
    #[error(
        "no steady motion near this state: relative residual {start:.3e} at the start; the closest Newton came in {iterations} steps has residual {best:.3e}, {relative_distance:.3} of a component's size away (near: residual at most 1e-10, within {limit})"
    )]
    NoSteadyMotionNearby {
        /// The start's relative residual.
        start: f64,
        /// The smallest one reached.
        best: f64,
        /// Newton steps taken.
        iterations: usize,
        /// The largest change of a component of the best state reached, in
        /// units of its size.
        relative_distance: f64,
        /// [`crate::NEARBY`].
        limit: f64,
    },
    /// A state vector of the wrong length.
    #[error("a state of {got} numbers where {expected} are needed")]
    StateLength {
        /// The family's dimension.
        expected: usize,
        /// What was given.
        got: usize,
    },
    /// A state component is not finite.
    #[error("{name} is {value}, not a finite number")]
    NotFinite {
        /// The component.
        name: String,
        /// Its value.
        value: f64,
    },
    /// A parameter of a family is out of its range.
    #[error("{name} must be {must}, got {value}")]
    Parameter {
        /// The parameter.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What it must be.
        must: &'static str,
    },
    /// The family has no steady motion with these parameters.
    #[error("no {kind}: {why}")]
    NoSuchMotion {
        /// The steady motion asked for.
        kind: &'static str,
        /// Why not, with the numbers.
        why: String,
    },
    /// A sweep that cannot be mapped.
    #[error("sweep {name}: {why}")]
    Sweep {
        /// The parameter's name.
        name: String,
        /// What is wrong, with the numbers.
        why: String,
    },
    /// The QR iteration for the eigenvalues did not converge.
    #[error("the eigenvalues of the reduced {dim}×{dim} Jacobian did not converge")]
    EigenvaluesDidNotConverge {
        /// The reduced dimension.
        dim: usize,
    },
    /// A body that the engine refuses.
    #[error(transparent)]
    Body(#[from] DynamicsError),
}
