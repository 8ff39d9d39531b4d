//! The fuzz targets' checks, in process, on proptest-mutated seeds.

use std::path::Path;

use kreisel_inertia::io::MeshFormat;
use proptest::prelude::*;

use crate::mutate::{corpus_dir, mutated};
use crate::targets;

/// Cases per parser: enough to reach every loader's error paths, cheap in debug.
const CASES: u32 = 96;

proptest! {
    #![proptest_config(crate::mutate::ci_config(CASES))]

    #[test]
    fn stl_loads_or_fails_cleanly(bytes in mutated("stl")) {
        targets::mesh_file(&bytes, MeshFormat::Stl);
    }

    #[test]
    fn obj_loads_or_fails_cleanly(bytes in mutated("obj")) {
        targets::mesh_file(&bytes, MeshFormat::Obj);
    }

    #[test]
    fn ply_loads_or_fails_cleanly(bytes in mutated("ply")) {
        targets::mesh_file(&bytes, MeshFormat::Ply);
    }

    #[test]
    fn gltf_loads_or_fails_cleanly(bytes in mutated("gltf")) {
        targets::mesh_file(&bytes, MeshFormat::Gltf);
    }

    #[test]
    fn glb_loads_or_fails_cleanly(bytes in mutated("glb")) {
        targets::mesh_file(&bytes, MeshFormat::Glb);
    }

    #[test]
    fn scenes_parse_or_fail_cleanly(bytes in mutated("scene_toml")) {
        targets::scene_toml(&bytes, &corpus_dir("obj").join("fuzz.toml"));
    }

    #[test]
    fn convert_lines_convert_or_fail_cleanly(bytes in mutated("convert_lines")) {
        targets::convert_lines(&bytes);
    }
}

#[test]
fn every_seed_is_valid_input() {
    // The unmutated seeds reach past the parsers (a corpus of files that all
    // fail early would fuzz only the first checks).
    for (target, format) in [
        ("stl", MeshFormat::Stl),
        ("obj", MeshFormat::Obj),
        ("ply", MeshFormat::Ply),
        ("glb", MeshFormat::Glb),
    ] {
        for seed in crate::mutate::seeds(target) {
            let bodies = kreisel_inertia::io::load_bodies_from_bytes(&seed, format, "seed", None);
            assert!(bodies.is_ok(), "{target}: {bodies:?}");
        }
    }
    let dir = corpus_dir("scene_toml");
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        // Scenes naming a mesh are parsed as if beside the OBJ seeds.
        let at = corpus_dir("obj").join("fuzz.toml");
        let parsed = kreisel_scene::scene_file::parse(Path::new(&at), &text);
        assert!(
            parsed.is_ok(),
            "{}: {:?}",
            path.display(),
            parsed.err().map(|e| e.to_string())
        );
    }
}
