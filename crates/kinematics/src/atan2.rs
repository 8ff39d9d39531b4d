//! A branch-free `atan2` for the Euler-angle extraction, within 1.5 ulp,
//! computed for several points side by side (SIMD lanes).
//!
//! Why hand-written: [`EulerSequence::from_quat`](crate::EulerSequence::from_quat)
//! spent most of its time in three `atan2` calls. On this project's machine
//! (AMD EPYC, x86-64 baseline = SSE2; 3·10⁶ random arguments, one
//! interleaved run of a scratch benchmark, time of three calls): glibc's
//! `atan2` 71 ns, the `libm` crate's 0.2.16 (musl/fdlibm) 86 ns (its
//! interval branches mispredict on random input), this one 53 ns one point
//! at a time and 21 ns two at a time: one division and no data-dependent
//! branch, so the compiler packs the lanes into SIMD registers, which no
//! crate's scalar `atan2` allows.
//!
//! ```text
//! a = |x|, b = |y|, lo = min(a, b), hi = max(a, b)        (lo/hi ∈ [0, 1])
//! t = lo / hi                 if lo ≤ hi/2
//! t = (lo − hi) / (lo + hi)   otherwise: atan(lo/hi) = π/4 + atan t
//! atan t = t + t·s·P(s),  s = t²,  |t| ≤ 1/2
//! atan2(y, x) = ±(k·π/4 ± atan t),  k ∈ {0, …, 4} from the octant
//! ```
//!
//! `P` (degree 12) is a Chebyshev fit of `(atan √s − √s)/(s √s)` on
//! `[0, 1/4]`, relative error 1e-18 in `atan t`, made by
//! `tests/data/gen/atan2.py` (mpmath), which also writes the reference values
//! (`tests/data/atan2.csv`, 5092 arguments: all octants, next to the
//! reduction's boundaries, subnormal, tiny and huge ratios) the tests check
//! against. Error: at most 1.26 ulp there (1.45 ulp on 4·10⁵ further random
//! arguments; glibc: 0.52), 96 % correctly rounded; the analysis bounds it
//! by ~1.7 ulp (`t` rounded twice, `lo − hi` exact by Sterbenz' lemma, then
//! `k·π/4 + σ atan t` summed with its rounding error recovered (Fast2Sum)
//! and π/4 in two parts, so rounded about once).
//!
//! Zeros, infinities, NaN and arguments near `f64::MAX` (where `lo + hi`
//! could overflow) go to the standard library's `atan2`, which also settles
//! the IEEE special cases (`atan2(±0, −0) = ±π`, …).

use crate::lanes::lanes;

/// Coefficients of `P(s)`, lowest degree first (`tests/data/gen/atan2.py`).
const P: [f64; 13] = [
    -0.333_333_333_333_333_3,
    0.199_999_999_999_994_85,
    -0.142_857_142_855_986_27,
    0.111_111_111_008_728_4,
    -0.090_909_086_185_005_05,
    0.076_922_946_687_059_78,
    -0.066_664_350_107_172_1,
    0.058_795_717_761_632_84,
    -0.052_400_553_103_219_65,
    0.046_278_313_756_564_78,
    -0.038_061_175_604_154_014,
    0.024_997_986_176_136_8,
    -0.009_209_881_792_239_817,
];

/// π/4 = `QUARTER_PI_HI + QUARTER_PI_LO` (to 2⁻¹⁰⁶); `QUARTER_PI_HI`,
/// π/4 rounded to nearest, ends in three zero bits, so `k·QUARTER_PI_HI`
/// is exact for `k = 0 … 4`.
const QUARTER_PI_HI: f64 = core::f64::consts::FRAC_PI_4;
const QUARTER_PI_LO: f64 = 3.061_616_997_868_383e-17;

/// Above this `|x| + |y|`, `lo + hi` might overflow: the standard library
/// takes over (2¹⁰²⁰).
const LARGE: f64 = 1.123_558_209_288_947_4e307;

/// `P(s)` by Estrin's scheme (shorter dependency chains than Horner's).
#[inline(always)]
fn poly(s: f64) -> f64 {
    let s2 = s * s;
    let s4 = s2 * s2;
    let s8 = s4 * s4;
    let a01 = P[0] + P[1] * s;
    let a23 = P[2] + P[3] * s;
    let a45 = P[4] + P[5] * s;
    let a67 = P[6] + P[7] * s;
    let a89 = P[8] + P[9] * s;
    let aab = P[10] + P[11] * s;
    let b03 = a01 + a23 * s2;
    let b47 = a45 + a67 * s2;
    let b8b = a89 + aab * s2;
    let c07 = b03 + b47 * s4;
    let c8c = b8b + P[12] * s4;
    c07 + c8c * s8
}

