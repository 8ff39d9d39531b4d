//! The Lagrange top — a heavy symmetric top on a fixed pivot — in closed form.
//!
//! A body with moments `I₁ = I₂` about the pivot and `I₃` about its symmetry
//! axis (body `e₃`), centre of mass on that axis at distance `l` from the
//! pivot. Euler angles (φ, θ, ψ) are intrinsic ZXZ,
//! `world_from_body = Rz(φ)·Rx(θ)·Rz(ψ)`, θ from the upward vertical, so the
//! potential is `+Mgl cos θ` (notes §3.8–3.11, ERRATA for their typos;
//! Goldstein, *Classical Mechanics*, §5.7; Landau & Lifshitz, *Mechanics*, §35).
//!
//! ```text
//! L = ½I₁(θ̇² + sin²θ φ̇²) + ½I₃(φ̇ cos θ + ψ̇)² − Mgl cos θ
//! ω₃ = φ̇ cos θ + ψ̇,  I₁a = p_ψ = I₃ω₃,  I₁b = p_φ = I₁ sin²θ φ̇ + I₃ω₃ cos θ
//! α = 2E'/I₁ (E' = E − ½I₃ω₃²),  β = 2Mgl/I₁,  u = cos θ
//! u̇² = f(u) = (1 − u²)(α − βu) − (b − au)²
//! φ̇ = (b − au)/(1 − u²),  ψ̇ = I₁a/I₃ − u (b − au)/(1 − u²)
//! ```
//!
//! [`LagrangeTop::try_solve`] turns initial Euler angles and rates into a
//! [`LagrangeTopMotion`]: `u(t)` by Jacobi's `sn²` between the turning points,
//! φ and ψ by elliptic integrals of the third kind (Byrd & Friedman,
//! *Handbook of Elliptic Integrals*, 1971), evaluated at any `t` without
//! integrating.

mod centre;
mod classify;
mod evaluate;
mod from_initial;
mod heavy;
mod motion;
mod passes;
mod roots;
mod steady;
#[cfg(test)]
mod tests;
mod third_kind;

pub use heavy::HeavyTopClosedForm;
pub use motion::LagrangeTopMotion;

use crate::DynamicsError;

/// A symmetric heavy top: moments about the pivot and the gravity moment.
///
/// ```text
/// I₁ = I₂ (about the pivot),  I₃ (symmetry axis, body e₃),  V = Mgl cos θ
/// ```
///
/// ```
/// use kreisel_dynamics::LagrangeTop;
/// let top = LagrangeTop::try_new(1.25, 0.5, 1.0)?;
/// assert_eq!((top.i1(), top.i3(), top.mgl()), (1.25, 0.5, 1.0));
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LagrangeTop {
    i1: f64,
    i3: f64,
    mgl: f64,
}

/// Initial Euler angles (intrinsic ZXZ, rad) and their rates (rad/s).
///
/// ```text
/// world_from_body = Rz(φ)·Rx(θ)·Rz(ψ),  θ from the upward vertical
/// ```
///
/// ```
/// use kreisel_dynamics::LagrangeTopInitial;
/// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
/// assert_eq!(init.phi_dot, 0.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LagrangeTopInitial {
    /// Precession angle φ, rad.
    pub phi: f64,
    /// Nutation angle θ from the upward vertical, rad.
    pub theta: f64,
    /// Spin angle ψ, rad.
    pub psi: f64,
    /// φ̇, rad/s.
    pub phi_dot: f64,
    /// θ̇, rad/s.
    pub theta_dot: f64,
    /// ψ̇, rad/s.
    pub psi_dot: f64,
}

/// The two precession rates φ̇ of a steady precession at a given θ and spin.
///
/// ```text
/// I₁ cos θ φ̇² − I₃ω₃ φ̇ + Mgl = 0;  slow: the root of smaller |φ̇|
/// ```
///
/// ```
/// use kreisel_dynamics::LagrangeTop;
/// let p = LagrangeTop::new(1.0, 0.5, 1.0).steady_precession_rates(20.0, 0.5).unwrap();
/// assert!(p.slow.abs() < p.fast.abs());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyPrecession {
    /// The slow precession rate φ̇, rad/s (≈ Mgl/(I₃ω₃) for a fast top).
    pub slow: f64,
    /// The fast precession rate φ̇, rad/s (≈ I₃ω₃/(I₁ cos θ) for a fast top).
    pub fast: f64,
}

