//! The constants, turning points, period and kind of a [`LagrangeTopMotion`].

use super::motion::{Kind, LagrangeTopMotion};
use super::third_kind::ThirdKind;
use super::{LagrangeTop, TopMotionKind};

/// Relative tolerance on `b − a uᵢ` for [`TopMotionKind::Cusps`] when the
/// cusp is not known exactly from the initial conditions.
const CUSP_TOLERANCE: f64 = 1e-12;

/// θ = 2 atan2(√(1 − u), √(1 + u)) from the two accurate complements.
fn theta_from(one_minus_u: f64, one_plus_u: f64) -> f64 {
    2.0 * one_minus_u
        .max(0.0)
        .sqrt()
        .atan2(one_plus_u.max(0.0).sqrt())
}

impl LagrangeTopMotion {
    /// The top.
    ///
    /// ```text
    /// (I₁, I₃, Mgl)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let top = LagrangeTop::new(1.0, 0.5, 1.0);
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// assert_eq!(top.try_solve(init)?.top(), top);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn top(&self) -> LagrangeTop {
        self.top
    }

    /// `a = p_ψ/I₁ = I₃ω₃/I₁`, rad/s.
    ///
    /// ```text
    /// I₁ a = I₃ (φ̇ cos θ + ψ̇)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// assert_eq!(LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?.a(), 10.0);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn a(&self) -> f64 {
        self.a
    }

    /// `b = p_φ/I₁`, rad/s.
    ///
    /// ```text
    /// I₁ b = I₁ sin²θ φ̇ + I₃ ω₃ cos θ
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// let m = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// assert!((m.b() - 10.0 * 0.5f64.cos()).abs() < 1e-14);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn b(&self) -> f64 {
        self.b
    }

    /// `α = 2E'/I₁`, with `E' = E − ½I₃ω₃²`, s⁻².
    ///
    /// ```text
    /// α = θ̇² + sin²θ φ̇² + β cos θ
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// let m = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// assert!((m.alpha() - 2.0 * 0.5f64.cos()).abs() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// `β = 2Mgl/I₁`, s⁻².
    ///
    /// ```text
    /// β = 2 Mgl / I₁
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// assert_eq!(LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?.beta(), 2.0);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn beta(&self) -> f64 {
        self.beta
    }

    /// The spin `ω₃` (constant), rad/s.
    ///
    /// ```text
    /// ω₃ = φ̇ cos θ + ψ̇
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// assert_eq!(LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?.omega3(), 20.0);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn omega3(&self) -> f64 {
        self.omega3
    }

    /// The cubic whose roots are the turning points (notes §3.10).
    ///
    /// ```text
    /// f(u) = (1 − u²)(α − βu) − (b − au)² = u̇²   (f(±1) = −(b ∓ a)²)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, theta_dot: 0.3, psi_dot: 20.0, ..Default::default() };
    /// let m = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// let udot = 0.5f64.sin() * 0.3;
    /// assert!((m.f(0.5f64.cos()) - udot * udot).abs() < 1e-13);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn f(&self, u: f64) -> f64 {
        let r = self.b - self.a * u;
        (1.0 - u * u) * (self.alpha - self.beta * u) - r * r
    }

    /// The real roots of [`f`](Self::f), ascending, with multiplicity:
    /// three for `β ≠ 0` (`u₁ ≤ u₂ ≤ 1 ≤ u₃` for β > 0, `u₃ ≤ −1 ≤ u₁ ≤ u₂`
    /// for β < 0), the two of the quadratic for `β = 0`. The third root
    /// `u₃ ≈ a²/β` of a top with a tiny β next to its spin is left out when
    /// it lies beyond the f64 range (as β → 0 it goes to infinity, and the
    /// cubic becomes the free top's quadratic).
    ///
    /// ```text
    /// f(u) = β (u − u₁)(u − u₂)(u − u₃)
    /// ```
    ///
    /// Found relative to `u₀ = cos θ₀`: divided out exactly when θ̇₀ = 0,
    /// else bracketed in `[−1, u₀]`, `[u₀, 1]` and polished by Newton; the
    /// third by Vieta (no generic cubic formula).
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, theta_dot: 0.3, psi_dot: 20.0, ..Default::default() };
    /// let m = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// let r = m.roots();
    /// assert_eq!(r.len(), 3);
    /// assert!(r[0] < 0.5f64.cos() && 0.5f64.cos() < r[1] && r[1] < 1.0 && 1.0 < r[2]);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn roots(&self) -> Vec<f64> {
        let mut r = vec![self.u0 + self.w1, self.u0 + self.w2];
        let u3 = self.u0 + self.g / self.beta;
        if self.beta != 0.0 && u3.is_finite() {
            r.push(u3);
        }
        r.sort_by(f64::total_cmp);
        r
    }

    /// The smallest θ reached (at the upper turning point `u₂`), rad.
    ///
    /// ```text
    /// θ_min = arccos u₂ = 2 atan2(√(1 − u₂), √(1 + u₂))
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, theta_dot: 0.3, psi_dot: 20.0, ..Default::default() };
    /// let m = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// assert!(m.theta_min() < 0.5 && 0.5 < m.theta_max());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn theta_min(&self) -> f64 {
        match self.kind {
            Kind::Vertical | Kind::Steady => self.init.theta,
            Kind::Nutating => theta_from(self.one_minus_u2, self.one_plus_u1 + self.delta),
        }
    }

    /// The largest θ reached (at the lower turning point `u₁`), rad.
    ///
    /// ```text
    /// θ_max = arccos u₁ = 2 atan2(√(1 − u₁), √(1 + u₁))
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// let m = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// assert!(m.theta_max() > 0.5 && m.theta_max() < 0.6);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn theta_max(&self) -> f64 {
        match self.kind {
            Kind::Vertical | Kind::Steady => self.init.theta,
            Kind::Nutating => theta_from(self.one_minus_u2 + self.delta, self.one_plus_u1),
        }
    }

    /// The period of `u(t) = cos θ(t)`, s; `None` for the sleeping top and
    /// when the period is infinite (`u₂ = u₃`: the asymptotic motion at the
    /// stability threshold).
    ///
    /// ```text
    /// T = 2K(m)/ν
    /// ```
    ///
    /// For steady precession (u₁ = u₂) this is the limit, the period of small
    /// nutations about it (`π/ν`). For a top passing through the vertical it
    /// is the period of `u` (and of the reported θ ≥ 0); the signed θ has
    /// twice that period.
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// let m = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// let t = m.nutation_period().unwrap();
    /// assert!((m.euler_at(t).theta - 0.5).abs() < 1e-12);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn nutation_period(&self) -> Option<f64> {
        if self.kind == Kind::Vertical || !self.k.is_finite() || self.nu <= 0.0 {
            return None;
        }
        Some(2.0 * self.k / self.nu)
    }

    /// The mean precession rate, rad/s: the change of φ over one nutation
    /// period divided by the period.
    ///
    /// ```text
    /// ⟨φ̇⟩ = [(b − a) Π(n₋ | m)/(1 − u_b) + (b + a) Π(n₊ | m)/(1 + u_b)] / (2K(m))
    ///      = r₁/(2(1 − u₁)) + r₂/(2(1 + u₂)) + [(b − a) R₋ + (b + a) R₊] / (4K(m)),  rᵢ = b − a uᵢ
    /// ```
    ///
    /// Evaluated in the second form: the partial fractions `½(b ∓ a)/(1 ∓ u)`
    /// are each ≈ ∓a/2 and cancel to ~Mgl/(I₃ω₃) for a fast top (at
    /// ψ̇₀ = 10¹⁰ rad/s to nothing), while their slopes `rᵢ/(2(1 ∓ uᵢ))` and
    /// the rests `Rᵢ = (Π(nᵢ | m) − K)/…` (Carlson R_J) carry no `a`. That
    /// form is accurate to rounding of the largest `|φ̇|` on the band, so it
    /// loses ~10⁻¹⁶ · max|φ̇| / |⟨φ̇⟩| when φ̇ swings far wider than its mean
    /// (a fast top kicked in θ̇: 10⁻² at ψ̇₀ = 10¹⁵ rad/s). Where its error
    /// estimate is smaller, the mean is instead expanded about the band
    /// centre `u_c = (u₁ + u₂)/2`, where the swing enters only squared:
    ///
    /// ```text
    /// ⟨φ̇⟩ = ⟨r_c h(u) − a h_c δ² (u + u_c) h(u)⟩ − a h_c ⟨δ⟩,  h = 1/(1 − u²),  δ = u − u_c
    /// ```
    ///
    /// (`r_c = b − a u_c` without cancellation, the average by the
    /// trapezoidal rule over a period, `⟨δ⟩` by a series in m), which holds
    /// such a top to ~10⁻¹⁶ relative at any spin.
    ///
    /// The initial φ̇ for steady precession; `None` where
    /// [`nutation_period`](Self::nutation_period) is `None`. Through a
    /// vertical, φ is taken without its jumps by π (the signed-θ form).
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// let m = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// let t = m.nutation_period().unwrap();
    /// let dphi = m.euler_at(t).phi - m.euler_at(0.0).phi;
    /// assert!((m.mean_precession_rate().unwrap() - dphi / t).abs() < 1e-12);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn mean_precession_rate(&self) -> Option<f64> {
        let mean = self.through_mean()?;
        let passes = self.pass_rate();
        Some(if passes == 0.0 { mean } else { mean + passes })
    }

    /// The mean precession rate without the steps of φ at close passes of
    /// a vertical (`passes`): the secular part of φ in the through form.
    pub(super) fn through_mean(&self) -> Option<f64> {
        self.nutation_period()?;
        if self.kind == Kind::Steady {
            return Some(self.init.phi_dot);
        }
        let rest = |part: &Option<(ThirdKind, f64)>, coef: f64| {
            part.as_ref()
                .map_or(0.0, |(tk, _)| 0.5 * coef * tk.per_period() / (2.0 * self.k))
        };
        let (rm, rp) = (rest(&self.minus, self.bma), rest(&self.plus, self.bpa));
        let turning = self.phi_slope + rm + rp;
        if self.minus.is_some() && self.plus.is_some() {
            // The centre expansion where its error estimate beats the
            // rounding of the turning-point form (ε · the terms it sums).
            let scale = (0.5 * self.r1.0 / (self.one_minus_u2 + self.delta)).abs()
                + (0.5 * self.r2.0 / (self.one_plus_u1 + self.delta)).abs()
                + rm.abs()
                + rp.abs();
            if let Some((centre, _)) = self
                .thin_band_mean()
                .filter(|&(_, err)| err < f64::EPSILON * scale)
            {
                return Some(centre);
            }
        }
        Some(turning)
    }

    /// The shape of the axis' path (notes §3.11), `None` for the sleeping top
    /// and steady precession (θ_min = θ_max).
    ///
    /// ```text
    /// φ̇(uᵢ) = (b − a uᵢ)/(1 − uᵢ²):  same sign → NoLoops, opposite → Loops, 0 → Cusps
    /// ```
    ///
    /// Cusps exactly when released with θ̇₀ = φ̇₀ = 0 (then `u₀` is a turning
    /// point with `b − a u₀ = 0`); otherwise when `|b − a uᵢ|` is below
    /// 10⁻¹² of the terms it is formed from (`|sin²θ₀ φ̇₀| + |a (uᵢ − u₀)|`,
    /// or `|b ∓ a| + |a (1 ∓ uᵢ)|` near a pole). At a turning point exactly at the vertical
    /// (`b = ±a`) the limit `φ̇ = (b ± a)/2 · 1/(1 ± u)` decides.
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial, TopMotionKind};
    /// let top = LagrangeTop::new(1.0, 0.5, 1.0);
    /// let init = LagrangeTopInitial { theta: 0.5, phi_dot: -0.5, psi_dot: 20.0, ..Default::default() };
    /// assert_eq!(top.try_solve(init)?.motion(), Some(TopMotionKind::Loops));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn motion(&self) -> Option<TopMotionKind> {
        if self.kind != Kind::Nutating {
            return None;
        }
        if self.init.theta_dot == 0.0 && self.init.phi_dot == 0.0 {
            return Some(TopMotionKind::Cusps);
        }
        let rate = |r: (f64, f64), at_top: bool| -> f64 {
            // A close pass: φ̇ ≈ (b ∓ a)/(2(1 ∓ u)) there, of the sign of b ∓ a.
            if at_top && self.pass_top != 0.0 {
                return self.pass_top;
            }
            if !at_top && self.pass_bottom != 0.0 {
                return self.pass_bottom;
            }
            if at_top && self.through_top {
                return self.bpa;
            }
            if !at_top && self.through_bottom {
                return self.bma;
            }
            if r.0.abs() <= CUSP_TOLERANCE * r.1 {
                0.0
            } else {
                r.0
            }
        };
        let (r1, r2) = (rate(self.r1, false), rate(self.r2, true));
        Some(if r1 == 0.0 || r2 == 0.0 {
            TopMotionKind::Cusps
        } else if (r1 > 0.0) == (r2 > 0.0) {
            TopMotionKind::NoLoops
        } else {
            TopMotionKind::Loops
        })
    }

    /// Whether this motion's spin would keep the upright top stable
    /// ([`LagrangeTop::sleeping_stable`] with [`omega3`](Self::omega3)).
    ///
    /// ```text
    /// ω₃² > 4 I₁ Mgl / I₃²
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { psi_dot: 5.0, ..Default::default() };
    /// let m = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// assert!(m.is_sleeping() && m.sleeping_stable());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn sleeping_stable(&self) -> bool {
        self.top.sleeping_stable(self.omega3)
    }

    /// Whether this is the sleeping top: started upright at rest in θ
    /// (θ₀ = 0 and θ̇₀ = 0, exactly), spinning about the vertical forever.
    ///
    /// ```text
    /// θ₀ = 0,  θ̇₀ = 0  ⇒  θ(t) = 0,  φ + ψ = φ₀ + ψ₀ + ω₃ t
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 1e-9, psi_dot: 5.0, ..Default::default() };
    /// assert!(!LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?.is_sleeping());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn is_sleeping(&self) -> bool {
        self.kind == Kind::Vertical
    }

    /// The effective potential of the θ motion (notes §3.10), J.
    ///
    /// ```text
    /// V_eff(θ) = ½ I₁ (b − a cos θ)² / sin²θ + Mgl cos θ,   E' = ½ I₁ θ̇² + V_eff(θ)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// let m = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// // Released at rest in θ: E' = V_eff(θ₀) = ½ I₁ α.
    /// assert!((m.effective_potential(0.5) - 0.5 * m.alpha()).abs() < 1e-15);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn effective_potential(&self, theta: f64) -> f64 {
        let (s, c) = theta.sin_cos();
        let r = self.b - self.a * c;
        0.5 * self.top.i1 * r * r / (s * s) + self.top.mgl * c
    }
}
