//! The preprocessed discrete Moser–Veselov algorithm (PDMV) of Hairer &
//! Vilmart, J. Phys. A 39 (2006) 13225: DMV applied with modified moments
//! of inertia, series in `h²` whose coefficients depend on the moments and
//! on the two invariants `|L|²` and the energy, chosen so that the method
//! is of order 4, 6, 8 or 10.
//!
//! Why moments suffice: DMV's `L` moves on the exact orbit, only at a
//! wrong speed, and its attitude precesses about `L` at a wrong rate
//! (McLachlan & Zanna 2005). Replacing `I⁻¹` by `s I⁻¹ + d` rescales the
//! speed of `L` by `s` and adds the rotation `d L` about `L` (since
//! `L × d L = 0`); `s` and `d` are functions of the invariants, constant
//! along the motion, so they are computed from the current `L` each step
//! at no loss of order.

// Coefficients are rationals of the paper; keep their published form.
#![allow(clippy::excessive_precision)]

use glam::DVec3;

use crate::moser_veselov::{MoserVeselov, dmv_step};
use crate::rigid_body::moment_scale;
use crate::{FreeBodyIntegrator, PrincipalState, Propagator};

/// Number of coefficients of `s` (and of `d`) through degree 4.
const COEFFICIENTS: usize = 14;

/// The coefficients of the corrections of the inverse moments,
/// `s = 1 + Σₙ Σᵢ sₙᵢ x^(n−i) yⁱ`, `d = Σₙ Σᵢ dₙᵢ x^(n−i) yⁱ` for
/// `n = 1 … terms`, `x = h²|L|²/2`, `y = h² H`: they depend on the
/// moments only. Stored degree by degree: `x, y, x², xy, y², x³, …, y⁴`.
///
/// The coefficients are those of Hairer & Vilmart (2006, §3 and their
/// DMV10 code), written with power sums of the moments: `P = I₁I₂I₃`,
/// `σₖ = Σ Iᵢᵏ`, `ρₖ = Σ Iᵢ⁻ᵏ`, `τₐᵦ = Σ_{i≠j} Iᵢᵃ/Iⱼᵇ = σₐρᵦ − Σ Iᵢ^(a−b)`.
/// Divisions by `P` are multiplications by `q = 1/P`, and the rational
/// constants are folded at compile time.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Series {
    /// How many degrees are used (0 … 4: order 2 … 10); the coefficients
    /// of the others are zero.
    terms: usize,
    s: [f64; COEFFICIENTS],
    d: [f64; COEFFICIENTS],
}

