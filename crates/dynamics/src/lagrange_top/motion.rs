//! The closed-form motion: `u = cos θ` by `sn²`, φ and ψ by Π.

use super::centre::centre_r_from_cubic;
use super::passes::close_pass;
use super::roots::{ShiftedCubic, polish_pole_distance};
use super::third_kind::{ThirdKind, complete_k};
use super::{LagrangeTop, LagrangeTopInitial};
use crate::elliptic::{JacobiElliptic, carlson_rf};

/// The motion of a [`LagrangeTop`] from given initial conditions, in closed
/// form (Goldstein §5.7; Landau & Lifshitz §35; notes §3.10–3.11).
///
/// ```text
/// u(t) = u_b + σ (u₂ − u₁) sn²(ν t + τ₀ | m)
///   β > 0: u_b = u₁, σ = +1, m = (u₂ − u₁)/(u₃ − u₁), ν = ½√(β (u₃ − u₁))
///   β < 0: u_b = u₂, σ = −1, m = (u₂ − u₁)/(u₂ − u₃), ν = ½√(β (u₃ − u₂))
///   β = 0: u_b = u₁, σ = +1, m = 0,                  ν = ½√(α + a²)
/// φ(t) = φ₀ + ½(b − a) ∫dt/(1 − u) + ½(b + a) ∫dt/(1 + u)
/// ψ(t) = ψ₀ + (ω₃ − a) t − ½(b − a) ∫dt/(1 − u) + ½(b + a) ∫dt/(1 + u)
/// ∫dt/(1 ∓ u) = Π(n; am τ | m)/(ν (1 ∓ u_b)),  n = ±σ(u₂ − u₁)/(1 ∓ u_b)
/// ```
///
/// (partial fractions of `φ̇ = (b − au)/(1 − u²)` and `ψ̇ = ω₃ − u φ̇`; the
/// integrals of the third kind as in Byrd & Friedman 1971, with a
/// cancellation-free form for `n < 0`). τ₀ is the incomplete `F` of the
/// initial phase, signed by the direction of `u̇₀`. φ is evaluated as the
/// mean precession times t plus its periodic swing about it
/// ([`LagrangeTopMotion::euler_at`]).
///
/// **Through the vertical.** When `b = a` exactly (θ₀ = 0 with θ̇₀ ≠ 0, or
/// φ̇₀ chosen so), `u₂ = 1` and the axis passes through the upward vertical.
/// The motion is then followed with a *signed* θ (`√(1 − u)` ∝ cn or sn, which
/// changes sign), so [`LagrangeTopMotion::world_from_body_at`] and
/// [`LagrangeTopMotion::omega_body_at`] are smooth; [`LagrangeTopMotion::euler_at`]
/// reports θ ∈ [0, π] and therefore the equivalent
/// `(φ + π, |θ|, ψ − π)` while θ is "negative": φ jumps by π (ψ by −π) at each
/// passage, θ̇ changes sign. Likewise at the downward vertical (`b = −a`).
///
/// ```
/// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
/// let top = LagrangeTop::new(1.0, 0.5, 1.0);
/// let init = LagrangeTopInitial { theta: 0.4, theta_dot: 0.3, psi_dot: 15.0, ..Default::default() };
/// let motion = top.try_solve(init)?;
/// let t = 2.7;
/// let e = motion.euler_at(t);
/// // Energy and both momenta are constants of the motion.
/// let energy = |e: &kreisel_dynamics::EulerAnglesAndRates| {
///     let w3 = e.phi_dot * e.theta.cos() + e.psi_dot;
///     0.5 * (e.theta_dot.powi(2) + (e.theta.sin() * e.phi_dot).powi(2))
///         + 0.25 * w3 * w3 + e.theta.cos()
/// };
/// assert!((energy(&e) - energy(&motion.euler_at(0.0))).abs() < 1e-13);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone)]
pub struct LagrangeTopMotion {
    pub(super) top: LagrangeTop,
    /// Initial conditions (θ₀ ∈ [0, π], snapped onto a pole within `POLE_SNAP`).
    pub(super) init: LagrangeTopInitial,
    pub(super) a: f64,
    pub(super) b: f64,
    /// `b − a` and `b + a`, each formed without cancellation.
    pub(super) bma: f64,
    pub(super) bpa: f64,
    pub(super) alpha: f64,
    pub(super) beta: f64,
    pub(super) omega3: f64,
    pub(super) u0: f64,
    pub(super) w1: f64,
    pub(super) w2: f64,
    /// `β u₃ − β u₀`.
    pub(super) g: f64,
    pub(super) delta: f64,
    pub(super) one_minus_u2: f64,
    pub(super) one_plus_u1: f64,
    /// `u₂ = 1` exactly (`b = a`): the axis passes through the upward vertical.
    pub(super) through_top: bool,
    /// `u₁ = −1` exactly (`b = −a`): the axis passes through the downward vertical.
    pub(super) through_bottom: bool,
    /// ±1 when the axis passes the upward vertical closer than f64
    /// resolves (sign of `b − a`; then `through_top` too), else 0 (`passes`).
    pub(super) pass_top: f64,
    /// ±1 when it so passes the downward vertical (sign of `b + a`), else 0.
    pub(super) pass_bottom: f64,
    pub(super) kind: Kind,
    /// +1 for β ≥ 0 (base u₁), −1 for β < 0 (base u₂).
    pub(super) sigma: f64,
    pub(super) nu: f64,
    pub(super) k: f64,
    pub(super) tau0: f64,
    pub(super) jacobi: JacobiElliptic,
    /// `r = b − a u` at the turning points u₁, u₂, each formed the better
    /// of two ways (`B₀ − a w` or from `b ∓ a` at the pole), with the size
    /// of the terms summed (its rounding scale).
    pub(super) r1: (f64, f64),
    pub(super) r2: (f64, f64),
    /// `r_c = b − a u_c` at the band centre `u_c = (u₁ + u₂)/2`, formed the
    /// better of two ways (`centre` module docs), with its rounding scale.
    pub(super) rc: (f64, f64),
    /// The parameter `m` of `sn²` (accurate also where `1 − mc` is not).
    pub(super) m: f64,
    /// `mc = 1 − m`, formed directly.
    pub(super) mc: f64,
    /// The mean slopes of φ and ψ in t, without the partial fractions'
    /// `∓a/2` (module docs of `third_kind`): φ(t) = φ₀ + slope t + rests.
    pub(super) phi_slope: f64,
    pub(super) psi_slope: f64,
    /// The mean precession rate ([`LagrangeTopMotion::mean_precession_rate`]),
    /// the secular part of φ(t) in `euler_at` (`None` for an infinite period).
    pub(super) phi_mean: Option<f64>,
    /// The rest of `∫dτ/(1 − u)` and its value at τ₀ (`None` if `b = a`).
    pub(super) minus: Option<(ThirdKind, f64)>,
    /// The rest of `∫dτ/(1 + u)` and its value at τ₀ (`None` if `b = −a`).
    pub(super) plus: Option<(ThirdKind, f64)>,
    /// Signs of `√(1 − u)`, `√(1 + u)` through a vertical.
    pub(super) zeta_y: f64,
    pub(super) zeta_x: f64,
}

