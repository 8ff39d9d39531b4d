//! `∫ dt / (1 ∓ u)` along the nutation by Legendre's elliptic integral of the
//! third kind, evaluated through Carlson's R_F and R_J with the
//! characteristic's complement `1 − n` supplied exactly.
//!
//! Along the motion `u = u_b + σ Δ sn²(τ | m)` (`τ = ν t + τ₀`), so each
//! denominator is `h(τ) = h_b − B sn²τ` with `h_b = h(turning point u_b)` and
//! `h_b − B = h_o = h(other turning point)`; with `n = B/h_b`,
//! `1 − n = h_o/h_b`,
//!
//! ```text
//! ∫ dτ / h = Π(n; am τ | m) / h_b                                     (0 ≤ n < 1)
//! Π(n; jπ + r | m) = 2j Π(n | m) + Π(n; r | m),  |r| ≤ π/2
//! Π(n; r | m) = sin r R_F(cos²r, dn², 1) + (n/3) sin³r R_J(cos²r, dn², 1, 1 − n sin²r)
//! Π(n | m) = R_F(0, mc, 1) + (n/3) R_J(0, mc, 1, 1 − n)
//! ```
//!
//! (Byrd & Friedman 1971, 110.xx and 400–410; DLMF 19.2.7, 19.25.14.)
//! For `n < 0` the sum `F + (n/3)…R_J` cancels (by a factor ≈ √|n| when the
//! top comes close to the vertical it is written for), so the integrand is
//! first rewritten at the shifted argument `τ' = τ − K`, where
//! `sn²τ = cn²τ'/dn²τ'`:
//!
//! ```text
//! 1/(1 − n sn²τ) = dn²τ' / ((1 − n)(1 − N sn²τ')),  N = (m − n)/(1 − n) ∈ (m, 1)
//! ∫ dτ/(1 − n sn²τ) = [ (m/N) τ' + ((N − m)/N) Π(N; am τ' | m) ] / (1 − n)
//! N − m = −n mc/(1 − n),  1 − N = mc/(1 − n)
//! ```
//!
//! (DLMF 19.7.9; Byrd & Friedman 117.03), which has no cancellation.
//!
//! Both forms are kept apart as a mean slope `τ/h_ref` (`h_ref` = `h` at the
//! turning point farther from the pole: `h_b` unshifted, `h_o` shifted) plus
//! an oscillating rest `∝ (n/3) sin³ R_J`, never summed here: for a fast top
//! the two partial fractions of φ̇ are each ≈ ±a/2 and cancel to ~β/a, so
//! the caller adds the slopes as `r(u)/(2h)` (no `a`) and the small rests.

use crate::elliptic::{carlson_rf, carlson_rj};

/// One antiderivative `T(τ)` of `1/h(τ)`, split into its mean slope and an
/// oscillating rest (module docs):
///
/// ```text
/// T(τ) = τ / h_ref + R(τ) + const,   R(τ + 2K) = R(τ) + per_period
/// unshifted (B ≥ 0): h_ref = h_b, R = (B/h_b²) Q_n(τ)
/// shifted   (B < 0): h_ref = h_o, R = −(B mc/h_o²) Q_N(τ − K)
/// Q_n(τ) = (Π(n; am τ | m) − τ)/n = ⅓ sin³r R_J(cos²r, dn², 1, 1 − n sin²r) + (2j/3) R_J(0, mc, 1, 1 − n)
/// ```
///
/// The slope `1/h_ref` is left to the caller: summed over the two partial
/// fractions of φ̇ it cancels (`−a/2 + a/2`) unless formed as `r(u)/(2h)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ThirdKind {
    /// Characteristic of the Π evaluated (`n`, or `N` for the shifted form).
    n: f64,
    /// `1 − n` (or `1 − N`), exact to rounding.
    one_minus_n: f64,
    /// Factor in front of `Q` (`B/h_b²` or `−B mc/h_o²`).
    coef: f64,
    /// Whether the argument is shifted by −K.
    shifted: bool,
    /// ⅓ R_J(0, mc, 1, 1 − n): the complete `Q` over a half period.
    complete: f64,
    mc: f64,
    k: f64,
    #[cfg(test)]
    m: f64,
}

