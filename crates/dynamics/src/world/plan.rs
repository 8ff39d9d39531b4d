//! Per-body plans: what each body of a [`crate::World`] is, which method
//! moves it and why — the cheapest exact path the body allows (the motion
//! that carries the plan out is in `motion`).
//!
//! ```text
//! free, ω = 0, exact method           resting:     nothing to compute
//! free, sphere or principal-axis spin uniform:     q(t) = q₀ ⊗ exp(t ω)
//! free, two equal moments             symmetric:   two commuting rotations
//! free, three distinct moments        asymmetric:  Jacobi elliptic functions, evaluated where asked
//! free, a stepping method chosen      stepping:    the method, every dt
//! pivot, Lagrange top, auto           Lagrange:    the closed form, evaluated where asked
//! pivot                               heavy top:   the heavy-top method, every dt (auto sub-steps)
//! free, with applied inputs           forced:      a torque splitting, every dt
//! pivot, with applied inputs          driven top:  the splitting with gravity kicked too, every dt
//! on the ground (a contact shape)     on ground:   the contact model's dopri5, error-controlled within every dt
//! on the table (contact shapes)       on table:    event-driven dopri5, its own steps within each move
//! ```

use std::fmt;

use crate::{DynamicsError, ForcedSplitting, FreeBodyMethod, HeavyTopMethod};

/// What a body of a [`crate::World`] is and how it is moved (see
/// [`crate::World::plans`]). Its [`Display`](fmt::Display) says what the
/// body is, which method and why.
///
/// A free body with applied [`crate::Inputs`] is [`Plan::Forced`]; the
/// enum is `non_exhaustive`.
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::{Body, Plan, World};
/// let mut world = World::try_new(DVec3::ZERO, 0.01)?;
/// let id = world.add(Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0)).omega_body(DVec3::new(0.1, 1.0, 0.0)).try_build()?)?;
/// assert_eq!(world.plan(id), Some(&Plan::Asymmetric));
/// assert!(world.plan(id).unwrap().to_string().starts_with("asymmetric free body"));
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Plan {
    /// A free body at rest (ω = 0) under the exact method: its attitude
    /// never changes, nothing is computed.
    Resting,
    /// A free sphere (three equal moments): one uniform rotation, exact.
    Sphere,
    /// A free body spinning about principal axis `axis` (0, 1 or 2): one
    /// uniform rotation, exact.
    PrincipalSpin {
        /// The principal axis, 0-based.
        axis: usize,
    },
    /// A free body with two equal moments: the closed form, two commuting
    /// rotations, exact.
    Symmetric {
        /// The symmetry axis (the odd moment), 0-based principal index.
        axis: usize,
    },
    /// A free body with three distinct moments: the exact solution in
    /// Jacobi elliptic functions, set up once and evaluated only at the
    /// times asked.
    Asymmetric,
    /// A free body moved by the stepping method the user chose, every `dt`.
    Stepping(FreeBodyMethod),
    /// A body on a pivot under gravity, moved by the heavy-top method
    /// every `dt`.
    HeavyTop(HeavyTopMethod),
    /// A heavy top moved by the Taylor series of the whole top
    /// ([`crate::HeavyTopTaylor`], order up to 18, sub-stepped to
    /// `h ω ≤ 0.8`) every `dt`: what a [`crate::Tolerance`] picks where it is
    /// the cheapest way to meet it.
    HeavyTopSeries,
    /// A Lagrange top (two equal moments about the pivot, the centre of
    /// mass on the symmetry axis) under the `auto` heavy-top method and
    /// without inputs: the closed form ([`crate::HeavyTopClosedForm`]),
    /// set up once and evaluated only at the times asked, at rounding
    /// level.
    LagrangeTop,
    /// A free body with applied inputs (torques, forces, damping, a law),
    /// moved by the kick–drift–kick splitting `method` every `dt`: the
    /// free flow alternates with exact kicks of the loads
    /// ([`ForcedSplitting`]). The free-body method chosen maps to it
    /// ([`Plan::forced_splitting`]).
    Forced {
        /// The splitting.
        method: ForcedSplitting,
    },
    /// A body on a pivot with applied inputs (a heavy top driven by a
    /// motor, pushed, damped): the kick–drift–kick splitting `method`
    /// every `dt`, gravity kicked exactly with the loads and the free flow
    /// about the pivot ([`crate::ForcedBody::try_on_pivot`]); under the
    /// `auto` heavy-top method order 8, sub-stepped as
    /// [`crate::HeavyTopAuto`] ([`Plan::driven_top_splitting`]).
    DrivenTop {
        /// The splitting.
        method: ForcedSplitting,
    },
    /// A body on the ground plane ([`crate::Support::Ground`]): the
    /// contact model's error-controlled Dormand–Prince 5(4) steps
    /// ([`crate::GroundTop::try_advance_adaptive`]) within every step the
    /// world takes, landing on its grid: `dt` is only where the states are
    /// read. Its accuracy is `tolerance`: 1e-11 without a world
    /// [`crate::Tolerance`], 1e-4 × its attitude error with one (clamped
    /// to [1e-13, 1e-8]); the world's methods do not change it.
    OnGround {
        /// The friction law at the contact.
        friction: crate::FrictionModel,
        /// How many further contact shapes are watched for touchdown
        /// ([`crate::BodyBuilder::other_contacts`]).
        watched: usize,
        /// The accuracy of the steps.
        tolerance: crate::AdaptiveTolerance,
    },
    /// A body above or on the table ([`crate::Support::Table`]): its
    /// [`crate::TableMotion`], Dormand–Prince 5(4) with error control
    /// between events (impacts, touchdowns, lift-offs, stick, slip, rest,
    /// recorded: [`crate::World::events`]), advanced to the end of each
    /// move in its own steps — the world's `dt` is only the grid the
    /// states are read on. Its tolerance is the world's
    /// ([`crate::table_tolerance`]); the methods do not change it.
    OnTable {
        /// How many contact shapes the body has.
        contacts: usize,
    },
}

