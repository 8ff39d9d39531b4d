//! # kreisel-inertia
//!
//! Mass properties of rigid bodies: mass, centre of mass, inertia tensor
//! about the centre of mass, principal moments and axes; for primitives in
//! closed form, point masses, compounds of parts, and closed triangle meshes
//! by exact polyhedral integration.
//!
//! ## Conventions
//! - SI units; tensors are about the centre of mass unless a name says
//!   otherwise (`inertia_about_point`), with elements
//!   `I_ab = Σ m (r² δ_ab − r_a r_b)` (so products of inertia carry their
//!   minus sign inside the tensor).
//! - Principal frames are right-handed; `principal_orientation` maps
//!   principal-frame coordinates to body (mesh) coordinates.
//! - Mesh integrals give the same bits on every machine and thread count:
//!   the integration kernel's portable, AVX2/FMA and AVX-512 builds (picked
//!   at run time, [`SolidKernel`]) perform the same operations in the same
//!   order. The environment variable `KREISEL_KERNEL=portable|avx2|avx512`
//!   forces a build for tests and benchmarks; a build the CPU lacks is never
//!   run (the fastest one it has runs instead, and
//!   [`SolidKernel::from_env`] says why).
#![deny(missing_docs)]
// One small module (`solid_kernel`) calls its AVX2/FMA and AVX-512 builds
// after a run-time CPU check; everything else is safe code.
#![deny(unsafe_code)]

mod convex_hull;
mod edge_uses;
mod error;
#[cfg(feature = "formats")]
pub mod io;
mod kernel_build;
mod mass_properties;
mod mass_properties_error;
mod mesh_check;
mod mesh_format;
mod mesh_integration;
mod mesh_mass;
mod mesh_unit;
mod parallel;
#[cfg(feature = "parry")]
mod parry_interop;
mod primitives;
mod principal_axes;
mod quickhull;
mod solid_kernel;
mod tri_mesh;
mod weld;

pub use convex_hull::convex_hull;
pub use error::InertiaError;
pub use kernel_build::{KERNEL_ENV, KernelError, SolidKernel};
pub use mass_properties::MassProperties;
pub use mass_properties_error::MassPropertiesError;
pub use mesh_check::{CheckedMesh, MeshWarning, prepare_shell, prepare_solid};
pub use mesh_integration::MeshMoments;
pub use mesh_mass::{MassModel, Material, MeshMassReport, mesh_mass_properties};
#[cfg(feature = "parry")]
pub use parry_interop::{from_parry, from_parry_mass_properties, parry_mass_properties, to_parry};
pub use principal_axes::PrincipalAxes;
pub use tri_mesh::TriMesh;
pub use weld::{DEFAULT_RELATIVE_WELD, Weld, Welded};
