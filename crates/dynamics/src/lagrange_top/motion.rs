//! The closed-form motion: `u = cos θ` by `sn²`, φ and ψ by Π.

use glam::{DQuat, DVec3};

use super::roots::ShiftedCubic;
use super::third_kind::{ThirdKind, complete_k};
use super::{EulerAnglesAndRates, LagrangeTop, LagrangeTopInitial};
use crate::elliptic::{JacobiElliptic, incomplete_f_complementary};

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
/// initial phase, signed by the direction of `u̇₀`.
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
    /// Initial conditions with θ₀ ∈ [0, π].
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
    /// `b − a u₀ = sin²θ₀ φ̇₀`.
    pub(super) b0: f64,
    pub(super) w1: f64,
    pub(super) w2: f64,
    /// `β u₃ − β u₀`.
    pub(super) g: f64,
    pub(super) delta: f64,
    pub(super) one_minus_u2: f64,
    pub(super) one_plus_u1: f64,
    pub(super) kind: Kind,
    /// +1 for β ≥ 0 (base u₁), −1 for β < 0 (base u₂).
    pub(super) sigma: f64,
    pub(super) nu: f64,
    pub(super) k: f64,
    pub(super) tau0: f64,
    jacobi: JacobiElliptic,
    minus: Option<(ThirdKind, f64)>,
    plus: Option<(ThirdKind, f64)>,
    zeta_y: f64,
    zeta_x: f64,
}

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

fn sign(x: f64) -> f64 {
    if x < 0.0 { -1.0 } else { 1.0 }
}

