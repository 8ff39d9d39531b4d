//! [`Verdict`]: stable, unstable or neutral, read off the eigenvalues
//! that remain once every zero eigenvalue is accounted for.

use std::fmt;

/// The linear stability of a steady motion.
///
/// ```text
/// unstable:  some Re λ > τ          (τ = 1e-7 · max |λ|)
/// stable:    every Re λ ≤ τ, none zero, no repeated λ short of modes
/// neutral:   an unexplained zero, or a repeated λ on the imaginary axis
///            with fewer modes than its multiplicity (secular growth)
/// ```
///
/// ```
/// use kreisel_analysis::Verdict;
/// let v = Verdict::Unstable { growth_rate: 2.0 };
/// assert_eq!(v.name(), "unstable");
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict {
    /// Every remaining eigenvalue has `Re λ ≤ 0` (to the tolerance): small
    /// perturbations stay small. `asymptotic`: every one has `Re λ < 0`
    /// (they die out).
    Stable {
        /// Whether every perturbation decays.
        asymptotic: bool,
    },
    /// An eigenvalue has a positive real part.
    Unstable {
        /// The largest `Re λ`, 1/s.
        growth_rate: f64,
    },
    /// The linearisation does not decide.
    Neutral {
        /// Why, in words.
        reason: String,
    },
}

impl Verdict {
    /// `"stable"`, `"unstable"` or `"neutral"`.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Stable { .. } => "stable",
            Self::Unstable { .. } => "unstable",
            Self::Neutral { .. } => "neutral",
        }
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Stable { asymptotic: true } => f.write_str("stable (perturbations decay)"),
            Self::Stable { asymptotic: false } => f.write_str("stable"),
            Self::Unstable { growth_rate } => {
                write!(f, "unstable (growth rate {growth_rate:.9e} 1/s)")
            }
            Self::Neutral { reason } => write!(f, "neutral ({reason})"),
        }
    }
}
