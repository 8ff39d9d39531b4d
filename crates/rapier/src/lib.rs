//! # kreisel-rapier
//!
//! Exact free rotation for [rapier3d](https://rapier.rs) bodies (`f32`, as
//! games use it). rapier keeps contacts, joints, forces and torques;
//! kreisel carries the torque-free part of each managed body's rotation
//! with the exact flow of Euler's equations, in `f64`
//! ([`kreisel_dynamics::World`]).
//!
//! ## Why
//! rapier 0.36 (`f32`) moves rapier's own Dzhanibekov scenario (I = (1, 2,
//! 3), ω₀ = (0.01, 1, 0), `examples/rapier_tumble`) with the period of ω
//! 4.2e-2 too long at dt = 1/60 and 15.7e-2 too short at 1/240. Its energy
//! grows by 4.8e-3 per 100 s at 1/60 and by 1.7e-2 at 1/240: the `f32`
//! rounding of its per-substep gyroscopic update adds up. With
//! [`ExactRotation`] the period is within 4e-9 of the 60-digit value at
//! every dt from 1/30 to 1/240, and |L| and the energy read from rapier's
//! `f32` state stay within 2e-7 of the start (`tests/rapier_adapter.rs`).
//!
//! ## The splitting
//! Each rapier step of `dt` is split into rapier's step with the managed
//! body's gyroscopic term off, then, for a body that is free after it
//! (no active contact in rapier's narrow phase, no joint, awake):
//!
//! ```text
//! J = R I Rᵀ (ω_after − ω_before)               the velocity change of rapier's step, as momentum
//! K½:  L ← L + J/2,   Φ:  (R, L) ← exact torque-free flow over dt,   K½:  L ← L + J/2
//! ```
//!
//! and `R`, `ω = R I⁻¹ Rᵀ L` written back (the attitude turned about the
//! centre of mass rapier moved the body to; the second half-kick is kept
//! and applied to the `f64` flow with the next step's first). Without
//! torques `J` is zero bit for bit and the rotation is exact to `f64`
//! rounding; with torques or damping `K½ Φ K½` is Strang's splitting,
//! second order in `dt` (measured 2.00 and 2.02 for a torque across the
//! spin, where rapier alone is first order), and exact for a torque along
//! the spin of a sphere (`crates/rapier/tests/torque_damping.rs`).
//!
//! ## Contacts and joints
//! A body that touches something (or sleeps) after a step is carried by
//! rapier alone, its gyroscopic term on again, and nothing is written; when
//! it is free again its `f64` state is re-synchronised from rapier's. We
//! tried carrying the rotation through contacts with `K` and `Φ`: rapier's
//! solver applies impulses over four substeps and corrects penetration
//! through the positions, so its velocity change is not a momentum change
//! at one attitude. Kicking at the initial attitude raised the energy at a
//! T-handle's impact by 4e-3 of the total; taking rapier's attitude with
//! the kicked momentum, by 1.2e-2; and writing our attitude over rapier's
//! contact corrections kept resting bodies from sleeping. Handing contact
//! steps to rapier, the adapter's own change of the energy is zero there
//! and within `f32` rounding (≤ 1.5e-7 of the total) elsewhere.
//!
//! ```
//! use kreisel_rapier::{Carrier, ExactRotation};
//! use rapier3d::prelude::*;
//! let mut world = PhysicsWorld::new(); // gravity −9.81 along y
//! world.insert_collider(ColliderBuilder::cuboid(10.0, 0.5, 10.0).translation(Vector::new(0.0, -0.5, 0.0)), None);
//! let (handle, _) = world.insert(
//!     RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 2.0, 0.0)).angvel(Vector::new(0.1, 5.0, 0.0)),
//!     ColliderBuilder::cuboid(0.4, 0.1, 0.05),
//! );
//! let mut exact = ExactRotation::new();
//! exact.manage(&mut world.bodies, &world.colliders, handle)?;
//! exact.step_world(&mut world)?;
//! assert_eq!(exact.carrier(handle), Some(Carrier::Kreisel)); // in flight
//! for _ in 0..120 {
//!     exact.step_world(&mut world)?;
//! }
//! assert_eq!(exact.carrier(handle), Some(Carrier::Rapier)); // on the ground
//! # Ok::<(), kreisel_rapier::RapierAdapterError>(())
//! ```
#![deny(missing_docs)]
#![forbid(unsafe_code)]

mod error;
mod exact_rotation;
mod stepping;

pub use error::RapierAdapterError;
pub use exact_rotation::{Carrier, ExactRotation, ManagedRotation};
pub use stepping::Touching;
