//! Symmetric compositions of the second-order splitting to orders 4, 6 and 8.

// Coefficients are written with all the digits the papers publish.
#![allow(clippy::excessive_precision)]

use glam::DVec3;

use crate::splitting::SymmetricTopSplitting;
use crate::{FreeBodyIntegrator, PrincipalState};

/// Coefficients of a symmetric composition: the first half, then the middle.
///
/// ```text
/// Ψₕ = Φ(γ₁h) ∘ … ∘ Φ(γₛh) ∘ Φ(γ_mid h) ∘ Φ(γₛh) ∘ … ∘ Φ(γ₁h),   2 Σγᵢ + γ_mid = 1
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompositionCoefficients {
    /// γ₁ … γₛ.
    pub half: &'static [f64],
    /// The middle coefficient.
    pub middle: f64,
}

impl CompositionCoefficients {
    /// The number of stages: `2 s + 1`.
    ///
    /// ```
    /// assert_eq!(kreisel_dynamics::KAHAN_LI_6.stages(), 9);
    /// ```
    pub fn stages(&self) -> usize {
        2 * self.half.len() + 1
    }

    /// The stage coefficients in order: the first half, the middle, the
    /// first half reversed.
    pub(crate) fn gammas(&self) -> impl Iterator<Item = f64> + '_ {
        self.half
            .iter()
            .chain(std::iter::once(&self.middle))
            .chain(self.half.iter().rev())
            .copied()
    }
}

/// Suzuki (Phys. Lett. A 146:319, 1990), order 4, 5 stages:
/// γ = 1/(4 − 4^{1/3}) four times, middle 1 − 4γ.
pub const SUZUKI_4: CompositionCoefficients = CompositionCoefficients {
    half: &[0.414_490_771_794_375_7, 0.414_490_771_794_375_7],
    middle: -0.657_963_087_177_502_8,
};

/// Kahan & Li (Math. Comp. 66:1089, 1997), order 6, 9 stages.
pub const KAHAN_LI_6: CompositionCoefficients = CompositionCoefficients {
    half: &[
        0.392_161_444_007_314_139_28,
        0.332_599_136_789_359_438_60,
        -0.706_246_172_557_639_359_81,
        0.082_213_596_293_550_800_23,
    ],
    middle: 0.798_543_990_934_829_963_40,
};

/// Kahan & Li (Math. Comp. 66:1089, 1997), order 8, 17 stages.
pub const KAHAN_LI_8: CompositionCoefficients = CompositionCoefficients {
    half: &[
        0.130_202_483_088_890_080_88,
        0.561_162_981_775_108_384_56,
        -0.389_474_962_644_847_286_41,
        0.158_841_906_555_155_600_90,
        -0.395_903_894_133_237_577_34,
        0.184_539_640_978_315_707_09,
        0.258_374_387_686_322_047_29,
        0.295_011_723_609_310_298_87,
    ],
    middle: -0.605_508_533_830_034_511_70,
};

/// A symmetric composition of [`SymmetricTopSplitting`]: the methods
/// `splitting4`, `splitting6` and `splitting8` ([`Composition::ORDER_4`],
/// [`Composition::ORDER_6`], [`Composition::ORDER_8`]), each with its
/// name, order, description and measured step limit.
#[derive(Debug, Clone, Copy)]
pub struct Composition {
    name: &'static str,
    order: u32,
    coefficients: &'static CompositionCoefficients,
    description: &'static str,
    step_limit: Option<f64>,
}

