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

mod classify;
mod motion;
mod roots;
mod third_kind;

pub use motion::LagrangeTopMotion;

use crate::DynamicsError;

/// A symmetric heavy top: moments about the pivot and the gravity moment.
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
    /// I₁ > 0, I₃ > 0 finite;  Mgl finite, any sign (< 0: centre of mass below the pivot; 0: free top)
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::InvalidTop`] for a non-finite value or `i1`, `i3` ≤ 0.
    ///
    /// ```
    /// use kreisel_dynamics::LagrangeTop;
    /// assert!(LagrangeTop::try_new(1.0, 0.5, -2.0).is_ok());
    /// assert!(LagrangeTop::try_new(0.0, 0.5, 1.0).is_err());
    /// assert!(LagrangeTop::try_new(1.0, f64::NAN, 1.0).is_err());
    /// ```
    pub fn try_new(i1: f64, i3: f64, mgl: f64) -> Result<Self, DynamicsError> {
        check("i1", i1, true)?;
        check("i3", i3, true)?;
        check("mgl", mgl, false)?;
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

    /// The slow and fast precession rates φ̇ of a steady precession at `theta`
    /// with spin `omega3` (θ̇ = θ̈ = 0 in Lagrange's θ-equation), or `None` if
    /// there is none.
    ///
    /// ```text
    /// I₁θ̈ = sin θ (I₁ cos θ φ̇² − I₃ω₃ φ̇ + Mgl) = 0
    /// q = ½(I₃ω₃ + sgn(I₃ω₃) √(I₃²ω₃² − 4 I₁ Mgl cos θ)),  fast = q/(I₁ cos θ),  slow = Mgl/q
    /// ```
    ///
    /// `None` when the discriminant is negative or θ is not finite. At
    /// `cos θ = 0` the equation is linear: `slow = Mgl/(I₃ω₃)` and `fast` is
    /// `±∞` (the limit); with also `ω₃ = 0` there is none unless `Mgl = 0`
    /// (then `slow = 0`, `fast = ∞`). θ = 0 or π are equilibria for any rate
    /// and not treated specially.
    ///
    /// ```
    /// use kreisel_dynamics::LagrangeTop;
    /// let top = LagrangeTop::new(1.0, 0.5, 1.0);
    /// let p = top.steady_precession_rates(20.0, 0.5).unwrap();
    /// for rate in [p.slow, p.fast] {
    ///     let residual = 0.5f64.cos() * rate * rate - 0.5 * 20.0 * rate + 1.0;
    ///     assert!(residual.abs() < 1e-12 * rate * rate);
    /// }
    /// assert!(top.steady_precession_rates(1.0, 0.5).is_none()); // spin too slow
    /// ```
    pub fn steady_precession_rates(&self, omega3: f64, theta: f64) -> Option<SteadyPrecession> {
        if !theta.is_finite() || !omega3.is_finite() {
            return None;
        }
        let a = self.i1 * theta.cos();
        let l3 = self.i3 * omega3;
        let c = self.mgl;
        if a == 0.0 {
            if l3 == 0.0 {
                return (c == 0.0).then_some(SteadyPrecession {
                    slow: 0.0,
                    fast: f64::INFINITY,
                });
            }
            return Some(SteadyPrecession {
                slow: c / l3,
                fast: f64::INFINITY.copysign(l3),
            });
        }
        let disc = l3 * l3 - 4.0 * a * c;
        if disc < 0.0 {
            return None;
        }
        let sign = if l3 < 0.0 { -1.0 } else { 1.0 };
        let q = 0.5 * (l3 + sign * disc.sqrt());
        if q == 0.0 {
            return Some(SteadyPrecession {
                slow: 0.0,
                fast: 0.0,
            });
        }
        Some(SteadyPrecession {
            slow: c / q,
            fast: q / a,
        })
    }

    /// The motion from initial Euler angles and rates, in closed form.
    ///
    /// ```text
    /// a = I₃ω₃/I₁,  b = sin²θ₀ φ̇₀ + a cos θ₀,  α = θ̇₀² + sin²θ₀ φ̇₀² + β cos θ₀,  β = 2Mgl/I₁
    /// ```
    ///
    /// Any finite angles: θ₀ outside [0, π] is brought there first by
    /// `(φ, θ, ψ) ≡ (φ + π, −θ, ψ − π)` (and θ̇ → −θ̇), which is the same
    /// attitude.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidTop`] if an angle or rate is not finite.
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
        Ok(LagrangeTopMotion::new(*self, initial))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steady_precession_satisfies_the_theta_equation() {
        let top = LagrangeTop::new(1.3, 0.4, 0.7);
        for (w3, th) in [(25.0, 0.3), (-25.0, 1.2), (10.0, 2.5), (3.0, 2.0)] {
            let p = top.steady_precession_rates(w3, th).unwrap();
            for r in [p.slow, p.fast] {
                let res = top.i1 * th.cos() * r * r - top.i3 * w3 * r + top.mgl;
                assert!(res.abs() < 1e-13 * (top.i3 * w3 * r).abs(), "{w3} {th} {r}");
            }
            assert!(p.slow.abs() <= p.fast.abs());
        }
        let p = top
            .steady_precession_rates(5.0, std::f64::consts::FRAC_PI_2)
            .unwrap();
        assert!((p.slow - 0.7 / 2.0).abs() < 1e-2); // cos(π/2) ≈ 6e-17
        assert!(top.steady_precession_rates(1.0, 0.3).is_none());
        assert!(top.steady_precession_rates(1.0, f64::NAN).is_none());
    }
}
