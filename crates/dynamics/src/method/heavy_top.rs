//! [`HeavyTopMethod`]: the heavy-top integrators, one line each
//! (`Variant => &INTEGRATOR`); name, order and description are the
//! integrator's.

#[cfg(doc)]
use crate::{HeavyTopAuto, HeavyTopIntegrator, HeavyTopRk4, HeavyTopSplitting};

/// Generates the heavy-top method enum from its list: one line per
/// method, `Variant => &INTEGRATOR`, `auto` first.
macro_rules! heavy_top_methods {
    (
        $(#[$attr:meta])*
        $vis:vis enum $Name:ident {
            $(#[$auto_doc:meta])* Auto => $auto:expr,
            $($(#[$doc:meta])* $Variant:ident => $integrator:expr),+ $(,)?
        }
    ) => {
        $crate::method::method_enum! {
            $(#[$attr])*
            $vis enum $Name {
                $(#[$auto_doc])* Auto,
                $($(#[$doc])* $Variant),+
            }
        }

        impl $Name {
            /// The integrator that runs the method, a constant that
            /// outlives every world.
            ///
            /// ```
            /// use kreisel_dynamics::HeavyTopMethod;
            /// let m = HeavyTopMethod::Rk4.integrator();
            /// assert_eq!((m.name(), m.order()), ("rk4", 4));
            /// ```
            pub fn integrator(self) -> &'static dyn $crate::HeavyTopIntegrator {
                match self {
                    Self::Auto => $auto,
                    $(Self::$Variant => $integrator,)+
                }
            }

            /// The name `FromStr` reads and `Display` writes: the
            /// integrator's.
            ///
            /// ```
            /// use kreisel_dynamics::HeavyTopMethod;
            /// assert_eq!(HeavyTopMethod::Strang.name(), "strang");
            /// ```
            pub fn name(self) -> &'static str {
                self.integrator().name()
            }

            /// The order `p` of the method (global error `O(hᵖ)`); every
            /// heavy-top method has one (there is no exact heavy-top flow
            /// here).
            ///
            /// ```text
            /// |x(t) − xₕ(t)| = O(hᵖ)
            /// ```
            ///
            /// ```
            /// use kreisel_dynamics::HeavyTopMethod;
            /// assert_eq!(HeavyTopMethod::Strang.order(), 2);
            /// ```
            pub fn order(self) -> u32 {
                self.integrator().order()
            }

            /// One line about the method, as `kreisel simulate
            /// --list-methods` shows it: the integrator's.
            ///
            /// ```
            /// use kreisel_dynamics::HeavyTopMethod;
            /// assert!(HeavyTopMethod::Splitting6.description().starts_with("Kahan and Li's"));
            /// ```
            pub fn description(self) -> &'static str {
                self.integrator().description()
            }
        }
    };
}

heavy_top_methods! {
    /// A method for the heavy top (a body on a fixed pivot under gravity).
    ///
    /// The variants, in [`HeavyTopMethod::ALL`]'s order, are `auto`, the RK4
    /// baseline, the kick–free–kick Strang splitting and its symmetric
    /// compositions. A scene's method name picks the heavy-top method of the
    /// same name for its bodies with a pivot
    /// ([`crate::FreeBodyMethod::heavy_top`]). Each is one line of a list
    /// (`Variant => &INTEGRATOR`, in `method/heavy_top.rs`); its name, order
    /// and description are its integrator's ([`HeavyTopIntegrator`]).
    ///
    /// ```text
    /// name  ──FromStr──▶  HeavyTopMethod  ──integrator()──▶  &'static dyn HeavyTopIntegrator
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
    pub enum HeavyTopMethod {
        /// `auto`, the default: [`HeavyTopMethod::Splitting8`] with every step
        /// cut into the fewest sub-steps that keep it inside its stability
        /// limits ([`HeavyTopAuto`]), order 8.
        Auto => &crate::HeavyTopAuto,
        /// `rk4`: classical Runge–Kutta (Kutta 1901) on `(q, L)` with the
        /// gravity torque ([`HeavyTopRk4`]), the baseline; not geometric.
        Rk4 => &crate::HeavyTopRk4,
        /// `strang`: half gravity kick, exact free-body flow, half kick
        /// ([`HeavyTopSplitting::STRANG`]; Strang 1968; Touma & Wisdom 1994;
        /// Dullweber, Leimkuhler & McLachlan 1997), order 2. The free flow is
        /// PDMV10 for three distinct moments.
        Strang => &crate::HeavyTopSplitting::STRANG,
        /// `splitting4`: Suzuki's 5-stage symmetric composition of
        /// [`HeavyTopMethod::Strang`] ([`HeavyTopSplitting::ORDER_4`]; Phys.
        /// Lett. A 146:319 (1990)), order 4.
        Splitting4 => &crate::HeavyTopSplitting::ORDER_4,
        /// `splitting6`: Kahan & Li's 9-stage symmetric composition of
        /// [`HeavyTopMethod::Strang`] ([`HeavyTopSplitting::ORDER_6`]; Math.
        /// Comp. 66:1089 (1997)), order 6.
        Splitting6 => &crate::HeavyTopSplitting::ORDER_6,
        /// `splitting8`: Kahan & Li's 17-stage symmetric composition of
        /// [`HeavyTopMethod::Strang`] ([`HeavyTopSplitting::ORDER_8`]; Math.
        /// Comp. 66:1089 (1997)), order 8.
        Splitting8 => &crate::HeavyTopSplitting::ORDER_8,
    }
}

#[cfg(test)]
mod tests {
    use std::collections::HashSet;

    use super::*;
    use crate::DynamicsError;

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
        }
    }

    /// What `--list-methods` printed before the facts moved into the
    /// integrators.
    #[test]
    fn orders_and_descriptions_keep_their_values() {
        let old = [
            (
                8,
                "the default; splitting8, sub-stepped where dt exceeds its stability limit",
            ),
            (
                4,
                "classical Runge-Kutta on L and q with the gravity torque, the baseline",
            ),
            (
                2,
                "half gravity kick, exact free-body flow, half kick (PDMV10 for 3 distinct moments)",
            ),
            (4, "Suzuki's 5-stage symmetric composition of strang"),
            (6, "Kahan and Li's 9-stage symmetric composition of strang"),
            (8, "Kahan and Li's 17-stage symmetric composition of strang"),
        ];
        for (m, facts) in HeavyTopMethod::ALL.into_iter().zip(old) {
            assert_eq!((m.order(), m.description()), facts, "{m}");
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