impl Series {
    fn new(m: DVec3, terms: usize) -> Self {
        let mut c = Self {
            terms,
            s: [0.0; COEFFICIENTS],
            d: [0.0; COEFFICIENTS],
        };
        if terms == 0 {
            return c;
        }
        let p = m.x * m.y * m.z;
        let q = 1.0 / p;
        let r = q * DVec3::new(m.y * m.z, m.z * m.x, m.x * m.y);
        let sum = |v: DVec3| v.element_sum();
        let (s1, s2, s3, s4) = (sum(m), sum(m * m), sum(m * m * m), sum(m * m * m * m));
        let (r1, r2, r3, r4) = (sum(r), sum(r * r), sum(r * r * r), sum(r * r * r * r));
        let (t11, t12, t21) = (s1 * r1 - 3.0, s1 * r2 - r1, s2 * r1 - s1);
        let (t13, t31, t22) = (s1 * r3 - r2, s3 * r1 - s2, s2 * r2 - 3.0);
        let (p2, q2) = (p * p, q * q);
        let (q3, q4) = (q2 * q, q2 * q2);
        // n = 1 (order 4).
        c.s[..2].copy_from_slice(&[s1 * q * (1.0 / 6.0), -r1 * (1.0 / 3.0)]);
        c.d[..2].copy_from_slice(&[-q * (1.0 / 3.0), s1 * q * (1.0 / 6.0)]);
        if terms == 1 {
            return c;
        }
        // n = 2 (order 6).
        c.s[2..5].copy_from_slice(&[
            (s2 * q - r1) * q * (1.0 / 30.0),
            (1.0 - t11) * q * (1.0 / 30.0),
            (3.0 * s1 * q + 2.0 * r2) * (1.0 / 60.0),
        ]);
        c.d[2..5].copy_from_slice(&[
            -s1 * q2 * (1.0 / 60.0),
            r1 * q * (1.0 / 10.0) - s2 * q2 * (1.0 / 60.0),
            -(9.0 + t11) * q * (1.0 / 60.0),
        ]);
        if terms == 2 {
            return c;
        }
        // n = 3 (order 8).
        c.s[5..9].copy_from_slice(&[
            (4.0 * p + 17.0 * s3 - 15.0 * p * t11) * q3 * (1.0 / 2520.0),
            (9.0 * s1 + 10.0 * p * r2 - 6.0 * t21) * q2 * (1.0 / 420.0),
            ((6.0 * t12 - 100.0 * r1) * p + 53.0 * s2) * q2 * (1.0 / 2520.0),
            (15.0 - p * r3 - 2.0 * t11) * q * (1.0 / 630.0),
        ]);
        c.d[5..9].copy_from_slice(&[
            (34.0 * p * r1 - 19.0 * s2) * q3 * (1.0 / 2520.0),
            (s3 + 2.0 * p * t11 - 85.0 * p) * q3 * (1.0 / 1260.0),
            (47.0 * s1 + 13.0 * t21 - 38.0 * p * r2) * q2 * (1.0 / 2520.0),
            (9.0 * p * r1 + p * t12 - 11.0 * s2) * q2 * (1.0 / 1260.0),
        ]);
        if terms == 3 {
            return c;
        }
        // n = 4 (order 10).
        c.s[9..].copy_from_slice(&[
            (62.0 * s4 - 94.0 * p * t21 + 66.0 * p2 * r2 + 81.0 * p * s1) * q4 * (1.0 / 45360.0),
            (-77.0 * t31 + 75.0 * p * t12 + 214.0 * s2 - 240.0 * p * r1) * q3 * (1.0 / 22680.0),
            (26.0 * p * t22 + 55.0 * s3 + 204.0 * p - 50.0 * p2 * r3 - 59.0 * p * t11)
                * q3
                * (1.0 / 7560.0),
            (137.0 * p * r2 - p * t13 + 3.0 * s1 - 69.0 * t21) * q2 * (1.0 / 11340.0),
            (2.0 * p2 * r4 + 5.0 * p * t12 - 171.0 * p * r1 + 159.0 * s2) * q2 * (1.0 / 45360.0),
        ]);
        c.d[9..].copy_from_slice(&[
            (60.0 * t11 * p - 61.0 * s3 - 247.0 * p) * q4 * (1.0 / 45360.0),
            (54.0 * p * s1 - s4 + 218.0 * p * t21 - 426.0 * p2 * r2) * q4 * (1.0 / 45360.0),
            (125.0 * p * r1 - 5.0 * t31 - 130.0 * s2 + 4.0 * p * t12) * q3 * (1.0 / 7560.0),
            (67.0 * s3 - 735.0 * p - 15.0 * p * t22 + 87.0 * p * t11 + 34.0 * p2 * r3)
                * q3
                * (1.0 / 22680.0),
            (165.0 * s1 - p * t13 - 9.0 * t21 - 145.0 * p * r2) * q2 * (1.0 / 45360.0),
        ]);
        c
    }

