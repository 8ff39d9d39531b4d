//! Mesh file loaders: a unit cube in every format, multi-body files, glTF
//! transforms, typed errors on broken files, and no panic on truncated or
//! corrupted input. The fixtures are written by `fixtures/make_fixtures.py`.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use glam::DVec3;
use kreisel_inertia::io::{Body, MeshFormat, load_bodies, load_bodies_from_bytes};
use kreisel_inertia::{InertiaError, TriMesh};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(name)
}

fn read(name: &str) -> Vec<u8> {
    std::fs::read(fixture(name)).unwrap()
}

fn read_text(name: &str) -> String {
    std::fs::read_to_string(fixture(name)).unwrap()
}

/// A fresh directory under the system temp dir, removed on drop.
struct TempDir(PathBuf);

impl TempDir {
    fn new() -> Self {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("kreisel-io-{}-{n}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Self(dir)
    }

    fn write(&self, name: &str, bytes: &[u8]) -> PathBuf {
        let path = self.0.join(name);
        std::fs::write(&path, bytes).unwrap();
        path
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Σ a·(b×c)/6 over the triangles.
fn signed_volume(mesh: &TriMesh) -> f64 {
    let v = mesh.vertices();
    mesh.triangles()
        .iter()
        .map(|t| v[t[0] as usize].dot(v[t[1] as usize].cross(v[t[2] as usize])) / 6.0)
        .sum()
}

fn assert_cube(body: &Body, name: &str, volume: f64) {
    assert_eq!(body.name, name);
    assert_eq!(
        body.mesh.vertices().len(),
        8,
        "{name}: vertices after merge"
    );
    assert_eq!(body.mesh.triangles().len(), 12, "{name}: triangles");
    let got = signed_volume(&body.mesh);
    assert!(
        (got - volume).abs() <= 1e-15 * volume,
        "{name}: volume {got}"
    );
}

fn assert_unit_cube(file: &str, name: &str) {
    let bodies = load_bodies(&fixture(file)).unwrap();
    assert_eq!(bodies.len(), 1, "{file}: one body");
    assert_cube(&bodies[0], name, 1.0);
}

fn bounds(body: &Body) -> ([f64; 3], [f64; 3]) {
    let v = body.mesh.vertices();
    let lo = v.iter().fold(DVec3::MAX, |a, &b| a.min(b));
    let hi = v.iter().fold(DVec3::MIN, |a, &b| a.max(b));
    (lo.to_array(), hi.to_array())
}

#[test]
fn stl_binary_even_with_a_header_starting_with_solid_and_ascii() {
    assert!(read("cube_binary.stl").starts_with(b"solid"));
    assert_unit_cube("cube_binary.stl", "cube_binary");
    assert_unit_cube("cube_ascii.stl", "unit_cube");
}

#[test]
fn obj_quads_are_triangulated_and_a_missing_mtl_is_ignored() {
    assert_unit_cube("cube.obj", "cube");
}

#[test]
fn obj_with_two_objects_gives_two_bodies() {
    let bodies = load_bodies(&fixture("two_cubes.obj")).unwrap();
    assert_eq!(bodies.len(), 2);
    assert_cube(&bodies[0], "left", 1.0);
    assert_cube(&bodies[1], "right", 1.0);
    assert_eq!(bounds(&bodies[1]), ([2.0, 0.0, 0.0], [3.0, 1.0, 1.0]));
}

#[test]
fn ply_ascii_and_binary_in_both_byte_orders() {
    assert_unit_cube("cube_ascii.ply", "cube_ascii");
    assert_unit_cube("cube_binary_le.ply", "cube_binary_le");
    assert_unit_cube("cube_binary_be.ply", "cube_binary_be");
}

#[test]
fn gltf_embedded_external_and_glb() {
    assert_unit_cube("cube.gltf", "cube_node");
    assert_unit_cube("cube_external.gltf", "cube_mesh");
    assert_unit_cube("cube.glb", "cube_mesh");
    // Without a directory an external buffer cannot be found.
    let json = read("cube_external.gltf");
    let err = load_bodies_from_bytes(&json, MeshFormat::Gltf, "x.gltf", None).unwrap_err();
    assert!(err.to_string().contains("x.gltf"), "{err}");
}

#[test]
fn gltf_node_transforms_compose_and_mirrors_keep_winding() {
    let bodies = load_bodies(&fixture("transforms.gltf")).unwrap();
    assert_eq!(bodies.len(), 2);
    assert_cube(&bodies[0], "big", 8.0);
    assert_eq!(bounds(&bodies[0]), ([1.0, 2.0, 3.0], [3.0, 4.0, 5.0]));
    assert_cube(&bodies[1], "mirror", 1.0);
    assert_eq!(bounds(&bodies[1]), ([-1.0, 0.0, 0.0], [0.0, 1.0, 1.0]));
}

#[test]
fn format_is_chosen_by_case_insensitive_extension() {
    assert_eq!(
        MeshFormat::from_path(Path::new("a/B.PlY")),
        Some(MeshFormat::Ply)
    );
    assert_eq!(
        MeshFormat::from_path(Path::new("x.Obj")),
        Some(MeshFormat::Obj)
    );
    assert_eq!(MeshFormat::from_path(Path::new("noext")), None);
    let dir = TempDir::new();
    let path = dir.write("UPPER.STL", &read("cube_binary.stl"));
    assert_eq!(load_bodies(&path).unwrap()[0].name, "UPPER");
}

/// Writes `bytes` as `name`, loads it, and returns the error after checking
/// that its message names the file.
fn load_error(name: &str, bytes: &[u8]) -> InertiaError {
    let dir = TempDir::new();
    let path = dir.write(name, bytes);
    let err = load_bodies(&path).expect_err(name);
    assert!(err.to_string().contains(name), "{err}");
    err
}

fn assert_parse_error(name: &str, bytes: &[u8], needle: &str) {
    match load_error(name, bytes) {
        InertiaError::Parse { reason, .. } => assert!(reason.contains(needle), "{name}: {reason}"),
        other => panic!("{name}: expected a parse error, got {other:?}"),
    }
}

#[test]
fn missing_file_and_unknown_extension() {
    let path = std::env::temp_dir().join("kreisel-io-surely-missing.stl");
    let err = load_bodies(&path).unwrap_err();
    assert!(matches!(err, InertiaError::Io { .. }), "{err:?}");
    assert!(err.to_string().contains("kreisel-io-surely-missing.stl"));
    let err = load_error("mesh.xyz", b"whatever");
    assert!(matches!(err, InertiaError::UnknownFormat { .. }), "{err:?}");
}

#[test]
fn empty_and_garbage_files_are_parse_errors() {
    for ext in ["stl", "obj", "ply", "gltf", "glb"] {
        assert_parse_error(&format!("empty.{ext}"), b"", "empty");
    }
    let mut state = 12345u64;
    let garbage: Vec<u8> = (0..300).map(|_| lcg(&mut state) as u8).collect();
    for ext in ["stl", "obj", "ply", "gltf", "glb"] {
        assert_parse_error(&format!("garbage.{ext}"), &garbage, "");
    }
    assert_parse_error("magic.glb", b"glTF\x02\0\0\0\x05\0\0\0", "header");
}

#[test]
fn binary_stl_with_lying_or_truncated_count() {
    let full = read("cube_binary.stl");
    let mut lying = full[..84 + 2 * 50].to_vec();
    lying[80..84].copy_from_slice(&1_000_000_000u32.to_le_bytes());
    let start = Instant::now();
    assert_parse_error("lying.stl", &lying, "1000000000 triangles");
    assert!(start.elapsed().as_secs() < 5);
    assert_parse_error("truncated.stl", &full[..full.len() - 7], "12 triangles");
    assert_parse_error("trailing.stl", &[&full[..], b"\0"].concat(), "12 triangles");
    assert_parse_error("short.stl", &full[..40], "");
}

#[test]
fn nan_and_out_of_range_indices_are_parse_errors() {
    let nan = read_text("cube_ascii.stl").replacen("vertex 0 0 0", "vertex 0 nan 0", 1);
    assert_parse_error("nan.stl", nan.as_bytes(), "non-finite");
    let obj = read_text("cube.obj").replace("f 5/", "f 9/");
    assert_parse_error(
        "bad.obj",
        obj.as_bytes(),
        "line 17: face refers to vertex 9",
    );
    let ply = read_text("cube_ascii.ply").replace("4 4 5 6 7", "4 4 5 6 8");
    assert_parse_error("bad.ply", ply.as_bytes(), "face 1 refers to vertex 8");
}

#[test]
fn gltf_accessor_past_its_buffer_is_a_parse_error() {
    let json = read_text("cube.gltf");
    let past = json.replace(r#""count": 36"#, r#""count": 37"#);
    assert_parse_error("past.gltf", past.as_bytes(), "reaches past");
    let view = json.replace(r#""byteLength": 72"#, r#""byteLength": 4000000000"#);
    assert_parse_error("view.gltf", view.as_bytes(), "reaches past");
    let dangling = json.replace(r#""POSITION": 0"#, r#""POSITION": 7"#);
    assert_parse_error("dangling.gltf", dangling.as_bytes(), "does not exist");
}

fn lcg(state: &mut u64) -> u64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    *state >> 33
}

#[test]
fn truncated_and_corrupted_files_never_panic() {
    let files = [
        ("cube_binary.stl", MeshFormat::Stl),
        ("cube_ascii.stl", MeshFormat::Stl),
        ("two_cubes.obj", MeshFormat::Obj),
        ("cube_ascii.ply", MeshFormat::Ply),
        ("cube_binary_le.ply", MeshFormat::Ply),
        ("cube_binary_be.ply", MeshFormat::Ply),
        ("transforms.gltf", MeshFormat::Gltf),
        ("cube.glb", MeshFormat::Glb),
    ];
    // KREISEL_IO_FUZZ=<n> runs n times as many corruptions (for a deeper local run).
    let rounds: usize = std::env::var("KREISEL_IO_FUZZ")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(1);
    let mut state = 7u64;
    for (file, format) in files {
        let bytes = read(file);
        assert!(
            load_bodies_from_bytes(&bytes, format, "f", None).is_ok(),
            "{file}"
        );
        for len in 0..bytes.len() {
            let _ = load_bodies_from_bytes(&bytes[..len], format, "f", None);
        }
        for _ in 0..300 * rounds {
            let mut corrupt = bytes.clone();
            for _ in 0..1 + lcg(&mut state) % 4 {
                let at = lcg(&mut state) as usize % corrupt.len();
                corrupt[at] = lcg(&mut state) as u8;
            }
            let _ = load_bodies_from_bytes(&corrupt, format, "f", None);
        }
    }
}
