//! Test helpers shared by the integration tests of kreisel-dynamics.
#![allow(dead_code)]

pub mod forced_refs;
