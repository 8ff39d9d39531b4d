//! The free-body part of the heavy-top splittings: the exact flow where it
//! is a rotation or two, preprocessed Moser–Veselov of order 10 otherwise.

use glam::DVec3;

use crate::splitting::{axis_flow, casimir_flow};
use crate::{FreeBodyIntegrator, PreprocessedMoserVeselov, PrincipalState};

/// How the kinetic flow `½ L·J⁻¹L` is advanced.
///
/// - two or three equal moments: **exact**, the Casimir rotation about `L`
///   and a rotation about the symmetry axis, which commute (notes §3.7);
/// - three distinct moments: PDMV of order 10 (Hairer & Vilmart 2006). The
///   exact elliptic solution (`ExactSolution`) needs its tables rebuilt from
///   every new state (tens of µs), which a splitting, whose free flow starts
///   from a new state after every kick, cannot amortise; PDMV10's local
///   error `O(h¹¹)` is below rounding at the sub-steps the compositions take
///   (`tests/heavy_top_reference.rs`).
#[derive(Debug, Clone)]
pub(crate) enum FreeFlow {
    /// `J_a = J_b = perpendicular` for the two axes other than `axis`.
    Symmetric {
        axis: usize,
        perpendicular: f64,
        c: f64,
    },
    /// PDMV10 prepared for the moments.
    Pdmv(Box<PreprocessedMoserVeselov>),
}

impl FreeFlow {
    /// The flow for principal moments `moments`.
    pub(crate) fn for_moments(moments: DVec3) -> Self {
        let m = moments.to_array();
        match (0..3).find(|&k| m[(k + 1) % 3] == m[(k + 2) % 3]) {
            Some(axis) => {
                let perpendicular = m[(axis + 1) % 3];
                FreeFlow::Symmetric {
                    axis,
                    perpendicular,
                    c: 1.0 / m[axis] - 1.0 / perpendicular,
                }
            }
            None => FreeFlow::Pdmv(Box::new(
                PreprocessedMoserVeselov::ORDER_10.for_body(moments),
            )),
        }
    }

    /// Advances `state` by the free flow for time `h`.
    ///
    /// ```text
    /// symmetric: q ← q ⊗ exp(h L/J⊥) ⊗ exp(h (1/J_k − 1/J⊥) L_k eₖ),  L ← Rₖ(−h (1/J_k − 1/J⊥) L_k) L
    /// ```
    #[inline]
    pub(crate) fn apply(&self, moments: DVec3, state: &mut PrincipalState, h: f64) {
        match self {
            FreeFlow::Symmetric {
                axis,
                perpendicular,
                c,
            } => {
                casimir_flow(*perpendicular, state, h);
                if *c != 0.0 {
                    axis_flow(*axis, *c, state, h);
                }
            }
            FreeFlow::Pdmv(pdmv) => pdmv.step(moments, state, h),
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::DQuat;

    use super::*;
    use crate::ExactSolution;

    /// The free flow against the exact solution, symmetric and asymmetric.
    #[test]
    fn matches_the_exact_solution() {
        let s0 = PrincipalState {
            world_from_principal: DQuat::from_rotation_y(0.4),
            l_principal: DVec3::new(0.3, -0.2, 1.5),
        };
        for moments in [
            DVec3::new(1.0, 1.0, 0.5),
            DVec3::new(0.5, 1.0, 1.0),
            DVec3::new(1.0, 1.2, 1.5),
        ] {
            let flow = FreeFlow::for_moments(moments);
            let exact = ExactSolution::try_new(moments, s0).unwrap().state_at(0.01);
            let mut s = s0;
            flow.apply(moments, &mut s, 0.01);
            let angle = kreisel_kinematics::rotation_angle_between(
                s.world_from_principal,
                exact.world_from_principal,
            );
            assert!(angle < 1e-15, "{moments}: {angle}");
            assert!((s.l_principal - exact.l_principal).length() < 1e-15);
        }
    }
}
