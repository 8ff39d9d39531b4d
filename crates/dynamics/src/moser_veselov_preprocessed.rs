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

use crate::moser_veselov::dmv_step;
use crate::{FreeBodyIntegrator, PrincipalState};

/// Corrections of the inverse moments: `s = 1 + Σₙ Σᵢ sₙᵢ x^(n−i) yⁱ`,
/// `d = Σₙ Σᵢ dₙᵢ x^(n−i) yⁱ`, `n = 1 … terms`, `x = h²|L|²/2`, `y = h² H`.
///
/// The coefficients are those of Hairer & Vilmart (2006, §3 and their
/// DMV10 code), written with power sums of the moments: `P = I₁I₂I₃`,
/// `σₖ = Σ Iᵢᵏ`, `ρₖ = Σ Iᵢ⁻ᵏ`, `τₐᵦ = Σ_{i≠j} Iᵢᵃ/Iⱼᵇ = σₐρᵦ − Σ Iᵢ^(a−b)`.
fn corrections(moments: DVec3, x: f64, y: f64, terms: usize) -> (f64, f64) {
    if terms == 0 {
        return (1.0, 0.0);
    }
    let m = moments;
    let r = DVec3::ONE / m;
    let p = m.x * m.y * m.z;
    let sum = |v: DVec3| v.element_sum();
    let (s1, s2) = (sum(m), sum(m * m));
    let (r1, r2) = (sum(r), sum(r * r));
    let t11 = s1 * r1 - 3.0;
    // n = 1 (order 4).
    let mut s = 1.0 + s1 / (6.0 * p) * x - r1 / 3.0 * y;
    let mut d = -1.0 / (3.0 * p) * x + s1 / (6.0 * p) * y;
    if terms == 1 {
        return (s, d);
    }
    let (xx, xy, yy) = (x * x, x * y, y * y);
    let p2 = p * p;
    // n = 2 (order 6).
    s += (s2 / p - r1) / (30.0 * p) * xx
        + (1.0 - t11) / (30.0 * p) * xy
        + (3.0 * s1 / p + 2.0 * r2) / 60.0 * yy;
    d += -s1 / (60.0 * p2) * xx + (r1 / (10.0 * p) - s2 / (60.0 * p2)) * xy
        - (9.0 + t11) / (60.0 * p) * yy;
    if terms == 2 {
        return (s, d);
    }
    let (s3, r3) = (sum(m * m * m), sum(r * r * r));
    let t12 = s1 * r2 - r1;
    let t21 = s2 * r1 - s1;
    let p3 = p2 * p;
    let (x3, x2y, xy2, y3) = (xx * x, xx * y, x * yy, yy * y);
    // n = 3 (order 8).
    s += (4.0 * p + 17.0 * s3 - 15.0 * p * t11) / (2520.0 * p3) * x3
        + (9.0 * s1 + 10.0 * p * r2 - 6.0 * t21) / (420.0 * p2) * x2y
        + ((6.0 * t12 - 100.0 * r1) * p + 53.0 * s2) / (2520.0 * p2) * xy2
        + (15.0 - p * r3 - 2.0 * t11) / (630.0 * p) * y3;
    d += (34.0 * p * r1 - 19.0 * s2) / (2520.0 * p3) * x3
        + (s3 + 2.0 * p * t11 - 85.0 * p) / (1260.0 * p3) * x2y
        + (47.0 * s1 + 13.0 * t21 - 38.0 * p * r2) / (2520.0 * p2) * xy2
        + (9.0 * p * r1 + p * t12 - 11.0 * s2) / (1260.0 * p2) * y3;
    if terms == 3 {
        return (s, d);
    }
    let (s4, r4) = (sum(m * m * m * m), sum(r * r * r * r));
    let t13 = s1 * r3 - r2;
    let t31 = s3 * r1 - s2;
    let t22 = s2 * r2 - 3.0;
    let p4 = p2 * p2;
    let (x4, x3y, x2y2, xy3, y4) = (xx * xx, x3 * y, xx * yy, x * y3, yy * yy);
    // n = 4 (order 10).
    s += (62.0 * s4 - 94.0 * p * t21 + 66.0 * p2 * r2 + 81.0 * p * s1) / (45360.0 * p4) * x4
        + (-77.0 * t31 + 75.0 * p * t12 + 214.0 * s2 - 240.0 * p * r1) / (22680.0 * p3) * x3y
        + (26.0 * p * t22 + 55.0 * s3 + 204.0 * p - 50.0 * p2 * r3 - 59.0 * p * t11)
            / (7560.0 * p3)
            * x2y2
        + (137.0 * p * r2 - p * t13 + 3.0 * s1 - 69.0 * t21) / (11340.0 * p2) * xy3
        + (2.0 * p2 * r4 + 5.0 * p * t12 - 171.0 * p * r1 + 159.0 * s2) / (45360.0 * p2) * y4;
    d += (60.0 * t11 * p - 61.0 * s3 - 247.0 * p) / (45360.0 * p4) * x4
        + (54.0 * p * s1 - s4 + 218.0 * p * t21 - 426.0 * p2 * r2) / (45360.0 * p4) * x3y
        + (125.0 * p * r1 - 5.0 * t31 - 130.0 * s2 + 4.0 * p * t12) / (7560.0 * p3) * x2y2
        + (67.0 * s3 - 735.0 * p - 15.0 * p * t22 + 87.0 * p * t11 + 34.0 * p2 * r3)
            / (22680.0 * p3)
            * xy3
        + (165.0 * s1 - p * t13 - 9.0 * t21 - 145.0 * p * r2) / (45360.0 * p2) * y4;
    (s, d)
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
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PreprocessedMoserVeselov {
    order: u32,
}

impl PreprocessedMoserVeselov {
    /// PDMV of order 4 (`"pdmv4"`): `s`, `d` to `O(h²)`.
    ///
    /// ```text
    /// s = 1 + s₁(x, y),   d = d₁(x, y)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{FreeBodyIntegrator, PreprocessedMoserVeselov};
    /// assert_eq!(PreprocessedMoserVeselov::ORDER_4.order(), 4);
    /// ```
    pub const ORDER_4: Self = Self { order: 4 };
    /// PDMV of order 6 (`"pdmv6"`): `s`, `d` to `O(h⁴)`.
    ///
    /// ```text
    /// s = 1 + s₁ + s₂,   d = d₁ + d₂
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{FreeBodyIntegrator, PreprocessedMoserVeselov};
    /// assert_eq!(PreprocessedMoserVeselov::ORDER_6.name(), "pdmv6");
    /// ```
    pub const ORDER_6: Self = Self { order: 6 };
    /// PDMV of order 8 (`"pdmv8"`): `s`, `d` to `O(h⁶)`.
    ///
    /// ```text
    /// s = 1 + s₁ + s₂ + s₃,   d = d₁ + d₂ + d₃
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{FreeBodyIntegrator, PreprocessedMoserVeselov};
    /// assert_eq!(PreprocessedMoserVeselov::ORDER_8.order(), 8);
    /// ```
    pub const ORDER_8: Self = Self { order: 8 };
    /// PDMV of order 10 (`"pdmv10"`): `s`, `d` to `O(h⁸)`.
    ///
    /// ```text
    /// s = 1 + s₁ + s₂ + s₃ + s₄,   d = d₁ + d₂ + d₃ + d₄
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{FreeBodyIntegrator, PreprocessedMoserVeselov};
    /// assert_eq!(PreprocessedMoserVeselov::ORDER_10.name(), "pdmv10");
    /// ```
    pub const ORDER_10: Self = Self { order: 10 };

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
            2 | 4 | 6 | 8 | 10 => Some(Self { order }),
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
        let h2 = h * h;
        let x = 0.5 * h2 * l.length_squared();
        let y = 0.5 * h2 * (l * l / moments).element_sum();
        let terms = (self.order / 2).saturating_sub(1) as usize;
        let (s, d) = corrections(moments, x, y, terms);
        s / moments + d
    }
}

impl FreeBodyIntegrator for PreprocessedMoserVeselov {
    fn name(&self) -> &'static str {
        match self.order {
            4 => "pdmv4",
            6 => "pdmv6",
            8 => "pdmv8",
            10 => "pdmv10",
            _ => "dmv",
        }
    }

    fn order(&self) -> u32 {
        self.order
    }

    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64) {
        let inv = self.modified_inverse_moments(moments, state.l_principal, h);
        dmv_step(inv, state, h);
    }
}