/// `true` where [`atan2_lanes`]' formula does not apply: a zero, infinite,
/// NaN or huge argument.
#[inline(always)]
fn special(y: f64, x: f64) -> bool {
    let sum = x.abs() + y.abs();
    !(sum > 0.0 && sum < LARGE)
}

/// The angles of `N` points `(x, y)`, in `[−π, π]`: `f64::atan2` within
/// 1.5 ulp, lane by lane (each lane's number does not depend on `N` or the
/// other lanes), with no branch on the data but for special arguments, so
/// that the compiler can put the lanes into SIMD registers.
///
/// ```text
/// atan2(y, x) = θ  with  (x, y) = r (cos θ, sin θ),  r > 0
/// ```
///
/// Same signs and special values as [`f64::atan2`] (`y` keeps its sign,
/// including `−0`; `atan2(±0, −0) = ±π`; NaN in, NaN out).
#[inline(always)]
pub(crate) fn atan2_lanes<const N: usize>(y: [f64; N], x: [f64; N]) -> [f64; N] {
    let mut theta: [f64; N] = lanes(0.0, |i| {
        let (a, b) = (x[i].abs(), y[i].abs());
        let swap = b > a;
        let lo = if swap { a } else { b };
        let hi = if swap { b } else { a };
        // f = 1 folds: atan(lo/hi) = π/4 + atan t. lo − hi is exact (Sterbenz).
        let f = if lo > 0.5 * hi { 1.0 } else { 0.0 };
        let t = (lo - f * hi) / (hi + f * lo);
        let s = t * t;
        // The octant: θ = k·π/4 + σ atan t for the first quadrant's
        // k₀ = f (or 2 − f when swapped, σ = −1), then π − that for x < 0.
        let x_negative = x[i].is_sign_negative();
        let k0 = if swap { 2.0 - f } else { f };
        let k = if x_negative { 4.0 - k0 } else { k0 };
        let st = if swap != x_negative { -t } else { t };
        // k·π/4 + σt exactly as h + e (Fast2Sum: |k·π/4| ≥ |t| whenever
        // k > 0, and e = 0 when k = 0), then the small terms.
        let k_hi = k * QUARTER_PI_HI;
        let h = k_hi + st;
        let e = (k_hi - h) + st;
        let theta = h + (e + (st * s * poly(s) + k * QUARTER_PI_LO));
        theta.copysign(y[i])
    });
    if (0..N).any(|i| special(y[i], x[i])) {
        for i in 0..N {
            if special(y[i], x[i]) {
                theta[i] = y[i].atan2(x[i]);
            }
        }
    }
    theta
}

#[cfg(test)]
mod tests {
    use super::*;

    fn atan2(y: f64, x: f64) -> f64 {
        atan2_lanes([y], [x])[0]
    }
    use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

    /// The size of one unit in the last place of `v`.
    fn ulp(v: f64) -> f64 {
        let a = v.abs();
        a.next_up() - a
    }

