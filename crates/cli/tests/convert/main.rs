//! Integration tests of `kreisel convert`, run through the real binary.
//!
//! Run with `cargo test -p kreisel-cli --test convert -- --nocapture` to see
//! the largest errors measured against the reference data.

mod errors;
mod logs;
mod reference;
mod representations;
mod support;
mod syntax;
