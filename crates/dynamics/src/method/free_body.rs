//! [`FreeBodyMethod`]: the torque-free integrators by name, order and
//! description.

use std::fmt;
use std::str::FromStr;

use super::{HeavyTopMethod, unknown_method};
use crate::composition::{Composition, KAHAN_LI_6, KAHAN_LI_8, SUZUKI_4};
use crate::{
    AxisStrang, DynamicsError, ExactFlow, FreeBodyIntegrator, MoserVeselov,
    PreprocessedMoserVeselov, Rk4, SymmetricTopSplitting,
};

/// A method for the torque-free rigid body: what `--method` names.
///
/// The variants, in [`FreeBodyMethod::ALL`]'s order, are `auto`, the exact
/// solution, the RK4 baseline, the splittings into exact rotations and
/// their symmetric compositions, and the discrete Moser–Veselov family.
///
/// ```text
/// name  ──FromStr──▶  FreeBodyMethod  ──integrator()──▶  Box<dyn FreeBodyIntegrator>
/// ```
///
/// ```
/// use kreisel_dynamics::{DynamicsError, FreeBodyIntegrator, FreeBodyMethod};
/// let m: FreeBodyMethod = "splitting6".parse()?;
/// assert_eq!(m, FreeBodyMethod::Splitting6);
/// assert_eq!((m.name(), m.order()), ("splitting6", Some(6)));
/// assert_eq!(m.integrator().order(), 6);
/// // `auto` runs the exact solution, which has no truncation error.
/// assert_eq!(FreeBodyMethod::Auto.resolve(), FreeBodyMethod::Exact);
/// assert_eq!(FreeBodyMethod::Auto.order(), None);
/// assert_eq!(FreeBodyMethod::Auto.integrator().name(), "exact");
/// let e = "euler".parse::<FreeBodyMethod>().unwrap_err();
/// assert!(matches!(e, DynamicsError::UnknownMethod { .. }));
/// assert!(e.to_string().starts_with("unknown method `euler` (known: auto, exact, rk4,"));
/// # Ok::<(), DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum FreeBodyMethod {
    /// `auto`, the default: the recommended method, today
    /// [`FreeBodyMethod::Exact`] ([`FreeBodyMethod::resolve`]). It skips
    /// what a body does not need, has no truncation error at any step
    /// (`tests/free_body_exact.rs`: ≤ 2e-14 rad against every reference
    /// sample), and a step costs less than one Strang splitting step
    /// (`BENCHMARKS.md`).
    #[default]
    Auto,
    /// `exact`: the exact solution ([`ExactFlow`], [`crate::ExactSolution`]) —
    /// a uniform rotation for a sphere or a spin about a principal axis, two
    /// commuting rotations for a symmetric body, Jacobi elliptic functions
    /// for an asymmetric one (Landau & Lifshitz, *Mechanics*, §37;
    /// Celledoni, Fassò, Säfström & Zanna, SIAM J. Sci. Comput. 30:2084
    /// (2008); van Zon & Schofield, J. Comput. Phys. 225:145 (2007)).
    Exact,
    /// `rk4`: classical Runge–Kutta (Kutta 1901) on `(q, L)` ([`Rk4`]), the
    /// baseline; not geometric.
    Rk4,
    /// `strang`: the five-rotation Strang splitting into rotations about
    /// the principal axes ([`AxisStrang`]; McLachlan 1993; Touma & Wisdom
    /// 1994), order 2.
    Strang,
    /// `splitting`: an exact symmetric top plus one exact axis rotation
    /// ([`SymmetricTopSplitting`]; Dullweber, Leimkuhler & McLachlan,
    /// J. Chem. Phys. 107:5840 (1997); ordering after Fassò, J. Comput.
    /// Phys. 189:527 (2003)), order 2.
    Splitting,
    /// `splitting4`: Suzuki's 5-stage symmetric composition of
    /// [`FreeBodyMethod::Splitting`] ([`SUZUKI_4`]; Phys. Lett. A 146:319
    /// (1990)), order 4.
    Splitting4,
    /// `splitting6`: Kahan & Li's 9-stage symmetric composition of
    /// [`FreeBodyMethod::Splitting`] ([`KAHAN_LI_6`]; Math. Comp. 66:1089
    /// (1997)), order 6.
    Splitting6,
    /// `splitting8`: Kahan & Li's 17-stage symmetric composition of
    /// [`FreeBodyMethod::Splitting`] ([`KAHAN_LI_8`]; Math. Comp. 66:1089
    /// (1997)), order 8.
    Splitting8,
    /// `dmv`: the discrete Moser–Veselov algorithm ([`MoserVeselov`];
    /// Moser & Veselov, Commun. Math. Phys. 139:217 (1991), in the
    /// quaternion form of Hairer & Vilmart, J. Phys. A 39:13225 (2006)),
    /// implicit, order 2.
    Dmv,
    /// `pdmv4`: Hairer & Vilmart's preprocessed discrete Moser–Veselov
    /// ([`PreprocessedMoserVeselov::ORDER_4`]; J. Phys. A 39:13225 (2006)),
    /// order 4.
    Pdmv4,
    /// `pdmv6`: preprocessed discrete Moser–Veselov
    /// ([`PreprocessedMoserVeselov::ORDER_6`]), order 6.
    Pdmv6,
    /// `pdmv8`: preprocessed discrete Moser–Veselov
    /// ([`PreprocessedMoserVeselov::ORDER_8`]), order 8.
    Pdmv8,
    /// `pdmv10`: preprocessed discrete Moser–Veselov
    /// ([`PreprocessedMoserVeselov::ORDER_10`]), order 10.
    Pdmv10,
}

