//! The closed form's constants from the initial conditions
//! (`LagrangeTopMotion::new`, called by `LagrangeTop::try_solve`): the
//! turning points, the pole distances, the close passes, `r` at the turning
//! points and the band centre, the parameter and phase of `sn²`, and the
//! rests of φ and ψ (the formulas in the docs of [`LagrangeTopMotion`]).

use super::centre::centre_r_from_cubic;
use super::motion::{Kind, LagrangeTopMotion};
use super::passes::close_pass;
use super::roots::{ShiftedCubic, polish_pole_distance};
use super::third_kind::{ThirdKind, complete_k};
use super::{LagrangeTop, LagrangeTopInitial};
use crate::elliptic::{JacobiElliptic, carlson_rf};

/// Starts closer than this to π (rad) are put on the downward vertical:
/// π itself is not an f64, and the f64 nearest it (1.2·10⁻¹⁶ below) means
/// π. Near θ = 0 nothing is snapped: a start 10⁻¹⁵ rad from upright nutates
/// in a band of that size, continuous with 10⁻⁸ (the closed form resolves
/// `1 − cos θ₀ = 2 sin²(θ₀/2)` to full relative accuracy).
const POLE_SNAP: f64 = 2e-16;

fn sign(x: f64) -> f64 {
    if x < 0.0 { -1.0 } else { 1.0 }
}