/// How the symmetry axis traces its path on the sphere (notes §3.11).
///
/// ```text
/// sign of φ̇ = (b − a u)/(1 − u²) at the turning points u₁, u₂:
/// same sign → NoLoops;  opposite → Loops;  zero at one → Cusps
/// ```
///
/// ```
/// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial, TopMotionKind};
/// // Released with θ̇ = φ̇ = 0: the axis falls, then rises back with cusps.
/// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
/// let motion = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
/// assert_eq!(motion.motion(), Some(TopMotionKind::Cusps));
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TopMotionKind {
    /// φ̇ keeps its sign: the axis precesses in undulations.
    NoLoops,
    /// φ̇ changes sign: the axis traces loops.
    Loops,
    /// φ̇ vanishes at a turning point: the axis traces cusps (released from rest).
    Cusps,
}

/// Euler angles (intrinsic ZXZ) and their rates at one instant.
///
/// ```text
/// ω₁ = φ̇ sin θ sin ψ + θ̇ cos ψ,  ω₂ = φ̇ sin θ cos ψ − θ̇ sin ψ,  ω₃ = φ̇ cos θ + ψ̇
/// ```
///
/// ```
/// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
/// let init = LagrangeTopInitial { theta: 0.5, phi_dot: 0.3, psi_dot: 20.0, ..Default::default() };
/// let e = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?.euler_at(0.0);
/// assert!((e.theta - 0.5).abs() < 1e-15 && (e.phi_dot - 0.3).abs() < 1e-14);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EulerAnglesAndRates {
    /// Precession angle φ, rad (continuous in t, not wrapped).
    pub phi: f64,
    /// Nutation angle θ ∈ [0, π], rad.
    pub theta: f64,
    /// Spin angle ψ, rad (continuous in t, not wrapped).
    pub psi: f64,
    /// φ̇, rad/s.
    pub phi_dot: f64,
    /// θ̇, rad/s.
    pub theta_dot: f64,
    /// ψ̇, rad/s.
    pub psi_dot: f64,
}

fn check(parameter: &'static str, value: f64, positive: bool) -> Result<(), DynamicsError> {
    if !value.is_finite() {
        return Err(DynamicsError::InvalidTop {
            parameter,
            value,
            reason: "must be finite",
        });
    }
    if positive && value <= 0.0 {
        return Err(DynamicsError::InvalidTop {
            parameter,
            value,
            reason: "must be positive",
        });
    }
    Ok(())
}

impl LagrangeTop {
    /// A top with moments `i1` (about a transverse axis through the pivot),
    /// `i3` (about the symmetry axis) and gravity moment `mgl = M g l`.
    ///
    /// ```text
    /// 0 < I₃ ≤ 2 I₁ (normal f64s);  Mgl finite, any sign (< 0: centre of mass below the pivot; 0: free top)
    /// I₁ (pivot) = I₁,cm + M l² ≥ I₁,cm ≥ I₃/2   since I₁,cm + I₂,cm − I₃ = 2 ∫ z² dm ≥ 0
    /// ```
    ///
    /// Every real body has `I₃ ≤ 2 I₁`: about the centre of mass the
    /// principal moments obey the triangle inequality `I₃ ≤ I₁ + I₂ = 2 I₁`
    /// (the difference is twice the second moment of the mass along the
    /// axis), and moving the transverse axis to the pivot only adds `M l²`
    /// (`I₃` is unchanged, the pivot being on the axis). Equality is a flat
    /// disc pivoted at its centre; `I₃` up to 4 ulp above `2 I₁` is accepted
    /// as that disc after rounding.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidTop`] for a non-finite value, `i1` or `i3`
    /// not positive or subnormal (below 2.2·10⁻³⁰⁸: the rates of such a top
    /// overflow f64; choose larger units), `i3 > 2 i1`, or
    /// `β = 2 Mgl/I₁` overflowing or underflowing f64.
    ///
    /// ```
    /// use kreisel_dynamics::LagrangeTop;
    /// assert!(LagrangeTop::try_new(1.0, 0.5, -2.0).is_ok());
    /// assert!(LagrangeTop::try_new(1.0, 2.0, 1.0).is_ok()); // a disc about its centre
    /// assert!(LagrangeTop::try_new(1.0, 2.1, 1.0).is_err()); // no such body
    /// assert!(LagrangeTop::try_new(0.0, 0.5, 1.0).is_err());
    /// assert!(LagrangeTop::try_new(1e-320, 1e-320, 1.0).is_err());
    /// assert!(LagrangeTop::try_new(1.0, f64::NAN, 1.0).is_err());
    /// ```
    pub fn try_new(i1: f64, i3: f64, mgl: f64) -> Result<Self, DynamicsError> {
        check("i1", i1, true)?;
        check("i3", i3, true)?;
        check("mgl", mgl, false)?;
        for (parameter, value) in [("i1", i1), ("i3", i3)] {
            if !value.is_normal() {
                return Err(DynamicsError::InvalidTop {
                    parameter,
                    value,
                    reason: "is subnormal (below 2.2e-308 kg m^2): choose larger units",
                });
            }
        }
        if i3 > 2.0 * i1 * (1.0 + 4.0 * f64::EPSILON) {
            return Err(DynamicsError::InvalidTop {
                parameter: "i3",
                value: i3,
                reason: "exceeds 2 i1: no real body has it (I3 <= I1 + I2 = 2 I1; I1 is about the pivot)",
            });
        }
        let beta = 2.0 * mgl / i1;
        if !beta.is_finite() || (mgl != 0.0 && !beta.is_normal()) {
            return Err(DynamicsError::InvalidTop {
                parameter: "mgl",
                value: mgl,
                reason: "2 mgl / i1 is not representable in f64 (overflow or underflow): choose other units",
            });
        }
        Ok(LagrangeTop { i1, i3, mgl })
    }