impl FreeBodyMethod {
    /// Every method, `auto` first: the order of `--list-methods` and of
    /// [`crate::METHODS`].
    pub const ALL: [Self; 13] = [
        Self::Auto,
        Self::Exact,
        Self::Rk4,
        Self::Strang,
        Self::Splitting,
        Self::Splitting4,
        Self::Splitting6,
        Self::Splitting8,
        Self::Dmv,
        Self::Pdmv4,
        Self::Pdmv6,
        Self::Pdmv8,
        Self::Pdmv10,
    ];

    /// The name `FromStr` reads and [`fmt::Display`] writes (e.g. `"rk4"`);
    /// the integrator of every method but `auto` reports the same name.
    ///
    /// ```
    /// use kreisel_dynamics::FreeBodyMethod;
    /// assert_eq!(FreeBodyMethod::Pdmv10.name(), "pdmv10");
    /// assert_eq!(FreeBodyMethod::Auto.name(), "auto");
    /// ```
    pub const fn name(self) -> &'static str {
        match self {
            Self::Auto => "auto",
            Self::Exact => "exact",
            Self::Rk4 => "rk4",
            Self::Strang => "strang",
            Self::Splitting => "splitting",
            Self::Splitting4 => "splitting4",
            Self::Splitting6 => "splitting6",
            Self::Splitting8 => "splitting8",
            Self::Dmv => "dmv",
            Self::Pdmv4 => "pdmv4",
            Self::Pdmv6 => "pdmv6",
            Self::Pdmv8 => "pdmv8",
            Self::Pdmv10 => "pdmv10",
        }
    }

    /// The order `p` of the method (global error `O(hᵖ)`), or `None` for
    /// the exact solution (and `auto`, which runs it): no truncation error
    /// at any step. [`FreeBodyIntegrator::order`] says the same with
    /// `u32::MAX` for `None`.
    ///
    /// ```
    /// use kreisel_dynamics::FreeBodyMethod;
    /// assert_eq!(FreeBodyMethod::Rk4.order(), Some(4));
    /// assert_eq!(FreeBodyMethod::Exact.order(), None);
    /// ```
    pub const fn order(self) -> Option<u32> {
        match self.resolve() {
            Self::Auto | Self::Exact => None,
            Self::Strang | Self::Splitting | Self::Dmv => Some(2),
            Self::Rk4 | Self::Splitting4 | Self::Pdmv4 => Some(4),
            Self::Splitting6 | Self::Pdmv6 => Some(6),
            Self::Splitting8 | Self::Pdmv8 => Some(8),
            Self::Pdmv10 => Some(10),
        }
    }

    /// One line about the method, as `kreisel simulate --list-methods`
    /// shows it.
    ///
    /// ```
    /// use kreisel_dynamics::FreeBodyMethod;
    /// assert!(FreeBodyMethod::Splitting.description().contains("Dullweber, Leimkuhler, McLachlan"));
    /// ```
    pub const fn description(self) -> &'static str {
        match self {
            Self::Auto => "the default; runs exact (no truncation error at any dt)",
            Self::Exact => {
                "the exact solution: uniform rotation, symmetric-top closed form, \
                 or Jacobi elliptic functions"
            }
            Self::Rk4 => {
                "classical Runge-Kutta on L and q, the baseline; energy, |L| and |q| drift"
            }
            Self::Strang => "five exact rotations about the principal axes, Strang-composed",
            Self::Splitting => {
                "exact symmetric top plus one exact axis rotation \
                 (Dullweber, Leimkuhler, McLachlan)"
            }
            Self::Splitting4 => "Suzuki's 5-stage symmetric composition of splitting",
            Self::Splitting6 => "Kahan and Li's 9-stage symmetric composition of splitting",
            Self::Splitting8 => "Kahan and Li's 17-stage symmetric composition of splitting",
            Self::Dmv => {
                "discrete Moser-Veselov (implicit, conserves |L|, L_world and a modified energy)"
            }
            Self::Pdmv4 => "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 4",
            Self::Pdmv6 => "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 6",
            Self::Pdmv8 => "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 8",
            Self::Pdmv10 => "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 10",
        }
    }

    /// The method that runs: `auto` resolves to the exact solution, every
    /// other method to itself.
    ///
    /// ```
    /// use kreisel_dynamics::FreeBodyMethod;
    /// assert_eq!(FreeBodyMethod::Auto.resolve(), FreeBodyMethod::Exact);
    /// assert_eq!(FreeBodyMethod::Dmv.resolve(), FreeBodyMethod::Dmv);
    /// ```
    pub const fn resolve(self) -> Self {
        match self {
            Self::Auto => Self::Exact,
            other => other,
        }
    }

    /// The heavy-top method of the same name, which moves bodies on a
    /// pivot when this method is chosen for a scene; `None` for the
    /// methods with no heavy-top version (`exact`, `splitting`, `dmv` and
    /// `pdmv*`).
    ///
    /// The names are shared, not the schemes: the heavy-top `strang` is
    /// the gravity kick around the exact free flow, and its `splitting4/6/8`
    /// compose that ([`HeavyTopMethod`]).
    ///
    /// ```
    /// use kreisel_dynamics::{FreeBodyMethod, HeavyTopMethod};
    /// assert_eq!(FreeBodyMethod::Auto.heavy_top(), Some(HeavyTopMethod::Auto));
    /// assert_eq!(FreeBodyMethod::Splitting8.heavy_top(), Some(HeavyTopMethod::Splitting8));
    /// assert_eq!(FreeBodyMethod::Pdmv6.heavy_top(), None);
    /// ```
    pub const fn heavy_top(self) -> Option<HeavyTopMethod> {
        match self {
            Self::Auto => Some(HeavyTopMethod::Auto),
            Self::Rk4 => Some(HeavyTopMethod::Rk4),
            Self::Strang => Some(HeavyTopMethod::Strang),
            Self::Splitting4 => Some(HeavyTopMethod::Splitting4),
            Self::Splitting6 => Some(HeavyTopMethod::Splitting6),
            Self::Splitting8 => Some(HeavyTopMethod::Splitting8),
            Self::Exact
            | Self::Splitting
            | Self::Dmv
            | Self::Pdmv4
            | Self::Pdmv6
            | Self::Pdmv8
            | Self::Pdmv10 => None,
        }
    }

    /// The integrator that runs the method ([`FreeBodyMethod::resolve`]d:
    /// `auto` builds the exact solution).
    ///
    /// ```
    /// use kreisel_dynamics::FreeBodyMethod;
    /// let pdmv = FreeBodyMethod::Pdmv8.integrator();
    /// assert_eq!((pdmv.name(), pdmv.order()), ("pdmv8", 8));
    /// ```
    pub fn integrator(self) -> Box<dyn FreeBodyIntegrator> {
        match self.resolve() {
            Self::Auto | Self::Exact => Box::new(ExactFlow),
            Self::Rk4 => Box::new(Rk4),
            Self::Strang => Box::new(AxisStrang),
            Self::Splitting => Box::new(SymmetricTopSplitting),
            Self::Splitting4 => Box::new(Composition::new(self.name(), 4, &SUZUKI_4)),
            Self::Splitting6 => Box::new(Composition::new(self.name(), 6, &KAHAN_LI_6)),
            Self::Splitting8 => Box::new(Composition::new(self.name(), 8, &KAHAN_LI_8)),
            Self::Dmv => Box::new(MoserVeselov),
            Self::Pdmv4 => Box::new(PreprocessedMoserVeselov::ORDER_4),
            Self::Pdmv6 => Box::new(PreprocessedMoserVeselov::ORDER_6),
            Self::Pdmv8 => Box::new(PreprocessedMoserVeselov::ORDER_8),
            Self::Pdmv10 => Box::new(PreprocessedMoserVeselov::ORDER_10),
        }
    }
}

