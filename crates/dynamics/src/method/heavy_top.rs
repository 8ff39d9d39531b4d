//! [`HeavyTopMethod`]: the heavy-top integrators by name, order and
//! description.

use std::fmt;
use std::str::FromStr;

use super::unknown_method;
use crate::{DynamicsError, HeavyTopAuto, HeavyTopIntegrator, HeavyTopRk4, HeavyTopSplitting};

/// A method for the heavy top (a body on a fixed pivot under gravity).
///
/// The variants, in [`HeavyTopMethod::ALL`]'s order, are `auto`, the RK4
/// baseline, the kick–free–kick Strang splitting and its symmetric
/// compositions. A scene's method name picks the heavy-top method of the
/// same name for its bodies with a pivot
/// ([`crate::FreeBodyMethod::heavy_top`]).
///
/// ```text
/// name  ──FromStr──▶  HeavyTopMethod  ──integrator()──▶  Box<dyn HeavyTopIntegrator>
/// ```
///
/// ```
/// use kreisel_dynamics::{DynamicsError, HeavyTopIntegrator, HeavyTopMethod};
/// let m: HeavyTopMethod = "splitting4".parse()?;
/// assert_eq!((m, m.order()), (HeavyTopMethod::Splitting4, 4));
/// assert_eq!(m.integrator().name(), "splitting4");
/// // `auto` is a method of its own: splitting8, sub-stepped.
/// assert_eq!((HeavyTopMethod::Auto.integrator().name(), HeavyTopMethod::Auto.order()), ("auto", 8));
/// let e = "exact".parse::<HeavyTopMethod>().unwrap_err();
/// assert_eq!(e.to_string(), "unknown method `exact` (known: auto, rk4, strang, splitting4, splitting6, splitting8)");
/// # Ok::<(), DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum HeavyTopMethod {
    /// `auto`, the default: [`HeavyTopMethod::Splitting8`] with every step
    /// cut into the fewest sub-steps that keep it inside its stability
    /// limits ([`HeavyTopAuto`]), order 8.
    #[default]
    Auto,
    /// `rk4`: classical Runge–Kutta (Kutta 1901) on `(q, L)` with the
    /// gravity torque ([`HeavyTopRk4`]), the baseline; not geometric.
    Rk4,
    /// `strang`: half gravity kick, exact free-body flow, half kick
    /// ([`HeavyTopSplitting::STRANG`]; Strang 1968; Touma & Wisdom 1994;
    /// Dullweber, Leimkuhler & McLachlan 1997), order 2. The free flow is
    /// PDMV10 for three distinct moments.
    Strang,
    /// `splitting4`: Suzuki's 5-stage symmetric composition of
    /// [`HeavyTopMethod::Strang`] ([`HeavyTopSplitting::ORDER_4`]; Phys.
    /// Lett. A 146:319 (1990)), order 4.
    Splitting4,
    /// `splitting6`: Kahan & Li's 9-stage symmetric composition of
    /// [`HeavyTopMethod::Strang`] ([`HeavyTopSplitting::ORDER_6`]; Math.
    /// Comp. 66:1089 (1997)), order 6.
    Splitting6,
    /// `splitting8`: Kahan & Li's 17-stage symmetric composition of
    /// [`HeavyTopMethod::Strang`] ([`HeavyTopSplitting::ORDER_8`]; Math.
    /// Comp. 66:1089 (1997)), order 8.
    Splitting8,
}

impl HeavyTopMethod {
    /// Every method, `auto` first: the order of `--list-methods` and of
    /// [`crate::HEAVY_TOP_METHODS`].
    pub const ALL: [Self; 6] = [
        Self::Auto,
        Self::Rk4,
        Self::Strang,
        Self::Splitting4,
        Self::Splitting6,
        Self::Splitting8,
    ];

