//! Jacobi elliptic functions sn, cn, dn and the amplitude am, parametrised by
//! the complementary parameter `mc = 1 − m` (any real mc, by the imaginary-
//! and reciprocal-modulus transformations onto `mc ∈ [0, 1]`).

use super::agm::{Agm, Reduced};
use super::dd::{Dd, PI};

/// sech u = 1/cosh u, also where cosh overflows (|u| > 710, down to subnormal results).
fn sech(u: f64) -> f64 {
    let a = u.abs();
    if a < 20.0 {
        1.0 / a.cosh()
    } else {
        let e = (-a).exp();
        2.0 * e / (1.0 + e * e)
    }
}

/// How the functions for one parameter are evaluated.
#[derive(Clone, Debug)]
enum Kind {
    /// NaN or infinite parameter.
    Invalid,
    /// mc = 0: tanh, sech, sech.
    Hyperbolic,
    /// 0 < mc ≤ 1.
    Standard(Agm),
    /// mc > 1 (m < 0): imaginary-modulus transformation to mc' = 1/mc.
    ImaginaryModulus { agm: Agm, sqrt_mc: Dd },
    /// mc < 0 (m > 1): reciprocal-modulus transformation to m' = 1/m.
    Reciprocal { agm: Agm, sqrt_m: Dd },
}

/// The Jacobi elliptic functions for one fixed complementary parameter `mc = 1 − m`.
///
/// ```text
/// u = ∫₀^φ dθ / √(1 − m sin²θ),  am(u) = φ,  sn u = sin φ,  cn u = cos φ,
/// dn u = √(1 − m sin²φ),  m = 1 − mc
/// ```
///
/// Precomputes the arithmetic–geometric mean of (1, √mc) once (about 15
/// levels for mc = 10⁻³⁰⁰), so that repeated evaluations at one parameter
/// (the free rigid body) cost one pass of Bulirsch's recurrence each. Any
/// real `mc` is accepted: `mc ∈ (0, 1]` directly, `mc = 0` as tanh/sech,
/// `mc > 1` (m < 0) and `mc < 0` (m > 1) by the imaginary- and
/// reciprocal-modulus transformations (DLMF 22.6.iv); NaN or infinite `mc`
/// gives NaN values.
///
/// ```
/// use kreisel_dynamics::elliptic::JacobiElliptic;
/// let f = JacobiElliptic::new(1e-300);
/// let (sn, cn, dn) = f.sn_cn_dn(2.0);
/// assert!((sn - 2.0f64.tanh()).abs() < 1e-16);
/// assert!((cn / (1.0 / 2.0f64.cosh()) - 1.0).abs() < 1e-15);
/// assert!((dn - cn).abs() < 1e-16);
/// ```
///
/// Reference: R. Bulirsch, "Numerical calculation of elliptic integrals and
/// elliptic functions", Numer. Math. 7:78–90 (1965), procedure `sncndn`;
/// DLMF 22.20(ii).
#[derive(Clone, Debug)]
pub struct JacobiElliptic {
    kind: Kind,
}

impl JacobiElliptic {
    /// Prepares the functions for the complementary parameter `mc = 1 − m`.
    ///
    /// ```text
    /// a₀ = 1, b₀ = √mc,  aₙ₊₁ = (aₙ + bₙ)/2,  bₙ₊₁ = √(aₙ bₙ),  K = π / (2 AGM(1, √mc))
    /// ```
    ///
    /// The AGM is run in double-double arithmetic, so that the quarter period
    /// K used in the argument reduction is known to ~10⁻³² relative.
    ///
    /// ```
    /// use kreisel_dynamics::elliptic::JacobiElliptic;
    /// let (sn, cn, dn) = JacobiElliptic::new(1.0).sn_cn_dn(0.5);
    /// assert!((sn - 0.5f64.sin()).abs() < 1e-16 && (cn - 0.5f64.cos()).abs() < 1e-16);
    /// assert_eq!(dn, 1.0);
    /// ```
    ///
    /// Reference: Bulirsch, Numer. Math. 7:78–90 (1965); DLMF 19.8.1, 22.20.1.
    pub fn new(mc: f64) -> JacobiElliptic {
        JacobiElliptic::from_dd(Dd::from_f64(mc))
    }

    /// Prepares the functions for the parameter `m` (`mc = 1 − m` formed exactly).
    ///
    /// ```text
    /// mc = 1 − m  (as an exact double-double)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::elliptic::JacobiElliptic;
    /// let (sn, _, dn) = JacobiElliptic::with_parameter(0.5).sn_cn_dn(1.0);
    /// assert!((dn * dn + 0.5 * sn * sn - 1.0).abs() < 2e-16);
    /// ```
    ///
    /// Reference: DLMF 22.2.
    pub fn with_parameter(m: f64) -> JacobiElliptic {
        JacobiElliptic::from_dd(Dd::from_f64(1.0).add(Dd::from_f64(-m)))
    }

