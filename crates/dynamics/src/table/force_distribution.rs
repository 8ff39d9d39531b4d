//! The contact forces of contacts that overconstrain the body: two
//! sticking contacts (a body pivoting about the line through them, or at
//! rest on both) fix fewer degrees of freedom than they have force
//! components, so their forces are not unique — the accelerations are,
//! and the forces that differ by a null-space vector `Σ z_k n_k` of the
//! mode system give the same total wrench. Of those forces this takes the
//! one deepest inside every cone: the largest margin `s`,
//!
//! ```text
//! maximise s over (z, s):   x = x₀ + Σ z_k n_k,
//!   N_i(x) ≥ s                          every closed contact
//!   μ_i N_i(x) − |T_i(x)| ≥ s           every sticking contact (friction cone)
//!   N_i(x) − |R_i(x)| ≥ s               every holding rolling resistance
//! ```
//!
//! a second-order cone program (Boyd & Vandenberghe, *Convex
//! Optimization*, 2004, §11: the barrier method). The sticking persists
//! while `s ≥ 0`: some admissible distribution exists; it ends where none
//! does, and the margin is then the event's continuous measure. The
//! optimum is bounded on a table: a null vector carries no net normal
//! force, so some normal decreases along it.
//!
//! Hand-written: a handful of unknowns (the null space is 1 to 6
//! dimensional) solved in every right-hand side where it is singular; a
//! conic solver crate (Clarabel) would bring its own linear algebra for
//! a problem of this size.

use super::dense::{dot, solve_in_place};

/// One contact's cone in the unknowns of a mode system.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Cone {
    /// The index of its normal unknown `N`.
    pub(crate) normal: usize,
    /// The indices of the components bounded by the cone.
    pub(crate) bounded: [usize; 3],
    /// How many of `bounded` (0: only `N ≥ s`).
    pub(crate) count: usize,
    /// The cone's opening: `|x_bounded| ≤ factor · N` (μ, or 1 for the
    /// rolling resistance, whose torque δ x_R is counted in `x_R`).
    pub(crate) factor: f64,
}

/// The relative duality gap at which the barrier method stops.
const GAP: f64 = 1e-14;

/// The Newton decrement at which a point counts as centred.
const CENTRED: f64 = 1e-10;

