//! Splitting the heavy top into the free body and the gravity kick, and the
//! symmetric compositions of that Strang splitting to orders 4, 6 and 8.

use super::HeavyTop;
use super::integrator::HeavyTopIntegrator;
use crate::PrincipalState;
use crate::composition::{CompositionCoefficients, KAHAN_LI_6, KAHAN_LI_8, SUZUKI_4};

/// Strang's splitting itself: one stage.
const STRANG: CompositionCoefficients = CompositionCoefficients {
    half: &[],
    middle: 1.0,
};

/// Kick–free–kick splitting of the heavy top (Strang 1968), and its
/// symmetric compositions (Suzuki 1990; Kahan & Li 1997).
///
/// ```text
/// H = T + V,   T = ½ L·J⁻¹L (free body),   V = −W·(R c) (gravity)
/// S_h = K(h/2) ∘ F(h) ∘ K(h/2),   Ψ_h = S(γ₁h) ∘ … ∘ S(γ_mid h) ∘ … ∘ S(γ₁h)
/// ```
/// Adjacent half kicks are merged, so a composition of `s` stages costs `s`
/// free flows and `s + 1` kicks. The free flow `F` is exact for a
/// symmetric top (two commuting rotations) and PDMV of order 10 otherwise;
/// the kick `K` is exact (`L += h c × RᵀW`). Every stage preserves `|q|`
/// and the vertical momentum `L_v` exactly (up to rounding); the energy
/// error stays bounded (symplectic), and for a Lagrange top `L·e₃` is
/// conserved too. Splitting the heavy top this way rather than splitting
/// the free body too follows Touma & Wisdom (1994), Dullweber, Leimkuhler &
/// McLachlan (1997) and Celledoni, Fassò, Säfström & Zanna (2008).
///
/// # Stability
/// See [`HeavyTopSplitting::stability_limit`].
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{HeavyTop, HeavyTopSplitting, HeavyTopIntegrator, PrincipalState};
/// let top = HeavyTop::try_from_principal(DVec3::new(0.02, 0.02, 0.01), DVec3::new(0.0, 0.0, 0.1), 1.0, DVec3::new(0.0, 0.0, -9.81))?;
/// let mut s = PrincipalState { world_from_principal: DQuat::from_rotation_x(0.3), l_principal: DVec3::new(0.0, 0.0, 0.5) };
/// let (lv, l3) = (top.vertical_momentum(&s), s.l_principal.z);
/// for _ in 0..1000 {
///     HeavyTopSplitting::ORDER_6.step(&top, &mut s, 1e-3);
/// }
/// // p_φ and p_ψ are conserved by every stage.
/// assert!((top.vertical_momentum(&s) - lv).abs() < 1e-14);
/// assert!((s.l_principal.z - l3).abs() < 1e-15);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct HeavyTopSplitting {
    name: &'static str,
    order: u32,
    coefficients: &'static CompositionCoefficients,
    stability_limit: f64,
}

impl HeavyTopSplitting {
    /// Strang (`"strang"`), order 2: one free flow, two half kicks.
    pub const STRANG: Self = Self {
        name: "strang",
        order: 2,
        coefficients: &STRANG,
        stability_limit: 2.0,
    };
    /// Suzuki's 5-stage composition (`"splitting4"`), order 4.
    pub const ORDER_4: Self = Self {
        name: "splitting4",
        order: 4,
        coefficients: &SUZUKI_4,
        stability_limit: 2.0,
    };
    /// Kahan & Li's 9-stage composition (`"splitting6"`), order 6.
    pub const ORDER_6: Self = Self {
        name: "splitting6",
        order: 6,
        coefficients: &KAHAN_LI_6,
        stability_limit: 2.0,
    };
    /// Kahan & Li's 17-stage composition (`"splitting8"`), order 8.
    pub const ORDER_8: Self = Self {
        name: "splitting8",
        order: 8,
        coefficients: &KAHAN_LI_8,
        stability_limit: 2.0,
    };

    /// All of them, lowest order first.
    pub const ALL: [Self; 4] = [Self::STRANG, Self::ORDER_4, Self::ORDER_6, Self::ORDER_8];

    /// The number of free flows per step.
    pub fn stages(&self) -> usize {
        2 * self.coefficients.half.len() + 1
    }

    /// The largest stable `h Ω` (see the type's docs).
    pub fn stability_limit(&self) -> f64 {
        self.stability_limit
    }

    /// The stage coefficients in order: the first half, the middle, the
    /// first half reversed.
    fn gammas(&self) -> impl Iterator<Item = f64> + '_ {
        let c = self.coefficients;
        c.half
            .iter()
            .chain(std::iter::once(&c.middle))
            .chain(c.half.iter().rev())
            .copied()
    }
}

impl HeavyTopIntegrator for HeavyTopSplitting {
    fn name(&self) -> &'static str {
        self.name
    }

    fn order(&self) -> u32 {
        self.order
    }

    fn step(&self, top: &HeavyTop, state: &mut PrincipalState, h: f64) {
        let mut pending = 0.0;
        for g in self.gammas() {
            top.kick(state, (pending + 0.5 * g) * h);
            top.free_flow(state, g * h);
            pending = 0.5 * g;
        }
        top.kick(state, pending * h);
    }
}
