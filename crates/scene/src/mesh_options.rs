//! The choices of a mass-properties request that are not the library's
//! own types: the length unit of the mesh, how vertices are welded, and
//! the defaults of density and wall thickness.

use kreisel_inertia::Weld;

/// What `--weld` chooses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WeldChoice {
    /// Without `--weld`: within `1e-6 ×` each body's bounding-box diagonal.
    Default,
    /// `--weld off`: only bit-identical vertices.
    Off,
    /// `--weld TOL`: within TOL metres (after scaling).
    Metres(f64),
}

impl WeldChoice {
    /// The library's weld for a mesh whose coordinates are multiplied by
    /// `scale` to get metres (welding happens in the file's units).
    pub fn weld(self, scale: f64) -> Weld {
        match self {
            WeldChoice::Default => Weld::default(),
            WeldChoice::Off => Weld::Exact,
            WeldChoice::Metres(t) => Weld::Absolute(t / scale),
        }
    }
}

/// Wall thickness of `--shell` without `--thickness`, m.
pub const DEFAULT_THICKNESS: f64 = 0.001;

/// Density without `--density` or `--mass`: water, kg/m³.
pub const DEFAULT_DENSITY: f64 = 1000.0;

/// The length unit of the mesh coordinates (`--units`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Units {
    /// Millimetres.
    Mm,
    /// Centimetres.
    Cm,
    /// Metres.
    M,
    /// Inches.
    In,
}

impl Units {
    /// Every unit, in the order the CLI lists them.
    pub const ALL: [Units; 4] = [Units::Mm, Units::Cm, Units::M, Units::In];

    /// Metres per unit.
    pub const fn scale(self) -> f64 {
        match self {
            Units::Mm => 0.001,
            Units::Cm => 0.01,
            Units::M => 1.0,
            Units::In => 0.0254,
        }
    }

    /// The unit's name in words, plural (`millimetres`).
    pub const fn name(self) -> &'static str {
        match self {
            Units::Mm => "millimetres",
            Units::Cm => "centimetres",
            Units::M => "metres",
            Units::In => "inches",
        }
    }

    /// The unit's symbol, as given to `--units`.
    pub const fn symbol(self) -> &'static str {
        match self {
            Units::Mm => "mm",
            Units::Cm => "cm",
            Units::M => "m",
            Units::In => "in",
        }
    }
}

impl core::str::FromStr for Units {
    type Err = String;

    /// Parses a unit's symbol ([`Units::symbol`]): `mm`, `cm`, `m` or `in`.
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        Units::ALL
            .into_iter()
            .find(|u| u.symbol() == text)
            .ok_or_else(|| format!("unknown unit `{text}` (mm, cm, m or in)"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_parse_their_symbols() {
        for u in Units::ALL {
            assert_eq!(u.symbol().parse::<Units>(), Ok(u));
        }
        assert!("ft".parse::<Units>().unwrap_err().contains("ft"));
        assert_eq!(Units::Mm.scale(), 0.001);
        assert_eq!(Units::In.scale(), 0.0254);
    }

    #[test]
    fn welds_are_in_file_units() {
        assert_eq!(WeldChoice::Metres(0.002).weld(0.001), Weld::Absolute(2.0));
        assert_eq!(WeldChoice::Off.weld(0.001), Weld::Exact);
    }
}
