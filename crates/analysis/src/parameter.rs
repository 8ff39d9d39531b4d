//! [`Parameter`]: the physical parameters a steady motion can be swept in
//! (`--sweep spin=0:60:200`, Python's `stability_map(..., spin=...)`).

use std::fmt;
use std::str::FromStr;

/// A parameter of a steady motion that a map can sweep.
///
/// ```
/// use kreisel_analysis::Parameter;
/// assert_eq!("com_offset".parse::<Parameter>(), Ok(Parameter::ComOffset));
/// assert_eq!(Parameter::Spin.to_string(), "spin");
/// assert!("omega".parse::<Parameter>().is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Parameter {
    /// The spin, rad/s: about the steady axis (free body), about the up
    /// vertical (sleeping top), `ω₃` about the symmetry axis (precession).
    Spin,
    /// The tilt `θ₀` of the symmetry axis from the up vertical, rad.
    Tilt,
    /// The distance from the pivot (or the contact shape's centre) to the
    /// centre of mass, m.
    ComOffset,
    /// The gravitational acceleration `|g|`, m/s².
    Gravity,
    /// The speed of the centre of mass, m/s (a rolling body).
    Speed,
}

impl Parameter {
    /// Every parameter, in the order of the docs.
    pub const ALL: [Self; 5] = [
        Self::Spin,
        Self::Tilt,
        Self::ComOffset,
        Self::Gravity,
        Self::Speed,
    ];

    /// Its key (`"spin"`, `"tilt"`, `"com_offset"`, `"gravity"`, `"speed"`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Spin => "spin",
            Self::Tilt => "tilt",
            Self::ComOffset => "com_offset",
            Self::Gravity => "gravity",
            Self::Speed => "speed",
        }
    }

    /// Its unit.
    pub fn unit(self) -> &'static str {
        match self {
            Self::Spin => "rad/s",
            Self::Tilt => "rad",
            Self::ComOffset => "m",
            Self::Gravity => "m/s²",
            Self::Speed => "m/s",
        }
    }
}

impl fmt::Display for Parameter {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Parameter {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|p| p.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(|p| p.name()).collect();
                format!("unknown parameter {s:?} (one of {})", names.join(", "))
            })
    }
}
