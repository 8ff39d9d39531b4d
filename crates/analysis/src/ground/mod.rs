//! Bodies on the ground: the engine's `kreisel_dynamics::GroundTop`
//! (a sphere, a disk rim or an ellipsoid touching the plane `z = 0`, with
//! its friction law) as reduced equations whose steady motions are
//! equilibria.
//!
//! - [`BodyOnGround`]: any such body in body axes — the up vector `γ`,
//!   the angular velocity `ω` and, unless it rolls, the centre of mass's
//!   velocity `v` — the position on the plane and the heading reduced
//!   away; spinning about the vertical is an equilibrium;
//! - [`TippeTop`]: a sphere whose centre is off the centre of mass on
//!   the axis of symmetry, spinning upright or inverted, with each
//!   friction law, and the published thresholds;
//! - [`Rattleback`]: Kane & Levinson's ellipsoid rolling, spinning
//!   upright either way;
//! - [`RollingDisk`]: a coin rolling on its rim, in axes that turn with
//!   the contact (Resal's), so that rolling straight and rolling in a
//!   circle are equilibria.
//!
//! # The model
//! The same physics as `kreisel_dynamics::contact` (its module docs have
//! the derivation in world axes): Newton and Euler about the centre of
//! mass, the contact force at the lowest point of the surface, rolling
//! as the constraint `v_P = 0` (its reaction solved), the friction laws
//! `F = N f(v_P)` with `N` solved from the contact staying on the plane.
//! In body axes (`γ = Aᵀẑ`, `r` from the contact to the centre of mass):
//!
//! ```text
//! γ̇ = γ × ω
//! rolling:   [I + m(|r|² 𝟙 − r rᵀ)] ω̇ = −ω × Iω − m r × (ω × ṙ + ω × (ω × r) + g γ)
//! sliding:   I ω̇ = −ω × Iω − N r × e,   m (v̇ + ω × v) = N e − m g γ,   e = γ̂ + f(v_P)
//! ```
//!
//! Each is written once for any [`crate::Scalar`], so the Jacobians at the
//! steady motions are exact; the tests check every conserved quantity's
//! rate `∇C · f` to rounding at random states, the equations against the
//! engine's accelerations, and each eigenvalue against a nonlinear run of
//! the engine started along its mode.

mod algebra;
mod body_on_ground;
mod contact_equations;
mod rattleback;
mod rolling_disk;
mod surface;
mod tippe_top;

pub use body_on_ground::BodyOnGround;
pub use rattleback::Rattleback;
pub use rolling_disk::RollingDisk;
pub use tippe_top::{LEINE_GLOCKER, TippeTop, TippeTopParameters};

/// Implements [`crate::VectorField`] for a family that wraps another one
/// in its field `$field`, method by method.
macro_rules! delegate_vector_field {
    ($family:ty, $field:ident) => {
        impl VectorField for $family {
            fn dim(&self) -> usize {
                self.$field.dim()
            }
            fn state_names(&self) -> Vec<String> {
                self.$field.state_names()
            }
            fn rates<D: Scalar>(&self, x: &[D], dx: &mut [D]) {
                self.$field.rates(x, dx)
            }
            fn conserved<D: Scalar>(&self, x: &[D]) -> Vec<(ZeroMode, D)> {
                self.$field.conserved(x)
            }
            fn symmetry_directions(&self, x: &[f64]) -> Vec<(ZeroMode, Vec<f64>)> {
                self.$field.symmetry_directions(x)
            }
            fn reduced_by(&self) -> Vec<String> {
                self.$field.reduced_by()
            }
            fn is_conservative(&self) -> bool {
                self.$field.is_conservative()
            }
            fn space_frequency(
                &self,
                x: &[f64],
                eigenvalue: Eigenvalue,
                shape: &[Eigenvalue],
            ) -> Option<f64> {
                self.$field.space_frequency(x, eigenvalue, shape)
            }
        }
    };
}
pub(crate) use delegate_vector_field;
