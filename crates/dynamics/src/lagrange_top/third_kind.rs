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

use crate::elliptic::{carlson_rf, carlson_rj};

/// One antiderivative `T(τ)` of `1/h(τ)` (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ThirdKind {
    /// Characteristic of the Π evaluated (`n`, or `N` for the shifted form).
    n: f64,
    /// `1 − n` (or `1 − N`), exact to rounding.
    one_minus_n: f64,
    /// Factor in front of Π.
    scale: f64,
    /// Factor in front of τ' (shifted form only, else 0).
    linear: f64,
    /// Whether the argument is shifted by −K.
    shifted: bool,
    /// Π(n | m) (complete).
    complete: f64,
    m: f64,
    mc: f64,
    k: f64,
}

impl ThirdKind {
    /// The antiderivative of `1/(h_b − B sn²τ)` with `h_o = h_b − B`; `k` = K(m).
    pub fn new(h_b: f64, b: f64, h_o: f64, m: f64, mc: f64, k: f64) -> ThirdKind {
        let n = b / h_b;
        let one_minus_n = h_o / h_b;
        if n >= 0.0 {
            let complete = complete_pi(n, one_minus_n, mc, k);
            ThirdKind {
                n,
                one_minus_n,
                scale: 1.0 / h_b,
                linear: 0.0,
                shifted: false,
                complete,
                m,
                mc,
                k,
            }
        } else {
            let big_n = (m - n) / one_minus_n;
            let one_minus_big_n = mc / one_minus_n;
            let n_minus_m = -n * mc / one_minus_n;
            let pre = 1.0 / (h_b * one_minus_n);
            ThirdKind {
                n: big_n,
                one_minus_n: one_minus_big_n,
                scale: pre * n_minus_m / big_n,
                linear: pre * m / big_n,
                shifted: true,
                complete: complete_pi(big_n, one_minus_big_n, mc, k),
                m,
                mc,
                k,
            }
        }
    }

    /// `T(τ)` from `τ` and `(sn τ, cn τ, dn τ)`.
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
        let mut v = incomplete_pi(self.n, self.one_minus_n, s, c, dn * dn);
        if j != 0.0 {
            v += 2.0 * j * self.complete;
        }
        self.scale * v + self.linear * tau
    }

    /// The increase of `T` over one period `τ → τ + 2K`.
    pub fn per_period(&self) -> f64 {
        self.scale * 2.0 * self.complete + self.linear * 2.0 * self.k
    }

    /// The parameter m (for tests).
    #[cfg(test)]
    pub fn m(&self) -> f64 {
        self.m
    }
}

/// Π(n; r | m) for `|r| ≤ π/2` from `sin r`, `cos r ≥ 0`, `Δ² = 1 − m sin²r`.
fn incomplete_pi(n: f64, one_minus_n: f64, s: f64, c: f64, d2: f64) -> f64 {
    let c2 = c * c;
    let s2 = s * s;
    let mut v = s * carlson_rf(c2, d2, 1.0);
    if n != 0.0 && s != 0.0 {
        let p = if n >= 0.5 {
            c2 + one_minus_n * s2
        } else {
            1.0 - n * s2
        };
        v += n / 3.0 * s * s2 * carlson_rj(c2, d2, 1.0, p);
    }
    v
}

/// Π(n | m) from `1 − n` and `mc`; `k` = K(m).
fn complete_pi(n: f64, one_minus_n: f64, mc: f64, k: f64) -> f64 {
    if n == 0.0 {
        k
    } else {
        k + n / 3.0 * carlson_rj(0.0, mc, 1.0, one_minus_n)
    }
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
            let t = ThirdKind::new(h_b, b, h_b - b, m, mc, k);
            assert_eq!(t.m(), m);
            let n = b / h_b;
            let t0 = {
                let (s, c, d) = jac.sn_cn_dn(0.0);
                t.eval(0.0, s, c, d)
            };
            for tau in [0.1, 1.0, 2.5, 7.0, -3.0] {
                let (s, c, d) = jac.sn_cn_dn(tau);
                let got = t.eval(tau, s, c, d) - t0;
                let want = legendre_pi(jac.amplitude(tau), n, m) / h_b;
                assert!(
                    (got - want).abs() < 1e-13 * want.abs().max(1.0),
                    "{h_b} {b} {tau}: {got} {want}"
                );
            }
        }
    }
}