    /// The name `FromStr` reads and [`fmt::Display`] writes; the
    /// integrator reports the same name.
    ///
    /// ```
    /// use kreisel_dynamics::HeavyTopMethod;
    /// assert_eq!(HeavyTopMethod::Strang.name(), "strang");
    /// ```
    pub const fn name(self) -> &'static str {
        match self {
            Self::Auto => "auto",
            Self::Rk4 => "rk4",
            Self::Strang => "strang",
            Self::Splitting4 => "splitting4",
            Self::Splitting6 => "splitting6",
            Self::Splitting8 => "splitting8",
        }
    }

    /// The order `p` of the method (global error `O(hᵖ)`); every
    /// heavy-top method has one (there is no exact heavy-top flow here).
    ///
    /// ```
    /// use kreisel_dynamics::HeavyTopMethod;
    /// assert_eq!(HeavyTopMethod::Strang.order(), 2);
    /// ```
    pub const fn order(self) -> u32 {
        match self {
            Self::Strang => 2,
            Self::Rk4 | Self::Splitting4 => 4,
            Self::Splitting6 => 6,
            Self::Auto | Self::Splitting8 => 8,
        }
    }

    /// One line about the method, as `kreisel simulate --list-methods`
    /// shows it.
    ///
    /// ```
    /// use kreisel_dynamics::HeavyTopMethod;
    /// assert!(HeavyTopMethod::Splitting6.description().starts_with("Kahan and Li's"));
    /// ```
    pub const fn description(self) -> &'static str {
        match self {
            Self::Auto => {
                "the default; splitting8, sub-stepped where dt exceeds its stability limit"
            }
            Self::Rk4 => "classical Runge-Kutta on L and q with the gravity torque, the baseline",
            Self::Strang => {
                "half gravity kick, exact free-body flow, half kick \
                 (PDMV10 for 3 distinct moments)"
            }
            Self::Splitting4 => "Suzuki's 5-stage symmetric composition of strang",
            Self::Splitting6 => "Kahan and Li's 9-stage symmetric composition of strang",
            Self::Splitting8 => "Kahan and Li's 17-stage symmetric composition of strang",
        }
    }

    /// The integrator that runs the method.
    ///
    /// ```
    /// use kreisel_dynamics::HeavyTopMethod;
    /// let m = HeavyTopMethod::Rk4.integrator();
    /// assert_eq!((m.name(), m.order()), ("rk4", 4));
    /// ```
    pub fn integrator(self) -> Box<dyn HeavyTopIntegrator> {
        match self {
            Self::Auto => Box::new(HeavyTopAuto),
            Self::Rk4 => Box::new(HeavyTopRk4),
            Self::Strang => Box::new(HeavyTopSplitting::STRANG),
            Self::Splitting4 => Box::new(HeavyTopSplitting::ORDER_4),
            Self::Splitting6 => Box::new(HeavyTopSplitting::ORDER_6),
            Self::Splitting8 => Box::new(HeavyTopSplitting::ORDER_8),
        }
    }
}

impl FromStr for HeavyTopMethod {
    type Err = DynamicsError;

    /// The method called `name` (exactly as [`HeavyTopMethod::name`]
    /// writes it).
    ///
    /// # Errors
    /// [`DynamicsError::UnknownMethod`] listing every name of
    /// [`HeavyTopMethod::ALL`].
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|m| m.name() == name)
            .ok_or_else(|| unknown_method(name, &Self::ALL.map(Self::name)))
    }
}

impl fmt::Display for HeavyTopMethod {
    /// The name; width and alignment apply (`{:<12}`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

#[cfg(test)]
mod tests {
    use std::collections::HashSet;

    use super::*;

    /// The names the string registry had before the enum: they stay.
    const OLD_HEAVY_TOP_METHODS: [&str; 6] = [
        "auto",
        "rk4",
        "strang",
        "splitting4",
        "splitting6",
        "splitting8",
    ];

    #[test]
    fn every_name_parses_back_to_its_method() {
        for m in HeavyTopMethod::ALL {
            assert_eq!(m.name().parse::<HeavyTopMethod>().unwrap(), m);
            assert_eq!(m.to_string(), m.name());
        }
        assert_eq!(format!("[{:>7}]", HeavyTopMethod::Rk4), "[    rk4]");
        assert_eq!(HeavyTopMethod::default(), HeavyTopMethod::Auto);
    }

    #[test]
    fn all_has_no_duplicates_and_keeps_the_old_names() {
        let names: Vec<&str> = HeavyTopMethod::ALL.map(HeavyTopMethod::name).to_vec();
        assert_eq!(names, OLD_HEAVY_TOP_METHODS);
        assert_eq!(names.iter().collect::<HashSet<_>>().len(), names.len());
        let variants: HashSet<HeavyTopMethod> = HeavyTopMethod::ALL.into_iter().collect();
        assert_eq!(variants.len(), HeavyTopMethod::ALL.len());
        assert_eq!(crate::HEAVY_TOP_METHODS, OLD_HEAVY_TOP_METHODS);
    }

    #[test]
    fn unknown_names_are_refused_with_the_list() {
        for name in [
            "exact",
            "splitting",
            "dmv",
            "pdmv10",
            "euler",
            "",
            "AUTO",
            "strang ",
        ] {
            match name.parse::<HeavyTopMethod>() {
                Err(DynamicsError::UnknownMethod { name: given, known }) => {
                    assert_eq!(given, name);
                    assert_eq!(known, OLD_HEAVY_TOP_METHODS.join(", "));
                }
                other => panic!("{name:?}: {other:?}"),
            }
            assert!(crate::heavy_top_method(name).is_err(), "{name:?}");
        }
    }

    #[test]
    fn each_integrator_reports_the_methods_name_and_order() {
        for m in HeavyTopMethod::ALL {
            let integrator = m.integrator();
            assert_eq!(
                (integrator.name(), integrator.order()),
                (m.name(), m.order())
            );
            let by_name = crate::heavy_top_method(m.name()).unwrap();
            assert_eq!((by_name.name(), by_name.order()), (m.name(), m.order()));
        }
    }

    #[test]
    fn descriptions_are_one_line() {
        for m in HeavyTopMethod::ALL {
            let text = m.description();
            assert!(!text.is_empty() && !text.contains('\n'), "{m}: {text:?}");
        }
    }
}
