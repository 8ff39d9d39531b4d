//! The in-CI fuzz pass over every parser, and the bigger campaign.
//!
//! Seeds are the cargo-fuzz corpus (`fuzz/corpus/<target>/`), mutated by
//! proptest (`mutate.rs`). Two contracts:
//! - in process (`in_process.rs`): the fuzz targets' own checks
//!   (`fuzz/src/lib.rs`, compiled in here) on STL, OBJ, PLY, glTF, GLB,
//!   scene TOML and convert lines: an error, or a result of finite numbers;
//!   never a panic;
//! - through the binary (`through_cli.rs`): no panic, no run past 10 s, never
//!   exit 0 with NaN or inf in the output.
//!
//! CI runs a few dozen cases per parser (a few seconds each in debug). The
//! campaign (`campaign.rs`, ignored) runs N cases per parser through the
//! binary and counts the defects:
//! `KREISEL_FUZZ_CASES=10000 KREISEL_FUZZ_FINDINGS=/tmp/findings cargo test
//! --release -p kreisel-cli --test fuzz -- --ignored --nocapture campaign`.

mod campaign;
mod in_process;
mod mutate;
mod through_cli;

/// The fuzz targets' checks (`fuzz/src/lib.rs`, which calls the CLI's
/// library for the scene and convert parsers).
#[path = "../../../../fuzz/src/lib.rs"]
mod targets;
