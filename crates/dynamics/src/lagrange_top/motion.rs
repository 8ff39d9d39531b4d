//! The closed-form motion: `u = cos θ` by `sn²`, φ and ψ by Π.

use super::third_kind::ThirdKind;
use super::{LagrangeTop, LagrangeTopInitial};
use crate::elliptic::JacobiElliptic;

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
}