    fn from_dd(mc: Dd) -> JacobiElliptic {
        let one = Dd::from_f64(1.0);
        let kind = if !mc.hi.is_finite() {
            Kind::Invalid
        } else if mc.hi == 0.0 {
            Kind::Hyperbolic
        } else if mc.hi > 1.0 || (mc.hi == 1.0 && mc.lo > 0.0) {
            Kind::ImaginaryModulus {
                agm: Agm::new(one.div(mc)),
                sqrt_mc: mc.sqrt(),
            }
        } else if mc.hi > 0.0 {
            Kind::Standard(Agm::new(mc))
        } else {
            let m = one.add(mc.neg());
            Kind::Reciprocal {
                agm: Agm::new(mc.neg().div(m)),
                sqrt_m: m.sqrt(),
            }
        };
        JacobiElliptic { kind }
    }

    /// (sn u, cn u, dn u) for this parameter.
    ///
    /// ```text
    /// sn(u + 2K) = −sn u,  cn(u + 2K) = −cn u,  dn(u + 2K) = dn u
    /// sn(K − v) = cd v,  cn(K − v) = √mc sd v,  dn(K − v) = √mc nd v
    /// ```
    ///
    /// `u` is reduced to `[−K, K]` by multiples of 2K in double-double
    /// arithmetic (the phase `u·π/(2K)` to ~10⁻³²), then to `[0, K/2]` by the
    /// quarter-period reflection, so the error does not grow with `|u|` while
    /// `|u|/K ≲ 10¹⁵` (beyond that it grows like `|u|/K · 10⁻³²`, and exceeds
    /// 1 past `|u|/K ≈ 10³²`). Measured for mc from 5·10⁻³²⁴ to 1 and `|u|`
    /// up to 10⁶ (`tests/elliptic.rs`): absolute error ≤ 5·10⁻¹⁶; relative
    /// error of sn ≤ 6·10⁻¹⁶ and of dn ≤ 2·10⁻¹⁵ (also where dn ≈ √mc ≪ 1),
    /// of cn ≤ 10⁻¹⁵ times `K/|K − |u′||` (u′ = u reduced to [−K, K]: the
    /// conditioning at the zero of cn). For mc ≤ 10⁻¹² the expansion in mc
    /// about tanh/sech (DLMF 22.10.ii) replaces the recurrence on |u′| ≤ K/2.
    /// `u = ±∞` or NaN gives NaN (tanh/sech limits for `mc = 0`).
    ///
    /// ```
    /// use kreisel_dynamics::elliptic::JacobiElliptic;
    /// let f = JacobiElliptic::new(0.5);
    /// let (sn, cn, dn) = f.sn_cn_dn(1.0e6);
    /// assert!((sn * sn + cn * cn - 1.0).abs() < 3e-16);
    /// assert!((dn * dn + 0.5 * sn * sn - 1.0).abs() < 3e-16);
    /// ```
    ///
    /// Reference: Bulirsch, Numer. Math. 7:78–90 (1965); DLMF 22.4.3, 22.6.iv, 22.20(ii).
    pub fn sn_cn_dn(&self, u: f64) -> (f64, f64, f64) {
        if let Kind::Hyperbolic = self.kind {
            let sech = sech(u);
            return (u.tanh(), sech, sech);
        }
        match self.eval(u) {
            Some(r) => (r.sn, r.cn, r.dn),
            None => (f64::NAN, f64::NAN, f64::NAN),
        }
    }

    /// The Jacobi amplitude am u = φ with sn u = sin φ, cn u = cos φ.
    ///
    /// ```text
    /// am u = jπ + atan2(sn(u − 2jK), cn(u − 2jK)),  am(u + 2K) = am u + π
    /// ```
    ///
    /// Continuous and increasing in `u`; `gd u = atan(sinh u)` for `mc = 0`.
    /// NaN for `mc < 0` (m > 1, where am is not monotone) and for NaN or
    /// infinite `u` (except `mc = 0`, where am(±∞) = ±π/2).
    ///
    /// ```
    /// use kreisel_dynamics::elliptic::{JacobiElliptic, incomplete_f_complementary};
    /// let f = JacobiElliptic::new(1e-8);
    /// let phi = f.amplitude(20.0);
    /// assert!((incomplete_f_complementary(phi, 1e-8) - 20.0).abs() < 1e-13);
    /// ```
    ///
    /// Reference: DLMF 22.16.1–22.16.3; Bulirsch, Numer. Math. 7:78–90 (1965).
    pub fn amplitude(&self, u: f64) -> f64 {
        if let Kind::Hyperbolic = self.kind {
            return u.sinh().atan();
        }
        if let Kind::Reciprocal { .. } = self.kind {
            return f64::NAN;
        }
        match self.eval(u) {
            Some(r) => PI
                .mul_f64(r.j)
                .add(Dd::from_f64(r.sn_r.atan2(r.cn_r)))
                .to_f64(),
            None => f64::NAN,
        }
    }

