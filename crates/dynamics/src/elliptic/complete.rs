//! Legendre's complete elliptic integrals K, E, Π through Carlson's symmetric
//! integrals, each by the parameter `m` and by the complementary parameter
//! `mc = 1 − m`.

use super::carlson::{carlson_rd, carlson_rf, carlson_rj};

/// Below this mc, E(m) = 1 + (mc/4)(ln(16/mc) − 1) to rounding (next term ~mc² ln mc).
const E_ASYMPTOTIC: f64 = 1e-18;

/// Complete elliptic integral of the first kind K(m).
///
/// ```text
/// K(m) = ∫₀^{π/2} dθ / √(1 − m sin²θ) = R_F(0, 1 − m, 1)
/// ```
///
/// Domain `m ≤ 1` (`m < 0` allowed); `+∞` at `m = 1`, NaN for `m > 1` or NaN.
/// For m near 1 use [`complete_k_complementary`], since `1 − m` in f64 cannot
/// be below 1.1·10⁻¹⁶. Relative error ≤ 5·10⁻¹⁶ measured.
///
/// ```
/// use kreisel_dynamics::elliptic::complete_k;
/// assert!((complete_k(0.0) - std::f64::consts::FRAC_PI_2).abs() < 3e-16);
/// assert!((complete_k(0.5) - 1.854_074_677_301_372).abs() < 5e-16);
/// ```
///
/// Reference: DLMF 19.2.8, 19.25.1; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn complete_k(m: f64) -> f64 {
    if m.is_nan() || m > 1.0 {
        return f64::NAN;
    }
    complete_k_complementary(1.0 - m)
}

/// Complete elliptic integral of the first kind as a function of `mc = 1 − m`.
///
/// ```text
/// K = R_F(0, mc, 1) = ln(4/√mc) + (mc/4)(ln(4/√mc) − 1) + O(mc² ln mc)  (mc → 0)
/// ```
///
/// Well conditioned for `mc → 0` (no `1 − m` is formed): full relative
/// accuracy down to the smallest subnormal mc (K(5·10⁻³²⁴) ≈ 373.6).
/// Domain `mc ≥ 0`; `+∞` at `mc = 0`, NaN for `mc < 0` or NaN; 0 at `+∞`.
/// Relative error ≤ 5·10⁻¹⁶ measured.
///
/// ```
/// use kreisel_dynamics::elliptic::complete_k_complementary;
/// let mc: f64 = 1e-300;
/// let asymptotic = (4.0 / mc.sqrt()).ln(); // error ~mc ln mc
/// assert!((complete_k_complementary(mc) - asymptotic).abs() < 1e-13);
/// ```
///
/// Reference: DLMF 19.25.1, 19.12.1; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn complete_k_complementary(mc: f64) -> f64 {
    if mc.is_nan() || mc < 0.0 {
        return f64::NAN;
    }
    carlson_rf(0.0, mc, 1.0)
}

/// Complete elliptic integral of the second kind E(m).
///
/// ```text
/// E(m) = ∫₀^{π/2} √(1 − m sin²θ) dθ = (mc/3)(R_D(0, mc, 1) + R_D(0, 1, mc)),  mc = 1 − m
/// ```
///
/// Domain `m ≤ 1`; `E(1) = 1`; NaN for `m > 1` or NaN. All terms are
/// positive (no cancellation). Relative error ≤ 4·10⁻¹⁶ measured.
///
/// ```
/// use kreisel_dynamics::elliptic::{complete_e, complete_k};
/// // Legendre's relation at m = 1/2: 2EK − K² = π/2
/// let (e, k) = (complete_e(0.5), complete_k(0.5));
/// assert!((2.0 * e * k - k * k - std::f64::consts::FRAC_PI_2).abs() < 2e-15);
/// ```
///
/// Reference: DLMF 19.2.8, 19.25.1; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn complete_e(m: f64) -> f64 {
    if m.is_nan() || m > 1.0 {
        return f64::NAN;
    }
    complete_e_complementary(1.0 - m)
}

/// Complete elliptic integral of the second kind as a function of `mc = 1 − m`.
///
/// ```text
/// E = (mc/3)(R_D(0, mc, 1) + R_D(0, 1, mc))
///   = 1 + (mc/4)(ln(16/mc) − 1) + O(mc² ln mc)   (used for mc < 10⁻¹⁸)
/// ```
///
/// Domain `mc ≥ 0`; `1` at `mc = 0`, NaN for `mc < 0` or NaN.
/// Relative error ≤ 4·10⁻¹⁶ measured, mc from 5·10⁻³²⁴ to 10³.
///
/// ```
/// use kreisel_dynamics::elliptic::complete_e_complementary;
/// assert!((complete_e_complementary(1.0) - std::f64::consts::FRAC_PI_2).abs() < 5e-16);
/// assert!((complete_e_complementary(1e-30) - 1.0).abs() < 1e-28);
/// ```
///
/// Reference: DLMF 19.25.1, 19.12.2; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn complete_e_complementary(mc: f64) -> f64 {
    if mc.is_nan() || mc < 0.0 {
        return f64::NAN;
    }
    if mc == f64::INFINITY {
        return f64::INFINITY;
    }
    if mc == 0.0 {
        return 1.0;
    }
    if mc < E_ASYMPTOTIC {
        return 1.0 + 0.25 * mc * (16f64.ln() - mc.ln() - 1.0);
    }
    mc / 3.0 * (carlson_rd(0.0, mc, 1.0) + carlson_rd(0.0, 1.0, mc))
}

