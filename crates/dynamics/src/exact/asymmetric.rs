//! The exact motion of a free asymmetric body (I₁ < I₂ < I₃): angular
//! momentum in Jacobi elliptic functions, attitude as a rotation about the
//! fixed L_world composed with the shortest rotation taking L to an axis.
//!
//! ## Body frame (Landau & Lifshitz, *Mechanics*, §37)
//! L circulates about axis `a` (the largest moment if Δ₂ > 0, the smallest if
//! Δ₂ < 0); `b` is the middle axis and `c` the remaining one:
//!
//! ```text
//! L_c = A_c cn τ,   L_b = A_b sn τ,   L_a = A_a dn τ,   τ = τ₀ + λ t,   m_c = 1 − m
//! D_k = |L² − 2E I_k|  (double-double, stability::energy_deltas)
//! A_c² = I_c D_a/|I_a − I_c|,  A_b² = I_b D_a/|I_a − I_b|,  A_a² = I_a D_c/|I_a − I_c|
//! λ² = |I_a − I_b| D_c/(I₁I₂I₃),   m_c = |I_a − I_c| D_b/(|I_a − I_b| D_c)
//! sign A_b = −ε sign(I_b − I_a) sign A_a   (ε = +1 if (c, b, a) is cyclic)
//! ```
//!
//! ## Attitude (derived here; cf. Celledoni, Fassò, Säfström & Zanna 2008,
//! van Zon & Schofield 2007, who use Euler angles about L instead)
//! With `l = L/|L|`, `e = sign(L_a) e_a` and `M(l)` the shortest rotation
//! taking `l` to `e` (never ill-conditioned: `l·e = |l_a| ≥ 0`):
//!
//! ```text
//! Q(t) = C R_e(ψ(t)) M(l(t)),   C = Q₀ M(l₀)⁻¹
//! ω·l = ψ̇ + e·(l × l̇)/(1 + l·e)   ⇒   ψ̇ = 2E/|L| − κ g/(1 + g)
//! g = l·e = c dn τ,   κ = (2E I_a − L²)/(|L| I_a),   c = |A_a|/|L|,   1 − c² = A_c²/L²
//! ψ(t) = ω̄ t − (κ/λ)(P(τ) − P(τ₀)),   ω̄ = 2E/|L| − κ h̄
//! h = g/(1 + g),  h̄ its mean,  P(τ) = ∫₀^τ (h − h̄)  (odd, period 2K)
//! ```
//!
//! (The equivalent `ψ̇ = |L|/I_a + κ/(1 + g)` loses digits when L is nearly
//! perpendicular to e_a: its two terms then nearly cancel, and for a thin
//! rod spinning at 3 rad/s they are ±224 rad/s.)
//!
//! sn, cn, dn and P are tabulated on `[0, K]` once (piecewise Chebyshev to
//! rounding) and extended by the quarter-period symmetries. On the
//! separatrix (`m_c = 0`, K = ∞) sn = tanh, cn = dn = sech and
//!
//! ```text
//! h̄ = 0,   P(τ) = (2c/√(1 − c²)) atan(√(1 − c²)/(1 + c) · tanh(τ/2))
//! ```

use glam::{DQuat, DVec3};

use super::chebyshev::PiecewiseChebyshev;
use crate::elliptic::{JacobiElliptic, complete_k_complementary, incomplete_f_complementary};
use crate::stability::energy_deltas;

/// The precomputed exact motion of an asymmetric free body.
#[derive(Clone, Debug)]
pub(crate) struct Asymmetric {
    /// Principal-frame indices of the axes `c`, `b`, `a`.
    axes: [usize; 3],
    /// Signed amplitudes `A_c`, `A_b`, `A_a`.
    amplitude: [f64; 3],
    lambda: f64,
    tau0: f64,
    /// The quarter period K, 1/K and 1/(4K) (unused on the separatrix).
    quarter: f64,
    inverse_quarter: f64,
    inverse_period: f64,
    /// sn, cn, dn, P on [0, K]; `None` on the separatrix.
    table: Option<PiecewiseChebyshev>,
    /// `c = |A_a|/|L|` and `√(1 − c²)` (for the separatrix closed form).
    c: f64,
    sqrt_one_minus_c2: f64,
    omega_bar: f64,
    kappa_over_lambda: f64,
    p0: f64,
    /// `e = sign(L_a) e_a`.
    e: DVec3,
    /// `C = Q₀ M(l₀)⁻¹`.
    frame: DQuat,
    l_norm: f64,
}

