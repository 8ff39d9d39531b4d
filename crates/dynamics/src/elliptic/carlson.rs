//! Carlson's symmetric elliptic integrals R_F, R_D, R_J, R_C by the
//! duplication theorem and a 7th-order Taylor series (Carlson 1995; DLMF §19.36(i)).

/// Duplication stops once every `|1 − x_n/A_n| ≤ TOL`: the 8th-order
/// remainder of the series is then below `TOL⁸ ≈ 2·10⁻²²`, far under 2⁻⁵³.
const TOL: f64 = 1.0 / 512.0;
/// Iteration cap: a safety net only (at most ~30 steps occur for f64 inputs).
const MAX_STEPS: usize = 200;
/// Arguments above this are scaled down by `SCALE` (and below `1/BIG` up), by
/// homogeneity, so that the duplication step cannot overflow.
const BIG: f64 = 1.0e300;
/// 2¹⁰⁰⁰: the exact power of two used for rescaling.
const SCALE: f64 = 1.071_508_607_186_267_3e301;
/// 2⁵⁰⁰ = √SCALE.
const SQRT_SCALE: f64 = 3.273_390_607_896_142e150;

/// The exact power-of-two scale `λ` for the arguments and the factor
/// `λ^(1/2)` for the result, or `(1, 1)` if the arguments are in range
/// (`largest` is the largest argument, `smallest` the smallest non-zero one).
fn scale_for(largest: f64, smallest: f64) -> (f64, f64) {
    // R_F(x) = R_F(λx) · λ^(1/2); R_D and R_J use the factor cubed.
    if largest > BIG {
        (1.0 / SCALE, 1.0 / SQRT_SCALE)
    } else if largest < 1.0 / BIG && smallest > 0.0 {
        (SCALE, SQRT_SCALE)
    } else {
        (1.0, 1.0)
    }
}

/// Carlson's symmetric integral of the first kind R_F(x, y, z).
///
/// ```text
/// R_F(x, y, z) = ½ ∫₀^∞ dt / √((t + x)(t + y)(t + z))
/// ```
///
/// Domain: `x, y, z ≥ 0` with at most one zero; returns `+∞` if two are zero,
/// `0` if one is `+∞`, NaN for a negative or NaN argument. Relative error
/// ≤ 4·10⁻¹⁶ measured over 10⁻²⁰⁰…10²⁰⁰ (`tests/elliptic.rs`).
///
/// ```
/// use kreisel_dynamics::elliptic::carlson_rf;
/// // R_F(0, 1, 2) = Γ(1/4)² / (4√(2π))
/// assert!((carlson_rf(0.0, 1.0, 2.0) - 1.311_028_777_146_059_9).abs() < 3e-16);
/// assert!(carlson_rf(-1.0, 1.0, 2.0).is_nan());
/// ```
///
/// Reference: B. C. Carlson, "Numerical computation of real or complex
/// elliptic integrals", Numer. Algorithms 10:13–26 (1995), the R_F algorithm;
/// DLMF 19.16.1 and 19.36.1.
pub fn carlson_rf(x: f64, y: f64, z: f64) -> f64 {
    if x.is_nan() || y.is_nan() || z.is_nan() || x < 0.0 || y < 0.0 || z < 0.0 {
        return f64::NAN;
    }
    let zeros = usize::from(x == 0.0) + usize::from(y == 0.0) + usize::from(z == 0.0);
    if zeros >= 2 {
        return f64::INFINITY;
    }
    if x.is_infinite() || y.is_infinite() || z.is_infinite() {
        return 0.0;
    }
    let (s, factor) = scale_for(x.max(y).max(z), min_positive(&[x, y, z]));
    rf_core(x * s, y * s, z * s) * factor
}

/// The smallest positive value (or 0 if none).
fn min_positive(v: &[f64]) -> f64 {
    v.iter()
        .copied()
        .filter(|&t| t > 0.0)
        .fold(0.0, |m, t| if m == 0.0 { t } else { m.min(t) })
}