    /// Like [`LagrangeTop::try_new`], panicking on bad input.
    ///
    /// ```text
    /// LagrangeTop::new(i1, i3, mgl) = LagrangeTop::try_new(i1, i3, mgl).unwrap()
    /// ```
    ///
    /// # Panics
    /// Where [`LagrangeTop::try_new`] returns an error.
    ///
    /// ```
    /// use kreisel_dynamics::LagrangeTop;
    /// assert_eq!(LagrangeTop::new(2.0, 1.0, 0.0).mgl(), 0.0);
    /// ```
    pub fn new(i1: f64, i3: f64, mgl: f64) -> Self {
        match Self::try_new(i1, i3, mgl) {
            Ok(top) => top,
            Err(e) => panic!("{e}"),
        }
    }

    /// The moment of inertia I₁ = I₂ about a transverse axis through the pivot, kg·m².
    ///
    /// ```text
    /// I₁ = I₁,cm + M l²
    /// ```
    ///
    /// ```
    /// assert_eq!(kreisel_dynamics::LagrangeTop::new(2.0, 1.0, 0.5).i1(), 2.0);
    /// ```
    pub fn i1(&self) -> f64 {
        self.i1
    }

    /// The moment of inertia I₃ about the symmetry axis, kg·m².
    ///
    /// ```text
    /// I₃ = ∫ (x² + y²) dm  (body axes)
    /// ```
    ///
    /// ```
    /// assert_eq!(kreisel_dynamics::LagrangeTop::new(2.0, 1.0, 0.5).i3(), 1.0);
    /// ```
    pub fn i3(&self) -> f64 {
        self.i3
    }

    /// The gravity moment M g l, J (l > 0: centre of mass above the pivot at θ = 0).
    ///
    /// ```text
    /// V(θ) = Mgl cos θ
    /// ```
    ///
    /// ```
    /// assert_eq!(kreisel_dynamics::LagrangeTop::new(2.0, 1.0, 0.5).mgl(), 0.5);
    /// ```
    pub fn mgl(&self) -> f64 {
        self.mgl
    }

    /// Whether the upright ("sleeping") top spinning at `omega3` is stable
    /// (notes §3.11; Goldstein §5.7).
    ///
    /// ```text
    /// stable ⇔ ω₃² > 4 I₁ Mgl / I₃²   (always for Mgl < 0)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::LagrangeTop;
    /// let top = LagrangeTop::new(1.0, 0.5, 1.0); // threshold ω₃ = 4
    /// assert!(top.sleeping_stable(4.01) && !top.sleeping_stable(3.99));
    /// ```
    pub fn sleeping_stable(&self, omega3: f64) -> bool {
        let l3 = self.i3 * omega3;
        l3 * l3 > 4.0 * self.i1 * self.mgl
    }

