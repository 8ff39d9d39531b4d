//! Integration tests of `kreisel inertia`, run through the real binary.
//!
//! Run with `cargo test -p kreisel-cli --test inertia -- --nocapture` to see
//! the largest errors measured against the exact reference values.

mod assets;
mod closed_in_practice;
mod errors;
mod frames;
mod meshes;
mod options;
mod reference;
mod support;
mod urdf;
mod urdf_campaign;
mod urdf_errors;
mod urdf_robots;
