//! The discrete Moser–Veselov algorithm (DMV) for the free rigid body, in
//! the quaternion form of Hairer & Vilmart, J. Phys. A 39 (2006) 13225:
//! one implicit equation for the Cayley vector of the step rotation, solved
//! by Newton's method to rounding level.
//!
//! Derivation, in principal axes with `L` the body angular momentum: the
//! step rotation is the unit quaternion `p = (1, c)/√(1 + |c|²)` (a
//! Cayley transform), and the Moser–Veselov equations `M = Ωᵀ J − J Ω`,
//! `M' = Ω M Ωᵀ` become, for the vector `c`,
//!
//! ```text
//! I c + c × (I c) = (h/2) (1 + |c|²) L        (implicit, solved for c)
//! I c − c × (I c) = (h/2) (1 + |c|²) L'       (so L' = p̄ L p)
//! ```
//!
//! Scaled by `I⁻¹` componentwise, with `b = (h/2) I⁻¹ L` and
//! `γᵢ = (Iⱼ − Iₖ)/Iᵢ` for cyclic `(i, j, k)`:
//! `cᵢ = (1 + |c|²) bᵢ + γᵢ cⱼ cₖ`. Since `|γᵢ| ≤ 1` for a physical body
//! and `c = O(h)`, Newton's method from the Taylor series of `c` to `h⁵`
//! converges in one or two iterations.

use glam::{DQuat, DVec3};

use crate::rigid_body::moment_scale;
use crate::{FreeBodyIntegrator, PrincipalState};

/// Most Newton iterations per step; one or two suffice at `|h ω| ≤ 0.5`.
const MAX_NEWTON: usize = 12;

/// The symmetric bilinear form of the product term, `B(c, c) = P(c)`,
/// `P(c)ᵢ = γᵢ cⱼ cₖ`.
#[inline]
fn bilinear(gamma: DVec3, u: DVec3, v: DVec3) -> DVec3 {
    0.5 * gamma
        * DVec3::new(
            u.y * v.z + v.y * u.z,
            u.z * v.x + v.z * u.x,
            u.x * v.y + v.x * u.y,
        )
}

/// The product term `P(c)ᵢ = γᵢ cⱼ cₖ` of the scaled DMV equation.
#[inline]
fn product_term(gamma: DVec3, c: DVec3) -> DVec3 {
    gamma * DVec3::new(c.y * c.z, c.z * c.x, c.x * c.y)
}

/// The solution's Taylor series in `h` to `O(h⁵)`, error `O(h⁶)`:
/// `c = c₁ + … + c₅` with `cₙ = O(hⁿ)` from `G(c) = 0` order by order.
///
/// ```text
/// c₁ = b,   c₂ = B(b, b),   c₃ = |b|² b + 2B(b, c₂),
/// c₄ = 2(b·c₂) b + 2B(b, c₃) + B(c₂, c₂),
/// c₅ = (2 b·c₃ + |c₂|²) b + 2B(b, c₄) + 2B(c₂, c₃)
/// ```
#[inline]
fn initial_guess(b: DVec3, gamma: DVec3) -> DVec3 {
    let c2 = product_term(gamma, b);
    let c3 = b.length_squared() * b + 2.0 * bilinear(gamma, b, c2);
    let c4 = 2.0 * b.dot(c2) * b + 2.0 * bilinear(gamma, b, c3) + product_term(gamma, c2);
    let c5 = (2.0 * b.dot(c3) + c2.length_squared()) * b
        + 2.0 * (bilinear(gamma, b, c4) + bilinear(gamma, c2, c3));
    b + (c2 + (c3 + (c4 + c5)))
}

