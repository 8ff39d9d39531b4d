//! Evaluating the closed form at a time: Euler angles, attitude, angular velocity.

use glam::{DQuat, DVec3};

use super::EulerAnglesAndRates;
use super::motion::{Kind, LagrangeTopMotion};
use super::third_kind::ThirdKind;

/// The nutation phase `ν t` split into whole periods and the rest:
/// `ν t = 2K j + s`, `|s| ≤ K` (`j = 0`, `s = ν t` for an infinite period).
#[derive(Debug, Clone, Copy)]
struct Phase {
    j: f64,
    s: f64,
}

/// Gauss–Legendre nodes and weights on [−1, 1], 4 points (exact to degree 7).
const GAUSS4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_85),
    (-0.339_981_043_584_856_26, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_26, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_85),
];

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
        let phase = self.phase(t);
        let tau = self.tau0 + phase.s;
        let (sn, cn, dn) = self.jacobi.sn_cn_dn(tau);
        let (omu, opu, s2, c2) = self.one_mp_u(sn, cn);
        let (theta, theta_dot) = self.signed_theta(phase.j, sn, cn, dn, omu, opu);
        let (phi, psi) = self.precession_and_spin(t, phase, sn, cn, dn);
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

    /// The signed θ and θ̇ at the reduced phase `τ₀ + s` (`sn`, `cn`, `dn`
    /// there, `1 ∓ u` = `omu`, `opu`), `j` whole periods on.
    fn signed_theta(&self, j: f64, sn: f64, cn: f64, dn: f64, omu: f64, opu: f64) -> (f64, f64) {
        let d = self.delta;
        let udot = 2.0 * self.sigma * d * self.nu * sn * cn * dn;
        let rd = d.sqrt();
        // sn, cn change sign over each period 2K: the signed θ through a
        // vertical needs them at the unreduced phase.
        let (sn, cn) = if j % 2.0 == 0.0 { (sn, cn) } else { (-sn, -cn) };
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
        (2.0 * y.atan2(x), x * ydot - y * xdot)
    }

    /// φ and ψ at `t`, the phase `ν t = 2K j + s` and `sn`, `cn`, `dn` at
    /// `τ₀ + s`. φ is the mean motion plus the oscillation about it:
    ///
    /// ```text
    /// φ(t) = φ₀ + φ_slope t + Σ± c± (R±(τ) − R±(τ₀)),   c± = (b ∓ a)/(2ν),  τ = τ₀ + ν t
    /// R±(τ + 2K) = R±(τ) + P±,   ⟨φ̇⟩ = φ_slope + Σ± c± ν P±/(2K)          (third_kind)
    /// ⇒ φ(t) = φ₀ + ⟨φ̇⟩ t + S(τ₀ + s) − S(τ₀),   S(τ) = Σ± c± (R±(τ) − P± τ/(2K))  (period 2K)
    /// S(τ₀ + s) − S(τ₀) = ∫₀ˢ (φ̇(τ₀ + σ) − ⟨φ̇⟩) dσ / ν
    /// ```
    ///
    /// `⟨φ̇⟩` is [`mean_precession_rate`](Self::mean_precession_rate) (the
    /// band-centre form for a thin band, to ~ε of itself), not
    /// `φ_slope + Σ c± ν P±/(2K)`, whose terms are of the size of the swing
    /// of φ̇ and cancel to the mean: for a fast top kicked in θ̇ the old
    /// `φ_slope t + Σ c± (R±(τ) − R±(τ₀))` kept that cancellation in φ, and
    /// rounded `φ_slope t` and the rests at different phases, so φ(T) − φ₀
    /// was ε · swing/⟨φ̇⟩ off (4·10⁻³ at ψ̇₀ = 10¹⁵ rad/s). The oscillation
    /// `S(τ₀ + s) − S(τ₀)` is of the size of the swing `|φ̇ − ⟨φ̇⟩|/ν` and
    /// rounds to ε of it; within `short_phase` of a whole period it is
    /// smaller than that rounding (≈ (φ̇(τ₀) − ⟨φ̇⟩) s/ν) and is taken by
    /// the integral (4-point Gauss–Legendre, error ~(s/ℓ)⁸ and ε of the
    /// integral), so that φ(N T) − φ₀ = N ⟨φ̇⟩ T keeps ~ε of itself.
    ///
    /// ψ keeps the form `ψ_slope t ∓ Σ…`: its accumulated `ω₃ t` dwarfs
    /// any swing. Without a finite period φ keeps it too (`⟨φ̇⟩` undefined).
    fn precession_and_spin(&self, t: f64, phase: Phase, sn: f64, cn: f64, dn: f64) -> (f64, f64) {
        let i = &self.init;
        let tau = self.tau0 + phase.s;
        // (c (R(τ) − R(τ₀)), c (R(τ₀ + s) − R(τ₀) − P s/(2K))) of one partial fraction
        let part = |p: &Option<(ThirdKind, f64)>, coef: f64| {
            p.as_ref().map_or((0.0, 0.0), |(tk, at0)| {
                let c = 0.5 * coef / self.nu;
                let d = c * (tk.eval(tau, sn, cn, dn) - at0);
                let per = c * tk.per_period();
                (d + phase.j * per, d - per * phase.s / (2.0 * self.k))
            })
        };
        let (rest_m, osc_m) = part(&self.minus, self.bma);
        let (rest_p, osc_p) = part(&self.plus, self.bpa);
        let psi = i.psi + self.psi_slope * t - rest_m + rest_p;
        let phi = match self.phi_mean {
            Some(mean) if phase.s.abs() <= self.short_phase() => {
                i.phi + mean * t + self.phi_swing_by_quadrature(phase.s, mean)
            }
            Some(mean) => i.phi + mean * t + (osc_m + osc_p),
            None => i.phi + self.phi_slope * t + rest_m + rest_p,
        };
        (phi, psi)
    }

    /// `ν t = 2K j + s` with `|s| ≤ K` (the whole periods taken out, so that
    /// every closed form below sees a phase within one period of τ₀).
    fn phase(&self, t: f64) -> Phase {
        let nt = self.nu * t;
        let period = 2.0 * self.k;
        let j = (nt / period).round();
        if !period.is_finite() || !j.is_finite() || j == 0.0 {
            return Phase { j: 0.0, s: nt };
        }
        Phase {
            j,
            s: nt - j * period,
        }
    }

    /// `(1 − u, 1 + u, sn², cn²)` at the phase whose `sn`, `cn` are given.
    fn one_mp_u(&self, sn: f64, cn: f64) -> (f64, f64, f64, f64) {
        let d = self.delta;
        let (s2, c2) = (sn * sn, cn * cn);
        let (omu, opu) = if self.sigma > 0.0 {
            (self.one_minus_u2 + d * c2, self.one_plus_u1 + d * s2)
        } else {
            (self.one_minus_u2 + d * s2, self.one_plus_u1 + d * c2)
        };
        (omu, opu, s2, c2)
    }

    /// The reduced phases `|s|` up to which φ's swing is integrated by
    /// quadrature: 10⁻³ of the scale on which φ̇ varies in τ (1, or
    /// `√((1 ∓ u)/Δ)` at a turning point close to a pole).
    fn short_phase(&self) -> f64 {
        let near_pole = self.one_minus_u2.min(self.one_plus_u1);
        1e-3 * (near_pole / self.delta).sqrt().min(1.0)
    }

    /// `∫₀ˢ (φ̇(τ₀ + σ) − ⟨φ̇⟩) dσ / ν` by 4-point Gauss–Legendre, for a
    /// short reduced phase `s` (see `precession_and_spin`).
    fn phi_swing_by_quadrature(&self, s: f64, mean: f64) -> f64 {
        if s == 0.0 {
            return 0.0;
        }
        let half = 0.5 * s;
        let sum: f64 = GAUSS4
            .iter()
            .map(|&(x, w)| {
                let (sn, cn, _) = self.jacobi.sn_cn_dn(self.tau0 + half * (1.0 + x));
                let (omu, opu, s2, c2) = self.one_mp_u(sn, cn);
                w * (self.rates(omu, opu, s2, c2).0 - mean)
            })
            .sum();
        half * sum / self.nu
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
    /// φ = φ₀ + ⟨φ̇⟩ t + (its oscillation about the mean motion, period T)
    /// ```
    ///
    /// φ is the mean precession ([`mean_precession_rate`](Self::mean_precession_rate))
    /// plus a periodic swing formed without cancellation, so that it keeps
    /// full precision also for a fast top whose φ̇ swings far wider than its
    /// mean (φ(N T) − φ₀ = N ⟨φ̇⟩ T to ~ε). Whatever the form, the phase
    /// `ν t` is only as good as ν (a few ulp): after N periods it is off by
    /// ~ε · 2πN rad, which is what the angles and rates of a fast top lose
    /// at long times.
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
        let mut flipped = false;
        if e.theta < 0.0 || e.theta > pi {
            // Rx(θ) = Rx(θ mod 2π); past π, (φ, θ, ψ) ≡ (φ + π, 2π − θ, ψ − π).
            let r = e.theta.rem_euclid(2.0 * pi);
            if r > pi {
                e.theta = 2.0 * pi - r;
                e.phi += pi;
                e.psi -= pi;
                e.theta_dot = -e.theta_dot;
                flipped = true;
            } else {
                e.theta = r;
            }
        }
        self.apply_passes(&mut e, t, flipped);
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
        attitude(&self.signed_euler(t))
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
        omega_body(&self.signed_euler(t))
    }

    /// [`LagrangeTopMotion::world_from_body_at`] and
    /// [`LagrangeTopMotion::omega_body_at`] from one evaluation of the
    /// angles.
    pub(super) fn world_from_body_and_omega_at(&self, t: f64) -> (DQuat, DVec3) {
        let e = self.signed_euler(t);
        (attitude(&e), omega_body(&e))
    }
}