    /// `(s, d)` at `x = h²|L|²/2`, `y = h² H`; unused degrees have zero
    /// coefficients. The degrees are summed separately (short dependency
    /// chains), smallest last.
    #[inline]
    fn eval(&self, x: f64, y: f64) -> (f64, f64) {
        if self.terms == 0 {
            return (1.0, 0.0);
        }
        let (xx, xy, yy) = (x * x, x * y, y * y);
        let m = [
            x,
            y,
            xx,
            xy,
            yy,
            xx * x,
            xx * y,
            x * yy,
            yy * y,
            xx * xx,
            xx * xy,
            xx * yy,
            xy * yy,
            yy * yy,
        ];
        let block = |c: &[f64; COEFFICIENTS]| {
            let d1 = c[0] * m[0] + c[1] * m[1];
            let d2 = c[2] * m[2] + c[3] * m[3] + c[4] * m[4];
            let d3 = (c[5] * m[5] + c[6] * m[6]) + (c[7] * m[7] + c[8] * m[8]);
            let d4 =
                (c[9] * m[9] + c[10] * m[10]) + (c[11] * m[11] + c[12] * m[12]) + c[13] * m[13];
            ((d4 + d3) + d2) + d1
        };
        (1.0 + block(&self.s), block(&self.d))
    }
}

/// The preprocessed discrete Moser–Veselov algorithm of order 2, 4, 6, 8
/// or 10 (Hairer & Vilmart, J. Phys. A 39 (2006) 13225): DMV
/// ([`crate::MoserVeselov`]) with the modified moments of
/// [`PreprocessedMoserVeselov::modified_inverse_moments`].
///
/// ```text
/// Ĩₖ⁻¹ = s(h) / Iₖ + d(h),   then one DMV step with Ĩ
/// ```
///
/// Order 2 has no corrections (`s = 1`, `d = 0`) and is DMV itself.
/// Conserves `|L|`, `L_world` and the energy like DMV.
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{FreeBodyIntegrator, PreprocessedMoserVeselov, PrincipalState};
/// let pdmv = PreprocessedMoserVeselov::new(10).unwrap();
/// assert_eq!((pdmv.name(), pdmv.order()), ("pdmv10", 10));
/// assert!(PreprocessedMoserVeselov::new(5).is_none());
/// // Spin about a principal axis: uniform rotation by ω t = 1 rad, in 5 steps.
/// let mut s = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.0, 0.0, 3.0) };
/// for _ in 0..5 {
///     pdmv.step(DVec3::new(1.0, 2.0, 3.0), &mut s, 0.2);
/// }
/// assert!(kreisel_kinematics::rotation_angle_between(s.world_from_principal, DQuat::from_rotation_z(1.0)) < 1e-11);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreprocessedMoserVeselov {
    name: &'static str,
    order: u32,
    description: &'static str,
    /// `h ω_max` beyond which the implicit step fails (no finite state).
    step_limit: f64,
    /// Moments and their series coefficients, if prepared by
    /// [`PreprocessedMoserVeselov::for_body`].
    prepared: Option<(DVec3, Series)>,
}

impl PreprocessedMoserVeselov {
    /// PDMV of order 4 (`"pdmv4"`): `s`, `d` to `O(h²)`.
    /// Step limit `h ω_max` = 2.8: beyond it the implicit step fails
    /// (no finite state).
    ///
    /// ```text
    /// s = 1 + s₁(x, y),   d = d₁(x, y)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{FreeBodyIntegrator, PreprocessedMoserVeselov};
    /// assert_eq!(PreprocessedMoserVeselov::ORDER_4.order(), 4);
    /// ```
    pub const ORDER_4: Self = Self {
        name: "pdmv4",
        order: 4,
        description: "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 4",
        step_limit: 2.8,
        prepared: None,
    };
    /// PDMV of order 6 (`"pdmv6"`): `s`, `d` to `O(h⁴)`.
    /// Step limit `h ω_max` = 1.4: beyond it the implicit step fails
    /// (no finite state).
    ///
    /// ```text
    /// s = 1 + s₁ + s₂,   d = d₁ + d₂
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{FreeBodyIntegrator, PreprocessedMoserVeselov};
    /// assert_eq!(PreprocessedMoserVeselov::ORDER_6.name(), "pdmv6");
    /// ```
    pub const ORDER_6: Self = Self {
        name: "pdmv6",
        order: 6,
        description: "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 6",
        step_limit: 1.4,
        prepared: None,
    };
    /// PDMV of order 8 (`"pdmv8"`): `s`, `d` to `O(h⁶)`.
    /// Step limit `h ω_max` = 2.0: beyond it the implicit step fails
    /// (no finite state).
    ///
    /// ```text
    /// s = 1 + s₁ + s₂ + s₃,   d = d₁ + d₂ + d₃
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{FreeBodyIntegrator, PreprocessedMoserVeselov};
    /// assert_eq!(PreprocessedMoserVeselov::ORDER_8.order(), 8);
    /// ```
    pub const ORDER_8: Self = Self {
        name: "pdmv8",
        order: 8,
        description: "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 8",
        step_limit: 2.0,
        prepared: None,
    };
    /// PDMV of order 10 (`"pdmv10"`): `s`, `d` to `O(h⁸)`.
    /// Step limit `h ω_max` = 1.5: beyond it the implicit step fails
    /// (no finite state).
    ///
    /// ```text
    /// s = 1 + s₁ + s₂ + s₃ + s₄,   d = d₁ + d₂ + d₃ + d₄
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{FreeBodyIntegrator, PreprocessedMoserVeselov};
    /// assert_eq!(PreprocessedMoserVeselov::ORDER_10.name(), "pdmv10");
    /// ```
    pub const ORDER_10: Self = Self {
        name: "pdmv10",
        order: 10,
        description: "Hairer and Vilmart's preprocessed discrete Moser-Veselov, order 10",
        step_limit: 1.5,
        prepared: None,
    };

