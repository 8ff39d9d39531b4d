//! # kreisel-kinematics
//!
//! Exact, robust rotation kinematics for [kreisel](https://github.com/kreisel-rs/kreisel):
//! unit quaternions, rotation matrices, axis–angle pairs, rotation vectors,
//! Euler angles in all 24 conventions, and Euler-angle rates ⇄ angular
//! velocity.
//!
//! ## Conventions
//! - SI units, radians; `f64` throughout, with glam's [`DQuat`](glam::DQuat),
//!   [`DMat3`](glam::DMat3) and [`DVec3`](glam::DVec3) in every signature.
//! - A rotation `world_from_body` maps body coordinates to world coordinates:
//!   `v_world = q ⊗ v_body ⊗ q⁻¹ = M v_body`. In text, quaternions are written
//!   scalar first: `w, x, y, z`. `q` and `−q` are the same rotation.
//! - Euler conventions are named as in scipy: uppercase `ZXZ` is intrinsic
//!   (rotations about the moving body axes), lowercase `zxz` extrinsic (about
//!   the fixed world axes). The lecture notes' (φ, θ, ψ) are intrinsic `ZXZ`.
//!   Ranges: first and third angle in `(−π, π]`, middle in `[0, π]` (proper
//!   Euler) or `[−π/2, π/2]` (Tait–Bryan).
//! - Frames are named in identifiers: `omega_body`, `omega_world`.
//!
//! ## Accuracy
//! [`EulerSequence::from_quat`] uses the direct method of Bernardes & Viollet
//! (2022) in atan2 form: the rotation recomposed from its angles matches the
//! input to ~1e-16 rad, also within 1e-12 rad of gimbal lock and exactly at
//! it. Exponential and logarithm maps keep full relative precision for angles
//! from 1e-300 rad to π.
//!
//! ```
//! use glam::DVec3;
//! use kreisel_kinematics::{EulerSequence, rotation_angle_between};
//! let zxz: EulerSequence = "ZXZ".parse()?;
//! let q = zxz.to_quat(DVec3::new(0.1, 0.2, 0.3));
//! let back = zxz.from_quat(q);
//! assert!((back.angles - DVec3::new(0.1, 0.2, 0.3)).length() < 1e-15);
//! assert!(rotation_angle_between(q, zxz.to_quat(back.angles)) < 1e-15);
//! # Ok::<(), kreisel_kinematics::KinematicsError>(())
//! ```
#![deny(missing_docs)]
#![forbid(unsafe_code)]

mod atan2;
mod axis_angle;
mod error;
mod euler_angles;
mod euler_f32;
mod euler_from_quat;
mod euler_rates;
mod euler_sequence;
#[cfg(feature = "glam033")]
pub mod glam033_interop;
mod lanes;
#[cfg(feature = "nalgebra")]
pub mod nalgebra_interop;
mod quaternion;
mod quaternion_kinematics;
mod rotation_matrix;
mod rotation_vector;

pub use axis_angle::AxisAngle;
pub use error::KinematicsError;
pub use euler_angles::EulerDecomposition;
pub use euler_f32::EulerDecompositionF32;
pub use euler_rates::RATE_SINGULARITY_TOLERANCE;
pub use euler_sequence::{Axis, EulerSequence, Frame};
pub use quaternion::{canonical_quat, rotation_angle_between, try_normalize_quat};
pub use quaternion_kinematics::{
    omega_body_from_attitudes, omega_world_from_attitudes, quat_derivative, quat_derivative_world,
    rotate_by_omega_body, slerp,
};
pub use rotation_matrix::{
    ORTHONORMALITY_TOLERANCE, orthonormality_error, quat_from_rotation_matrix,
    rotation_matrix_from_quat, try_quat_from_rotation_matrix,
};
pub use rotation_vector::{quat_from_rotation_vector, rotation_vector_from_quat};

pub use glam;