impl Asymmetric {
    /// The motion from `(q₀, L₀)` for distinct `moments`; `None` for steady
    /// rotation about a principal axis (no elliptic motion to follow).
    pub(crate) fn new(moments: DVec3, q0: DQuat, l0: DVec3) -> Option<Asymmetric> {
        let m = moments.to_array();
        let l = l0.to_array();
        let mut idx = [0, 1, 2];
        idx.sort_by(|&i, &j| m[i].total_cmp(&m[j]));
        let [d1, d2, d3] = energy_deltas(idx.map(|k| m[k]), idx.map(|k| l[k]));
        // Δ₂ ≥ 0: about the largest axis (on the separatrix either is exact).
        let (c, a, d_a, d_c) = if d2 >= 0.0 {
            (idx[0], idx[2], d3, d1)
        } else {
            (idx[2], idx[0], d1, d3)
        };
        let b = idx[1];
        let (i_a, i_b, i_c) = (m[a], m[b], m[c]);
        let amp_c = (i_c * d_a / (i_a - i_c).abs()).sqrt();
        let amp_b = (i_b * d_a / (i_a - i_b).abs()).sqrt();
        let amp_a = (i_a * d_c / (i_a - i_c).abs()).sqrt();
        if !(amp_c > 0.0 && amp_b > 0.0 && amp_a > 0.0) {
            return None;
        }
        let sign_a = if l[a] < 0.0 { -1.0 } else { 1.0 };
        let cyclic = if b == (c + 1) % 3 { 1.0 } else { -1.0 };
        let amplitude = [
            amp_c,
            -cyclic * (i_b - i_a).signum() * sign_a * amp_b,
            sign_a * amp_a,
        ];
        let lambda = ((i_a - i_b).abs() * d_c / (m[0] * m[1] * m[2])).sqrt();
        let mc = ((i_a - i_c).abs() * d2.abs() / ((i_a - i_b).abs() * d_c)).min(1.0);
        let phi0 = (l[b] / amplitude[1]).atan2(l[c] / amplitude[0]);
        let tau0 = incomplete_f_complementary(phi0, mc);
        let l_norm = l0.length();
        let energy = 0.5 * (l0 * l0 / moments).element_sum();
        let cc = amp_a / l_norm;
        let sqrt_one_minus_c2 = amp_c / l_norm;
        let (quarter, table, h_mean) = if mc > 0.0 {
            let quarter = complete_k_complementary(mc);
            let jacobi = JacobiElliptic::new(mc);
            let mut table = PiecewiseChebyshev::fit(quarter, |tau| {
                let (sn, cn, dn) = jacobi.sn_cn_dn(tau);
                glam::DVec4::new(sn, cn, dn, cc * dn / (1.0 + cc * dn))
            });
            let mean = table.integrate_lane(3);
            (quarter, Some(table), mean)
        } else {
            (f64::INFINITY, None, 0.0)
        };
        // κ = (2E I_a − L²)/(|L| I_a): +D_a about the largest axis, −D_a about the smallest.
        let kappa = if a == idx[2] { d_a } else { -d_a } / (l_norm * i_a);
        let mut e = [0.0; 3];
        e[a] = sign_a;
        let mut motion = Asymmetric {
            axes: [c, b, a],
            amplitude,
            lambda,
            tau0,
            quarter,
            inverse_quarter: 1.0 / quarter,
            inverse_period: 0.25 / quarter,
            table,
            c: cc,
            sqrt_one_minus_c2,
            omega_bar: 2.0 * energy / l_norm - kappa * h_mean,
            kappa_over_lambda: -kappa / lambda,
            p0: 0.0,
            e: DVec3::from_array(e),
            frame: DQuat::IDENTITY,
            l_norm,
        };
        motion.p0 = motion.functions(tau0)[3];
        motion.frame = q0 * motion.shortest_rotation(l0 / l_norm).conjugate();
        Some(motion)
    }

