//! # kreisel
//!
//! A rigid-body rotation engine for tops and Euler angles. This facade
//! re-exports the kreisel crates:
//!
//! - [`kinematics`]: quaternions, rotation matrices, axis–angle, rotation
//!   vectors, all 24 Euler conventions, Euler rates ⇄ angular velocity.
//! - [`inertia`]: mass, centre of mass, inertia tensor and principal axes of
//!   primitives, point masses, compounds and closed triangle meshes.
//! - [`dynamics`]: free bodies, heavy tops and tops on a table, solved
//!   exactly or integrated, and the [`dynamics::World`] a game steps.
//! - `scene` (feature `scene`): scene files to a World and its
//!   run along the output grid, mesh and heavy-top requests, rotations as
//!   lines of numbers — what the CLI and the Python package are made of.
//! - `analysis` (feature `analysis`): steady motions, their linear
//!   stability with exact derivatives, and stability maps.
//!
//! ```
//! use kreisel::kinematics::{EulerSequence, glam::DVec3};
//! let zxz: EulerSequence = "ZXZ".parse()?;
//! let q = zxz.to_quat(DVec3::new(0.1, 0.2, 0.3));
//! assert!((zxz.from_quat(q).angles - DVec3::new(0.1, 0.2, 0.3)).length() < 1e-15);
//! # Ok::<(), kreisel::kinematics::KinematicsError>(())
//! ```
#![deny(missing_docs)]
#![forbid(unsafe_code)]

#[cfg(feature = "analysis")]
pub use kreisel_analysis as analysis;
pub use kreisel_dynamics as dynamics;
pub use kreisel_inertia as inertia;
pub use kreisel_kinematics as kinematics;
#[cfg(feature = "scene")]
pub use kreisel_scene as scene;

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