impl LagrangeTopMotion {
    pub(super) fn new(top: LagrangeTop, initial: LagrangeTopInitial) -> LagrangeTopMotion {
        let pi = std::f64::consts::PI;
        // θ₀ ∈ [0, π] (checked by `LagrangeTop::try_solve`).
        let mut init = initial;
        // Within POLE_SNAP of π the start is put exactly on the downward
        // vertical (see `LagrangeTop::try_solve`); π itself is not an f64,
        // so the bottom is flagged and given sin θ₀ = 0, cos θ₀ = −1 exactly.
        let at_bottom = pi - init.theta < POLE_SNAP;
        if at_bottom {
            init.theta = pi;
        }
        let (th, phd, thd) = (init.theta, init.phi_dot, init.theta_dot);
        let (s0, u0) = if at_bottom { (0.0, -1.0) } else { th.sin_cos() };
        let s2 = s0 * s0;
        let (one_minus_u0, one_plus_u0) = if at_bottom {
            (2.0, 0.0)
        } else {
            (
                2.0 * (0.5 * th).sin().powi(2),
                2.0 * (0.5 * th).cos().powi(2),
            )
        };
        let omega3 = phd * u0 + init.psi_dot;
        let a = top.i3 * omega3 / top.i1;
        let beta = 2.0 * top.mgl / top.i1;
        let b0 = s2 * phd;
        let a0 = thd * thd + b0 * phd;
        let b = b0 + a * u0;
        let alpha = a0 + beta * u0;
        let bma = one_minus_u0 * (one_plus_u0 * phd - a);
        let bpa = one_plus_u0 * (one_minus_u0 * phd + a);
        let cubic = ShiftedCubic {
            beta,
            c2: 2.0 * u0 * beta - a0 - a * a,
            c1: -beta * s2 - 2.0 * u0 * a0 + 2.0 * a * b0,
            c0: s2 * thd * thd,
        };
        let mut tp = cubic.turning_points(one_plus_u0, one_minus_u0);
        // With b = ±a the pole u = ±1 is a root of f: a turning point (the
        // axis passes through the vertical) if f > 0 next to it, i.e.
        // f(u)/(1 ∓ u) → 2(α ∓ β) > 0 there; otherwise the third root.
        // α ∓ β = A₀ ∓ β (1 ∓ u₀), without cancellation.
        let alpha_minus_beta = a0 - beta * one_minus_u0;
        let alpha_plus_beta = a0 + beta * one_plus_u0;
        let mut through_top = bma == 0.0 && alpha_minus_beta > 0.0;
        let mut through_bottom = bpa == 0.0 && alpha_plus_beta > 0.0;
        if through_top {
            tp.w2 = one_minus_u0;
        }
        if through_bottom {
            tp.w1 = -one_plus_u0;
        }
        // 1 − u₂ and 1 + u₁ from f(±1) = −(b ∓ a)² = the factorised cubic
        // at the pole (no difference of nearly equal numbers near the pole),
        // polished; unless its factor β(u₃ ∓ 1) = g ∓ β(1 ∓ u₀) cancels
        // worse than the plain `(1 ∓ u₀) ∓ w` (a third root just beyond the
        // pole: by more than 10⁻¹² once).
        let pole_distance = |b_pole: f64, near: f64, far_w: f64, g_pole: f64, direct: f64| {
            let by_product = b_pole * b_pole / ((near + far_w) * (tp.g + g_pole));
            let cond_product = (near.abs() + far_w.abs()) / (near + far_w).abs()
                + (tp.g.abs() + g_pole.abs()) / (tp.g + g_pole).abs();
            let cond_direct = (near.abs() + (direct - near).abs()) / direct.abs();
            // (a NaN condition, 0/0 at the pole, keeps the product)
            let product_worse = cond_product > 4.0 * cond_direct;
            if b_pole != 0.0 && by_product.is_finite() && by_product > 0.0 && !product_worse {
                by_product
            } else {
                direct.max(0.0)
            }
        };
        let mut one_minus_u2 = if through_top {
            0.0
        } else {
            let v0 = pole_distance(
                bma,
                one_minus_u0,
                -tp.w1,
                -beta * one_minus_u0,
                one_minus_u0 - tp.w2,
            );
            polish_pole_distance(v0, alpha_minus_beta, beta, bma, a)
        };
        let mut one_plus_u1 = if through_bottom {
            0.0
        } else {
            let v0 = pole_distance(
                bpa,
                one_plus_u0,
                tp.w2,
                beta * one_plus_u0,
                one_plus_u0 + tp.w1,
            );
            polish_pole_distance(v0, alpha_plus_beta, -beta, bpa, -a)
        };
        // A pole passed closer than f64 resolves is passed through, with
        // steps of φ and ψ (`passes`); not next to an exact passage of the
        // other pole (its jumps are the through-form's).
        let width = tp.w2 - tp.w1;
        let near_top = close_pass(one_minus_u2, bma, through_top, width) && !through_bottom;
        let near_bottom = close_pass(one_plus_u1, bpa, through_bottom, width) && !through_top;
        let (mut pass_top, mut pass_bottom) = (0.0, 0.0);
        if near_top {
            (through_top, one_minus_u2, tp.w2, pass_top) = (true, 0.0, one_minus_u0, sign(bma));
        }
        if near_bottom {
            (through_bottom, one_plus_u1, tp.w1, pass_bottom) =
                (true, 0.0, -one_plus_u0, sign(bpa));
        }
        let delta = tp.w2 - tp.w1;
        // r = b − a u at u₁ = u₀ + w₁ = −1 + (1 + u₁) and u₂ = u₀ + w₂ = 1 − (1 − u₂):
        // whichever way sums the smaller terms (no cancellation of b against a u₀
        // for a fast top, none of b ∓ a against a(1 ± u) near a pole).
        let better = |x: (f64, f64), y: (f64, f64)| {
            let (cx, cy) = (x.0.abs() + x.1.abs(), y.0.abs() + y.1.abs());
            if cx <= cy {
                (x.0 + x.1, cx)
            } else {
                (y.0 + y.1, cy)
            }
        };
        let r1 = better((b0, -a * tp.w1), (bpa, -a * one_plus_u1));
        let r2 = better((b0, -a * tp.w2), (bma, a * one_minus_u2));
        let rc = {
            let half = ((r1.0 + r2.0) / 2.0, (r1.1 + r2.1) / 2.0);
            let w_sum = (cubic.c1 + beta * cubic.c0 / tp.g) / tp.g;
            let from_cubic = centre_r_from_cubic(a, beta, u0, s2, a0, b0, cubic.c0, tp.g, w_sum);
            if from_cubic.0.is_finite() && from_cubic.1 < half.1 {
                from_cubic
            } else {
                half
            }
        };
        let sigma = if beta >= 0.0 { 1.0 } else { -1.0 };
        let (wb, wo) = if sigma > 0.0 {
            (tp.w1, tp.w2)
        } else {
            (tp.w2, tp.w1)
        };
        let p = tp.g - beta * wb;
        let kind = if s0 == 0.0 && thd == 0.0 && u0 > 0.0 {
            Kind::Vertical
        } else if (s0 == 0.0 && thd == 0.0) || delta == 0.0 || p.is_nan() || p <= 0.0 {
            // at rest in θ on the downward vertical (an equilibrium, even
            // where it is unstable), steady precession, or no motion at all
            Kind::Steady
        } else {
            Kind::Nutating
        };
        let mc = ((tp.g - beta * wo) / p).clamp(0.0, 1.0);
        let m = (beta.abs() * delta / p).clamp(0.0, 1.0);
        let nu = 0.5 * p.max(0.0).sqrt();
        let k = complete_k(mc);
        let jacobi = JacobiElliptic::new(mc);
        let mut motion = LagrangeTopMotion {
            top,
            init,
            a,
            b,
            bma,
            bpa,
            alpha,
            beta,
            omega3,
            u0,
            r1,
            r2,
            rc,
            m,
            mc,
            phi_slope: 0.0,
            psi_slope: 0.0,
            phi_mean: None,
            w1: tp.w1,
            w2: tp.w2,
            g: tp.g,
            delta,
            one_minus_u2,
            one_plus_u1,
            through_top,
            through_bottom,
            pass_top,
            pass_bottom,
            kind,
            sigma,
            nu,
            k,
            tau0: 0.0,
            jacobi,
            minus: None,
            plus: None,
            zeta_y: 1.0,
            zeta_x: 1.0,
        };
        if kind != Kind::Nutating {
            return motion;
        }
        // sn²τ₀ = |w_b|/Δ, cn²τ₀ = |w_o|/Δ: F(am τ₀) = sn R_F(cn², cn² + mc sn², 1)
        // straight from them (no amplitude round trip, exact K at a turning point).
        let (sn0, cn0) = ((wb.abs() / delta).sqrt(), (wo.abs() / delta).sqrt());
        let f = sn0 * carlson_rf(cn0 * cn0, cn0 * cn0 + mc * sn0 * sn0, 1.0);
        let udot0 = -s0 * thd;
        let tau0 = if udot0 * sigma < 0.0 { -f } else { f };
        motion.tau0 = tau0;
        let (sn, cn, dn) = motion.jacobi.sn_cn_dn(tau0);
        // 1 − u at u₁, u₂ and 1 + u at u₁, u₂.
        let (omu1, omu2) = (one_minus_u2 + delta, one_minus_u2);
        let (opu1, opu2) = (one_plus_u1, one_plus_u1 + delta);
        if bma != 0.0 && !through_top {
            let (hb, ho) = if sigma > 0.0 {
                (omu1, omu2)
            } else {
                (omu2, omu1)
            };
            let (tk, h_ref) = ThirdKind::new(hb, sigma * delta, ho, m, mc, k);
            debug_assert_eq!(h_ref, omu1);
            motion.minus = Some((tk, tk.eval(tau0, sn, cn, dn)));
        } else {
            // √(1 − u) = ζ √Δ G, G = cn (β ≥ 0) or sn (β < 0)
            let (gv, gd) = if sigma > 0.0 {
                (cn, -sn * dn)
            } else {
                (sn, cn * dn)
            };
            motion.zeta_y = if s0 != 0.0 { sign(gv) } else { sign(thd * gd) };
        }
        if bpa != 0.0 && !through_bottom {
            let (hb, ho) = if sigma > 0.0 {
                (opu1, opu2)
            } else {
                (opu2, opu1)
            };
            let (tk, h_ref) = ThirdKind::new(hb, -sigma * delta, ho, m, mc, k);
            debug_assert_eq!(h_ref, opu2);
            motion.plus = Some((tk, tk.eval(tau0, sn, cn, dn)));
        } else {
            // √(1 + u) = ζ √Δ H, H = sn (β ≥ 0) or cn (β < 0)
            let (hv, hd) = if sigma > 0.0 {
                (sn, cn * dn)
            } else {
                (cn, -sn * dn)
            };
            motion.zeta_x = if one_plus_u0 != 0.0 {
                sign(hv)
            } else {
                -sign(thd * hd)
            };
        }
        // The slopes: ½(b − a)/(1 − u₁) = −a/2 + r₁/(2(1 − u₁)) and
        // ½(b + a)/(1 + u₂) = a/2 + r₂/(2(1 + u₂)); the ±a/2 cancel in φ̇ and
        // add to −a in ψ̇ = ω₃ − a − ½(b − a)/(1 − u) + ½(b + a)/(1 + u).
        let (minus_slope, plus_slope) = (0.5 * r1.0 / omu1, 0.5 * r2.0 / opu2);
        let (phi_slope, psi_slope) = match (motion.minus.is_some(), motion.plus.is_some()) {
            (true, true) => (minus_slope + plus_slope, omega3 - minus_slope + plus_slope),
            (true, false) => {
                let s = 0.5 * bma / omu1;
                (s, omega3 - a - s)
            }
            (false, true) => {
                let s = 0.5 * bpa / opu2;
                (s, omega3 - a + s)
            }
            (false, false) => (0.0, omega3 - a),
        };
        motion.phi_slope = phi_slope;
        motion.psi_slope = psi_slope;
        motion.phi_mean = motion.through_mean();
        motion
    }
}
