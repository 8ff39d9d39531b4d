//! Splitting the heavy top into the free body and the gravity kick, and the
//! symmetric compositions of that Strang splitting to orders 4, 6 and 8.

use super::HeavyTop;
use crate::PrincipalState;
use crate::composition::{CompositionCoefficients, KAHAN_LI_6, KAHAN_LI_8, SUZUKI_4};
use crate::stepping::HeavyTopIntegrator;

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
/// Two limits, both measured (`tests/heavy_top_stability.rs`):
/// - **gravity swings**: for small swings of frequency `Ω_g`
///   ([`HeavyTop::gravity_frequency`]) the kick–free–kick step acts on
///   them as Störmer–Verlet on the harmonic oscillator, and the
///   composition is stable while `h Ω_g` stays below its first instability
///   (`|tr M(hΩ_g)| = 2` of the composed 2×2 map):
///
///   | method | stages | `h Ω_g` limit | per stage |
///   |---|---|---|---|
///   | `strang` | 1 | 2.000 | 2.00 |
///   | `splitting4` | 5 | 2.721 | 0.54 |
///   | `splitting6` | 9 | 2.533 | 0.28 |
///   | `splitting8` | 17 | 3.096 | 0.18 |
///
///   Per step the high orders are as stable as Strang or more; per unit
///   of work (free flows) they are 4–11 times less stable. Beyond the
///   first instability some regain stability in windows (`splitting6`:
///   2.92–3.33, `splitting8`: 3.14–5.63; the linear scan in the test) that
///   nothing should rely on.
/// - **the free flow** of an asymmetric top (PDMV10) breaks down when a
///   stage's `|γ| h |ω|` passes ≈ 1.6; the largest stage is `h`, `0.658 h`,
///   `0.799 h` and `0.606 h` ([`HeavyTopSplitting::largest_stage`]). With
///   two equal moments the free flow is exact and has no limit.
///
/// [`crate::HeavyTopAuto`] sub-steps to stay inside both.
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
    description: &'static str,
}

impl HeavyTopSplitting {
    /// Strang (`"strang"`), order 2: one free flow, two half kicks.
    pub const STRANG: Self = Self {
        name: "strang",
        order: 2,
        coefficients: &STRANG,
        stability_limit: 2.0,
        description: "half gravity kick, exact free-body flow, half kick \
                      (PDMV10 for 3 distinct moments)",
    };
    /// Suzuki's 5-stage composition (`"splitting4"`), order 4.
    pub const ORDER_4: Self = Self {
        name: "splitting4",
        order: 4,
        coefficients: &SUZUKI_4,
        stability_limit: 2.721,
        description: "Suzuki's 5-stage symmetric composition of strang",
    };
    /// Kahan & Li's 9-stage composition (`"splitting6"`), order 6.
    pub const ORDER_6: Self = Self {
        name: "splitting6",
        order: 6,
        coefficients: &KAHAN_LI_6,
        stability_limit: 2.533,
        description: "Kahan and Li's 9-stage symmetric composition of strang",
    };
    /// Kahan & Li's 17-stage composition (`"splitting8"`), order 8.
    pub const ORDER_8: Self = Self {
        name: "splitting8",
        order: 8,
        coefficients: &KAHAN_LI_8,
        stability_limit: 3.096,
        description: "Kahan and Li's 17-stage symmetric composition of strang",
    };

    /// All of them, lowest order first.
    pub const ALL: [Self; 4] = [Self::STRANG, Self::ORDER_4, Self::ORDER_6, Self::ORDER_8];

    /// The number of free flows per step.
    pub fn stages(&self) -> usize {
        self.coefficients.stages()
    }

    /// The largest stable `h Ω_g` for small gravity swings (see the type's
    /// docs), to 4 digits.
    ///
    /// ```text
    /// stable  ⇔  |tr Π S(γᵢ h Ω_g)| < 2,   S(y) = [[1 − y²/2, y], [−y(1 − y²/4), 1 − y²/2]]
    /// ```
    pub fn stability_limit(&self) -> f64 {
        self.stability_limit
    }

    /// The largest `|γᵢ|`: a stage's free flow spans at most this times `h`.
    pub fn largest_stage(&self) -> f64 {
        self.coefficients.gammas().fold(0.0, |m, g| m.max(g.abs()))
    }
}

impl HeavyTopIntegrator for HeavyTopSplitting {
    fn name(&self) -> &'static str {
        self.name
    }

    fn order(&self) -> u32 {
        self.order
    }

    fn description(&self) -> &'static str {
        self.description
    }

    fn step(&self, top: &HeavyTop, state: &mut PrincipalState, h: f64) {
        let mut pending = 0.0;
        for g in self.coefficients.gammas() {
            top.kick(state, (pending + 0.5 * g) * h);
            top.free_flow(state, g * h);
            pending = 0.5 * g;
        }
        top.kick(state, pending * h);
    }
}
