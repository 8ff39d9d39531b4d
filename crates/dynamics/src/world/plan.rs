//! Per-body plans: what each body of a [`crate::World`] is, which method
//! moves it and why — the cheapest exact path the body allows — and the
//! motion that carries the plan out.
//!
//! ```text
//! free, ω = 0, exact method           resting:     nothing to compute
//! free, sphere or principal-axis spin uniform:     q(t) = q₀ ⊗ exp(t ω)
//! free, two equal moments             symmetric:   two commuting rotations
//! free, three distinct moments        asymmetric:  Jacobi elliptic functions, evaluated where asked
//! free, a stepping method chosen      stepping:    the method, every dt
//! pivot                               heavy top:   the heavy-top method, every dt (auto sub-steps)
//! ```

use std::fmt;

use super::registry;
use crate::elliptic::dd::Dd;
use crate::exact::ExactKind;
use crate::{
    DivergenceCheck, DynamicsError, ExactSolution, FreeBodyMethod, HeavyTopMethod, PrincipalState,
    Propagator,
};

/// What a body of a [`crate::World`] is and how it is moved (see
/// [`crate::World::plans`]). Its [`Display`](fmt::Display) says what the
/// body is, which method and why.
///
/// Torques and forces are not offered yet; a plan for them will be a new
/// variant (the enum is `non_exhaustive`).
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
        )
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
        }
    }
}

/// The motion that carries a plan out, from the state when it was made.
pub(crate) enum Motion {
    /// The state never changes: `state` is the one given, `settled` the
    /// exact solution's own (attitude normalised), reported once the world
    /// has moved on.
    Resting {
        state: PrincipalState,
        settled: PrincipalState,
    },
    /// The exact solution from the world time `start`, and its last value.
    Exact {
        solution: ExactSolution,
        start: Dd,
        state: PrincipalState,
    },
    /// A free-body propagator.
    Stepping(Box<dyn Propagator>),
    /// A heavy top: its state, stepped by the world's heavy-top method.
    HeavyTop(PrincipalState),
}

impl fmt::Debug for Motion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_tuple("Motion").field(&self.state()).finish()
    }
}

impl Motion {
    /// The plan and motion of a free body from `state` at world time `start`.
    ///
    /// # Errors
    /// The exact solution's set-up errors.
    pub(crate) fn free(
        method: FreeBodyMethod,
        moments: glam::DVec3,
        state: PrincipalState,
        start: Dd,
    ) -> Result<(Plan, Motion), DynamicsError> {
        if method.resolve() != FreeBodyMethod::Exact {
            let propagator = registry::free_body(method).propagator(moments, state);
            return Ok((Plan::Stepping(method), Motion::Stepping(propagator)));
        }
        let solution = ExactSolution::try_new(moments, state)?;
        if state.l_principal == glam::DVec3::ZERO {
            // ω t = 0 at every t: the exact solution at any time is its
            // value at 0, computed once.
            let settled = solution.state_at(0.0);
            DivergenceCheck::free_body("exact", moments, &state).check(&settled, 0.0)?;
            return Ok((Plan::Resting, Motion::Resting { state, settled }));
        }
        let plan = match solution.kind() {
            ExactKind::Uniform if moments.x == moments.y && moments.y == moments.z => Plan::Sphere,
            ExactKind::Uniform => {
                let l = state.l_principal.abs();
                let axis = if l.x >= l.y && l.x >= l.z {
                    0
                } else if l.y >= l.z {
                    1
                } else {
                    2
                };
                Plan::PrincipalSpin { axis }
            }
            ExactKind::Symmetric { axis } => Plan::Symmetric { axis },
            ExactKind::Asymmetric => Plan::Asymmetric,
        };
        Ok((
            plan,
            Motion::Exact {
                solution,
                start,
                state,
            },
        ))
    }

    /// The plan and motion of a heavy top.
    pub(crate) fn heavy_top(method: HeavyTopMethod, state: PrincipalState) -> (Plan, Motion) {
        (Plan::HeavyTop(method), Motion::HeavyTop(state))
    }

    /// The current state.
    pub(crate) fn state(&self) -> PrincipalState {
        match self {
            Motion::Resting { state, .. } | Motion::HeavyTop(state) => *state,
            Motion::Exact { state, .. } => *state,
            Motion::Stepping(propagator) => propagator.state(),
        }
    }

    /// For the exact motion: evaluates it at world time `now`.
    pub(crate) fn evaluate_at(&mut self, now: Dd) {
        if let Motion::Exact {
            solution,
            start,
            state,
        } = self
        {
            let t = if start.hi == 0.0 && start.lo == 0.0 {
                now
            } else {
                now.add(start.neg())
            };
            *state = solution.state_at_split(t.hi, t.lo);
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::{DQuat, DVec3};

    use super::*;

    fn plan(moments: DVec3, l: DVec3) -> Plan {
        let state = PrincipalState {
            world_from_principal: DQuat::IDENTITY,
            l_principal: l,
        };
        Motion::free(FreeBodyMethod::Auto, moments, state, Dd::from_f64(0.0))
            .unwrap()
            .0
    }

    #[test]
    fn each_body_gets_the_cheapest_exact_plan() {
        let asym = DVec3::new(1.0, 2.0, 3.0);
        assert_eq!(plan(asym, DVec3::ZERO), Plan::Resting);
        assert_eq!(
            plan(DVec3::splat(2.0), DVec3::new(1.0, 2.0, 3.0)),
            Plan::Sphere
        );
        assert_eq!(
            plan(asym, DVec3::new(0.0, -2.0, 0.0)),
            Plan::PrincipalSpin { axis: 1 }
        );
        assert_eq!(
            plan(DVec3::new(1.0, 1.0, 1.5), DVec3::new(0.3, 0.0, 1.0)),
            Plan::Symmetric { axis: 2 }
        );
        assert_eq!(plan(asym, DVec3::new(0.1, 2.0, 0.0)), Plan::Asymmetric);
    }

    #[test]
    fn stepping_methods_are_run_as_chosen() {
        let rk4 = FreeBodyMethod::Rk4;
        let state = PrincipalState {
            world_from_principal: DQuat::IDENTITY,
            l_principal: DVec3::ZERO,
        };
        let (plan, _) = Motion::free(rk4, DVec3::ONE, state, Dd::from_f64(0.0)).unwrap();
        assert_eq!(plan, Plan::Stepping(rk4));
        assert_eq!(
            plan.to_string(),
            "free body stepped by rk4 (order 4) every dt (the method chosen)"
        );
    }
}