/// Starts closer than this to π (rad) are put on the downward vertical:
/// π itself is not an f64, and the f64 nearest it (1.2·10⁻¹⁶ below) means
/// π. Near θ = 0 nothing is snapped: a start 10⁻¹⁵ rad from upright nutates
/// in a band of that size, continuous with 10⁻⁸ (the closed form resolves
/// `1 − cos θ₀ = 2 sin²(θ₀/2)` to full relative accuracy).
pub(super) const POLE_SNAP: f64 = 2e-16;

/// Which closed form applies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    /// θ₀ = 0 and θ̇₀ = 0: the sleeping top (a uniform spin about the vertical).
    Vertical,
    /// u₁ = u₂: steady precession.
    Steady,
    /// Nutation between u₁ < u₂.
    Nutating,
}

pub(super) fn sign(x: f64) -> f64 {
    if x < 0.0 { -1.0 } else { 1.0 }
}

impl LagrangeTopMotion {
    /// Whether every constant of the closed form is a finite number (the
    /// guard of `LagrangeTop::try_solve` against overflow).
    pub(super) fn is_finite(&self) -> bool {
        let rests = [&self.minus, &self.plus].iter().all(|r| {
            r.as_ref()
                .is_none_or(|(tk, at0)| at0.is_finite() && tk.per_period().is_finite())
        });
        rests
            && [
                self.a,
                self.b,
                self.bma,
                self.bpa,
                self.alpha,
                self.beta,
                self.omega3,
                self.w1,
                self.w2,
                self.delta,
                self.one_minus_u2,
                self.one_plus_u1,
                self.r1.0,
                self.r2.0,
                self.phi_slope,
                self.psi_slope,
                self.nu,
                self.tau0,
            ]
            .iter()
            .all(|x| x.is_finite())
            && (self.kind != Kind::Nutating || self.g.is_finite())
    }

    /// Whether a turning point's distance from a pole, `1 − u₂` or
    /// `1 + u₁`, is below 10⁻²⁹⁰ (near or in the subnormal range, where
    /// `(b ∓ a)²` that forms it has lost its digits: a mean precession rate
    /// 30 % off at ψ̇₀ = 10⁻¹⁶⁰ rad/s) although the axis does not pass
    /// through that vertical (`b ∓ a ≠ 0`): it comes closer than f64 resolves.
    pub(super) fn pole_distance_underflows(&self) -> bool {
        let unresolved = |distance: f64, b_pole: f64, through: bool| {
            distance < 1e-290 && b_pole != 0.0 && !through
        };
        self.kind == Kind::Nutating
            && (unresolved(self.one_minus_u2, self.bma, self.through_top)
                || unresolved(self.one_plus_u1, self.bpa, self.through_bottom))
    }

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