impl Plan {
    /// Whether the plan follows the exact solution (no truncation error at
    /// any step, no stepping between the times asked).
    ///
    /// ```
    /// use kreisel_dynamics::Plan;
    /// assert!(Plan::Sphere.is_exact());
    /// assert!(!Plan::Stepping(kreisel_dynamics::FreeBodyMethod::Rk4).is_exact());
    /// ```
    pub fn is_exact(&self) -> bool {
        matches!(
            self,
            Plan::Resting
                | Plan::Sphere
                | Plan::PrincipalSpin { .. }
                | Plan::Symmetric { .. }
                | Plan::Asymmetric
                | Plan::LagrangeTop
        )
    }
}

/// The torque splitting called `name` (a free-body or heavy-top method of
/// that name runs it on a body with inputs; `auto` runs `auto`).
///
/// # Errors
/// For a method without a torque kick: the names of those with one,
/// comma-separated, for [`DynamicsError::MethodTakesNoInputs`].
fn splitting_named(name: &str, auto: ForcedSplitting) -> Result<ForcedSplitting, String> {
    if name == "auto" {
        return Ok(auto);
    }
    ForcedSplitting::ALL
        .into_iter()
        .find(|f| f.name() == name)
        .ok_or_else(|| {
            let names = ForcedSplitting::ALL.map(|f| f.name());
            format!("auto, {}", names.join(", "))
        })
}

impl Plan {
    /// The torque splitting that free-body method `method` means for a body
    /// with applied inputs.
    ///
    /// ```text
    /// auto → splitting6 (ForcedSplitting::DEFAULT),  strang → strang,
    /// splitting4 → splitting4,  splitting6 → splitting6,  splitting8 → splitting8
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::MethodTakesNoInputs`] for every other method (no
    /// torque kick: the exact solution, RK4, the axis splittings, the
    /// Moser–Veselov family).
    ///
    /// ```
    /// use kreisel_dynamics::{ForcedSplitting, FreeBodyMethod, Plan};
    /// assert_eq!(Plan::forced_splitting(FreeBodyMethod::Auto)?, ForcedSplitting::DEFAULT);
    /// assert_eq!(Plan::forced_splitting(FreeBodyMethod::Strang)?, ForcedSplitting::STRANG);
    /// let e = Plan::forced_splitting(FreeBodyMethod::Pdmv6).unwrap_err();
    /// assert_eq!(e.to_string(), "free-body method `pdmv6` cannot move a body with applied inputs (methods that can: auto, strang, splitting4, splitting6, splitting8)");
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn forced_splitting(method: FreeBodyMethod) -> Result<ForcedSplitting, DynamicsError> {
        splitting_named(method.name(), ForcedSplitting::DEFAULT).map_err(|known| {
            DynamicsError::MethodTakesNoInputs {
                kind: "free-body",
                method: method.integrator().name(),
                known,
            }
        })
    }
}

