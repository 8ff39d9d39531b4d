//! Steady precession: the rates φ̇ at which θ stays constant.

use super::{LagrangeTop, SteadyPrecession};

impl LagrangeTop {
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