    /// `(q, L)` at time `t = t_hi + t_lo` after the initial state.
    #[inline]
    pub(crate) fn eval(&self, t_hi: f64, t_lo: f64) -> (DQuat, DVec3) {
        // λ and K carry a relative rounding error of ~ε, so the phase at t
        // is uncertain by ~ε λ t whatever the arithmetic: f64 suffices here
        // (measured: double-double phase arithmetic changed no error in
        // tests/free_body_exact.rs and cost a third of the evaluation).
        let tau = (self.lambda * t_hi + self.lambda * t_lo) + self.tau0;
        let [sn, cn, dn, p] = self.functions(tau);
        let [c, b, a] = self.axes;
        let mut l = [0.0; 3];
        l[c] = self.amplitude[0] * cn;
        l[b] = self.amplitude[1] * sn;
        l[a] = self.amplitude[2] * dn;
        let l = DVec3::from_array(l);
        let psi =
            self.omega_bar * t_hi + self.omega_bar * t_lo + self.kappa_over_lambda * (p - self.p0);
        let (s, co) = (0.5 * psi).sin_cos();
        let spin = DQuat::from_xyzw(s * self.e.x, s * self.e.y, s * self.e.z, co);
        let q = self.frame * spin * self.shortest_rotation(l / self.l_norm);
        (q, l)
    }

    /// sn, cn, dn and P at phase `tau`.
    #[inline]
    fn functions(&self, tau: f64) -> [f64; 4] {
        let Some(table) = &self.table else {
            let sech = 1.0 / tau.cosh();
            let ratio = self.sqrt_one_minus_c2 / (1.0 + self.c);
            let p = 2.0 * self.c / self.sqrt_one_minus_c2 * (ratio * (0.5 * tau).tanh()).atan();
            return [tau.tanh(), sech, sech, p];
        };
        let k = self.quarter;
        let period = 4.0 * k;
        // Reduce to [0, 4K) with the multiple of the period removed exactly
        // (a truncating cast instead of `floor`, a libm call on baseline x86-64).
        let ratio = tau * self.inverse_period;
        let mut n = ratio as i64 as f64;
        if n > ratio {
            n -= 1.0;
        }
        let mut r = tau - n * period;
        if r < 0.0 {
            r += period;
        }
        let quarter_index = ((r * self.inverse_quarter) as usize).min(3);
        let rho = r - quarter_index as f64 * k;
        let (x, s_sign, c_sign, p_sign) = match quarter_index {
            0 => (rho, 1.0, 1.0, 1.0),
            1 => (k - rho, 1.0, -1.0, -1.0),
            2 => (rho, -1.0, -1.0, 1.0),
            _ => (k - rho, -1.0, 1.0, -1.0),
        };
        let v = table.eval(x.max(0.0));
        [s_sign * v.x, c_sign * v.y, v.z, p_sign * v.w]
    }

    /// The shortest rotation `M` with `M l = e` for a unit `l` with `l·e ≥ 0`.
    ///
    /// ```text
    /// M = normalise(1 + l·e, l × e)
    /// ```
    #[inline]
    fn shortest_rotation(&self, l: DVec3) -> DQuat {
        let v = l.cross(self.e);
        DQuat::from_xyzw(v.x, v.y, v.z, 1.0 + l.dot(self.e)).normalize()
    }

    /// Time between sign changes of `L_b` and `L_c` (half the period of ω),
    /// infinite on the separatrix.
    pub(crate) fn half_period(&self) -> f64 {
        2.0 * self.quarter / self.lambda
    }

    /// The mean precession rate ω̄ about L_world, rad/s.
    pub(crate) fn mean_precession_rate(&self) -> f64 {
        self.omega_bar
    }

    /// The number of Chebyshev pieces tabulated (0 on the separatrix).
    pub(crate) fn pieces(&self) -> usize {
        self.table.as_ref().map_or(0, PiecewiseChebyshev::pieces)
    }
}
