//! The mean precession rate of a thin nutation band, expanded about its
//! centre `u_c = (u₁ + u₂)/2` (used by `mean_precession_rate` when it is the
//! more accurate of the two forms).
//!
//! With `u = u_c + δ`, `h(u) = 1/(1 − u²)` and `r(u) = b − a u = r_c − a δ`,
//! and the exact divided difference `h(u) − h_c = δ (u + u_c) h(u) h_c`:
//!
//! ```text
//! φ̇ = r(u) h(u) = r_c h(u) − a h_c δ − a h_c δ² (u + u_c) h(u)
//! ⟨φ̇⟩ = ⟨r_c h(u) − a h_c δ² (u + u_c) h(u)⟩ − a h_c ⟨δ⟩
//! δ = σ (Δ/2) (sn² − cn²),  ⟨δ⟩ = σ (Δ/2) (2⟨sn²⟩ − 1),  ⟨sn²⟩ = (K − E)/(m K)
//! 2⟨sn²⟩ − 1 = (π/2)/K · Σ_{j≥1} c_j² j/(j + 1) mʲ,  c_j = (2j)!/(4ʲ j!²)
//! ```
//!
//! (the series from those of K and E, DLMF 19.5.1–2; every term positive).
//! For a fast top kicked in θ̇, φ̇ swings by far more than its mean, and the
//! turning-point form (`r₁/(2(1 − u₁)) + r₂/(2(1 + u₂))` plus rests) loses
//! `ε · swing/mean`; here the swing enters only through `δ²` (a positive,
//! smooth average, taken by the trapezoidal rule over one period of `sn²`,
//! which converges geometrically for a periodic analytic integrand) and the
//! tiny `⟨δ⟩ = O(m Δ)` in closed form. `r_c` is formed the better of two
//! ways (`LagrangeTopMotion::new`, by the sum of the magnitudes of the
//! terms): `½(r₁ + r₂)` (no cancellation when `r₁, r₂` share a sign), or from
//! the coefficients of the cubic, with no `a`-sized difference
//! (`u_c − u₀ = ½(w₁ + w₂)`, `A₀, B₀, c₀, c₁` as in `roots`):
//!
//! ```text
//! w₁ + w₂ = (c₁ + β c₀/g)/g   (f(u₀ + w) = (w − w₁)(w − w₂)(β w − g))
//! r_c = B₀ (g − a²)/g + a (β s² + 2u₀A₀)/(2g) − a β c₀/(2g²),  g − a² = A₀ − 2u₀β − β(w₁ + w₂)
//! ```

use super::motion::LagrangeTopMotion;
use crate::elliptic::{carlson_rd, carlson_rf};

/// Nodes of the trapezoidal rule over one period of `sn²` (its half, 16,
/// checks the convergence).
const NODES: usize = 32;

/// `2⟨sn²(· | m)⟩ − 1` over a period, `k` = K(m), `mc = 1 − m` (module docs).
pub(super) fn mean_sn2_excess(m: f64, mc: f64, k: f64) -> f64 {
    if m > 0.5 {
        return 2.0 * carlson_rd(0.0, mc, 1.0) / (3.0 * carlson_rf(0.0, mc, 1.0)) - 1.0;
    }
    let (mut c2, mut mj, mut sum) = (1.0, 1.0, 0.0);
    for j in 1..400 {
        let jf = j as f64;
        let cj = (2.0 * jf - 1.0) / (2.0 * jf);
        c2 *= cj * cj;
        mj *= m;
        let term = c2 * jf / (jf + 1.0) * mj;
        sum += term;
        if term <= 1e-18 * sum {
            break;
        }
    }
    std::f64::consts::FRAC_PI_2 / k * sum
}

/// `r_c = b − a u_c` from the coefficients of the shifted cubic (module
/// docs), with the sum of the magnitudes of its terms (its rounding scale).
#[allow(clippy::too_many_arguments)]
pub(super) fn centre_r_from_cubic(
    a: f64,
    beta: f64,
    u0: f64,
    s2: f64,
    a0: f64,
    b0: f64,
    c0: f64,
    g: f64,
    w_sum: f64,
) -> (f64, f64) {
    let g_minus_a2 = a0 - 2.0 * u0 * beta - beta * w_sum;
    let scale_g = a0.abs() + (2.0 * u0 * beta).abs() + (beta * w_sum).abs();
    let inner = beta * s2 + 2.0 * u0 * a0;
    let scale_inner = (beta * s2).abs() + (2.0 * u0 * a0).abs();
    let t1 = b0 * g_minus_a2 / g;
    let t2 = a * inner / (2.0 * g);
    let t3 = -a * beta * c0 / (2.0 * g * g);
    let scale = (b0 * scale_g / g).abs() + (a * scale_inner / (2.0 * g)).abs() + t3.abs();
    (t1 + t2 + t3, scale)
}