/// `x₀ + Σ z_k n_k` with the largest margin over `cones`, and that
/// margin.
///
/// ```text
/// minimise  −t s − Σ log(N_i − s) − Σ log((c_i N_i − s)² − |B_i|²),   t → ∞
/// ```
///
/// by Newton's method with a backtracking line search that keeps every
/// constraint strictly satisfied, `t` multiplied by 16 per stage until
/// the gap (constraints)/t is below [`GAP`] times the forces' scale.
pub(crate) fn largest_margin(x0: &[f64], null: &[Vec<f64>], cones: &[Cone]) -> (Vec<f64>, f64) {
    let k = null.len();
    let at = |u: &[f64]| {
        let mut x = x0.to_vec();
        for (n, z) in null.iter().zip(u) {
            x.iter_mut().zip(n).for_each(|(x, n)| *x += z * n);
        }
        x
    };
    let margin = |x: &[f64]| {
        cones.iter().fold(f64::INFINITY, |m, c| {
            let b = (0..c.count).map(|j| x[c.bounded[j]].powi(2)).sum::<f64>();
            m.min(x[c.normal]).min(if c.count > 0 {
                c.factor * x[c.normal] - b.sqrt()
            } else {
                f64::INFINITY
            })
        })
    };
    let scale = x0.iter().fold(f64::MIN_POSITIVE, |m, v| m.max(v.abs()));
    if k == 0 || cones.is_empty() {
        return (x0.to_vec(), margin(x0));
    }
    // u = (z, s); strictly feasible at z = 0 below the current margin.
    let n1 = k + 1;
    let mut u = vec![0.0; n1];
    u[k] = margin(x0) - scale;
    // Each constraint's affine parts `c + g·u` (n1 + 1 numbers: c, g):
    // per cone the normal's `N − s`, and with a cone `c N − s` and the
    // bounded components.
    let affine = |j: usize, factor: f64, s_coefficient: f64| {
        let mut v = Vec::with_capacity(n1 + 1);
        v.push(factor * x0[j]);
        v.extend(null.iter().map(|n| factor * n[j]));
        v.push(s_coefficient);
        v
    };
    let linear: Vec<Vec<f64>> = cones.iter().map(|c| affine(c.normal, 1.0, -1.0)).collect();
    let conic: Vec<(Vec<f64>, Vec<Vec<f64>>)> = cones
        .iter()
        .filter(|c| c.count > 0)
        .map(|c| {
            let bounded = (0..c.count)
                .map(|j| affine(c.bounded[j], 1.0, 0.0))
                .collect();
            (affine(c.normal, c.factor, -1.0), bounded)
        })
        .collect();
    let constraints = (linear.len() + conic.len()) as f64;
    let eval = |a: &[f64], u: &[f64]| a[0] + dot(&a[1..], u);
    // The barrier's value, gradient and Hessian at `u` (None outside).
    let barrier = |u: &[f64], grad: &mut [f64], hess: &mut [f64], df: &mut [f64]| -> Option<f64> {
        grad.iter_mut().for_each(|g| *g = 0.0);
        hess.iter_mut().for_each(|h| *h = 0.0);
        let mut value = 0.0;
        for l in &linear {
            let (a, da) = (eval(l, u), &l[1..]);
            if a.is_nan() || a <= 0.0 {
                return None;
            }
            value -= a.ln();
            for p in 0..n1 {
                grad[p] -= da[p] / a;
                for q in 0..n1 {
                    hess[p * n1 + q] += da[p] * da[q] / (a * a);
                }
            }
        }
        // f = a² − |b|² > 0 with a > 0.
        for (al, bounded) in &conic {
            let (a, da) = (eval(al, u), &al[1..]);
            let f = a * a - bounded.iter().map(|b| eval(b, u).powi(2)).sum::<f64>();
            if a.is_nan() || a <= 0.0 || f.is_nan() || f <= 0.0 {
                return None;
            }
            value -= f.ln();
            df.iter_mut().zip(da).for_each(|(g, d)| *g = 2.0 * a * d);
            for bl in bounded {
                let b = eval(bl, u);
                df.iter_mut()
                    .zip(&bl[1..])
                    .for_each(|(g, d)| *g -= 2.0 * b * d);
            }
            for p in 0..n1 {
                grad[p] -= df[p] / f;
                for q in 0..n1 {
                    let mut d2f = 2.0 * da[p] * da[q];
                    for bl in bounded {
                        d2f -= 2.0 * bl[1 + p] * bl[1 + q];
                    }
                    hess[p * n1 + q] += -d2f / f + df[p] * df[q] / (f * f);
                }
            }
        }
        Some(value)
    };
    let mut grad = vec![0.0; n1];
    let mut hess = vec![0.0; n1 * n1];
    let mut df = vec![0.0; n1];
    let mut step = vec![0.0; n1];
    let mut trial = vec![0.0; n1];
    let mut scratch = (vec![0.0; n1], vec![0.0; n1 * n1]);
    let mut t = constraints / scale;
    while constraints / t > GAP * scale {
        for _newton in 0..100 {
            let Some(value) = barrier(&u, &mut grad, &mut hess, &mut df) else {
                break;
            };
            grad[k] -= t;
            let objective = value - t * u[k];
            step.iter_mut().zip(&grad).for_each(|(d, g)| *d = -g);
            if !solve_in_place(&mut hess, &mut step, n1) {
                break;
            }
            // Newton decrement λ² = −∇φ·Δu (the objective's distance from
            // the centre, in the barrier's units): centred enough below
            // 1e-10, past which rounding stalls the line search.
            let decrement = -dot(&grad, &step);
            if decrement.is_nan() || decrement <= CENTRED {
                break;
            }
            let mut alpha = 1.0;
            loop {
                trial
                    .iter_mut()
                    .zip(&u)
                    .zip(&step)
                    .for_each(|((v, u), d)| *v = u + alpha * d);
                if let Some(v) = barrier(&trial, &mut scratch.0, &mut scratch.1, &mut df)
                    && v - t * trial[k] <= objective - 0.25 * alpha * decrement
                {
                    break;
                }
                alpha *= 0.5;
                if alpha < 1e-12 {
                    break;
                }
            }
            if alpha < 1e-12 {
                break;
            }
            u.copy_from_slice(&trial);
        }
        t *= 16.0;
    }
    let x = at(&u);
    let m = margin(&x);
    (x, m)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two contacts each pressed with N = 5 whose frictions must add up
    /// to `total` (x = (N₁, T₁, N₂, T₂), the null vector (0, 1, 0, −1)/√2),
    /// μ = 0.5: the margins 2.5 − |T_i| are largest at T₁ = T₂ = total/2.
    fn shared_friction(total: f64) -> (Vec<f64>, f64) {
        let r = std::f64::consts::FRAC_1_SQRT_2;
        let cone = |n, t| Cone {
            normal: n,
            bounded: [t, 0, 0],
            count: 1,
            factor: 0.5,
        };
        largest_margin(
            &[5.0, total, 5.0, 0.0],
            &[vec![0.0, r, 0.0, -r]],
            &[cone(0, 1), cone(2, 3)],
        )
    }

    #[test]
    fn the_friction_is_shared_to_the_largest_margin() {
        let (x, s) = shared_friction(2.0);
        assert!(
            (x[1] - 1.0).abs() < 1e-12 && (x[3] - 1.0).abs() < 1e-12,
            "{x:?}"
        );
        assert!((s - 1.5).abs() < 1e-12, "{s}");
        assert_eq!((x[0], x[2]), (5.0, 5.0));
    }

    #[test]
    fn no_admissible_share_has_a_negative_margin() {
        // T₁ + T₂ = 6 > 2 μ N: the best is T₁ = T₂ = 3, 0.5 outside.
        let (x, s) = shared_friction(6.0);
        assert!(
            (x[1] - 3.0).abs() < 1e-12 && (x[3] - 3.0).abs() < 1e-12,
            "{x:?}"
        );
        assert!((s + 0.5).abs() < 1e-12, "{s}");
    }

    #[test]
    fn a_normal_shared_between_two_contacts_is_split_evenly() {
        // N₁ + N₂ = 4 (null vector (1, −1)/√2), no friction: N = 2 each.
        let r = std::f64::consts::FRAC_1_SQRT_2;
        let normal = |n| Cone {
            normal: n,
            bounded: [0; 3],
            count: 0,
            factor: 0.0,
        };
        let (x, s) = largest_margin(&[4.0, 0.0], &[vec![r, -r]], &[normal(0), normal(1)]);
        assert!(
            (x[0] - 2.0).abs() < 1e-12 && (x[1] - 2.0).abs() < 1e-12,
            "{x:?}"
        );
        assert!((s - 2.0).abs() < 1e-12);
    }
}
