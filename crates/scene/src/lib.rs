//! kreisel's application layer: what turns a user's request into a run or
//! a report, shared by the `kreisel` CLI, the Python package, the fuzz
//! targets and the demos (none of them holds physics of its own).
//!
//! - **Scenes**: a TOML scene file read and checked ([`scene_file`],
//!   every error naming the file, line and key) into a
//!   [`kreisel_dynamics::World`]; the run along the output grid
//!   ([`schedule`], [`run`]); the columns of a row ([`columns`]) and the
//!   table's events ([`events`]).
//! - **Mass properties of a mesh file**: [`inertia_request`] (units, model,
//!   material → the bodies' and the assembly's mass properties, with
//!   warnings worded in metres and advice for bodies that are not solids).
//! - **The heavy top**: [`top_summary`] (parameters → the library's answers).
//! - **Rotations as lines of numbers**: [`representation`] names,
//!   [`rotation_lines`] conversions, [`numbers`] parsing and shortest
//!   round-trip formatting.
//!
//! Errors are [`error::SceneError`] (and [`line_problem::LineProblem`] for
//! a line of numbers), one line each, naming what to fix.

#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub mod body_key;
pub mod body_keys;
pub mod body_request;
pub mod columns;
pub mod contact_key;
pub mod contact_keys;
pub mod contact_list;
pub mod contact_request;
mod contact_shape;
pub mod error;
pub mod escape;
pub mod events;
pub mod inertia_request;
pub mod line_problem;
pub mod mesh_options;
pub mod methods;
pub mod numbers;
pub mod representation;
pub mod rotation_lines;
pub mod run;
pub mod scene_file;
pub mod scene_keys;
pub mod schedule;
pub mod stop;
pub mod table_start;
pub mod top_summary;

pub use error::SceneError;
