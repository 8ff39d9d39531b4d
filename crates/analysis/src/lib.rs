//! # kreisel-analysis
//!
//! Is this motion stable? The lecture notes' method (§2, §3.7, §3.11), for
//! the bodies kreisel simulates: find a steady motion (a relative
//! equilibrium), linearise the equations there with exact derivatives,
//! account for every zero eigenvalue (a Casimir, an energy level, a
//! momentum, a symmetry direction — each named), and read the verdict,
//! the frequencies and the growth rates off what remains.
//!
//! ```text
//! family (reduced equations, generic over dual numbers)
//!   ──find_steady_motion──▶ x*   (Newton, minimum-norm steps)
//!   ──Linearisation──▶ A = ∂f/∂x (exact) ─reduce─▶ B ─eigen─▶ modes, verdict
//!   ──StabilityMap──▶ max Re λ on a grid, boundaries by bisection to rounding
//! ```
//!
//! Each family writes its equations once ([`VectorField::rates`]) for any
//! [`Scalar`]: `f64` for values, [`num_dual`]'s dual numbers for the
//! Jacobian. Conventions are the workspace's: SI units, radians, body
//! axes named in identifiers.
//!
//! ```
//! use glam::DVec3;
//! use kreisel_analysis::{FreeBodyRotation, Linearisation, Verdict};
//! // The T-handle (Dzhanibekov): spin about the intermediate axis grows.
//! let family = FreeBodyRotation::try_new(DVec3::new(1.0, 2.0, 3.0))?;
//! let lin = Linearisation::try_new(&family, &family.about_axis(1, 2.0)?)?;
//! assert_eq!(lin.verdict.name(), "unstable");
//! # Ok::<(), kreisel_analysis::AnalysisError>(())
//! ```
#![deny(missing_docs)]
#![forbid(unsafe_code)]

mod eigen;
mod error;
mod free_body;
mod ground;
mod heavy_top_pivot;
mod hessenberg_qr;
mod linearisation;
mod mode;
mod parameter;
mod precessing_top;
mod stability_map;
mod steady_kind;
mod steady_problem;
mod steady_search;
mod vector_field;
mod verdict;
mod zero_mode;

pub use error::AnalysisError;
pub use free_body::FreeBodyRotation;
pub use ground::{
    BodyOnGround, LEINE_GLOCKER, Rattleback, RollingDisk, TippeTop, TippeTopParameters,
};
pub use heavy_top_pivot::HeavyTopPivot;
pub use linearisation::{GROWTH_TOLERANCE, Linearisation, STEADY_RESIDUAL};
pub use mode::{Eigenvalue, Frame, Mode};
pub use parameter::Parameter;
pub use precessing_top::{PrecessingTop, Precession};
pub use stability_map::{
    BoundaryEdge, BoundaryPoint, GridPoint, StabilityMap, Sweep, bisect_boundary, boundary_edges,
    grid_point,
};
pub use steady_kind::SteadyKind;
pub use steady_problem::{PivotBody, SteadyProblem};
pub use steady_search::{NEARBY, SteadyMotion, find_steady_motion};
pub use vector_field::{Scalar, VectorField};
pub use verdict::Verdict;
pub use zero_mode::{ZeroMode, ZeroModeKind};