/// Solves `cᵢ = (1 + |c|²) bᵢ + γᵢ cⱼ cₖ` by Newton's method from the
/// series [`initial_guess`].
///
/// Returns `None` if the iteration produced a non-finite vector or a
/// singular Jacobian, or had not converged after `MAX_NEWTON` iterations
/// (steps far beyond `|h ω| ~ 1`, or unphysical moments). All the
/// quantities are pure numbers (`b = (h/2) I⁻¹L`, `γ`), so the tolerances
/// are relative and the same in every unit system.
///
/// Stopping rule: Newton's error after an update `δ` is about
/// `κ |δ|²` with `κ = max|γᵢ| + 2|b|` (the size of the second derivative
/// of the equation); iteration stops once that is below a quarter ulp of
/// `|c|`, or once the update stops shrinking (rounding noise). From the
/// `O(h⁶)` guess that is one iteration at `|c| ≲ 0.02` (`h ω ≲ 0.04`),
/// two up to `|c| ≈ 0.2`.
#[inline]
pub(crate) fn solve_cayley(b: DVec3, gamma: DVec3) -> Option<DVec3> {
    let mut c = initial_guess(b, gamma);
    let kappa = gamma.abs().max_element() + 2.0 * b.length();
    let mut last = f64::INFINITY;
    let mut done = false;
    for _ in 0..MAX_NEWTON {
        let alpha = 1.0 + c.length_squared();
        let residual = c - alpha * b - product_term(gamma, c);
        // Jacobian columns ∂G/∂cⱼ of G(c) = c − (1 + |c|²) b − P(c).
        let a0 = DVec3::X - 2.0 * c.x * b - DVec3::new(0.0, gamma.y * c.z, gamma.z * c.y);
        let a1 = DVec3::Y - 2.0 * c.y * b - DVec3::new(gamma.x * c.z, 0.0, gamma.z * c.x);
        let a2 = DVec3::Z - 2.0 * c.z * b - DVec3::new(gamma.x * c.y, gamma.y * c.x, 0.0);
        let a12 = a1.cross(a2);
        let det = a0.dot(a12);
        if !(det.is_finite() && det != 0.0) {
            return None;
        }
        // Cramer's rule for J δ = −G.
        let r = -residual;
        let delta = DVec3::new(r.dot(a12), a0.dot(r.cross(a2)), a0.dot(a1.cross(r))) * (1.0 / det);
        c += delta;
        let size = delta.abs().max_element();
        if !size.is_finite() {
            return None;
        }
        let scale = c.abs().max_element();
        let converged = kappa * size * size <= 0.25 * f64::EPSILON * scale;
        let stalled = size >= last && size <= 1e-8 * scale;
        if converged || stalled || size == 0.0 {
            done = true;
            break;
        }
        last = size;
    }
    // Newton still moving after MAX_NEWTON iterations has found no
    // solution (the step is beyond the method's range): never a guess.
    (done && c.is_finite()).then_some(c)
}

/// One DMV step with the inverse moments `s / Iₖ + d` (`s = 1`, `d = 0`
/// for DMV itself): solve for `c`, then `q ← q ⊗ p`, `L ← p̄ L p`. A step
/// whose implicit equation has no usable solution (`|h ω|` far beyond 1)
/// leaves a NaN state, for the caller's divergence check to report.
///
/// Nondimensional: `moments` are in the body's unit of inertia
/// ([`crate::rigid_body::moment_scale`], the largest in `[1, 2)`), `d` in
/// its inverse; `L` is divided by `unit` here and multiplied back (both
/// exact), so `b`, `γ` and `c` are pure numbers whatever the unit system.
///
/// Two divisions for the moments: with `P = I₁I₂I₃`, `1/Iᵢ = IⱼIₖ/P`; and
/// with `Ĩᵢ⁻¹ = s/Iᵢ + d`, `γᵢ = (Ĩⱼ − Ĩₖ) Ĩᵢ⁻¹ = s (Iⱼ − Iₖ) Iᵢ Ĩᵢ⁻² / (P Π Ĩ⁻¹)`
/// (the differences `Iⱼ − Iₖ` taken of the moments themselves).
#[inline]
pub(crate) fn dmv_step(
    moments: DVec3,
    unit: f64,
    s: f64,
    d: f64,
    state: &mut PrincipalState,
    h: f64,
) {
    let m = moments;
    let inv_p = 1.0 / (m.x * m.y * m.z);
    let inv = s * inv_p * DVec3::new(m.y * m.z, m.z * m.x, m.x * m.y) + d;
    let diff = DVec3::new(m.y - m.z, m.z - m.x, m.x - m.y);
    let gamma = if d == 0.0 {
        // Ĩ = I / s: γᵢ = (Iⱼ − Iₖ)/Iᵢ, no further division.
        diff * inv * (1.0 / s)
    } else {
        diff * m * inv * inv * (s * inv_p / (inv.x * inv.y * inv.z))
    };
    let l = state.l_principal / unit;
    let b = (0.5 * h) * inv * l;
    let Some(c) = solve_cayley(b, gamma) else {
        *state = PrincipalState {
            world_from_principal: DQuat::NAN,
            l_principal: DVec3::NAN,
        };
        return;
    };
    let alpha = 1.0 + c.length_squared();
    // 1/α and √α side by side, then 1/√α = √α/α: no sqrt after a division.
    let (inv_alpha, root) = (1.0 / alpha, alpha.sqrt());
    // L' = R(p)ᵀ L = L + (2/α) (c × (c × L) − c × L).
    let t = c.cross(l);
    let l_new = l + (2.0 * inv_alpha) * (c.cross(t) - t);
    let w = root * inv_alpha;
    let p = DQuat::from_xyzw(c.x * w, c.y * w, c.z * w, w);
    state.l_principal = l_new * unit;
    state.world_from_principal *= p;
}

