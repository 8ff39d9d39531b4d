//! `cargo fuzz run gltf`: bytes as a glTF file through kreisel-inertia's loader
//! and every mass model: an error or finite numbers, never a panic.
#![no_main]

use kreisel_fuzz::mesh_file;
use kreisel_inertia::io::MeshFormat;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| mesh_file(bytes, MeshFormat::Gltf));