    /// The arguments of `tests/data/atan2.csv` (`tests/data/gen/atan2.py`)
    /// and `atan2(y, x)` there, as `hi + lo`.
    fn reference() -> Vec<[f64; 4]> {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/atan2.csv");
        let text = std::fs::read_to_string(path).expect("tests/data/atan2.csv");
        let rows = text.lines().filter(|l| !l.starts_with('#')).skip(1);
        rows.map(|line| {
            let v: Vec<f64> = line.split(',').map(|t| t.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
    }

    /// Against mpmath: at most 1.5 ulp everywhere (1.26 found), and most
    /// results correctly rounded.
    #[test]
    fn within_one_and_a_half_ulp_of_mpmath() {
        let (mut worst, mut rounded) = (0.0_f64, 0);
        let rows = reference();
        for &[y, x, hi, lo] in &rows {
            let found = atan2(y, x);
            // found − hi is exact (both within a few ulps); lo is the rest.
            let err = ((found - hi) - lo).abs() / ulp(hi);
            assert!(
                err <= 1.5,
                "atan2({y:e}, {x:e}) = {found:e}, exact {hi:e} + {lo:e}: {err} ulp"
            );
            worst = worst.max(err);
            rounded += usize::from(found == hi);
        }
        assert!(rows.len() > 5000, "{} rows", rows.len());
        let share = rounded as f64 / rows.len() as f64;
        eprintln!(
            "atan2: {} arguments, max error {worst:.3} ulp, correctly rounded {:.1} %",
            rows.len(),
            100.0 * share
        );
        assert!(share > 0.95, "{share}");
    }

    /// A lane's number does not depend on the other lanes (SIMD or not),
    /// special arguments among them included.
    #[test]
    fn lanes_are_independent() {
        let mut points: Vec<(f64, f64)> = reference().iter().map(|r| (r[0], r[1])).collect();
        points.extend([
            (0.0, -0.0),
            (f64::INFINITY, 1.0),
            (-1.0, f64::NAN),
            (1e308, 1e308),
        ]);
        for block in points.chunks_exact(4) {
            let y: [f64; 4] = core::array::from_fn(|i| block[i].0);
            let x: [f64; 4] = core::array::from_fn(|i| block[i].1);
            let four = atan2_lanes(y, x);
            let two = [
                atan2_lanes([y[0], y[1]], [x[0], x[1]]),
                atan2_lanes([y[2], y[3]], [x[2], x[3]]),
            ];
            for i in 0..4 {
                let one = atan2(y[i], x[i]);
                assert_eq!(four[i].to_bits(), one.to_bits(), "({}, {})", y[i], x[i]);
                assert_eq!(
                    two[i / 2][i % 2].to_bits(),
                    one.to_bits(),
                    "({}, {})",
                    y[i],
                    x[i]
                );
            }
        }
    }

    /// IEEE 754 / C99 Annex F.9.1.4.
    #[test]
    fn special_values() {
        let inf = f64::INFINITY;
        let cases = [
            (0.0, 0.0, 0.0),
            (-0.0, 0.0, -0.0),
            (0.0, -0.0, PI),
            (-0.0, -0.0, -PI),
            (0.0, 1.0, 0.0),
            (-0.0, 1.0, -0.0),
            (0.0, -1.0, PI),
            (-0.0, -1.0, -PI),
            (1.0, 0.0, FRAC_PI_2),
            (1.0, -0.0, FRAC_PI_2),
            (-1.0, 0.0, -FRAC_PI_2),
            (-1.0, -0.0, -FRAC_PI_2),
            (1.0, inf, 0.0),
            (-1.0, inf, -0.0),
            (1.0, -inf, PI),
            (-1.0, -inf, -PI),
            (inf, 1.0, FRAC_PI_2),
            (-inf, -1.0, -FRAC_PI_2),
            (inf, inf, FRAC_PI_4),
            (-inf, inf, -FRAC_PI_4),
            (inf, -inf, 3.0 * FRAC_PI_4),
            (-inf, -inf, -3.0 * FRAC_PI_4),
            (5e-324, 0.0, FRAC_PI_2),
            (0.0, 5e-324, 0.0),
        ];
        for (y, x, expect) in cases {
            let found = atan2(y, x);
            assert!(
                found == expect && found.is_sign_negative() == expect.is_sign_negative(),
                "atan2({y}, {x}) = {found}, expected {expect}"
            );
        }
        for (y, x) in [
            (f64::NAN, 1.0),
            (1.0, f64::NAN),
            (f64::NAN, f64::NAN),
            (inf, f64::NAN),
        ] {
            assert!(atan2(y, x).is_nan(), "atan2({y}, {x})");
        }
    }

    /// Exact for the arguments whose angle is a multiple of π/4 in f64.
    #[test]
    fn axes_and_diagonals_exact() {
        for r in [1e-300, 1e-3, 1.0, 7.0, 1e300] {
            assert_eq!(atan2(r, r), FRAC_PI_4);
            assert_eq!(atan2(r, -r), 3.0 * FRAC_PI_4);
            assert_eq!(atan2(-r, r), -FRAC_PI_4);
            assert_eq!(atan2(-r, -r), -3.0 * FRAC_PI_4);
            assert_eq!(atan2(r, 0.0), FRAC_PI_2);
            assert_eq!(atan2(0.0, -r), PI);
            assert_eq!(atan2(-0.0, -r), -PI);
        }
    }
}
