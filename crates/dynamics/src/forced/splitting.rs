//! The drift–kick splitting of a body under applied loads and its symmetric
//! compositions to orders 4, 6 and 8.

use std::str::FromStr;

use super::{ForcedBody, ForcedState};
use crate::DynamicsError;
use crate::composition::{CompositionCoefficients, KAHAN_LI_6, KAHAN_LI_8, SUZUKI_4};

/// Strang's splitting itself: one stage.
const STRANG: CompositionCoefficients = CompositionCoefficients {
    half: &[],
    middle: 1.0,
};

/// Kick–drift–kick splitting of a body under applied loads (Strang 1968)
/// and its symmetric compositions (Suzuki 1990; Kahan & Li 1997), the
/// heavy top's scheme ([`crate::HeavyTopSplitting`]) with time as a
/// coordinate.
///
/// ```text
/// y = (q, L, x, v, t),   ẏ = A(y) + B(y)
/// A (drift): free rotation of (q, L), ẋ = v, ṫ = 1                    exact*
/// B (kick):  q, x, t frozen:  L̇ = τ(t, q, x) − c I⁻¹ L,  m v̇ = F(t, q, x) + m g  exact
/// S_h = B(h/2) ∘ A(h) ∘ B(h/2),   Ψ_h = S(γ₁h) ∘ … ∘ S(γ_mid h) ∘ … ∘ S(γ₁h)
/// ```
/// (*) The free rotation is exact for two or three equal moments and
/// PDMV10 (local error `O(h¹¹)`) otherwise, like the heavy top's.
///
/// The kick `B` is the exact flow for every load that depends on time,
/// attitude and position only: torques in world or body axes, forces at
/// body points, a [`crate::Inputs::with_load`] law, and the linear
/// damping (`Lᵢ ← Lᵢ e^{−kᵢh} + h τᵢ φ(−kᵢh)`, see `flows.rs`). Then the
/// compositions have their full order for any such load, adjacent half
/// kicks are merged (`s` drifts and `s + 1` kicks per step), and:
/// - **constant force and gravity**: the centre of mass is exact
///   (`x ← x + v h + a h²/2` step after step, up to rounding);
/// - **position-dependent forces** (a spring on the centre of mass): the
///   translation is Störmer–Verlet, composed to the method's order.
///
/// A law that reads `L` or `v` ([`crate::Inputs::with_velocity_load`]) has
/// no exact kick; its kick is `E(h/2) ∘ M(h) ∘ E(h/2)` with `E` the exact
/// kick of the rest and `M` the implicit midpoint rule (symmetric, order 2),
/// so each `S_h` stays symmetric and of order 2 and the compositions keep
/// orders 4, 6, 8 (Hairer, Lubich & Wanner, *Geometric Numerical
/// Integration*, II.4); half kicks are then not merged (`2s` kicks).
///
/// With no inputs every kick leaves `L` untouched: the rotation is
/// bit for bit the free flow the heavy-top splitting takes with no
/// gravity (`tests/forced_reference.rs`).
///
/// Every stage keeps `|q|` (rotations only); with a world-constant torque
/// `L_world(t) = L₀ + τ t` at every step, for any body and any `h`, to
/// rounding (each drift keeps `L_world`, the kick durations add up to `h`).
///
/// ```
/// use glam::{DQuat, DVec3};
/// use kreisel_dynamics::{ForcedBody, ForcedSplitting, ForcedState, Inputs, RigidBody};
/// // A sphere spun up about its own axis: ω = ω₀ + τ t / I.
/// let body = RigidBody::try_from_principal_moments(DVec3::splat(0.5))?;
/// let forced = ForcedBody::try_new(body, 1.0, DVec3::ZERO, Inputs::default().with_torque_world(DVec3::Z))?;
/// let mut s = ForcedState::try_new(&body, DQuat::IDENTITY, DVec3::Z, DVec3::ZERO, DVec3::ZERO)?;
/// for k in 0..100 {
///     ForcedSplitting::DEFAULT.step(&forced, &mut s, k as f64 * 0.01, 0.01);
/// }
/// // θ = ω₀ t + τ t²/2I = 1 + 1 = 2 rad about z (the drifts take the
/// // midpoint rule of a linear rate: exact; rounding of 1 800 stages).
/// let angle = kreisel_kinematics::rotation_angle_between(s.rotation.world_from_principal, DQuat::from_rotation_z(2.0));
/// assert!(angle < 1e-13);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForcedSplitting {
    name: &'static str,
    order: u32,
    coefficients: &'static CompositionCoefficients,
}

