//! [`Eigenvalue`] and [`Mode`]: one eigenvalue of a linearisation in
//! physical units, and the small motion that goes with it.

use std::fmt;

/// A complex eigenvalue `λ = σ + iω` of a linearisation, 1/s: a small
/// perturbation along its mode goes like `e^{σt} cos(ωt + φ)`.
///
/// ```text
/// growth rate σ = Re λ (1/s, negative: decay),   frequency ω = |Im λ| (rad/s)
/// ```
///
/// ```
/// use kreisel_analysis::Eigenvalue;
/// let l = Eigenvalue::new(-0.5, 2.0);
/// assert_eq!((l.growth_rate(), l.frequency()), (-0.5, 2.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Eigenvalue {
    /// `Re λ`, 1/s.
    pub re: f64,
    /// `Im λ`, rad/s.
    pub im: f64,
}

impl Eigenvalue {
    /// `re + i im`.
    pub const fn new(re: f64, im: f64) -> Self {
        Self { re, im }
    }

    /// The growth rate `Re λ`, 1/s (negative: the mode decays).
    pub fn growth_rate(self) -> f64 {
        self.re
    }

    /// The angular frequency `|Im λ|`, rad/s.
    pub fn frequency(self) -> f64 {
        self.im.abs()
    }

    /// `|λ|`.
    pub fn norm(self) -> f64 {
        self.re.hypot(self.im)
    }
}

impl fmt::Display for Eigenvalue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let sign = if self.im < 0.0 { '−' } else { '+' };
        write!(f, "{:.9e} {sign} {:.9e}i", self.re, self.im.abs())
    }
}

/// The frame a frequency is seen in.
///
/// ```
/// use kreisel_analysis::Frame;
/// assert_eq!(Frame::Space.to_string(), "space");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Frame {
    /// Axes fixed in the body (the reduced coordinates' frame).
    Body,
    /// Axes fixed in space (the ground, the lab).
    Space,
}

impl fmt::Display for Frame {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Body => "body",
            Self::Space => "space",
        })
    }
}

/// One mode of the linearisation: its eigenvalue and shape.
///
/// ```text
/// δx(t) = Re(v e^{λt}),   v ∈ ℂⁿ in the reduced state's coordinates
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Mode {
    /// The eigenvalue, in the frame of the reduced coordinates
    /// ([`crate::Linearisation::frame`]).
    pub eigenvalue: Eigenvalue,
    /// The shape `v` (unit length, largest component real), one complex
    /// number per state component (names:
    /// [`crate::Linearisation::state_names`]).
    pub shape: Vec<Eigenvalue>,
    /// The frequency as seen in space, rad/s, where the reduced frame
    /// turns steadily and the mode is circular (a sleeping top's
    /// precession); `None` otherwise.
    pub space_frequency: Option<f64>,
}
