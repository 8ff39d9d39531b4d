//! Double-double arithmetic (an unevaluated sum `hi + lo`, ~106 bits) for the
//! argument reduction of the Jacobi functions.
//!
//! Error-free transformations after Dekker (1971) and Knuth (TAOCP vol. 2,
//! §4.2.2); the product uses `f64::mul_add`, which is exact (a hardware FMA or
//! the correctly rounded software `fma`).

/// A double-double number `hi + lo` with `|lo| ≤ ulp(hi)/2`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Dd {
    pub(crate) hi: f64,
    pub(crate) lo: f64,
}

/// π as a double-double (π − PI_HI = 1.2246467991473532e-16 to ~1e-33).
pub(crate) const PI: Dd = Dd {
    hi: std::f64::consts::PI,
    lo: 1.224_646_799_147_353_2e-16,
};

/// π/2 as a double-double.
pub(crate) const FRAC_PI_2: Dd = Dd {
    hi: std::f64::consts::FRAC_PI_2,
    lo: 6.123_233_995_736_766e-17,
};

/// `a + b = s + e` exactly (Knuth's two-sum).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// `a + b = s + e` exactly, assuming `|a| ≥ |b|` (Dekker's fast two-sum).
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a · b = p + e` exactly (barring over/underflow): one FMA where the
/// target has it, Dekker's product of Veltkamp halves otherwise (the
/// portable `f64::mul_add` falls back to a software FMA ~20× slower).
#[cfg(target_feature = "fma")]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// `a · b = p + e` exactly (barring over/underflow): Dekker (1971).
#[cfg(not(target_feature = "fma"))]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (a_hi, a_lo) = split(a);
    let (b_hi, b_lo) = split(b);
    let e = ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
    (p, e)
}

/// Veltkamp's split of `x` into two 26-bit halves, `x = hi + lo` exactly
/// (for |x| < 2⁹⁹⁶).
#[cfg(not(target_feature = "fma"))]
fn split(x: f64) -> (f64, f64) {
    const FACTOR: f64 = 134_217_729.0; // 2²⁷ + 1
    let t = FACTOR * x;
    let hi = t - (t - x);
    (hi, x - hi)
}

impl Dd {
    /// A double as a double-double.
    pub(crate) fn from_f64(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// The nearest double.
    pub(crate) fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// `self + other`, accurate also under cancellation.
    pub(crate) fn add(self, other: Dd) -> Dd {
        let (s1, s2) = two_sum(self.hi, other.hi);
        let (t1, t2) = two_sum(self.lo, other.lo);
        let (s1, s2) = quick_two_sum(s1, s2 + t1);
        let (hi, lo) = quick_two_sum(s1, s2 + t2);
        Dd { hi, lo }
    }

    /// `−self`.
    pub(crate) fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    /// `self · other`.
    pub(crate) fn mul(self, other: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, other.hi);
        let e = e + (self.hi * other.lo + self.lo * other.hi);
        let (hi, lo) = quick_two_sum(p, e);
        Dd { hi, lo }
    }

    /// `self · x` for a double `x`.
    pub(crate) fn mul_f64(self, x: f64) -> Dd {
        let (p, e) = two_prod(self.hi, x);
        let (hi, lo) = quick_two_sum(p, e + self.lo * x);
        Dd { hi, lo }
    }

    /// `self / 2` (exact).
    pub(crate) fn half(self) -> Dd {
        Dd {
            hi: 0.5 * self.hi,
            lo: 0.5 * self.lo,
        }
    }

    /// `self / other` (three quotient digits).
    pub(crate) fn div(self, other: Dd) -> Dd {
        let q1 = self.hi / other.hi;
        let r = self.add(other.mul_f64(q1).neg());
        let q2 = r.hi / other.hi;
        let r = r.add(other.mul_f64(q2).neg());
        let q3 = r.hi / other.hi;
        let (hi, lo) = quick_two_sum(q1, q2);
        Dd { hi, lo }.add(Dd::from_f64(q3))
    }

    /// `√self` for `self ≥ 0` by one Newton step on the double square root.
    pub(crate) fn sqrt(self) -> Dd {
        if self.hi <= 0.0 {
            return Dd::from_f64(self.hi.sqrt());
        }
        let s = self.hi.sqrt();
        let (p, e) = two_prod(s, s);
        let r = ((self.hi - p) - e) + self.lo;
        let (hi, lo) = quick_two_sum(s, r / (2.0 * s));
        Dd { hi, lo }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sqrt_two_squared() {
        let r = Dd::from_f64(2.0).sqrt();
        let back = r.mul(r).add(Dd::from_f64(-2.0));
        assert!(back.to_f64().abs() < 1e-30);
        // π − PI_HI − PI_LO is below 1e-32.
        let x = PI.add(Dd::from_f64(-std::f64::consts::PI));
        assert_eq!(x.hi, PI.lo);
        assert_eq!(FRAC_PI_2.mul_f64(2.0).hi, PI.hi);
        assert_eq!(FRAC_PI_2.mul_f64(2.0).lo, PI.lo);
        assert_eq!(PI.half().neg().hi, -FRAC_PI_2.hi);
        let third = Dd::from_f64(1.0).div(Dd::from_f64(3.0));
        let back = third.mul_f64(3.0).add(Dd::from_f64(-1.0));
        assert!(back.to_f64().abs() < 1e-31);
    }
}