/// Complete elliptic integral of the third kind Π(n | m).
///
/// ```text
/// Π(n | m) = ∫₀^{π/2} dθ / ((1 − n sin²θ) √(1 − m sin²θ))
///          = R_F(0, mc, 1) + (n/3) R_J(0, mc, 1, 1 − n)
/// ```
///
/// See [`complete_pi_complementary`] for the method, domain and accuracy.
///
/// ```
/// use kreisel_dynamics::elliptic::{complete_k, complete_pi};
/// assert_eq!(complete_pi(0.0, 0.3), complete_k(0.3));
/// // Π(n | 0) = π / (2√(1 − n))
/// assert!((complete_pi(-3.0, 0.0) - std::f64::consts::FRAC_PI_4).abs() < 3e-16);
/// ```
///
/// Reference: DLMF 19.2.8, 19.25.2; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn complete_pi(n: f64, m: f64) -> f64 {
    if m.is_nan() || m > 1.0 {
        return f64::NAN;
    }
    complete_pi_core(n, m, 1.0 - m)
}

/// Complete elliptic integral of the third kind Π(n | m) as a function of `mc = 1 − m`.
///
/// ```text
/// 0 ≤ n < 1:  Π = R_F(0, mc, 1) + (n/3) R_J(0, mc, 1, 1 − n)
/// n < 0 ≤ m:  Π = m/(m − n) K + (−n mc)/((1 − n)(m − n)) Π(N),  N = (m − n)/(1 − n)
/// n > 1:      Π = −(m/(3n)) R_J(0, mc, 1, 1 − m/n)        (Cauchy principal value)
/// ```
///
/// For `m ≥ 0` every form adds terms of one sign (DLMF 19.6.5 and §19.7(iii)
/// map n < 0 and n > 1 into (0, 1)), also for mc → 0; only `m < 0, n < 0`
/// keeps the first form, whose terms partly cancel. Relative error ≤ 2.3·10⁻¹⁵
/// measured (the worst at m = −10, n = −100), ≤ 5·10⁻¹⁶ for n > 1.
/// Domain `mc ≥ 0`, `n ≠ 1`; `+∞` at `n = 1` and at `mc = 0` (n < 1), `−∞`
/// at `mc = 0` (n > 1); NaN for `mc < 0` or NaN.
///
/// ```
/// use kreisel_dynamics::elliptic::{complete_k_complementary, complete_pi_complementary};
/// // mc → 0: Π(n | m) = (K(m) − √n artanh √n)/(1 − n) + O(mc ln mc)
/// let mc = 1e-300;
/// let limit = (complete_k_complementary(mc) - 0.5 * 0.5f64.atanh()) / 0.75;
/// assert!((complete_pi_complementary(0.25, mc) - limit).abs() < 1e-13);
/// ```
///
/// Reference: DLMF 19.6.5, 19.7(iii), 19.25.2; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn complete_pi_complementary(n: f64, mc: f64) -> f64 {
    if mc.is_nan() || mc < 0.0 {
        return f64::NAN;
    }
    complete_pi_core(n, 1.0 - mc, mc)
}

pub(super) fn complete_pi_core(n: f64, m: f64, mc: f64) -> f64 {
    if n.is_nan() || mc.is_nan() {
        return f64::NAN;
    }
    if n == 1.0 {
        return f64::INFINITY;
    }
    if mc == 0.0 {
        return if n < 1.0 {
            f64::INFINITY
        } else {
            f64::NEG_INFINITY
        };
    }
    let k = carlson_rf(0.0, mc, 1.0);
    if n > 1.0 {
        // Π(n) = K − Π(m/n) = −(m/(3n)) R_J(0, mc, 1, 1 − m/n), 1 − m/n = (n − 1 + mc)/n
        if m == 0.0 {
            return 0.0;
        }
        return -(m / (3.0 * n)) * carlson_rj(0.0, mc, 1.0, ((n - 1.0) + mc) / n);
    }
    if n < 0.0 && m >= 0.0 {
        let nc = 1.0 - n;
        let m_minus_n = nc - mc;
        let big_n = m_minus_n / nc;
        let pi_big_n = k + big_n / 3.0 * carlson_rj(0.0, mc, 1.0, mc / nc);
        return m / m_minus_n * k + (-n * mc) / (nc * m_minus_n) * pi_big_n;
    }
    if n == 0.0 {
        return k;
    }
    k + n / 3.0 * carlson_rj(0.0, mc, 1.0, 1.0 - n)
}