impl Plan {
    /// The torque splitting that heavy-top method `method` means for a body
    /// on a pivot with applied inputs.
    ///
    /// ```text
    /// auto → splitting8 (sub-stepped within its stability limit),  strang → strang,
    /// splitting4 → splitting4,  splitting6 → splitting6,  splitting8 → splitting8
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::MethodTakesNoInputs`] for `rk4`.
    ///
    /// ```
    /// use kreisel_dynamics::{ForcedSplitting, HeavyTopMethod, Plan};
    /// assert_eq!(Plan::driven_top_splitting(HeavyTopMethod::Auto)?, ForcedSplitting::ORDER_8);
    /// assert!(Plan::driven_top_splitting(HeavyTopMethod::Rk4).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn driven_top_splitting(method: HeavyTopMethod) -> Result<ForcedSplitting, DynamicsError> {
        splitting_named(method.name(), ForcedSplitting::ORDER_8).map_err(|known| {
            DynamicsError::MethodTakesNoInputs {
                kind: "heavy-top",
                method: method.integrator().name(),
                known,
            }
        })
    }

    /// The heavy-top method that runs the splitting of order `order`
    /// (a tolerance's choice for a heavy top).
    pub(crate) fn heavy_top_method_of(method: ForcedSplitting) -> HeavyTopMethod {
        match method.order() {
            2 => HeavyTopMethod::Strang,
            4 => HeavyTopMethod::Splitting4,
            6 => HeavyTopMethod::Splitting6,
            _ => HeavyTopMethod::Splitting8,
        }
    }
}

impl fmt::Display for Plan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Plan::Resting => write!(
                f,
                "resting free body: exact, nothing to compute (omega = 0 and no torque)"
            ),
            Plan::Sphere => write!(
                f,
                "free sphere: exact, one uniform rotation (three equal moments: omega is constant)"
            ),
            Plan::PrincipalSpin { axis } => write!(
                f,
                "free spin about principal axis {}: exact, one uniform rotation (L along a principal axis stays there)",
                axis + 1
            ),
            Plan::Symmetric { axis } => write!(
                f,
                "symmetric free body: exact, closed form of two commuting rotations (two equal moments, symmetry axis {})",
                axis + 1
            ),
            Plan::Asymmetric => write!(
                f,
                "asymmetric free body: exact, Jacobi elliptic solution set up once and evaluated only at the times asked (three distinct moments)"
            ),
            Plan::Stepping(method) => {
                write!(f, "free body stepped by {method}")?;
                if let Some(order) = method.order() {
                    write!(f, " (order {order})")?;
                }
                write!(f, " every dt (the method chosen)")
            }
            Plan::HeavyTop(method) => {
                write!(
                    f,
                    "heavy top on a pivot: {method} (order {}",
                    method.order()
                )?;
                if *method == HeavyTopMethod::Auto {
                    write!(f, ", splitting8 sub-stepped within its stability limit")?;
                }
                write!(f, ") every dt (gravity exerts a torque about the pivot)")
            }
            Plan::Forced { method } => write!(
                f,
                "forced free body: {} (order {}) every dt, kick-drift-kick splitting of the free flow and exact kicks of the loads (torques, forces or damping are applied)",
                method.name(),
                method.order()
            ),
            Plan::HeavyTopSeries => write!(
                f,
                "heavy top on a pivot: taylor (series of the whole top, order up to 18, sub-steps of h omega <= 0.8) every dt (gravity exerts a torque about the pivot)"
            ),
            Plan::LagrangeTop => write!(
                f,
                "Lagrange top on a pivot: exact, closed form in elliptic functions set up once and evaluated only at the times asked (two equal moments, centre of mass on the symmetry axis)"
            ),
            Plan::DrivenTop { method } => write!(
                f,
                "driven heavy top on a pivot: {} (order {}) every dt, kick-drift-kick splitting of the free flow about the pivot and exact kicks of gravity and the loads (torques, forces or damping are applied)",
                method.name(),
                method.order()
            ),
            Plan::OnGround {
                friction,
                watched,
                tolerance,
            } => {
                write!(
                    f,
                    "body on the ground: ground-top dopri5 (order 5), error-controlled steps at rtol {:e}, atol {:e} within every dt, landing on it (contact with the plane z = 0, friction {friction}; ",
                    tolerance.rtol(),
                    tolerance.atol()
                )?;
                match watched {
                    0 => write!(f, "lift-off stops the run)"),
                    1 => write!(
                        f,
                        "1 further contact watched; lift-off or a touchdown stops the run)"
                    ),
                    n => write!(
                        f,
                        "{n} further contacts watched; lift-off or a touchdown stops the run)"
                    ),
                }
            }
            Plan::OnTable { contacts } => write!(
                f,
                "body on the table: event-driven dopri5 (order 5) with error control, its own steps within each dt (unilateral contact of {contacts} shape{} with the plane z = 0, Coulomb-Contensou friction, Newton impacts; impacts, lift-off, stick-slip and rest are events and the run goes on)",
                if *contacts == 1 { "" } else { "s" }
            ),
        }
    }
}
