//! [`FreeBodyMethod`]: the torque-free integrators, one line each
//! (`Variant => &INTEGRATOR`); name, order, description and step limit
//! are the integrator's.

#[cfg(doc)]
use crate::{
    AxisStrang, Composition, ExactFlow, FreeBodyIntegrator, KAHAN_LI_6, KAHAN_LI_8, MoserVeselov,
    PreprocessedMoserVeselov, Rk4, SUZUKI_4, SymmetricTopSplitting,
};

/// Generates a free-body method enum from its list: `auto` (the default,
/// which runs `$Resolved`, with its own description), then one line per
/// method, `Variant => &INTEGRATOR`.
macro_rules! free_body_method_enum {
    (
        $(#[$attr:meta])*
        $vis:vis enum $Name:ident {
            $(#[$auto_doc:meta])* Auto runs $Resolved:ident, $auto_description:literal;
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
            /// The integrator that runs the method ([`Self::resolve`]d:
            /// `auto` runs the exact solution), a constant that outlives
            /// every world.
            ///
            /// ```
            /// use kreisel_dynamics::FreeBodyMethod;
            /// let pdmv = FreeBodyMethod::Pdmv8.integrator();
            /// assert_eq!((pdmv.name(), pdmv.order()), ("pdmv8", 8));
            /// assert_eq!(FreeBodyMethod::Auto.integrator().name(), "exact");
            /// ```
            pub fn integrator(self) -> &'static dyn $crate::FreeBodyIntegrator {
                match self {
                    Self::Auto => Self::$Resolved.integrator(),
                    $(Self::$Variant => $integrator,)+
                }
            }

            /// The name `FromStr` reads and `Display` writes (e.g.
            /// `"rk4"`): the integrator's, `"auto"` for `auto`.
            ///
            /// ```
            /// use kreisel_dynamics::FreeBodyMethod;
            /// assert_eq!(FreeBodyMethod::Pdmv10.name(), "pdmv10");
            /// assert_eq!(FreeBodyMethod::Auto.name(), "auto");
            /// ```
            pub fn name(self) -> &'static str {
                match self {
                    Self::Auto => "auto",
                    other => other.integrator().name(),
                }
            }

            /// The order `p` of the method (global error `O(hᵖ)`), or
            /// `None` for the exact solution (and `auto`, which runs it):
            /// no truncation error at any step, which
            /// [`FreeBodyIntegrator::order`](crate::FreeBodyIntegrator::order)
            /// writes as `u32::MAX`.
            ///
            /// ```text
            /// |x(t) − xₕ(t)| = O(hᵖ)
            /// ```
            ///
            /// ```
            /// use kreisel_dynamics::FreeBodyMethod;
            /// assert_eq!(FreeBodyMethod::Rk4.order(), Some(4));
            /// assert_eq!(FreeBodyMethod::Exact.order(), None);
            /// ```
            pub fn order(self) -> Option<u32> {
                match self.integrator().order() {
                    u32::MAX => None,
                    p => Some(p),
                }
            }

            /// One line about the method, as `kreisel simulate
            /// --list-methods` shows it: the integrator's, `auto`'s own.
            ///
            /// ```
            /// use kreisel_dynamics::FreeBodyMethod;
            /// assert!(FreeBodyMethod::Splitting.description().contains("Dullweber, Leimkuhler, McLachlan"));
            /// assert!(FreeBodyMethod::Auto.description().starts_with("the default; runs exact"));
            /// ```
            pub fn description(self) -> &'static str {
                match self {
                    Self::Auto => $auto_description,
                    other => other.integrator().description(),
                }
            }

            /// The largest `h ω_max` (to 0.1) at which the method still
            /// follows a torque-free body, `ω_max = |L| / I₁` the fastest
            /// angular speed the body can reach (`I₁` the smallest moment):
            /// the integrator's
            /// [`step_limit`](crate::FreeBodyIntegrator::step_limit),
            /// `None` for the exact solution (and `auto`), which has no
            /// limit.
            ///
            /// ```text
            /// h ω_max ≤ limit,   ω_max = |L| / min(I₁, I₂, I₃)
            /// ```
            ///
            /// Measured, not assumed
            /// (`crates/dynamics/tests/free_body_step_limit.rs`): 6 bodies
            /// (moment ratios from 1 : 1 : 1.9 to 1 : 3 : 3) × 16 directions
            /// of `L` spread over the sphere, 2000 steps each, scanned in
            /// `h ω_max` (steps of 0.1, 0.02 near the dmv family's
            /// breakdown). Up to the limit every run keeps its state finite
            /// and its energy within
            /// [`STEP_LIMIT_ENERGY_ERROR`](crate::STEP_LIMIT_ENERGY_ERROR)
            /// (10 %) of the start (the test checks 0.5, 0.75, 0.9 and 1
            /// times it); within 25 % beyond it some run does not: the
            /// energy drifts (`rk4`) or swings (the splittings) beyond
            /// 10 %, or the implicit step fails (the dmv family). Each
            /// integrator's file gives its limit and what happens beyond it.
            ///
            /// The splittings move `L` by exact rotations, so they never
            /// blow up: past the limit the energy (and with it the motion)
            /// is simply no longer followed — at `h ω_max` = 30 (`I` =
            /// (1, 2, 3) kg m², `ω` = (1, 30, 0.5) rad/s, `h` = 0.5 s)
            /// `strang` swings the energy between 0.67 and 1.98 times its
            /// start. Below the limit each error falls as `(h ω_max)ᵖ`
            /// (order `p`), far below 10 % well inside it.
            ///
            /// ```
            /// use kreisel_dynamics::FreeBodyMethod;
            /// assert_eq!(FreeBodyMethod::Strang.step_limit(), Some(1.8));
            /// assert_eq!(FreeBodyMethod::Auto.step_limit(), None);
            /// ```
            pub fn step_limit(self) -> Option<f64> {
                self.integrator().step_limit()
            }

            /// The method that runs: `auto` resolves to the exact
            /// solution, every other method to itself.
            ///
            /// ```
            /// use kreisel_dynamics::FreeBodyMethod;
            /// assert_eq!(FreeBodyMethod::Auto.resolve(), FreeBodyMethod::Exact);
            /// assert_eq!(FreeBodyMethod::Dmv.resolve(), FreeBodyMethod::Dmv);
            /// ```
            pub const fn resolve(self) -> Self {
                match self {
                    Self::Auto => Self::$Resolved,
                    other => other,
                }
            }

            /// The heavy-top method of the same name
            /// ([`HeavyTopMethod::ALL`](crate::HeavyTopMethod::ALL)),
            /// which moves bodies on a pivot when this method is chosen
            /// for a scene; `None` for the methods with no heavy-top
            /// version (`exact`, `splitting`, `dmv` and `pdmv*`).
            ///
            /// The names are shared, not the schemes: the heavy-top
            /// `strang` is the gravity kick around the exact free flow,
            /// and its `splitting4/6/8` compose that.
            ///
            /// ```
            /// use kreisel_dynamics::{FreeBodyMethod, HeavyTopMethod};
            /// assert_eq!(FreeBodyMethod::Auto.heavy_top(), Some(HeavyTopMethod::Auto));
            /// assert_eq!(FreeBodyMethod::Splitting8.heavy_top(), Some(HeavyTopMethod::Splitting8));
            /// assert_eq!(FreeBodyMethod::Pdmv6.heavy_top(), None);
            /// ```
            pub fn heavy_top(self) -> Option<$crate::HeavyTopMethod> {
                let name = self.name();
                $crate::HeavyTopMethod::ALL
                    .into_iter()
                    .find(|m| m.name() == name)
            }
        }
    };
}