    /// The motion from initial Euler angles and rates, in closed form.
    ///
    /// ```text
    /// a = I₃ω₃/I₁,  b = sin²θ₀ φ̇₀ + a cos θ₀,  α = θ̇₀² + sin²θ₀ φ̇₀² + β cos θ₀,  β = 2Mgl/I₁
    /// ```
    ///
    /// θ₀ must lie in [0, π] (the angle from the upward vertical; the
    /// equivalent attitude `(φ + π, −θ, ψ − π)` is the caller's choice to
    /// make). The f64 nearest π (and anything within 2·10⁻¹⁶ of π) is
    /// taken as π; a θ₀ just above 0 is kept (10⁻¹⁵ rad nutates in a band of
    /// that size, continuous with 10⁻⁸).
    ///
    /// # Errors
    /// [`DynamicsError::InvalidTop`] if an angle or rate is not finite, θ₀
    /// is outside [0, π], or a rate is so large that the constants of the
    /// motion overflow f64 (`(I₃ω₃/I₁)²`, `θ̇₀² + sin²θ₀ φ̇₀²`, the
    /// coefficients of f(u), the frequency of the nutation), or so small
    /// that a turning point lies closer to a vertical than `1 ∓ cos θ`
    /// resolves on a band that small too (θ₀ below ~10⁻⁸⁰ with a stable
    /// spin), or whose momentum `I₃ω₃/I₁`, `sin²θ₀ φ̇₀` underflows to 0. A
    /// tiny spin released off the vertical (ψ̇₀ = 10⁻³⁰⁰ rad/s) is solved:
    /// the axis passes the vertical closer than f64 resolves, as in the
    /// limit, φ and ψ stepping by π there.
    ///
    /// ```
    /// use kreisel_dynamics::{LagrangeTop, LagrangeTopInitial};
    /// let init = LagrangeTopInitial { theta: 0.5, psi_dot: 20.0, ..Default::default() };
    /// let motion = LagrangeTop::new(1.0, 0.5, 1.0).try_solve(init)?;
    /// // Released from rest at θ = 0.5, the axis first falls.
    /// assert!((motion.theta_min() - 0.5).abs() < 1e-15);
    /// assert!(motion.theta_max() > 0.5);
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_solve(
        &self,
        initial: LagrangeTopInitial,
    ) -> Result<LagrangeTopMotion, DynamicsError> {
        let LagrangeTopInitial {
            phi,
            theta,
            psi,
            phi_dot,
            theta_dot,
            psi_dot,
        } = initial;
        for (name, v) in [
            ("phi", phi),
            ("theta", theta),
            ("psi", psi),
            ("phi_dot", phi_dot),
            ("theta_dot", theta_dot),
            ("psi_dot", psi_dot),
        ] {
            check(name, v, false)?;
        }
        if !(0.0..=std::f64::consts::PI).contains(&theta) {
            return Err(DynamicsError::InvalidTop {
                parameter: "theta",
                value: theta,
                reason: "must lie in [0, pi] (the angle of the axis from the upward vertical)",
            });
        }
        let too_large = |parameter, value| DynamicsError::InvalidTop {
            parameter,
            value,
            reason: "too large: the constants of the motion overflow f64 (choose other units)",
        };
        let omega3 = phi_dot * theta.cos() + psi_dot;
        let a = self.i3 * omega3 / self.i1;
        if !(a * a * 4.0).is_finite() {
            return Err(if (phi_dot * theta.cos()).abs() > psi_dot.abs() {
                too_large("phi_dot", phi_dot)
            } else {
                too_large("psi_dot", psi_dot)
            });
        }
        let s = theta.sin();
        let b0 = s * s * phi_dot;
        // A rate whose momentum underflows to 0 would silently become 0.
        let lost = |momentum: f64, from: f64| momentum == 0.0 && from != 0.0;
        if lost(a, omega3) || lost(b0, s * phi_dot) {
            let (parameter, value) = if lost(a, omega3) && psi_dot != 0.0 {
                ("psi_dot", psi_dot)
            } else {
                ("phi_dot", phi_dot)
            };
            return Err(DynamicsError::InvalidTop {
                parameter,
                value,
                reason: "too small: its angular momentum underflows f64 (use 0 or a larger value)",
            });
        }
        let a0 = theta_dot * theta_dot + b0 * phi_dot;
        if !(a0 * 4.0).is_finite() || !(a * b0 * 4.0).is_finite() {
            return Err(if theta_dot.abs() >= phi_dot.abs() {
                too_large("theta_dot", theta_dot)
            } else {
                too_large("phi_dot", phi_dot)
            });
        }
        let beta = 2.0 * self.mgl / self.i1;
        if !((a0 + a * a + beta.abs()) * 4.0).is_finite() {
            return Err(too_large("psi_dot", psi_dot));
        }
        let motion = LagrangeTopMotion::new(*self, initial);
        let tiny_tilt = theta > 0.0 && theta < 1e-60;
        if motion.pole_distance_underflows() || (tiny_tilt && !motion.is_finite()) {
            return Err({
                // The axis comes closer to a vertical than 1 ∓ cos θ resolves.
                let (parameter, value) = if tiny_tilt {
                    ("theta", theta)
                } else if (phi_dot * theta.cos()).abs() > psi_dot.abs() {
                    ("phi_dot", phi_dot)
                } else {
                    ("psi_dot", psi_dot)
                };
                DynamicsError::InvalidTop {
                    parameter,
                    value,
                    reason: "too small: the axis comes closer to the vertical than f64 resolves \
                             (1 - |cos theta| underflows); use 0 (exactly on or through the vertical) \
                             or a larger value",
                }
            });
        }
        if !motion.is_finite() {
            return Err(too_large("psi_dot", psi_dot));
        }
        Ok(motion)
    }
}