impl ThirdKind {
    /// The rest of the antiderivative of `1/(h_b − B sn²τ)` with
    /// `h_o = h_b − B`; `k` = K(m). Returns it with `h_ref` (`h_b` for
    /// `B ≥ 0`, else `h_o`: the larger of the two, the turning point farther
    /// from the pole).
    pub fn new(h_b: f64, b: f64, h_o: f64, m: f64, mc: f64, k: f64) -> (ThirdKind, f64) {
        let (n, one_minus_n, coef, shifted, h_ref) = if b >= 0.0 {
            (b / h_b, h_o / h_b, b / (h_b * h_b), false, h_b)
        } else {
            // Multiplied through by h_b, so that h_b → 0 (n → −∞) stays finite:
            // N = (m h_b − B)/h_o, 1 − N = mc h_b/h_o, N − m = −B mc/h_o.
            let big_n = (m * h_b - b) / h_o;
            (big_n, mc * h_b / h_o, -b * mc / (h_o * h_o), true, h_o)
        };
        let complete = if n == 0.0 {
            0.0
        } else {
            carlson_rj(0.0, mc, 1.0, one_minus_n) / 3.0
        };
        let tk = ThirdKind {
            n,
            one_minus_n,
            coef,
            shifted,
            complete,
            mc,
            k,
            #[cfg(test)]
            m,
        };
        (tk, h_ref)
    }

    /// `R(τ)` from `τ` and `(sn τ, cn τ, dn τ)`.
    pub fn eval(&self, tau: f64, sn: f64, cn: f64, dn: f64) -> f64 {
        let (tau, sn, cn, dn) = if self.shifted {
            // sn(τ − K) = −cd τ, cn(τ − K) = √mc sd τ, dn(τ − K) = √mc nd τ
            let r = self.mc.sqrt();
            (tau - self.k, -cn / dn, r * sn / dn, r / dn)
        } else {
            (tau, sn, cn, dn)
        };
        let mut j = (tau / (2.0 * self.k)).round();
        if !j.is_finite() {
            j = 0.0;
        }
        let parity = if j % 2.0 == 0.0 { 1.0 } else { -1.0 };
        let (mut s, mut c) = (parity * sn, parity * cn);
        if c < 0.0 {
            // τ sits just across a half-period boundary from the rounding of j.
            j += if s > 0.0 { 1.0 } else { -1.0 };
            s = -s;
            c = -c;
        }
        let mut v = incomplete_q(self.n, self.one_minus_n, s, c, dn * dn);
        if j != 0.0 {
            v += 2.0 * j * self.complete;
        }
        self.coef * v
    }

    /// The increase of `R` over one period `τ → τ + 2K`.
    pub fn per_period(&self) -> f64 {
        self.coef * 2.0 * self.complete
    }

    /// The parameter m (for tests).
    #[cfg(test)]
    pub fn m(&self) -> f64 {
        self.m
    }
}

/// `(Π(n; r | m) − F(r | m))/n` for `|r| ≤ π/2` from `sin r`, `cos r ≥ 0`,
/// `Δ² = 1 − m sin²r`: ⅓ sin³r R_J(cos²r, Δ², 1, 1 − n sin²r).
fn incomplete_q(n: f64, one_minus_n: f64, s: f64, c: f64, d2: f64) -> f64 {
    if s == 0.0 {
        return 0.0;
    }
    let c2 = c * c;
    let s2 = s * s;
    let p = if n >= 0.5 {
        c2 + one_minus_n * s2
    } else {
        1.0 - n * s2
    };
    s * s2 * carlson_rj(c2, d2, 1.0, p) / 3.0
}

/// K(m) = R_F(0, mc, 1).
pub(crate) fn complete_k(mc: f64) -> f64 {
    carlson_rf(0.0, mc, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::elliptic::{JacobiElliptic, incomplete_pi as legendre_pi};

    /// Both forms agree with the library's Π(n; am τ | m) for n of either sign.
    #[test]
    fn matches_legendre_pi_on_both_sides() {
        let (m, mc) = (0.3, 0.7);
        let k = complete_k(mc);
        let jac = JacobiElliptic::new(mc);
        for (h_b, b) in [(2.0, 0.5), (2.0, -0.5), (1.0, 0.9), (0.01, -0.5)] {
            let (t, h_ref) = ThirdKind::new(h_b, b, h_b - b, m, mc, k);
            assert_eq!(t.m(), m);
            assert_eq!(h_ref, h_b.max(h_b - b));
            let n = b / h_b;
            let t0 = {
                let (s, c, d) = jac.sn_cn_dn(0.0);
                t.eval(0.0, s, c, d)
            };
            for tau in [0.1, 1.0, 2.5, 7.0, -3.0] {
                let (s, c, d) = jac.sn_cn_dn(tau);
                let got = tau / h_ref + t.eval(tau, s, c, d) - t0;
                let want = legendre_pi(jac.amplitude(tau), n, m) / h_b;
                assert!(
                    (got - want).abs() < 1e-13 * want.abs().max(1.0),
                    "{h_b} {b} {tau}: {got} {want}"
                );
            }
        }
    }
}
