//! `cargo fuzz run scene_toml`: bytes as a `kreisel simulate` scene file
//! through the CLI's scene parser: an error or a scene, never a panic. The
//! scene is parsed as if it were in `corpus/obj/`, so `mesh = "cube.obj"`
//! names a seed mesh.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/corpus/obj/fuzz.toml"));
    kreisel_fuzz::scene_toml(bytes, path);
});
