//! [`SteadyKind`]: the steady motion a scene names for a body (`steady =
//! "sleeping"` in its `[[body]]` table), or the one nearest its state.

use std::fmt;
use std::str::FromStr;

/// Which steady motion of a body to analyse.
///
/// ```
/// use kreisel_analysis::SteadyKind;
/// assert_eq!("slow_precession".parse::<SteadyKind>(), Ok(SteadyKind::SlowPrecession));
/// assert_eq!(SteadyKind::Nearest.to_string(), "nearest");
/// assert!("wobbling".parse::<SteadyKind>().is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SteadyKind {
    /// The steady motion nearest the body's state, with its Casimirs and
    /// momenta ([`crate::SteadyProblem::near`]).
    #[default]
    Nearest,
    /// A top on a pivot spinning upright at its spin about the axis
    /// through the centre of mass.
    Sleeping,
    /// A top on a pivot spinning with its centre of mass straight below.
    Hanging,
    /// A symmetric top on a pivot in slow steady precession at its tilt
    /// and spin.
    SlowPrecession,
    /// The same, fast.
    FastPrecession,
}

impl SteadyKind {
    /// Every kind, in the order of the docs.
    pub const ALL: [Self; 5] = [
        Self::Nearest,
        Self::Sleeping,
        Self::Hanging,
        Self::SlowPrecession,
        Self::FastPrecession,
    ];

    /// Its name in a scene.
    pub fn name(self) -> &'static str {
        match self {
            Self::Nearest => "nearest",
            Self::Sleeping => "sleeping",
            Self::Hanging => "hanging",
            Self::SlowPrecession => "slow_precession",
            Self::FastPrecession => "fast_precession",
        }
    }
}

impl fmt::Display for SteadyKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for SteadyKind {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(|k| k.name()).collect();
                format!("unknown steady motion {s:?} (one of {})", names.join(", "))
            })
    }
}