/// `Rz(φ) · Rx(θ) · Rz(ψ)`.
fn attitude(e: &EulerAnglesAndRates) -> DQuat {
    DQuat::from_rotation_z(e.phi) * DQuat::from_rotation_x(e.theta) * DQuat::from_rotation_z(e.psi)
}

/// `ω = (φ̇ sin θ sin ψ + θ̇ cos ψ,  φ̇ sin θ cos ψ − θ̇ sin ψ,  φ̇ cos θ + ψ̇)`.
fn omega_body(e: &EulerAnglesAndRates) -> DVec3 {
    let (st, ct) = e.theta.sin_cos();
    let (sp, cp) = e.psi.sin_cos();
    DVec3::new(
        e.phi_dot * st * sp + e.theta_dot * cp,
        e.phi_dot * st * cp - e.theta_dot * sp,
        e.phi_dot * ct + e.psi_dot,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lagrange_top::{LagrangeTop, LagrangeTopInitial};

    /// The two forms of φ's oscillation, the closed form (just past
    /// `short_phase`) and the quadrature (up to it), agree where they meet,
    /// on slow and fast tops, either side of a whole period: to the
    /// rounding of the closed form, ~ε of the swing `max|φ̇|/ν`.
    #[test]
    fn quadrature_and_closed_form_meet() {
        let cases = [
            (LagrangeTop::new(1.0, 0.5, 1.0), 0.5, 0.3, 0.2, 20.0),
            (LagrangeTop::new(1.0, 0.5, 1.0), 2.5, -0.3, -0.7, 3.0),
            (LagrangeTop::new(2.0, 0.3, -1.5), 2.0, 0.4, 0.1, 5.0),
            (LagrangeTop::new(1.25, 0.5, -1.0), 2.5, 0.0, 0.3, 1e7),
            (LagrangeTop::new(1.25, 0.5, 1.0), 0.05, 0.3, 0.02, 30.0),
        ];
        for (top, theta, phi_dot, theta_dot, psi_dot) in cases {
            let init = LagrangeTopInitial {
                theta,
                phi_dot,
                theta_dot,
                psi_dot,
                ..Default::default()
            };
            let m = top.try_solve(init).unwrap();
            let mean = m.phi_mean.unwrap();
            let short = m.short_phase();
            assert!(short > 0.0, "{init:?}");
            let period = m.nutation_period().unwrap();
            let swing = (0..16)
                .map(|k| (m.euler_at(period * k as f64 / 16.0).phi_dot - mean).abs())
                .fold(0.0, f64::max);
            for s in [short, -short] {
                let s = s * (1.0 + 1e-9);
                let (sn, cn, dn) = m.jacobi.sn_cn_dn(m.tau0 + s);
                let t = s / m.nu;
                let phase = Phase { j: 0.0, s };
                let closed = m.precession_and_spin(t, phase, sn, cn, dn).0 - mean * t;
                let quad = m.phi_swing_by_quadrature(s, mean);
                let tol = 8.0 * f64::EPSILON * swing / m.nu + 1e-12 * quad.abs();
                assert!(
                    (closed - quad).abs() <= tol,
                    "{init:?} s {s:e}: {closed:e} {quad:e} ({tol:e})"
                );
            }
        }
    }
}