impl FromStr for FreeBodyMethod {
    type Err = DynamicsError;

    /// The method called `name` (exactly as [`FreeBodyMethod::name`]
    /// writes it).
    ///
    /// # Errors
    /// [`DynamicsError::UnknownMethod`] listing every name of
    /// [`FreeBodyMethod::ALL`].
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|m| m.name() == name)
            .ok_or_else(|| unknown_method(name, &Self::ALL.map(Self::name)))
    }
}

impl fmt::Display for FreeBodyMethod {
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
    const OLD_METHODS: [&str; 13] = [
        "auto",
        "exact",
        "rk4",
        "strang",
        "splitting",
        "splitting4",
        "splitting6",
        "splitting8",
        "dmv",
        "pdmv4",
        "pdmv6",
        "pdmv8",
        "pdmv10",
    ];

    #[test]
    fn every_name_parses_back_to_its_method() {
        for m in FreeBodyMethod::ALL {
            assert_eq!(m.name().parse::<FreeBodyMethod>().unwrap(), m);
            assert_eq!(m.to_string(), m.name());
        }
        assert_eq!(format!("[{:<8}]", FreeBodyMethod::Rk4), "[rk4     ]");
        assert_eq!(FreeBodyMethod::default(), FreeBodyMethod::Auto);
    }

