//! A free rigid body under applied torques and forces: the inputs, the
//! state (rotation about the centre of mass and the motion of the centre of
//! mass), the structure-preserving splittings that advance it and the
//! propagator that steps it with checks.
//!
//! ```text
//! L̇_world = τ(t, s),   q̇ = ½ q ⊗ (0, I⁻¹L),   ẋ = v,   m v̇ = F(t, s) + m g
//! ```
//! The torque-free part is the exact (or PDMV10) free flow of the heavy
//! top's splitting; the loads are exact kicks with the attitude frozen
//! ([`ForcedSplitting`]).

mod body;
mod flows;
mod inputs;
mod propagator;
mod splitting;
mod state;

pub use self::body::ForcedBody;
pub use self::inputs::{Inputs, Load, LoadFn, PointForce};
pub use self::propagator::ForcedPropagator;
pub(crate) use self::propagator::checked_step;
pub use self::splitting::ForcedSplitting;
pub use self::state::ForcedState;
