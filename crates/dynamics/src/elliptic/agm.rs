//! The arithmetic–geometric mean of (1, √mc) and Bulirsch's descending
//! Landen recurrence for sn, cn, dn at one complementary parameter
//! `mc ∈ (0, 1]`, with the argument reduced modulo 2K in double-double.

use std::f64::consts::FRAC_PI_4;

use super::dd::{Dd, FRAC_PI_2, PI};

/// Largest number of AGM levels kept (at most ~15 occur, for mc = 5·10⁻³²⁴).
const LEVELS: usize = 40;
/// Bulirsch's stopping test `|a − b| ≤ CA·a`: the neglected terms are O(CA²) ≈ 10⁻¹⁸.
const CA: f64 = 1.0 / 1_073_741_824.0;
/// Below this |u| the Taylor series to O(u⁴) is exact to rounding.
const TAYLOR: f64 = 1.0 / 67_108_864.0;
/// At or below this mc, the first-order expansion in mc about tanh/sech
/// (DLMF 22.10.ii) replaces Bulirsch's recurrence on `|u| ≤ K/2`: its relative
/// error there is ≤ 4·10⁻¹⁹ at mc = 10⁻¹² and falls like mc^(3/2) (mpmath).
const HYPERBOLIC: f64 = 1e-12;

/// The arithmetic–geometric mean sequence of (1, √mc) for one `mc ∈ (0, 1]`.
#[derive(Clone, Debug)]
pub(super) struct Agm {
    a: [f64; LEVELS],
    b: [f64; LEVELS],
    levels: usize,
    /// AGM(1, √mc) = π/(2K) to ~10⁻³² relative.
    mean: Dd,
    m: f64,
    mc: f64,
    sqrt_mc: f64,
}

impl Agm {
    /// The sequence for `0 < mc ≤ 1` given as a double-double.
    pub(super) fn new(mc: Dd) -> Agm {
        let mut a = Dd::from_f64(1.0);
        let mut b = mc.sqrt();
        let sqrt_mc = b.to_f64();
        let (mut arr_a, mut arr_b) = ([0.0; LEVELS], [0.0; LEVELS]);
        let mut levels = 0;
        while levels < LEVELS {
            arr_a[levels] = a.hi;
            arr_b[levels] = b.hi;
            levels += 1;
            if (a.hi - b.hi).abs() <= CA * a.hi {
                break;
            }
            let next = a.add(b).half();
            b = a.mul(b).sqrt();
            a = next;
        }
        // Two more (quadratically convergent) steps take |a − b|/a from
        // ≤ 2⁻³⁰ to ~10⁻³⁹, below the double-double resolution.
        for _ in 0..2 {
            let next = a.add(b).half();
            b = a.mul(b).sqrt();
            a = next;
        }
        Agm {
            a: arr_a,
            b: arr_b,
            levels,
            mean: a.add(b).half(),
            m: 1.0 - mc.to_f64(),
            mc: mc.to_f64(),
            sqrt_mc,
        }
    }

    /// (sn, cn, dn) at phase θ = u·AGM ∈ [0, π/4] by Bulirsch's recurrence.
    fn at_phase(&self, theta: Dd) -> (f64, f64, f64) {
        let mean = self.mean.hi;
        let u = theta.hi / mean;
        if u < TAYLOR {
            let u2 = u * u;
            let m = self.m;
            return (
                u * (1.0 - (1.0 + m) * u2 / 6.0),
                1.0 - 0.5 * u2,
                1.0 - 0.5 * m * u2,
            );
        }
        // sin and cos of the double-double phase, to first order in its low part
        let (sin, cos) = theta.hi.sin_cos();
        let (sin, cos) = (sin + cos * theta.lo, cos - sin * theta.lo);
        if self.mc == 1.0 {
            return (sin, cos, 1.0);
        }
        let mut a = cos / sin;
        let mut c = mean * a;
        let mut dn = 1.0;
        for i in (0..self.levels).rev() {
            let b = self.a[i];
            a *= c;
            c *= dn;
            dn = (self.b[i] + a) / (b + a);
            a = c / b;
        }
        // c = cn/sn now
        let sn = 1.0 / (c * c + 1.0).sqrt();
        (sn, c * sn, dn)
    }

    /// (sn, cn, dn) at `v ∈ [0, K/2]` (a double-double) for `mc ≤ HYPERBOLIC`.
    ///
    /// `sn = tanh v + (mc/4)(sinh v cosh v − v) sech²v`,
    /// `cn = sech v − (mc/4)(sinh v cosh v − v) tanh v sech v`,
    /// `dn = sech v + (mc/4)(sinh v cosh v + v) tanh v sech v`  (DLMF 22.10.ii);
    /// tanh and sech get the first-order correction for the low part of v.
    fn near_separatrix(&self, v: Dd) -> (f64, f64, f64) {
        let (vh, vl) = (v.hi, v.lo);
        let t0 = vh.tanh();
        let s0 = 1.0 / vh.cosh();
        let t = t0 + s0 * s0 * vl;
        let sech = s0 - s0 * t0 * vl;
        let sc = vh.sinh() * vh.cosh();
        let q = 0.25 * self.mc;
        (
            t + q * (sc - vh) * sech * sech,
            sech - q * (sc - vh) * t * sech,
            sech + q * (sc + vh) * t * sech,
        )
    }

    /// (sn, cn, dn) at `u` and, for the amplitude, `j` and (sn, cn) at `u − 2jK`.
    pub(super) fn eval(&self, u: Dd) -> Reduced {
        let theta = self.mean.mul(u);
        let j = (theta.hi / PI.hi).round();
        let r = theta.add(PI.mul_f64(j).neg());
        let negative = r.hi < 0.0;
        let r = if negative { r.neg() } else { r };
        // phase w ∈ [0, π/4]: u itself, or v = K − |u| (reflected)
        let reflect = r.hi > FRAC_PI_4;
        let mut w = if reflect { FRAC_PI_2.add(r.neg()) } else { r };
        if w.hi < 0.0 {
            w = Dd::from_f64(0.0);
        }
        let (s, c, d) = if self.mc <= HYPERBOLIC {
            self.near_separatrix(w.div(self.mean))
        } else {
            self.at_phase(w)
        };
        let (mut sn, mut cn, dn) = if reflect {
            // u = K − v: sn = cd(v), cn = √mc sd(v), dn = √mc nd(v)  (DLMF 22.4.3);
            // sn as 1/√(1 + mc sc²v), which damps the error of cn(v), dn(v) by cn²u
            let sc = s / c;
            (
                1.0 / (1.0 + self.mc * sc * sc).sqrt(),
                self.sqrt_mc * s / d,
                self.sqrt_mc / d,
            )
        } else {
            (s, c, d)
        };
        if negative {
            sn = -sn;
        }
        let (sn_r, cn_r) = (sn, cn);
        if j % 2.0 != 0.0 {
            sn = -sn;
            cn = -cn;
        }
        Reduced {
            sn,
            cn,
            dn,
            j,
            sn_r,
            cn_r,
        }
    }
}

/// Values at `u` and at the reduced argument `u − 2jK` (for the amplitude).
pub(super) struct Reduced {
    pub(super) sn: f64,
    pub(super) cn: f64,
    pub(super) dn: f64,
    pub(super) j: f64,
    pub(super) sn_r: f64,
    pub(super) cn_r: f64,
}