// The coefficients are constants, never NaN: equality is an equivalence.
impl Eq for ForcedSplitting {}

impl ForcedSplitting {
    /// Strang (`"strang"`), order 2: one drift, two half kicks.
    pub const STRANG: Self = Self {
        name: "strang",
        order: 2,
        coefficients: &STRANG,
    };
    /// Suzuki's 5-stage composition (`"splitting4"`), order 4.
    pub const ORDER_4: Self = Self {
        name: "splitting4",
        order: 4,
        coefficients: &SUZUKI_4,
    };
    /// Kahan & Li's 9-stage composition (`"splitting6"`), order 6.
    pub const ORDER_6: Self = Self {
        name: "splitting6",
        order: 6,
        coefficients: &KAHAN_LI_6,
    };
    /// Kahan & Li's 17-stage composition (`"splitting8"`), order 8.
    pub const ORDER_8: Self = Self {
        name: "splitting8",
        order: 8,
        coefficients: &KAHAN_LI_8,
    };

    /// All of them, lowest order first.
    pub const ALL: [Self; 4] = [Self::STRANG, Self::ORDER_4, Self::ORDER_6, Self::ORDER_8];

    /// The default: order 6 (Kahan & Li, 9 drifts per step). Measured
    /// against the 32-digit references of `tests/forced_reference.rs` at
    /// `dt = 0.01` over 10 s it is as accurate as order 8 or more (≤ 6e-12
    /// rad on every reference, against ≤ 1.2e-11 for order 8: at that step
    /// both are at rounding, and order 8's 17 kicks per step add more of it
    /// to `L`) for half the work. At coarse steps (`h |ω| ≳ 0.5`) order 8
    /// is the more accurate: see [`ForcedSplitting::ORDER_8`].
    pub const DEFAULT: Self = Self::ORDER_6;

    /// The method's name (`"strang"`, `"splitting4"`, …).
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// The order of the method (global error `O(hᵖ)`).
    pub fn order(&self) -> u32 {
        self.order
    }

    /// The number of drifts (free flows) per step.
    pub fn stages(&self) -> usize {
        self.coefficients.stages()
    }

    /// Advances `state` from time `t` by `h` seconds.
    ///
    /// Infallible (the inner loop of every run): a step the method cannot
    /// take, or a law returning non-finite loads, leaves a non-finite
    /// state, which [`crate::ForcedPropagator::try_advance`] reports.
    ///
    /// ```text
    /// exact kicks:     B(γ₁h/2) A(γ₁h) B((γ₁+γ₂)h/2) A(γ₂h) … A(γ₁h) B(γ₁h/2)
    /// velocity law:    B̃(γ₁h/2) A(γ₁h) B̃(γ₁h/2) B̃(γ₂h/2) A(γ₂h) …
    /// kick at time t + h Σ_{j<i} γⱼ
    /// ```
    pub fn step(&self, body: &ForcedBody, state: &mut ForcedState, t: f64, h: f64) {
        let merged = !body
            .inputs()
            .load
            .as_ref()
            .is_some_and(|l| l.reads_velocity());
        let mut elapsed = 0.0;
        if merged {
            let mut pending = 0.0;
            for g in self.coefficients.gammas() {
                body.kick(state, t + elapsed * h, (pending + 0.5 * g) * h);
                body.drift(state, g * h);
                elapsed += g;
                pending = 0.5 * g;
            }
            body.kick(state, t + elapsed * h, pending * h);
        } else {
            for g in self.coefficients.gammas() {
                body.kick(state, t + elapsed * h, 0.5 * g * h);
                body.drift(state, g * h);
                elapsed += g;
                body.kick(state, t + elapsed * h, 0.5 * g * h);
            }
        }
        // On a pivot: the centre of mass where the attitude puts it.
        body.follow_pivot(state);
    }
}

impl FromStr for ForcedSplitting {
    type Err = DynamicsError;

    /// The method named `name` (see [`ForcedSplitting::ALL`]).
    ///
    /// ```
    /// use kreisel_dynamics::ForcedSplitting;
    /// assert_eq!("splitting6".parse::<ForcedSplitting>()?.order(), 6);
    /// assert!("rk4".parse::<ForcedSplitting>().is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    fn from_str(name: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|m| m.name == name)
            .ok_or_else(|| DynamicsError::UnknownMethod {
                name: name.to_owned(),
                known: Self::ALL.map(|m| m.name).join(", "),
            })
    }
}