impl Composition {
    /// `splitting4`: Suzuki's 5-stage composition ([`SUZUKI_4`]), order 4;
    /// step limit `h ω_max` = 4.2 (beyond it the energy swings beyond
    /// 10 %; |L| stays exact).
    ///
    /// ```text
    /// Ψₕ = Φ(γh) ∘ Φ(γh) ∘ Φ((1 − 4γ)h) ∘ Φ(γh) ∘ Φ(γh),   γ = 1/(4 − 4^{1/3})
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{Composition, FreeBodyIntegrator};
    /// let m = Composition::ORDER_4;
    /// assert_eq!((m.name(), m.order(), m.step_limit()), ("splitting4", 4, Some(4.2)));
    /// ```
    pub const ORDER_4: Self = Self {
        name: "splitting4",
        order: 4,
        coefficients: &SUZUKI_4,
        description: "Suzuki's 5-stage symmetric composition of splitting",
        step_limit: Some(4.2),
    };
    /// `splitting6`: Kahan & Li's 9-stage composition ([`KAHAN_LI_6`]),
    /// order 6; step limit `h ω_max` = 6.5 (beyond it the energy swings
    /// beyond 10 %; |L| stays exact).
    ///
    /// ```text
    /// Ψₕ = Φ(γ₁h) ∘ … ∘ Φ(γ₄h) ∘ Φ(γ_mid h) ∘ Φ(γ₄h) ∘ … ∘ Φ(γ₁h)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{Composition, FreeBodyIntegrator};
    /// let m = Composition::ORDER_6;
    /// assert_eq!((m.name(), m.order(), m.step_limit()), ("splitting6", 6, Some(6.5)));
    /// ```
    pub const ORDER_6: Self = Self {
        name: "splitting6",
        order: 6,
        coefficients: &KAHAN_LI_6,
        description: "Kahan and Li's 9-stage symmetric composition of splitting",
        step_limit: Some(6.5),
    };
    /// `splitting8`: Kahan & Li's 17-stage composition ([`KAHAN_LI_8`]),
    /// order 8; step limit `h ω_max` = 7.6 (beyond it the energy swings
    /// beyond 10 %; |L| stays exact).
    ///
    /// ```text
    /// Ψₕ = Φ(γ₁h) ∘ … ∘ Φ(γ₈h) ∘ Φ(γ_mid h) ∘ Φ(γ₈h) ∘ … ∘ Φ(γ₁h)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{Composition, FreeBodyIntegrator};
    /// let m = Composition::ORDER_8;
    /// assert_eq!((m.name(), m.order(), m.step_limit()), ("splitting8", 8, Some(7.6)));
    /// ```
    pub const ORDER_8: Self = Self {
        name: "splitting8",
        order: 8,
        coefficients: &KAHAN_LI_8,
        description: "Kahan and Li's 17-stage symmetric composition of splitting",
        step_limit: Some(7.6),
    };

    /// A composition method of your own, with its name, order and
    /// description (no measured step limit).
    ///
    /// ```text
    /// Ψₕ = Φ(γ₁h) ∘ … ∘ Φ(γ_mid h) ∘ … ∘ Φ(γ₁h)
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::{Composition, FreeBodyIntegrator, SUZUKI_4};
    /// let m = Composition::new("suzuki", 4, &SUZUKI_4, "Suzuki's composition");
    /// assert_eq!((m.order(), m.description(), m.step_limit()), (4, "Suzuki's composition", None));
    /// ```
    pub const fn new(
        name: &'static str,
        order: u32,
        coefficients: &'static CompositionCoefficients,
        description: &'static str,
    ) -> Self {
        Self {
            name,
            order,
            coefficients,
            description,
            step_limit: None,
        }
    }
}

impl FreeBodyIntegrator for Composition {
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
        self.step_limit
    }

    fn step(&self, moments: DVec3, state: &mut PrincipalState, h: f64) {
        let base = SymmetricTopSplitting;
        let c = self.coefficients;
        for &g in c.half {
            base.step(moments, state, g * h);
        }
        base.step(moments, state, c.middle * h);
        for &g in c.half.iter().rev() {
            base.step(moments, state, g * h);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coefficients_sum_to_one() {
        for c in [SUZUKI_4, KAHAN_LI_6, KAHAN_LI_8] {
            let sum = 2.0 * c.half.iter().sum::<f64>() + c.middle;
            assert!((sum - 1.0).abs() < 1e-15, "{sum}");
        }
        let g = 1.0 / (4.0 - 4f64.powf(1.0 / 3.0));
        assert!((SUZUKI_4.half[0] - g).abs() < 1e-16);
    }
}
