//! Legendre's incomplete elliptic integrals F, E, Π through Carlson's
//! symmetric integrals, for any amplitude φ (by quasi-periodicity), each by
//! the parameter `m` and by the complementary parameter `mc = 1 − m`.

use std::f64::consts::PI;

use super::carlson::{carlson_rd, carlson_rf, carlson_rj};
use super::complete::{complete_e_complementary, complete_pi_core};

/// π − `PI` (the low part of a two-part π for the amplitude reduction).
const PI_LO: f64 = 1.224_646_799_147_353_2e-16;

/// Splits `φ = jπ + r` with `|r| ≤ π/2` (so `cos r ≥ 0`), using a two-part π.
fn reduce_amplitude(phi: f64) -> (f64, f64) {
    let remainder = |j: f64| (-j).mul_add(PI_LO, (-j).mul_add(PI, phi));
    let j = (phi / PI).round();
    let r = remainder(j);
    if r.cos() < 0.0 {
        // φ/π rounded to a half-integer the wrong way (e.g. φ = π/2 in f64)
        let j = j + r.signum();
        return (j, remainder(j));
    }
    (j, r)
}

/// `Δ² = 1 − m sin²φ`, formed as `cos²φ + mc sin²φ` when `m ∈ [½, 1]`.
fn delta_squared(s: f64, c: f64, m: f64, mc: f64) -> f64 {
    if (0.5..=1.0).contains(&m) {
        c * c + mc * s * s
    } else {
        1.0 - m * s * s
    }
}

/// Incomplete elliptic integral of the first kind F(φ | m).
///
/// ```text
/// F(φ | m) = ∫₀^φ dθ / √(1 − m sin²θ) = sin φ R_F(cos²φ, 1 − m sin²φ, 1)   (|φ| ≤ π/2)
/// F(φ + jπ | m) = F(φ | m) + 2j K(m)
/// ```
///
/// Any finite φ for `m ≤ 1`; for `m > 1` only `m sin²φ ≤ 1`, `|φ| ≤ π/2`.
/// NaN outside, for infinite φ, or NaN. Relative error ≤ 6·10⁻¹⁶ measured.
///
/// ```
/// use kreisel_dynamics::elliptic::{complete_k, incomplete_f};
/// let half = std::f64::consts::FRAC_PI_2;
/// assert!((incomplete_f(half, 0.7) - complete_k(0.7)).abs() < 1e-15);
/// assert!((incomplete_f(5.0 * half, 0.7) - 5.0 * complete_k(0.7)).abs() < 1e-14);
/// ```
///
/// Reference: DLMF 19.2.4, 19.25.5, 19.2.10; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn incomplete_f(phi: f64, m: f64) -> f64 {
    f_core(phi, m, 1.0 - m)
}

/// Incomplete elliptic integral of the first kind F(φ | m) from `mc = 1 − m`.
///
/// ```text
/// F(φ | m) = sin φ R_F(cos²φ, cos²φ + mc sin²φ, 1)   (|φ| ≤ π/2)
/// ```
///
/// Like [`incomplete_f`], accurate for `mc → 0` (`mc = 0`: F = artanh(sin φ)).
///
/// ```
/// use kreisel_dynamics::elliptic::incomplete_f_complementary;
/// assert!((incomplete_f_complementary(1.0, 0.0) - 1.0f64.sin().atanh()).abs() < 1e-15);
/// ```
///
/// Reference: DLMF 19.25.5; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn incomplete_f_complementary(phi: f64, mc: f64) -> f64 {
    f_core(phi, 1.0 - mc, mc)
}

fn f_core(phi: f64, m: f64, mc: f64) -> f64 {
    if phi.is_nan() || m.is_nan() || !phi.is_finite() {
        return f64::NAN;
    }
    let (j, r) = reduce_amplitude(phi);
    if j != 0.0 && m > 1.0 {
        return f64::NAN;
    }
    let (s, c) = r.sin_cos();
    let f = s * carlson_rf(c * c, delta_squared(s, c, m, mc), 1.0);
    if j == 0.0 {
        f
    } else {
        f + 2.0 * j * carlson_rf(0.0, mc, 1.0)
    }
}

/// Incomplete elliptic integral of the second kind E(φ | m).
///
/// ```text
/// E(φ | m) = ∫₀^φ √(1 − m sin²θ) dθ
///   = sin φ R_F(c², Δ², 1) − (m/3) sin³φ R_D(c², Δ², 1)                          (m < ½, m > 1)
///   = mc sin φ R_F(c², Δ², 1) + (m mc/3) sin³φ R_D(c², 1, Δ²) + m sin φ cos φ / Δ  (½ ≤ m ≤ 1)
/// c = cos φ, Δ² = 1 − m sin²φ;  E(φ + jπ | m) = E(φ | m) + 2j E(m)
/// ```
///
/// The second form has no cancellation as m → 1. Domain as [`incomplete_f`].
/// Relative error ≤ 7·10⁻¹⁶ measured.
///
/// ```
/// use kreisel_dynamics::elliptic::incomplete_e;
/// assert!((incomplete_e(0.6, 1.0) - 0.6f64.sin()).abs() < 2e-16);
/// assert!((incomplete_e(0.6, 0.0) - 0.6).abs() < 2e-16);
/// ```
///
/// Reference: DLMF 19.2.5, 19.25.9, 19.25.10; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn incomplete_e(phi: f64, m: f64) -> f64 {
    e_core(phi, m, 1.0 - m)
}

