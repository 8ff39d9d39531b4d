//! [`ZeroMode`]: what a zero eigenvalue of a linearisation stands for — a
//! conserved quantity's level or a symmetry direction — so that none is
//! dropped unexplained.

use std::fmt;

/// What kind of thing accounts for a zero eigenvalue.
///
/// ```
/// use kreisel_analysis::ZeroModeKind;
/// assert_eq!(ZeroModeKind::Casimir.to_string(), "Casimir");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ZeroModeKind {
    /// A quantity conserved by any motion of the reduced equations,
    /// whatever the forces (`|L|²` of a free body, `|γ|²`).
    Casimir,
    /// The energy: a neighbouring steady motion at another energy level.
    Energy,
    /// A momentum conserved because of a symmetry (`L·ẑ` about the
    /// vertical, the spin `ω₃` of a symmetric body, Jellett's integral).
    Momentum,
    /// A direction along which the steady motion repeats itself (a
    /// symmetry of the reduced equations, or a family of steady motions
    /// at the same conserved values).
    Symmetry,
}

impl fmt::Display for ZeroModeKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Casimir => "Casimir",
            Self::Energy => "energy level",
            Self::Momentum => "momentum",
            Self::Symmetry => "symmetry direction",
        })
    }
}

/// One zero eigenvalue and what it stands for.
///
/// ```text
/// conserved C:  ∇C(x*)ᵀ A = 0      (a left null vector of the Jacobian A)
/// symmetry ξ:   A ξ = 0            (a right null vector)
/// ```
///
/// ```
/// use kreisel_analysis::{ZeroMode, ZeroModeKind};
/// let z = ZeroMode::new(ZeroModeKind::Casimir, "|L|²");
/// assert_eq!(z.to_string(), "Casimir |L|²");
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct ZeroMode {
    /// The kind.
    pub kind: ZeroModeKind,
    /// The quantity or direction, in the notes' symbols (`"|L|²"`).
    pub name: String,
}

impl ZeroMode {
    /// A zero mode of `kind` named `name`.
    pub fn new(kind: ZeroModeKind, name: impl Into<String>) -> Self {
        Self {
            kind,
            name: name.into(),
        }
    }
}

impl fmt::Display for ZeroMode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.kind, self.name)
    }
}