    /// The method of the given order: 2, 4, 6, 8 or 10 (`None` otherwise).
    ///
    /// ```text
    /// order 2p:  s, d summed to h^(2p−2)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::PreprocessedMoserVeselov;
    /// assert!(PreprocessedMoserVeselov::new(8).is_some());
    /// assert!(PreprocessedMoserVeselov::new(12).is_none());
    /// ```
    pub const fn new(order: u32) -> Option<Self> {
        match order {
            // DMV itself: its name, description and step limit.
            2 => Some(Self {
                name: MoserVeselov::NAME,
                order,
                description: MoserVeselov::DESCRIPTION,
                step_limit: MoserVeselov::STEP_LIMIT,
                prepared: None,
            }),
            4 => Some(Self::ORDER_4),
            6 => Some(Self::ORDER_6),
            8 => Some(Self::ORDER_8),
            10 => Some(Self::ORDER_10),
            _ => None,
        }
    }

    /// The modified inverse moments for step `h` at angular momentum `L`
    /// (Hairer & Vilmart 2006, §3), with the energy `H = ½ Σ Lₖ²/Iₖ`.
    ///
    /// ```text
    /// Ĩₖ⁻¹ = s / Iₖ + d,   s = 1 + Σₙ sₙ(x, y),   d = Σₙ dₙ(x, y),
    /// x = h²|L|²/2,   y = h² H,   sₙ, dₙ homogeneous of degree n
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::PreprocessedMoserVeselov;
    /// let (m, l) = (DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.01, 2.0, 0.0));
    /// let pdmv4 = PreprocessedMoserVeselov::new(4).unwrap();
    /// // h → 0: the moments themselves; order 2 never modifies them.
    /// assert_eq!(pdmv4.modified_inverse_moments(m, l, 0.0), DVec3::ONE / m);
    /// let dmv = PreprocessedMoserVeselov::new(2).unwrap();
    /// assert_eq!(dmv.modified_inverse_moments(m, l, 0.1), DVec3::ONE / m);
    /// // The correction is O(h²).
    /// let dev = (pdmv4.modified_inverse_moments(m, l, 0.1) - DVec3::ONE / m).abs().max_element();
    /// assert!(dev > 1e-4 && dev < 1e-2);
    /// ```
    pub fn modified_inverse_moments(&self, moments: DVec3, l: DVec3, h: f64) -> DVec3 {
        let unit = moment_scale(moments);
        let m = moments / unit;
        let (s, d) = self.scale_and_shift(m, l / unit, h);
        (s / m + d) / unit
    }

