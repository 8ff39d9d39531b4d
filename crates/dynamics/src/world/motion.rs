//! The motion that carries a body's [`Plan`] out, from the state when the
//! plan was made: a resting body, a slot of the world's uniform batch, an
//! exact solution, a stepping method, a heavy top, a Lagrange top's closed
//! form, a body under inputs, a body on the ground or on the table.

use std::fmt;

use super::ground_motion::GroundMotion;
use super::plan::Plan;
use super::table_run::TableRun;
use super::uniform::UniformBatch;
use crate::elliptic::dd::Dd;
use crate::exact::ExactKind;
use crate::{
    DivergenceCheck, DynamicsError, ExactSolution, ForcedBody, ForcedSplitting, ForcedState,
    FreeBodyMethod, HeavyTopClosedForm, HeavyTopIntegrator, HeavyTopMethod, PrincipalState,
    Propagator,
};

/// The motion that carries a plan out, from the state when it was made.
pub(crate) enum Motion {
    /// The state never changes: `state` is the one given, `settled` the
    /// exact solution's own (attitude normalised), reported once the world
    /// has moved on.
    Resting {
        state: PrincipalState,
        settled: PrincipalState,
    },
    /// A uniform rotation (sphere, principal spin), evaluated in the
    /// world's batch: its slot there.
    Uniform { slot: usize },
    /// The exact solution from the world time `start`, and its last value.
    Exact {
        solution: ExactSolution,
        start: Dd,
        state: PrincipalState,
    },
    /// A free-body propagator.
    Stepping(Box<dyn Propagator>),
    /// A heavy top: its state, stepped by `integrator` (the world's
    /// heavy-top method, or the Taylor series a tolerance chose).
    HeavyTop {
        state: PrincipalState,
        integrator: &'static (dyn HeavyTopIntegrator + Sync),
    },
    /// A Lagrange top's closed form from the world time `start`, and its
    /// last value.
    LagrangeTop {
        closed: Box<HeavyTopClosedForm>,
        start: Dd,
        state: PrincipalState,
    },
    /// A body under inputs, or a heavy top under a tolerance.
    Forced(ForcedMotion),
    /// A body on the ground plane: its contact model and state.
    Ground(Box<GroundMotion>),
    /// A body on the table: its nonsmooth run.
    Table(Box<TableRun>),
}

/// A body under inputs (or a heavy top under a tolerance) as the world
/// moves it: the splitting, its sub-steps, the body with its loads, the
/// state, and `|q|` when the plan was made (the checks' reference).
pub(crate) struct ForcedMotion {
    method: ForcedSplitting,
    substeps: u32,
    /// Whether each step takes at least the sub-steps its stability needs
    /// ([`ForcedBody::stable_substeps`]: heavy tops under `auto`).
    stabilise: bool,
    body: Box<ForcedBody>,
    pub(crate) state: ForcedState,
    q_norm: f64,
}

impl ForcedMotion {
    /// One step of `h` from time `t`: `substeps` equal sub-steps (at least
    /// the stable number if `stabilise`), each checked as
    /// [`crate::ForcedPropagator::try_advance`] checks.
    ///
    /// # Errors
    /// [`DynamicsError::TooManySubsteps`] from the stability limit;
    /// [`DynamicsError::Diverged`] from a sub-step.
    pub(crate) fn step(&mut self, t: f64, h: f64) -> Result<(), DynamicsError> {
        let n = if self.stabilise {
            self.substeps
                .max(self.body.stable_substeps(&self.state, h)?)
        } else {
            self.substeps
        };
        let sub = h / f64::from(n);
        for j in 0..n {
            let t = t + f64::from(j) * sub;
            self.state = crate::forced::checked_step(
                self.method,
                &self.body,
                &self.state,
                t,
                sub,
                self.q_norm,
            )?;
        }
        Ok(())
    }
}

impl fmt::Debug for Motion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Motion::Uniform { slot } => f.debug_struct("Uniform").field("slot", slot).finish(),
            other => f
                .debug_tuple("Motion")
                .field(&other.state(&UniformBatch::default()))
                .finish(),
        }
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
            let propagator = method.integrator().propagator(moments, state);
            return Ok((Plan::Stepping(method), Motion::Stepping(propagator)));
        }
        let solution = ExactSolution::try_new(moments, state)?;
        if state.l_principal == glam::DVec3::ZERO {
            // ω t = 0 at every t: the exact solution at any time is its
            // value at 0, computed once.
            let settled = solution.state_at(0.0);
            DivergenceCheck::free_body(FreeBodyMethod::Exact.name(), moments, &state)
                .check(&settled, 0.0)?;
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
        let integrator = method.integrator();
        (
            Plan::HeavyTop(method),
            Motion::HeavyTop { state, integrator },
        )
    }

    /// The motion of a body under inputs (or a heavy top under a
    /// tolerance), moved by `substeps` steps of `method` per step of the
    /// world (at least the stable number if `stabilise`).
    pub(crate) fn forced(
        method: ForcedSplitting,
        substeps: u32,
        stabilise: bool,
        body: ForcedBody,
        state: ForcedState,
    ) -> Motion {
        Motion::Forced(ForcedMotion {
            method,
            substeps,
            stabilise,
            body: Box::new(body),
            q_norm: state.rotation.world_from_principal.length(),
            state,
        })
    }

    /// The current state (`batch`: the world's uniform rotations).
    pub(crate) fn state(&self, batch: &UniformBatch) -> PrincipalState {
        match self {
            Motion::Uniform { slot } => {
                let (world_from_principal, l_principal) = batch.state(*slot);
                PrincipalState {
                    world_from_principal,
                    l_principal,
                }
            }
            Motion::Resting { state, .. } | Motion::HeavyTop { state, .. } => *state,
            Motion::Exact { state, .. } | Motion::LagrangeTop { state, .. } => *state,
            Motion::Stepping(propagator) => propagator.state(),
            Motion::Forced(forced) => forced.state.rotation,
            Motion::Ground(ground) => ground.principal_state(),
            Motion::Table(table) => table.principal_state(),
        }
    }

    /// Whether a move visits this motion in the world's `moving` list:
    /// every motion but a resting body and a uniform rotation (in the
    /// batch, or an exact solution that will be put there).
    pub(crate) fn is_moving(&self) -> bool {
        match self {
            Motion::Resting { .. } | Motion::Uniform { .. } => false,
            Motion::Exact { solution, .. } => solution.uniform_parts().is_none(),
            _ => true,
        }
    }

    /// A forced body's state and body (`None` for the other motions).
    pub(crate) fn forced_state(&self) -> Option<(&ForcedBody, &ForcedState)> {
        match self {
            Motion::Forced(forced) => Some((&forced.body, &forced.state)),
            _ => None,
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