/// The discrete Moser–Veselov algorithm (Moser & Veselov, Commun. Math.
/// Phys. 139 (1991) 217), quaternion form after Hairer & Vilmart, J. Phys.
/// A 39 (2006) 13225, order 2.
///
/// ```text
/// solve  I c + c × (I c) = (h/2)(1 + |c|²) L   for c,   p = (1, c)/√(1 + |c|²)
/// q ← q ⊗ p,   L ← p̄ L p
/// ```
///
/// Conserves `|L|` and `L_world` (one rotation each way) and the energy
/// `½ Σ Lₖ²/Iₖ` exactly up to rounding and the solve: its `L` moves on the
/// exact orbit, at a slightly wrong speed (McLachlan & Zanna, Found. Comput.
/// Math. 5 (2005) 87), which the preprocessed versions correct
/// ([`crate::PreprocessedMoserVeselov`]).
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{FreeBodyIntegrator, MoserVeselov, PrincipalState};
/// let moments = DVec3::new(1.0, 2.0, 3.0);
/// let mut s = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.3, 2.0, -0.5) };
/// let energy = |l: DVec3| 0.5 * (l * l / moments).element_sum();
/// let (e0, n0) = (energy(s.l_principal), s.l_principal.length());
/// for _ in 0..1000 {
///     MoserVeselov.step(moments, &mut s, 0.1);
/// }
/// assert!((energy(s.l_principal) - e0).abs() < 1e-13);
/// assert!((s.l_principal.length() - n0).abs() < 1e-13);
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct MoserVeselov;

impl MoserVeselov {
    /// Its [`FreeBodyIntegrator::name`], which
    /// [`crate::PreprocessedMoserVeselov`] of order 2 (DMV itself) shares.
    pub(crate) const NAME: &str = "dmv";
    /// Its [`FreeBodyIntegrator::description`], which
    /// [`crate::PreprocessedMoserVeselov`] of order 2 (DMV itself) shares.
    pub(crate) const DESCRIPTION: &str =
        "discrete Moser-Veselov (implicit, conserves |L|, L_world and a modified energy)";
    /// Its [`FreeBodyIntegrator::step_limit`] (`h ω_max`), which
    /// [`crate::PreprocessedMoserVeselov`] of order 2 shares.
    pub(crate) const STEP_LIMIT: f64 = 1.0;
}

impl FreeBodyIntegrator for MoserVeselov {
    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn order(&self) -> u32 {
        2
    }

    fn description(&self) -> &'static str {
        Self::DESCRIPTION
    }

    /// 1.0: beyond it the implicit step fails (no finite state).
    fn step_limit(&self) -> Option<f64> {
        Some(Self::STEP_LIMIT)
    }

    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64) {
        let unit = moment_scale(moments);
        dmv_step(moments / unit, unit, 1.0, 0.0, state, h);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Newton stopping rule stops at the fully converged solution: one
    /// more Newton update changes `c` by at most an ulp or two.
    #[test]
    fn newton_stops_at_rounding_level() {
        let gamma = DVec3::new(-0.5, 1.0, -1.0 / 3.0);
        for scale in [1e-3, 1e-2, 0.1, 0.3] {
            let b = scale * DVec3::new(0.4, -0.7, 0.55);
            let c = solve_cayley(b, gamma).unwrap();
            let alpha = 1.0 + c.length_squared();
            let residual = c - alpha * b - product_term(gamma, c);
            assert!(
                residual.abs().max_element() <= 4.0 * f64::EPSILON * c.abs().max_element(),
                "{scale}: residual {residual:?}"
            );
        }
    }

    /// The two forms of `L'` agree: `p̄ L p` and `(2/(hα))(I c − c × I c)`.
    #[test]
    fn rotation_form_matches_the_moser_veselov_update() {
        let moments = DVec3::new(0.6, 0.8, 1.0);
        let l = DVec3::new(1.8, 0.4, -0.9);
        let h = 0.2;
        let mut s = PrincipalState {
            world_from_principal: DQuat::IDENTITY,
            l_principal: l,
        };
        MoserVeselov.step(moments, &mut s, h);
        let c = s.world_from_principal.xyz() / s.world_from_principal.w;
        let alpha = 1.0 + c.length_squared();
        let w = moments * c;
        let l_new = (2.0 / (h * alpha)) * (w - c.cross(w));
        let l_old = (2.0 / (h * alpha)) * (w + c.cross(w));
        assert!(
            (l_new - s.l_principal).length() < 1e-14,
            "{l_new} {}",
            s.l_principal
        );
        assert!((l_old - l).length() < 1e-14);
    }
}