impl LagrangeTopMotion {
    pub(super) fn new(top: LagrangeTop, initial: LagrangeTopInitial) -> LagrangeTopMotion {
        let mut init = initial;
        let t = init.theta.rem_euclid(2.0 * std::f64::consts::PI);
        init.theta = t;
        if t > std::f64::consts::PI {
            init.theta = 2.0 * std::f64::consts::PI - t;
            init.phi += std::f64::consts::PI;
            init.psi -= std::f64::consts::PI;
            init.theta_dot = -init.theta_dot;
        }
        let (th, phd, thd) = (init.theta, init.phi_dot, init.theta_dot);
        let (s0, u0) = th.sin_cos();
        let s2 = s0 * s0;
        let one_minus_u0 = 2.0 * (0.5 * th).sin().powi(2);
        let one_plus_u0 = 2.0 * (0.5 * th).cos().powi(2);
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
        if bma == 0.0 {
            tp.w2 = one_minus_u0;
        }
        if bpa == 0.0 {
            tp.w1 = -one_plus_u0;
        }
        let one_minus_u2 = if bma == 0.0 {
            0.0
        } else {
            (one_minus_u0 - tp.w2).max(0.0)
        };
        let one_plus_u1 = if bpa == 0.0 {
            0.0
        } else {
            (one_plus_u0 + tp.w1).max(0.0)
        };
        let delta = tp.w2 - tp.w1;
        let kind = if s0 == 0.0 && thd == 0.0 && u0 > 0.0 {
            Kind::Vertical
        } else if delta == 0.0 {
            Kind::Steady
        } else {
            Kind::Nutating
        };
        let sigma = if beta >= 0.0 { 1.0 } else { -1.0 };
        let (wb, wo) = if sigma > 0.0 {
            (tp.w1, tp.w2)
        } else {
            (tp.w2, tp.w1)
        };
        let p = tp.g - beta * wb;
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
            b0,
            w1: tp.w1,
            w2: tp.w2,
            g: tp.g,
            delta,
            one_minus_u2,
            one_plus_u1,
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
        let amp = wb.abs().sqrt().atan2(wo.abs().sqrt());
        let f = incomplete_f_complementary(amp, mc);
        let udot0 = -s0 * thd;
        let tau0 = if udot0 * sigma < 0.0 { -f } else { f };
        motion.tau0 = tau0;
        let (sn, cn, dn) = motion.jacobi.sn_cn_dn(tau0);
        // 1 − u at u₁, u₂ and 1 + u at u₁, u₂.
        let (omu1, omu2) = (one_minus_u2 + delta, one_minus_u2);
        let (opu1, opu2) = (one_plus_u1, one_plus_u1 + delta);
        if bma != 0.0 {
            let (hb, ho) = if sigma > 0.0 {
                (omu1, omu2)
            } else {
                (omu2, omu1)
            };
            let tk = ThirdKind::new(hb, sigma * delta, ho, m, mc, k);
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
        if bpa != 0.0 {
            let (hb, ho) = if sigma > 0.0 {
                (opu1, opu2)
            } else {
                (opu2, opu1)
            };
            let tk = ThirdKind::new(hb, -sigma * delta, ho, m, mc, k);
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
        motion
    }

    /// The `∫dt/(1 − u)` term and its value at τ₀, if `b ≠ a`.
    pub(super) fn minus_term(&self) -> Option<&(ThirdKind, f64)> {
        self.minus.as_ref()
    }

    /// The `∫dt/(1 + u)` term and its value at τ₀, if `b ≠ −a`.
    pub(super) fn plus_term(&self) -> Option<&(ThirdKind, f64)> {
        self.plus.as_ref()
    }

    /// (φ, signed θ, ψ, φ̇, θ̇, ψ̇): θ may leave [0, π] when the axis passes
    /// through a vertical (see the type's docs).
    fn signed_euler(&self, t: f64) -> EulerAnglesAndRates {
        let i = &self.init;
        match self.kind {
            Kind::Vertical | Kind::Steady => {
                return EulerAnglesAndRates {
                    phi: i.phi + i.phi_dot * t,
                    theta: i.theta,
                    psi: i.psi + i.psi_dot * t,
                    phi_dot: i.phi_dot,
                    theta_dot: 0.0,
                    psi_dot: i.psi_dot,
                };
            }
            Kind::Nutating => {}
        }
        let tau = self.nu * t + self.tau0;
        let (sn, cn, dn) = self.jacobi.sn_cn_dn(tau);
        let d = self.delta;
        let (s2, c2) = (sn * sn, cn * cn);
        let (omu, opu) = if self.sigma > 0.0 {
            (self.one_minus_u2 + d * c2, self.one_plus_u1 + d * s2)
        } else {
            (self.one_minus_u2 + d * s2, self.one_plus_u1 + d * c2)
        };
        let udot = 2.0 * self.sigma * d * self.nu * sn * cn * dn;
        let rd = d.sqrt();
        let (y, ydot) = if self.bma == 0.0 {
            let (gv, gd) = if self.sigma > 0.0 {
                (cn, -sn * dn)
            } else {
                (sn, cn * dn)
            };
            (self.zeta_y * rd * gv, self.zeta_y * rd * gd * self.nu)
        } else {
            let y = omu.sqrt();
            (y, -udot / (2.0 * y))
        };
        let (x, xdot) = if self.bpa == 0.0 {
            let (hv, hd) = if self.sigma > 0.0 {
                (sn, cn * dn)
            } else {
                (cn, -sn * dn)
            };
            (self.zeta_x * rd * hv, self.zeta_x * rd * hd * self.nu)
        } else {
            let x = opu.sqrt();
            (x, udot / (2.0 * x))
        };
        let theta = 2.0 * y.atan2(x);
        let theta_dot = x * ydot - y * xdot;
        let mut phi = i.phi;
        let mut psi = i.psi + (self.omega3 - self.a) * t;
        let mut phi_dot = 0.0;
        let mut psi_dot = self.omega3 - self.a;
        if let Some((tk, at0)) = &self.minus {
            let integral = (tk.eval(tau, sn, cn, dn) - at0) / self.nu;
            phi += 0.5 * self.bma * integral;
            psi -= 0.5 * self.bma * integral;
            phi_dot += 0.5 * self.bma / omu;
            psi_dot -= 0.5 * self.bma / omu;
        }
        if let Some((tk, at0)) = &self.plus {
            let integral = (tk.eval(tau, sn, cn, dn) - at0) / self.nu;
            phi += 0.5 * self.bpa * integral;
            psi += 0.5 * self.bpa * integral;
            phi_dot += 0.5 * self.bpa / opu;
            psi_dot += 0.5 * self.bpa / opu;
        }
        EulerAnglesAndRates {
            phi,
            theta,
            psi,
            phi_dot,
            theta_dot,
            psi_dot,
        }
    }

    /// Euler angles and rates at time `t` (s), in closed form, any `t`.
    ///
    /// ```text
    /// u = cos θ = u_b + σ Δ sn²(ν t + τ₀ | m),  φ, ψ: see the type's docs
    /// θ = 2 atan2(√(1 − u), √(1 + u)),  θ̇ = −u̇ / sin θ
    /// ```
    ///
    /// θ ∈ [0, π]; φ and ψ are continuous except for the jumps by ±π where
    /// the axis passes exactly through a vertical (type docs). For the
    /// sleeping top and steady precession the initial rates continue
    /// uniformly.
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// let motion = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// let e = motion.euler_at(123.4);
    /// assert!(e.theta >= motion.theta_min() - 1e-15 && e.theta <= motion.theta_max() + 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn euler_at(&self, t: f64) -> EulerAnglesAndRates {
        let mut e = self.signed_euler(t);
        let pi = std::f64::consts::PI;
        if e.theta < 0.0 || e.theta > pi {
            e.theta = if e.theta < 0.0 {
                -e.theta
            } else {
                2.0 * pi - e.theta
            };
            e.phi += pi;
            e.psi -= pi;
            e.theta_dot = -e.theta_dot;
        }
        e
    }

    /// The attitude `world_from_body` at time `t` (s).
    ///
    /// ```text
    /// q(t) = Rz(φ) · Rx(θ) · Rz(ψ)   (θ signed through a vertical: continuous in t)
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// let motion = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// let axis = motion.world_from_body_at(1.0) * DVec3::Z;
    /// assert!((axis.z - motion.euler_at(1.0).theta.cos()).abs() < 1e-14);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn world_from_body_at(&self, t: f64) -> DQuat {
        let e = self.signed_euler(t);
        DQuat::from_rotation_z(e.phi)
            * DQuat::from_rotation_x(e.theta)
            * DQuat::from_rotation_z(e.psi)
    }

    /// The angular velocity in body axes at time `t` (s), rad/s.
    ///
    /// ```text
    /// ω = (φ̇ sin θ sin ψ + θ̇ cos ψ,  φ̇ sin θ cos ψ − θ̇ sin ψ,  φ̇ cos θ + ψ̇)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, phi_dot: 0.2, psi_dot: 20.0, ..Default::default() };
    /// let motion = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// // The spin ω₃ is constant.
    /// assert!((motion.omega_body_at(3.3).z - motion.omega3()).abs() < 1e-12);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn omega_body_at(&self, t: f64) -> DVec3 {
        let e = self.signed_euler(t);
        let (st, ct) = e.theta.sin_cos();
        let (sp, cp) = e.psi.sin_cos();
        DVec3::new(
            e.phi_dot * st * sp + e.theta_dot * cp,
            e.phi_dot * st * cp - e.theta_dot * sp,
            e.phi_dot * ct + e.psi_dot,
        )
    }
}