    #[test]
    fn all_has_no_duplicates_and_keeps_the_old_names() {
        let names: Vec<&str> = FreeBodyMethod::ALL.map(FreeBodyMethod::name).to_vec();
        assert_eq!(names, OLD_METHODS);
        assert_eq!(names.iter().collect::<HashSet<_>>().len(), names.len());
        let variants: HashSet<FreeBodyMethod> = FreeBodyMethod::ALL.into_iter().collect();
        assert_eq!(variants.len(), FreeBodyMethod::ALL.len());
        assert_eq!(crate::METHODS, OLD_METHODS);
        assert_eq!(crate::AUTO, "exact");
    }

    #[test]
    fn unknown_names_are_refused_with_the_list() {
        for name in [
            "euler",
            "",
            "Auto",
            "RK4",
            " rk4",
            "exact ",
            "pdmv2",
            "splitting10",
        ] {
            match name.parse::<FreeBodyMethod>() {
                Err(DynamicsError::UnknownMethod { name: given, known }) => {
                    assert_eq!(given, name);
                    assert_eq!(known, OLD_METHODS.join(", "));
                }
                other => panic!("{name:?}: {other:?}"),
            }
            assert!(crate::method(name).is_err(), "{name:?}");
        }
    }

    #[test]
    fn each_integrator_reports_the_methods_name_and_order() {
        for m in FreeBodyMethod::ALL {
            let integrator = m.integrator();
            assert_eq!(integrator.name(), m.resolve().name(), "{m}");
            assert_eq!(
                integrator.order(),
                m.order().unwrap_or(u32::MAX),
                "{m}: the trait writes `exact` as u32::MAX"
            );
            let by_name = crate::method(m.name()).unwrap();
            assert_eq!(
                (by_name.name(), by_name.order()),
                (integrator.name(), integrator.order())
            );
        }
        assert_eq!(FreeBodyMethod::Auto.integrator().name(), "exact");
    }

    #[test]
    fn descriptions_are_one_line_and_auto_names_what_it_runs() {
        for m in FreeBodyMethod::ALL {
            let text = m.description();
            assert!(!text.is_empty() && !text.contains('\n'), "{m}: {text:?}");
        }
        let runs = format!("runs {} ", FreeBodyMethod::Auto.resolve());
        assert!(FreeBodyMethod::Auto.description().contains(&runs));
    }

    #[test]
    fn heavy_top_versions_share_the_name() {
        let mut reached = HashSet::new();
        for m in FreeBodyMethod::ALL {
            let by_name = m.name().parse::<HeavyTopMethod>().ok();
            assert_eq!(m.heavy_top(), by_name, "{m}");
            reached.extend(m.heavy_top());
        }
        assert_eq!(reached.len(), HeavyTopMethod::ALL.len());
        let without: Vec<&str> = FreeBodyMethod::ALL
            .into_iter()
            .filter(|m| m.heavy_top().is_none())
            .map(FreeBodyMethod::name)
            .collect();
        // As `kreisel simulate --help` says: exact, splitting, dmv and pdmv*.
        assert_eq!(
            without,
            [
                "exact",
                "splitting",
                "dmv",
                "pdmv4",
                "pdmv6",
                "pdmv8",
                "pdmv10"
            ]
        );
    }
}