/// Incomplete elliptic integral of the second kind E(φ | m) from `mc = 1 − m`.
///
/// ```text
/// E(φ | m) = mc sin φ R_F(c², Δ², 1) + (m mc/3) sin³φ R_D(c², 1, Δ²) + m sin φ cos φ / Δ
/// Δ² = cos²φ + mc sin²φ
/// ```
///
/// Like [`incomplete_e`], accurate for `mc → 0` (`mc = 0`: E = sin φ).
///
/// ```
/// use kreisel_dynamics::elliptic::incomplete_e_complementary;
/// assert!((incomplete_e_complementary(1.2, 1e-300) - 1.2f64.sin()).abs() < 2e-16);
/// ```
///
/// Reference: DLMF 19.25.10; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn incomplete_e_complementary(phi: f64, mc: f64) -> f64 {
    e_core(phi, 1.0 - mc, mc)
}

fn e_core(phi: f64, m: f64, mc: f64) -> f64 {
    if phi.is_nan() || m.is_nan() || !phi.is_finite() {
        return f64::NAN;
    }
    let (j, r) = reduce_amplitude(phi);
    if j != 0.0 && m > 1.0 {
        return f64::NAN;
    }
    let (s, c) = r.sin_cos();
    let e = if mc == 0.0 {
        s
    } else if (0.5..=1.0).contains(&m) {
        let d2 = c * c + mc * s * s;
        mc * s * carlson_rf(c * c, d2, 1.0)
            + m * mc / 3.0 * s * s * s * carlson_rd(c * c, 1.0, d2)
            + m * s * c / d2.sqrt()
    } else {
        let d2 = 1.0 - m * s * s;
        s * carlson_rf(c * c, d2, 1.0) - m / 3.0 * s * s * s * carlson_rd(c * c, d2, 1.0)
    };
    if j == 0.0 {
        e
    } else {
        e + 2.0 * j * complete_e_complementary(mc)
    }
}

/// Incomplete elliptic integral of the third kind Π(n; φ | m).
///
/// ```text
/// Π(n; φ | m) = ∫₀^φ dθ / ((1 − n sin²θ) √(1 − m sin²θ))
///            = sin φ R_F(c², Δ², 1) + (n/3) sin³φ R_J(c², Δ², 1, 1 − n sin²φ)   (|φ| ≤ π/2)
/// Π(n; φ + jπ | m) = Π(n; φ | m) + 2j Π(n | m)
/// ```
///
/// Cauchy principal value where `n sin²φ > 1`; `±∞` where `n sin²φ = 1`.
/// Domain as [`incomplete_f`]. Relative error ≤ 2·10⁻¹⁵ measured (the sum
/// cancels partly for `n < 0`; see `tests/elliptic.rs`).
///
/// ```
/// use kreisel_dynamics::elliptic::{incomplete_f, incomplete_pi};
/// assert_eq!(incomplete_pi(0.8, 0.0, 0.3), incomplete_f(0.8, 0.3));
/// // Π(n; φ | 0) = atan(√(1 − n) tan φ)/√(1 − n)
/// assert!((incomplete_pi(0.8, -3.0, 0.0) - (2.0 * 0.8f64.tan()).atan() / 2.0).abs() < 3e-16);
/// ```
///
/// Reference: DLMF 19.2.7, 19.25.14; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn incomplete_pi(phi: f64, n: f64, m: f64) -> f64 {
    pi_core(phi, n, m, 1.0 - m)
}

/// Incomplete elliptic integral of the third kind Π(n; φ | m) from `mc = 1 − m`.
///
/// ```text
/// Π(n; φ | m) = sin φ R_F(c², c² + mc sin²φ, 1) + (n/3) sin³φ R_J(c², c² + mc sin²φ, 1, 1 − n sin²φ)
/// ```
///
/// Like [`incomplete_pi`], accurate for `mc → 0`.
///
/// ```
/// use kreisel_dynamics::elliptic::incomplete_pi_complementary;
/// // m → 1: Π(n; φ | 1) = (artanh(sin φ) − √n artanh(√n sin φ)) / (1 − n)
/// let s = 1.0f64.sin();
/// let exact = (s.atanh() - 0.5 * (0.5 * s).atanh()) / 0.75;
/// assert!((incomplete_pi_complementary(1.0, 0.25, 1e-300) - exact).abs() < 1e-15);
/// ```
///
/// Reference: DLMF 19.25.14; Carlson, Numer. Algorithms 10:13–26 (1995).
pub fn incomplete_pi_complementary(phi: f64, n: f64, mc: f64) -> f64 {
    pi_core(phi, n, 1.0 - mc, mc)
}

fn pi_core(phi: f64, n: f64, m: f64, mc: f64) -> f64 {
    if n.is_nan() || phi.is_nan() || m.is_nan() || !phi.is_finite() {
        return f64::NAN;
    }
    let (j, r) = reduce_amplitude(phi);
    if j != 0.0 && m > 1.0 {
        return f64::NAN;
    }
    let (s, c) = r.sin_cos();
    let d2 = delta_squared(s, c, m, mc);
    let mut v = s * carlson_rf(c * c, d2, 1.0);
    if n != 0.0 {
        let s2 = s * s;
        let p = if (0.5..=2.0).contains(&n) {
            c * c + (1.0 - n) * s2
        } else {
            1.0 - n * s2
        };
        v += n / 3.0 * s * s2 * carlson_rj(c * c, d2, 1.0, p);
    }
    if j == 0.0 {
        v
    } else {
        v + 2.0 * j * complete_pi_core(n, m, mc)
    }
}