fn rf_core(x0: f64, y0: f64, z0: f64) -> f64 {
    let a0 = (x0 + y0 + z0) / 3.0;
    let q = (a0 - x0).abs().max((a0 - y0).abs()).max((a0 - z0).abs()) / TOL;
    let (mut x, mut y, mut z, mut a, mut f) = (x0, y0, z0, a0, 1.0);
    for _ in 0..MAX_STEPS {
        if q * f <= a {
            break;
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lam = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        a = 0.25 * (a + lam);
        f *= 0.25;
    }
    let xx = (a0 - x0) * f / a;
    let yy = (a0 - y0) * f / a;
    let zz = -(xx + yy);
    let e2 = xx * yy - zz * zz;
    let e3 = xx * yy * zz;
    // 1 − E2/10 + E3/14 + E2²/24 − 3E2E3/44 − 5E2³/208 + 3E3²/104 + E2²E3/16
    let series = 1.0
        + e2 * (-1.0 / 10.0 + e2 * (1.0 / 24.0 - 5.0 / 208.0 * e2) + e3 * (-3.0 / 44.0))
        + e3 * (1.0 / 14.0 + 3.0 / 104.0 * e3 + e2 * e2 / 16.0);
    series / a.sqrt()
}

/// The 7th-order series shared by R_D and R_J (DLMF 19.36.2).
fn rj_series(e2: f64, e3: f64, e4: f64, e5: f64) -> f64 {
    1.0 - 3.0 / 14.0 * e2 + e3 / 6.0 + 9.0 / 88.0 * e2 * e2 - 3.0 / 22.0 * e4 - 9.0 / 52.0 * e2 * e3
        + 3.0 / 26.0 * e5
        - e2 * e2 * e2 / 16.0
        + 3.0 / 40.0 * e3 * e3
        + 3.0 / 20.0 * e2 * e4
        + 45.0 / 272.0 * e2 * e2 * e3
        - 9.0 / 68.0 * (e3 * e4 + e2 * e5)
}

/// Carlson's symmetric integral of the second kind R_D(x, y, z) = R_J(x, y, z, z).
///
/// ```text
/// R_D(x, y, z) = 3/2 ∫₀^∞ dt / ((t + z) √((t + x)(t + y)(t + z)))
/// ```
///
/// Domain: `x, y ≥ 0` with at most one zero and `z > 0`; returns `+∞` for
/// `z = 0` or `x = y = 0`, `0` if an argument is `+∞`, NaN for negative or
/// NaN arguments. Relative error ≤ 5·10⁻¹⁶ measured (`tests/elliptic.rs`).
///
/// ```
/// use kreisel_dynamics::elliptic::carlson_rd;
/// // R_D(0, 2, 1) = 3 Γ(3/4)² / √(2π)  (Carlson 1995, test values)
/// assert!((carlson_rd(0.0, 2.0, 1.0) - 1.797_210_352_103_388_3).abs() < 5e-16);
/// // R_D(x, x, x) = x^(-3/2)
/// assert!((carlson_rd(4.0, 4.0, 4.0) - 0.125).abs() < 1e-16);
/// ```
///
/// Reference: Carlson, Numer. Algorithms 10:13–26 (1995), the R_D algorithm;
/// DLMF 19.16.5 and 19.36.2.
pub fn carlson_rd(x: f64, y: f64, z: f64) -> f64 {
    if x.is_nan() || y.is_nan() || z.is_nan() || x < 0.0 || y < 0.0 || z < 0.0 {
        return f64::NAN;
    }
    if z == 0.0 || (x == 0.0 && y == 0.0) {
        return f64::INFINITY;
    }
    if x.is_infinite() || y.is_infinite() || z.is_infinite() {
        return 0.0;
    }
    // Homogeneous of degree −3/2: factor³ = s^(3/2), applied in three steps.
    let (s, factor) = scale_for(x.max(y).max(z), min_positive(&[x, y, z]));
    rd_core(x * s, y * s, z * s) * factor * factor * factor
}

fn rd_core(x0: f64, y0: f64, z0: f64) -> f64 {
    let a0 = (x0 + y0 + 3.0 * z0) / 5.0;
    let q = (a0 - x0).abs().max((a0 - y0).abs()).max((a0 - z0).abs()) / TOL;
    let (mut x, mut y, mut z, mut a, mut f) = (x0, y0, z0, a0, 1.0);
    let mut sum = 0.0;
    for _ in 0..MAX_STEPS {
        if q * f <= a {
            break;
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lam = sx * (sy + sz) + sy * sz;
        sum += f / (sz * (z + lam));
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        a = 0.25 * (a + lam);
        f *= 0.25;
    }
    let xx = (a0 - x0) * f / a;
    let yy = (a0 - y0) * f / a;
    let zz = -(xx + yy) / 3.0;
    let xy = xx * yy;
    let z2 = zz * zz;
    let e2 = xy - 6.0 * z2;
    let e3 = (3.0 * xy - 8.0 * z2) * zz;
    let e4 = 3.0 * (xy - z2) * z2;
    let e5 = xy * z2 * zz;
    f * rj_series(e2, e3, e4, e5) / (a * a.sqrt()) + 3.0 * sum
}

/// Carlson's symmetric integral of the third kind R_J(x, y, z, p).
///
/// ```text
/// R_J(x, y, z, p) = 3/2 ∫₀^∞ dt / ((t + p) √((t + x)(t + y)(t + z)))
/// ```
///
/// Domain: `x, y, z ≥ 0` with at most one zero, `p ≠ 0`. For `p < 0` the
/// Cauchy principal value is returned, reduced to `p > 0` by DLMF 19.20.14
/// (its terms partly cancel: ≤ 2·10⁻¹⁵ relative measured on 24 cases).
/// Returns `+∞` for `p = 0` or two zero arguments, NaN for negative `x, y, z`
/// or NaN. Relative error for `p > 0` ≤ 6·10⁻¹⁶ measured (`tests/elliptic.rs`).
///
/// ```
/// use kreisel_dynamics::elliptic::{carlson_rd, carlson_rj};
/// // R_J(2, 3, 4, 5) (Carlson 1995, test values)
/// assert!((carlson_rj(2.0, 3.0, 4.0, 5.0) - 0.142_975_796_671_567_5).abs() < 1e-16);
/// assert_eq!(carlson_rj(1.0, 2.0, 3.0, 3.0), carlson_rd(1.0, 2.0, 3.0));
/// ```
///
/// Reference: Carlson, Numer. Algorithms 10:13–26 (1995), the R_J algorithm
/// and its principal-value reduction; DLMF 19.16.2, 19.20.14, 19.36.2.
pub fn carlson_rj(x: f64, y: f64, z: f64, p: f64) -> f64 {
    if x.is_nan() || y.is_nan() || z.is_nan() || p.is_nan() || x < 0.0 || y < 0.0 || z < 0.0 {
        return f64::NAN;
    }
    let zeros = usize::from(x == 0.0) + usize::from(y == 0.0) + usize::from(z == 0.0);
    if zeros >= 2 || p == 0.0 {
        return f64::INFINITY;
    }
    if p == z {
        return carlson_rd(x, y, z);
    }
    if x.is_infinite() || y.is_infinite() || z.is_infinite() || p.is_infinite() {
        return 0.0;
    }
    if p < 0.0 {
        return rj_principal_value(x, y, z, p);
    }
    let (s, factor) = scale_for(x.max(y).max(z).max(p), min_positive(&[x, y, z, p]));
    rj_core(x * s, y * s, z * s, p * s) * factor * factor * factor
}

/// Cauchy principal value for `p < 0` by DLMF 19.20.14 with `x ≤ y ≤ z`:
/// `(z + q) R_J(x, y, z, −q) = (p′ − z) R_J(x, y, z, p′) − 3 R_F(x, y, z)
/// + 3 √(xyz/(xy + p′q)) R_C(xy + p′q, p′q)`, `p′ = z − (z − x)(z − y)/(z + q) > 0`.
fn rj_principal_value(x: f64, y: f64, z: f64, p: f64) -> f64 {
    let mut v = [x, y, z];
    v.sort_by(f64::total_cmp);
    let [x, y, z] = v;
    let q = -p;
    // p′ − z and p′ = (zx + zq + y(z − x))/(z + q), each without cancellation
    let dz = (z - x) * (z - y) / (z + q);
    let pp = (z * x + z * q + y * (z - x)) / (z + q);
    let xy = x * y;
    let rc_term = if xy == 0.0 {
        0.0
    } else {
        let t = xy + pp * q;
        3.0 * (xy * z / t).sqrt() * carlson_rc(t, pp * q)
    };
    (-dz * carlson_rj(x, y, z, pp) - 3.0 * carlson_rf(x, y, z) + rc_term) / (z + q)
}

fn rj_core(x0: f64, y0: f64, z0: f64, p0: f64) -> f64 {
    let a0 = (x0 + y0 + z0 + 2.0 * p0) / 5.0;
    let q = (a0 - x0)
        .abs()
        .max((a0 - y0).abs())
        .max((a0 - z0).abs())
        .max((a0 - p0).abs())
        / TOL;
    // p − x etc. stay exact multiples of 4^(−m) under duplication.
    let (dx, dy, dz) = (p0 - x0, p0 - y0, p0 - z0);
    let (mut x, mut y, mut z, mut p, mut a, mut f) = (x0, y0, z0, p0, a0, 1.0);
    let mut sum = 0.0;
    for _ in 0..MAX_STEPS {
        if q * f <= a {
            break;
        }
        let (sx, sy, sz, sp) = (x.sqrt(), y.sqrt(), z.sqrt(), p.sqrt());
        let lam = sx * (sy + sz) + sy * sz;
        let (px, py, pz) = (sp + sx, sp + sy, sp + sz);
        let d = px * py * pz;
        // e = 4^(−3m) δ / d² = r_x r_y r_z with r = (√p − √x)/(√p + √x) ∈ (−1, 1)
        let e = (dx * f / (px * px)) * (dy * f / (py * py)) * (dz * f / (pz * pz));
        let one_plus_e = if e < -0.5 {
            // 1 + e = 1 − Π(1 − δ) with δ = 1 − |r| = 2 min(√p, √x)/(√p + √x), no cancellation
            let l = (-2.0 * sp.min(sx) / px).ln_1p()
                + (-2.0 * sp.min(sy) / py).ln_1p()
                + (-2.0 * sp.min(sz) / pz).ln_1p();
            -l.exp_m1()
        } else {
            1.0 + e
        };
        sum += f * rc1p(e, one_plus_e) / d;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        p = 0.25 * (p + lam);
        a = 0.25 * (a + lam);
        f *= 0.25;
    }
    let xx = (a0 - x0) * f / a;
    let yy = (a0 - y0) * f / a;
    let zz = (a0 - z0) * f / a;
    let pp = -0.5 * (xx + yy + zz);
    let xyz = xx * yy * zz;
    let p2 = pp * pp;
    let e2 = xx * yy + xx * zz + yy * zz - 3.0 * p2;
    let e3 = xyz + 2.0 * e2 * pp + 4.0 * p2 * pp;
    let e4 = (2.0 * xyz + e2 * pp + 3.0 * p2 * pp) * pp;
    let e5 = xyz * p2;
    f * rj_series(e2, e3, e4, e5) / (a * a.sqrt()) + 6.0 * sum
}

/// R_C(1, 1 + e) for −1 < e in closed form (DLMF 19.2.18, 19.2.19), given
/// also `1 + e` accurately (it may be tiny when e is near −1).
fn rc1p(e: f64, one_plus_e: f64) -> f64 {
    if e > 0.0 {
        let t = e.sqrt();
        t.atan() / t
    } else if e < -0.5 {
        // artanh t = ln(1 + t) − ½ ln(1 − t²), 1 − t² = 1 + e
        let t = (-e).sqrt();
        (t.ln_1p() - 0.5 * one_plus_e.ln()) / t
    } else if e < 0.0 {
        let t = (-e).sqrt();
        t.atanh() / t
    } else {
        1.0
    }
}

/// Carlson's degenerate integral R_C(x, y) = R_F(x, y, y).
///
/// ```text
/// R_C(x, y) = ½ ∫₀^∞ dt / ((t + y) √(t + x))
///           = arctan(√((y − x)/x)) / √(y − x)    (0 ≤ x < y)
/// ```
///
/// Domain: `x ≥ 0`, `y ≠ 0`; for `y < 0` the Cauchy principal value
/// `√(x/(x − y)) R_C(x − y, −y)` is returned. Returns `+∞` for `y = 0`, `0`
/// if an argument is `±∞`, NaN for `x < 0` or NaN. Relative error
/// ≤ 5·10⁻¹⁶ measured (`tests/elliptic.rs`).
///
/// ```
/// use kreisel_dynamics::elliptic::carlson_rc;
/// // R_C(0, 1/4) = π,  R_C(9/4, 2) = ln 2  (Carlson 1995, test values)
/// assert!((carlson_rc(0.0, 0.25) - std::f64::consts::PI).abs() < 5e-16);
/// assert!((carlson_rc(2.25, 2.0) - std::f64::consts::LN_2).abs() < 2e-16);
/// ```
///
/// Reference: Carlson, Numer. Algorithms 10:13–26 (1995), the R_C algorithm;
/// DLMF 19.2.17–19.2.20 and 19.36(i).
pub fn carlson_rc(x: f64, y: f64) -> f64 {
    if x.is_nan() || y.is_nan() || x < 0.0 {
        return f64::NAN;
    }
    if y == 0.0 {
        return f64::INFINITY;
    }
    if x.is_infinite() || y.is_infinite() {
        return 0.0;
    }
    if y < 0.0 {
        if x == 0.0 {
            return 0.0;
        }
        return (x / (x - y)).sqrt() * carlson_rc(x - y, -y);
    }
    let (s, factor) = scale_for(x.max(y), min_positive(&[x, y]));
    rc_core(x * s, y * s) * factor
}

fn rc_core(x0: f64, y0: f64) -> f64 {
    let a0 = (x0 + 2.0 * y0) / 3.0;
    let q = (a0 - x0).abs() / TOL;
    let (mut x, mut y, mut a, mut f) = (x0, y0, a0, 1.0);
    for _ in 0..MAX_STEPS {
        if q * f <= a {
            break;
        }
        let lam = 2.0 * x.sqrt() * y.sqrt() + y;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        a = 0.25 * (a + lam);
        f *= 0.25;
    }
    let s = (y0 - a0) * f / a;
    // 1 + 3s²/10 + s³/7 + 3s⁴/8 + 9s⁵/22 + 159s⁶/208 + 9s⁷/8
    let series = 1.0
        + s * s
            * (3.0 / 10.0
                + s * (1.0 / 7.0
                    + s * (3.0 / 8.0 + s * (9.0 / 22.0 + s * (159.0 / 208.0 + s * (9.0 / 8.0))))));
    series / a.sqrt()
}