    /// Evaluates at finite `u` through the AGM; `None` otherwise (and for mc = 0).
    fn eval(&self, u: f64) -> Option<Reduced> {
        if !u.is_finite() {
            return None;
        }
        match &self.kind {
            Kind::Invalid | Kind::Hyperbolic => None,
            Kind::Standard(agm) => Some(agm.eval(Dd::from_f64(u))),
            Kind::ImaginaryModulus { agm, sqrt_mc } => {
                // sn(u|m) = sd(u√mc | m')/√mc, cn = cd, dn = nd, m' = −m/mc  (DLMF 22.6.16–18)
                let r = agm.eval(sqrt_mc.mul_f64(u));
                let s = sqrt_mc.hi;
                Some(Reduced {
                    sn: r.sn / (r.dn * s),
                    cn: r.cn / r.dn,
                    dn: 1.0 / r.dn,
                    j: r.j,
                    sn_r: r.sn_r / s,
                    cn_r: r.cn_r,
                })
            }
            Kind::Reciprocal { agm, sqrt_m } => {
                // sn(u|m) = sn(u√m | 1/m)/√m, cn = dn(·), dn = cn(·)  (DLMF 22.6.12–14)
                let r = agm.eval(sqrt_m.mul_f64(u));
                Some(Reduced {
                    sn: r.sn / sqrt_m.hi,
                    cn: r.dn,
                    dn: r.cn,
                    j: f64::NAN,
                    sn_r: f64::NAN,
                    cn_r: f64::NAN,
                })
            }
        }
    }
}

/// Jacobi elliptic functions (sn, cn, dn)(u | m) from the complementary parameter `mc = 1 − m`.
///
/// ```text
/// sn u = sin am u,  cn u = cos am u,  dn u = √(1 − m sn²u),  m = 1 − mc
/// mc = 0:  sn = tanh u,  cn = dn = sech u;   mc = 1:  sin u, cos u, 1
/// ```
///
/// Accurate for every `u` and for `mc` down to the smallest subnormal, where
/// `m = 1 − mc` is not representable; see [`JacobiElliptic::sn_cn_dn`] for
/// the accuracy and the treatment of `|u| ≫ K`, and use [`JacobiElliptic`]
/// to evaluate many `u` at one `mc`. `mc > 1` and `mc < 0` are accepted
/// (imaginary and reciprocal modulus); NaN or infinite `mc` gives NaN.
///
/// ```
/// use kreisel_dynamics::elliptic::{complete_k_complementary, jacobi_sn_cn_dn};
/// // Near the separatrix: at u = K, sn = 1, cn = 0, dn = √mc.
/// let mc = 1e-200;
/// let k = complete_k_complementary(mc);
/// let (sn, cn, dn) = jacobi_sn_cn_dn(k, mc);
/// assert!((sn - 1.0).abs() < 1e-16 && cn.abs() < 1e-100);
/// assert!((dn / 1e-100 - 1.0).abs() < 1e-15);
/// ```
///
/// Reference: Bulirsch, Numer. Math. 7:78–90 (1965), `sncndn`; DLMF 22.20(ii), 22.5.ii.
pub fn jacobi_sn_cn_dn(u: f64, mc: f64) -> (f64, f64, f64) {
    JacobiElliptic::new(mc).sn_cn_dn(u)
}

/// Jacobi elliptic functions (sn, cn, dn)(u | m) from the parameter `m`.
///
/// ```text
/// jacobi_sn_cn_dn_m(u, m) = jacobi_sn_cn_dn(u, 1 − m)   (1 − m formed exactly)
/// ```
///
/// For `m` within 10⁻¹⁶ of 1 pass `mc` to [`jacobi_sn_cn_dn`] instead.
///
/// ```
/// use kreisel_dynamics::elliptic::jacobi_sn_cn_dn_m;
/// let (sn, cn, dn) = jacobi_sn_cn_dn_m(0.3, 0.0);
/// assert!((sn - 0.3f64.sin()).abs() < 1e-16 && (cn - 0.3f64.cos()).abs() < 1e-16);
/// assert_eq!(dn, 1.0);
/// ```
///
/// Reference: DLMF 22.2; Bulirsch, Numer. Math. 7:78–90 (1965).
pub fn jacobi_sn_cn_dn_m(u: f64, m: f64) -> (f64, f64, f64) {
    JacobiElliptic::with_parameter(m).sn_cn_dn(u)
}

/// The Jacobi amplitude am(u | m) from the complementary parameter `mc = 1 − m`.
///
/// ```text
/// am u = φ  with  u = F(φ | m) = ∫₀^φ dθ / √(1 − m sin²θ)
/// ```
///
/// See [`JacobiElliptic::amplitude`]; NaN for `mc < 0` or NaN arguments.
///
/// ```
/// use kreisel_dynamics::elliptic::{complete_k_complementary, jacobi_amplitude};
/// let k = complete_k_complementary(0.25);
/// assert!((jacobi_amplitude(3.0 * k, 0.25) - 1.5 * std::f64::consts::PI).abs() < 1e-15);
/// ```
///
/// Reference: DLMF 22.16.1; Bulirsch, Numer. Math. 7:78–90 (1965).
pub fn jacobi_amplitude(u: f64, mc: f64) -> f64 {
    JacobiElliptic::new(mc).amplitude(u)
}