    /// The same method with the moment-only part of the corrections
    /// (Hairer & Vilmart 2006, §3: about 150 operations for order 10)
    /// computed once for `moments`. Steps with these moments give the same
    /// results bit for bit, only faster; steps with other moments compute
    /// the coefficients as usual.
    ///
    /// ```text
    /// sₙᵢ, dₙᵢ = functions of (I₁, I₂, I₃) only
    /// ```
    ///
    /// ```
    /// use glam::{DQuat, DVec3};
    /// use kreisel_dynamics::{FreeBodyIntegrator, PreprocessedMoserVeselov, PrincipalState};
    /// let m = DVec3::new(1.0, 2.0, 3.0);
    /// let fast = PreprocessedMoserVeselov::ORDER_10.for_body(m);
    /// let s0 = PrincipalState { world_from_principal: DQuat::IDENTITY, l_principal: DVec3::new(0.01, 2.0, 0.0) };
    /// let (mut a, mut b) = (s0, s0);
    /// for _ in 0..100 {
    ///     fast.step(m, &mut a, 0.05);
    ///     PreprocessedMoserVeselov::ORDER_10.step(m, &mut b, 0.05);
    /// }
    /// assert_eq!(a, b);
    /// ```
    pub fn for_body(self, moments: DVec3) -> Self {
        let m = moments / moment_scale(moments);
        Self {
            prepared: Some((m, Series::new(m, self.terms()))),
            ..self
        }
    }

    /// Degrees of the corrections: `order/2 − 1`.
    fn terms(&self) -> usize {
        (self.order / 2).saturating_sub(1) as usize
    }

    /// `(s, d)` of [`Self::modified_inverse_moments`] for moments `m` and
    /// `l` in the body's unit of inertia (the largest moment in `[1, 2)`):
    /// `x`, `y` are then the pure numbers `(hω)²`-like they are meant to
    /// be, and the coefficients (up to `1/(I₁I₂I₃)⁴`) stay in range; in SI
    /// units they overflowed for moments ≤ 1e-26 kg m².
    #[inline]
    fn scale_and_shift(&self, moments: DVec3, l: DVec3, h: f64) -> (f64, f64) {
        if self.terms() == 0 {
            return (1.0, 0.0);
        }
        let m = moments;
        let r = DVec3::new(m.y * m.z, m.z * m.x, m.x * m.y) * (1.0 / (m.x * m.y * m.z));
        let h2 = h * h;
        let x = 0.5 * h2 * l.length_squared();
        let y = 0.5 * h2 * (l * l * r).element_sum();
        match self.prepared {
            Some((prepared, series)) if prepared == moments => series.eval(x, y),
            _ => Series::new(moments, self.terms()).eval(x, y),
        }
    }
}

impl FreeBodyIntegrator for PreprocessedMoserVeselov {
    fn name(&self) -> &'static str {
        self.name
    }

    fn order(&self) -> u32 {
        self.order
    }

    fn description(&self) -> &'static str {
        self.description
    }

    fn step_limit(&self) -> Option<f64> {
        Some(self.step_limit)
    }

    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64) {
        let unit = moment_scale(moments);
        let m = moments / unit;
        let (s, d) = self.scale_and_shift(m, state.l_principal / unit, h);
        dmv_step(m, unit, s, d, state, h);
    }

    /// Steps of [`PreprocessedMoserVeselov::for_body`]: the same results,
    /// the moment-only coefficients computed once.
    fn propagator<'a>(&'a self, moments: DVec3, state: PrincipalState) -> Box<dyn Propagator + 'a> {
        Box::new(Prepared {
            method: self.for_body(moments),
            moments,
            state,
        })
    }
}

/// One body stepped by a PDMV prepared for its moments.
struct Prepared {
    method: PreprocessedMoserVeselov,
    moments: DVec3,
    state: PrincipalState,
}

impl Propagator for Prepared {
    fn advance(&mut self, h: f64) {
        self.method.step(self.moments, &mut self.state, h);
    }

    fn state(&self) -> PrincipalState {
        self.state
    }
}