impl LagrangeTopMotion {
    /// The mean precession rate by the centre expansion (module docs), with
    /// an estimate of its absolute error; `None` if it cannot be formed.
    pub(super) fn thin_band_mean(&self) -> Option<(f64, f64)> {
        let (rc, rc_scale) = self.rc;
        let half = 0.5 * self.delta;
        let (omc, opc) = (self.one_minus_u2 + half, self.one_plus_u1 + half);
        if !(omc > 0.0 && opc > 0.0 && rc.is_finite() && rc_scale.is_finite()) {
            return None;
        }
        let hc = 1.0 / (omc * opc);
        let uc = self.u0 + 0.5 * (self.w1 + self.w2);
        let step = 2.0 * self.k / NODES as f64;
        // (Σ Q over all nodes, Σ Q over the even ones, Σ |terms|)
        let (mut all, mut even, mut abs) = (0.0, 0.0, 0.0);
        for j in 0..NODES {
            let (sn, cn, _) = self.jacobi.sn_cn_dn(j as f64 * step);
            let d = self.sigma * half * (sn * sn - cn * cn);
            let h = 1.0 / ((omc - d) * (opc + d));
            let first = rc * h;
            let second = self.a * hc * d * d * (2.0 * uc + d) * h;
            let q = first - second;
            all += q;
            if j % 2 == 0 {
                even += q;
            }
            abs += (rc_scale * h).abs() + second.abs();
        }
        let n = NODES as f64;
        let (mean, coarse) = (all / n, even / (0.5 * n));
        let excess = mean_sn2_excess(self.m, self.mc, self.k);
        let drift = self.a * hc * self.sigma * half * excess;
        let value = mean - drift;
        // Rounding of the terms summed, and the fine rule's miss: for a
        // geometrically converging rule it is about the square of the coarse
        // one's (relative to the size of the integrand), bounded by it.
        let miss = (mean - coarse).abs();
        let size = abs / n;
        let err = f64::EPSILON * (size + drift.abs()) + miss * (10.0 * miss / size).min(1.0);
        value.is_finite().then_some((value, err))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lagrange_top::third_kind::complete_k;
    use crate::lagrange_top::{LagrangeTop, LagrangeTopInitial};

    /// The series agrees with the closed form 2R_D/(3R_F) − 1 where both are
    /// accurate, and with its leading terms m/8 + m²/16 for small m.
    #[test]
    fn sn2_excess_series_and_closed_form() {
        for m in [0.05, 0.3, 0.5] {
            let mc = 1.0 - m;
            let series = mean_sn2_excess(m, mc, complete_k(mc));
            let closed = 2.0 * carlson_rd(0.0, mc, 1.0) / (3.0 * carlson_rf(0.0, mc, 1.0)) - 1.0;
            // the closed form cancels to ⟨y⟩ from ~1: a few ε absolute
            assert!((series - closed).abs() <= 1e-15, "{m}: {series} {closed}");
        }
        let m = 1e-6;
        let got = mean_sn2_excess(m, 1.0 - m, complete_k(1.0 - m));
        let lead = m / 8.0 + m * m / 16.0;
        assert!((got - lead).abs() <= 1e-11 * lead, "{got} {lead}");
        assert_eq!(mean_sn2_excess(0.0, 1.0, complete_k(1.0)), 0.0);
    }

    /// On ordinary bands (broad or narrow, either sign of β, with and
    /// without loops) the centre form matches φ(T) − φ(0) of the evaluated
    /// closed form over one period within its error estimate (which on a
    /// broad band is large, so `mean_precession_rate` keeps the other form).
    #[test]
    fn centre_form_matches_phi_over_a_period() {
        let cases = [
            (LagrangeTop::new(1.0, 0.5, 1.0), 0.5, 0.3, 0.2, 20.0),
            (LagrangeTop::new(1.0, 0.5, 1.0), 2.5, -0.3, -0.7, 3.0),
            (LagrangeTop::new(2.0, 0.3, -1.5), 2.0, 0.4, 0.1, 5.0),
            (LagrangeTop::new(2.0, 0.3, 1.5), 1.0, 0.0, 0.0, 5.0),
            (LagrangeTop::new(1.25, 0.5, 1.0), 0.5, 0.0, 0.3, 50.0),
        ];
        for (top, theta, phi_dot, theta_dot, psi_dot) in cases {
            let init = LagrangeTopInitial {
                theta,
                phi_dot,
                theta_dot,
                psi_dot,
                ..Default::default()
            };
            let motion = top.try_solve(init).unwrap();
            let t = motion.nutation_period().unwrap();
            let want = (motion.euler_at(t).phi - motion.euler_at(0.0).phi) / t;
            let (got, err) = motion.thin_band_mean().unwrap();
            let swing = (motion.r1.0 / (1.0 - (motion.u0 + motion.w1).powi(2))).abs()
                + (motion.r2.0 / (1.0 - (motion.u0 + motion.w2).powi(2))).abs();
            // φ(T) − φ(0) is itself good to a few ε · swing
            assert!(
                (got - want).abs() <= err + 1e-14 * swing,
                "{init:?}: {got} {want} {err:e}"
            );
            if psi_dot >= 20.0 {
                // the two fast tops' bands are thin: converged to rounding
                assert!(err <= 1e-15 * swing, "{init:?}: {err:e}");
            }
        }
    }
}