pub(crate) use free_body_method_enum;

/// The list of free-body methods, in `ALL`'s order: `auto`, then one line
/// per method, `Variant => &INTEGRATOR`. Lines given to it (a test's
/// method) come last.
macro_rules! free_body_methods {
    (
        $(#[$attr:meta])*
        $vis:vis enum $Name:ident { $($extra:tt)* }
    ) => {
        $crate::method::free_body::free_body_method_enum! {
            $(#[$attr])*
            $vis enum $Name {
                /// `auto`, the default: the recommended method, today
                /// [`FreeBodyMethod::Exact`] ([`FreeBodyMethod::resolve`]). It skips
                /// what a body does not need, has no truncation error at any step
                /// (`crates/dynamics/tests/free_body_exact.rs`: ≤ 2e-14 rad against every
                /// reference sample), and a step costs less than one Strang splitting step
                /// (`BENCHMARKS.md`).
                Auto runs Exact, "the default; runs exact (no truncation error at any dt)";
                /// `exact`: the exact solution ([`ExactFlow`], [`crate::ExactSolution`]) —
                /// a uniform rotation for a sphere or a spin about a principal axis, two
                /// commuting rotations for a symmetric body, Jacobi elliptic functions
                /// for an asymmetric one (Landau & Lifshitz, *Mechanics*, §37;
                /// Celledoni, Fassò, Säfström & Zanna, SIAM J. Sci. Comput. 30:2084
                /// (2008); van Zon & Schofield, J. Comput. Phys. 225:145 (2007)).
                Exact => &$crate::ExactFlow,
                /// `rk4`: classical Runge–Kutta (Kutta 1901) on `(q, L)` ([`Rk4`]), the
                /// baseline; not geometric.
                Rk4 => &$crate::Rk4,
                /// `strang`: the five-rotation Strang splitting into rotations about
                /// the principal axes ([`AxisStrang`]; McLachlan 1993; Touma & Wisdom
                /// 1994), order 2.
                Strang => &$crate::AxisStrang,
                /// `splitting`: an exact symmetric top plus one exact axis rotation
                /// ([`SymmetricTopSplitting`]; Dullweber, Leimkuhler & McLachlan,
                /// J. Chem. Phys. 107:5840 (1997); ordering after Fassò, J. Comput.
                /// Phys. 189:527 (2003)), order 2.
                Splitting => &$crate::SymmetricTopSplitting,
                /// `splitting4`: Suzuki's 5-stage symmetric composition of
                /// [`FreeBodyMethod::Splitting`] ([`Composition::ORDER_4`], [`SUZUKI_4`];
                /// Phys. Lett. A 146:319 (1990)), order 4.
                Splitting4 => &$crate::Composition::ORDER_4,
                /// `splitting6`: Kahan & Li's 9-stage symmetric composition of
                /// [`FreeBodyMethod::Splitting`] ([`Composition::ORDER_6`], [`KAHAN_LI_6`];
                /// Math. Comp. 66:1089 (1997)), order 6.
                Splitting6 => &$crate::Composition::ORDER_6,
                /// `splitting8`: Kahan & Li's 17-stage symmetric composition of
                /// [`FreeBodyMethod::Splitting`] ([`Composition::ORDER_8`], [`KAHAN_LI_8`];
                /// Math. Comp. 66:1089 (1997)), order 8.
                Splitting8 => &$crate::Composition::ORDER_8,
                /// `dmv`: the discrete Moser–Veselov algorithm ([`MoserVeselov`];
                /// Moser & Veselov, Commun. Math. Phys. 139:217 (1991), in the
                /// quaternion form of Hairer & Vilmart, J. Phys. A 39:13225 (2006)),
                /// implicit, order 2.
                Dmv => &$crate::MoserVeselov,
                /// `pdmv4`: Hairer & Vilmart's preprocessed discrete Moser–Veselov
                /// ([`PreprocessedMoserVeselov::ORDER_4`]; J. Phys. A 39:13225 (2006)),
                /// order 4.
                Pdmv4 => &$crate::PreprocessedMoserVeselov::ORDER_4,
                /// `pdmv6`: preprocessed discrete Moser–Veselov
                /// ([`PreprocessedMoserVeselov::ORDER_6`]), order 6.
                Pdmv6 => &$crate::PreprocessedMoserVeselov::ORDER_6,
                /// `pdmv8`: preprocessed discrete Moser–Veselov
                /// ([`PreprocessedMoserVeselov::ORDER_8`]), order 8.
                Pdmv8 => &$crate::PreprocessedMoserVeselov::ORDER_8,
                /// `pdmv10`: preprocessed discrete Moser–Veselov
                /// ([`PreprocessedMoserVeselov::ORDER_10`]), order 10.
                Pdmv10 => &$crate::PreprocessedMoserVeselov::ORDER_10,
                $($extra)*
            }
        }
    };
}
#[cfg(test)]
pub(crate) use free_body_methods;

free_body_methods! {
    /// A method for the torque-free rigid body: what `--method` names.
    ///
    /// The variants, in [`FreeBodyMethod::ALL`]'s order, are `auto`, the exact
    /// solution, the RK4 baseline, the splittings into exact rotations and
    /// their symmetric compositions, and the discrete Moser–Veselov family.
    /// Each is one line of a list (`Variant => &INTEGRATOR`, in
    /// `method/free_body.rs`); its name, order, description and step limit
    /// are its integrator's ([`FreeBodyIntegrator`]).
    ///
    /// ```text
    /// name  ──FromStr──▶  FreeBodyMethod  ──integrator()──▶  &'static dyn FreeBodyIntegrator
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
    pub enum FreeBodyMethod {}
}

#[cfg(test)]
mod tests {
    use std::collections::HashSet;

    use super::*;
    use crate::{DynamicsError, FreeBodyIntegrator, HeavyTopMethod};

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
    }

    /// What `--list-methods` and `--explain` printed before the facts moved
    /// into the integrators: order, description and step limit, per method.
    #[test]
    fn orders_descriptions_and_step_limits_keep_their_values() {
        let old: [(Option<u32>, &str, Option<f64>); 13] = [
            (
                None,
                "the default; runs exact (no truncation error at any dt)",
                None,
            ),
            (
                None,
                "the exact solution: uniform rotation, symmetric-top closed form, \
                 or Jacobi elliptic functions",
                None,
            ),
            (
                Some(4),
                "classical Runge-Kutta on L and q, the baseline; energy, |L| and |q| drift",
                Some(1.0),
            ),
            (
                Some(2),
                "five exact rotations about the principal axes, Strang-composed",
                Some(1.8),
            ),
            (
                Some(2),
                "exact symmetric top plus one exact axis rotation \
                 (Dullweber, Leimkuhler, McLachlan)",
                Some(3.3),
            ),
            (
                Some(4),
                "Suzuki's 5-stage symmetric composition of splitting",
                Some(4.2),
            ),
            (
                Some(6),
                "Kahan and Li's 9-stage symmetric composition of splitting",
                Some(6.5),
            ),
            (
                Some(8),
                "Kahan and Li's 17-stage symmetric composition of splitting",
                Some(7.6),
            ),
            (
                Some(2),
                "discrete Moser-Veselov (implicit, conserves |L|, L_world and a modified energy)",
                Some(1.0),
            ),
            (
                Some(4),
                "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 4",
                Some(2.8),
            ),
            (
                Some(6),
                "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 6",
                Some(1.4),
            ),
            (
                Some(8),
                "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 8",
                Some(2.0),
            ),
            (
                Some(10),
                "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 10",
                Some(1.5),
            ),
        ];
        for (m, (order, description, limit)) in FreeBodyMethod::ALL.into_iter().zip(old) {
            assert_eq!(
                (m.order(), m.description(), m.step_limit()),
                (order, description, limit),
                "{m}"
            );
        }
        // PDMV of order 2 is DMV itself, and says so.
        let dmv = crate::PreprocessedMoserVeselov::new(2).unwrap();
        let facts =
            |i: &dyn FreeBodyIntegrator| (i.name(), i.order(), i.description(), i.step_limit());
        assert_eq!(facts(&dmv), facts(FreeBodyMethod::Dmv.integrator()));
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
