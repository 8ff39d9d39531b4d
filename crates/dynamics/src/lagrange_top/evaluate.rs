//! Evaluating the closed form at a time: Euler angles, attitude, angular velocity.

use glam::{DQuat, DVec3};

use super::EulerAnglesAndRates;
use super::motion::{Kind, LagrangeTopMotion};

impl LagrangeTopMotion {
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
        let (y, ydot) = if self.through_top {
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
        let (x, xdot) = if self.through_bottom {
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
        let mut phi = i.phi + self.phi_slope * t;
        let mut psi = i.psi + self.psi_slope * t;
        if let Some((tk, at0)) = &self.minus {
            let rest = 0.5 * self.bma * (tk.eval(tau, sn, cn, dn) - at0) / self.nu;
            phi += rest;
            psi -= rest;
        }
        if let Some((tk, at0)) = &self.plus {
            let rest = 0.5 * self.bpa * (tk.eval(tau, sn, cn, dn) - at0) / self.nu;
            phi += rest;
            psi += rest;
        }
        let (phi_dot, psi_dot) = self.rates(omu, opu, s2, c2);
        EulerAnglesAndRates {
            phi,
            theta,
            psi,
            phi_dot,
            theta_dot,
            psi_dot,
        }
    }

    /// φ̇ and ψ̇ at `1 − u = omu`, `1 + u = opu` (`sn²`, `cn²` of the phase):
    /// by the partial fractions `½(b ∓ a)/(1 ∓ u)` or directly as
    /// `φ̇ = r(u)/((1 − u)(1 + u))`, `ψ̇ = ω₃ − u φ̇`, whichever sums smaller
    /// terms (the partial fractions cancel to ~β/a for a fast top, the
    /// direct form loses `r` next to a pole).
    fn rates(&self, omu: f64, opu: f64, s2: f64, c2: f64) -> (f64, f64) {
        let (minus, plus) = (0.5 * self.bma / omu, 0.5 * self.bpa / opu);
        let (phi_dot, psi_dot) = match (&self.minus, &self.plus) {
            (Some(_), Some(_)) => (minus + plus, self.omega3 - self.a - minus + plus),
            (Some(_), None) => (minus, self.omega3 - self.a - minus),
            (None, Some(_)) => (plus, self.omega3 - self.a + plus),
            (None, None) => (0.0, self.omega3 - self.a),
        };
        if self.minus.is_none() || self.plus.is_none() {
            return (phi_dot, psi_dot);
        }
        // r(u) from the nearer turning point: u = u_b + σΔ sn² = u_o − σΔ cn².
        let (rb, ro) = if self.sigma > 0.0 {
            (self.r1, self.r2)
        } else {
            (self.r2, self.r1)
        };
        let ad = self.a * self.sigma * self.delta;
        let (r, scale) = if s2 <= 0.5 {
            (rb.0 - ad * s2, rb.1 + ad.abs())
        } else {
            (ro.0 + ad * c2, ro.1 + ad.abs())
        };
        if scale / (omu * opu) >= minus.abs() + plus.abs() {
            return (phi_dot, psi_dot);
        }
        let direct = r / (omu * opu);
        let u = if omu < opu { 1.0 - omu } else { opu - 1.0 };
        (direct, self.omega3 - u * direct)
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
            // Rx(θ) = Rx(θ mod 2π); past π, (φ, θ, ψ) ≡ (φ + π, 2π − θ, ψ − π).
            let r = e.theta.rem_euclid(2.0 * pi);
            if r > pi {
                e.theta = 2.0 * pi - r;
                e.phi += pi;
                e.psi -= pi;
                e.theta_dot = -e.theta_dot;
            } else {
                e.theta = r;
            }
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
