//! Integration tests of `kreisel simulate`, run through the real binary:
//! the CSV's shape, the physics against closed forms and reference periods,
//! mesh bodies and gravity, and one-line errors for bad scenes.
//!
//! Run with `cargo test -p kreisel-cli --test simulate -- --nocapture` to see
//! the measured errors and flip intervals.

mod divergence;
mod errors;
mod ground;
mod ground_guard;
mod ground_inputs;
mod ground_touchdown;
mod heavy_top;
mod inputs;
mod outcomes;
mod output;
mod physics;
mod plot;
mod rattleback;
mod support;
mod table;
mod table_painleve;
mod table_rolling;
mod table_superball;
mod threads;
mod tolerance;
