//! Meshes that are closed in practice are solids: the patterns that made
//! real robot meshes fail (issue 12), as small committed fixtures
//! (`crates/inertia/tests/fixtures/closed_in_practice/make.py`) with
//! closed-form answers, and refusals that say what gives the right answer.

use glam::{DMat3, DVec3};

use crate::support::{inertia, max_abs, num, rel, rows, vec3, workspace};

/// A fixture of `crates/inertia/tests/fixtures/closed_in_practice`.
fn fixture(name: &str) -> std::path::PathBuf {
    workspace("crates/inertia/tests/fixtures/closed_in_practice").join(name)
}

/// The warnings of a JSON report, as text.
fn warnings(json: &serde_json::Value) -> Vec<String> {
    json["warnings"]
        .as_array()
        .expect("warnings")
        .iter()
        .map(|w| w.as_str().expect("string").to_owned())
        .collect()
}

/// Asserts a unit cube at density 1000 (mass 1000, I = 1000/6 on the diagonal).
fn assert_unit_cube(json: &serde_json::Value) {
    assert!(rel(num(&json["mass"]), 1000.0) <= 1e-14, "{}", json["mass"]);
    let c = vec3(&json["center_of_mass"]);
    assert!((c - DVec3::splat(0.5)).abs().max_element() <= 1e-15, "{c}");
    let err = max_abs(rows(&json["inertia"]) - DMat3::from_diagonal(DVec3::splat(1000.0 / 6.0)));
    assert!(err <= 1e-12, "{err}");
}

#[test]
fn near_duplicate_vertices_are_welded_and_reported() {
    let path = fixture("near_duplicates.stl");
    let run = inertia(&path, &["--format", "json"]);
    let json = run.json();
    // Welding keeps each vertex's first occurrence, which is the exact box
    // corner: 0.2 x 0.1 x 0.05 m of water, 1 kg, I = m (b² + c²) / 12, ….
    assert!(rel(num(&json["mass"]), 1.0) <= 1e-14, "{}", json["mass"]);
    let c = vec3(&json["center_of_mass"]);
    assert!(
        (c - DVec3::new(0.1, 0.05, 0.025)).abs().max_element() <= 1e-16,
        "{c}"
    );
    let (a, b, h) = (0.2f64, 0.1f64, 0.05f64);
    let expected = DVec3::new(b * b + h * h, a * a + h * h, a * a + b * b) / 12.0;
    let err = max_abs(rows(&json["inertia"]) - DMat3::from_diagonal(expected));
    assert!(err <= 1e-17, "{err}");
    let w = warnings(&json);
    assert!(
        w.iter()
            .any(|w| w.contains("welded 26 vertices lying within 2.29e-7 m")
                && w.contains("largest move 1.00e-8 m")
                && w.contains("--weld")),
        "{w:?}"
    );
    assert!(run.stderr.contains("warning") && run.stderr.contains("welded"));
}

#[test]
fn without_welding_the_refusal_names_the_cracks_and_the_weld_that_closes_them() {
    let run = inertia(&fixture("near_duplicates.stl"), &["--weld", "off"]);
    let line = run.error_line(1);
    for words in ["mesh is open", "boundary edges", "one at (", "--weld 2e-8"] {
        assert!(line.contains(words), "{words:?} in {line}");
    }
    // Never advice that gives a wrong mass for a badly welded mesh.
    assert!(
        !line.contains("--hull") && !line.contains("--shell"),
        "{line}"
    );
    // The suggested tolerance does close it, with the right answer.
    let json = inertia(
        &fixture("near_duplicates.stl"),
        &["--weld", "2e-8", "--format", "json"],
    )
    .json();
    assert!(rel(num(&json["mass"]), 1.0) <= 1e-14, "{}", json["mass"]);
}

#[test]
fn a_zero_area_sliver_keeps_the_cube_closed() {
    let json = inertia(&fixture("sliver_cube.obj"), &["--format", "json"]).json();
    assert_unit_cube(&json);
    assert_eq!(num(&json["triangles"]), 13.0);
    let w = warnings(&json);
    assert!(
        w.iter().any(|w| w.contains("1 degenerate triangles")),
        "{w:?}"
    );
}

#[test]
fn two_objects_closed_only_as_a_whole_need_merge_and_the_refusal_says_so() {
    let path = fixture("two_halves.obj");
    let line = inertia(&path, &[]).error_line(1).to_owned();
    for words in ["first_half", "mesh is open", "--merge"] {
        assert!(line.contains(words), "{words:?} in {line}");
    }
    assert!(!line.contains("--hull"), "{line}");
    let json = inertia(&path, &["--merge", "--format", "json"]).json();
    assert_unit_cube(&json);
    assert_eq!(json["bodies"].as_array().map(Vec::len), Some(1));
    assert_eq!(json["bodies"][0]["name"], "two_halves");
}

#[test]
fn a_closed_non_manifold_surface_is_a_solid_with_a_warning() {
    // Cubes [0,1]³ and [1,2]×[1,2]×[0,1]: centre of mass (1, 1, 0.5); each
    // cube m/6 about its centre plus m (|d|² E − d dᵀ), d = ±(0.5, 0.5, 0).
    let json = inertia(&fixture("edge_cubes.obj"), &["--format", "json"]).json();
    assert!(rel(num(&json["mass"]), 2000.0) <= 1e-14, "{}", json["mass"]);
    let c = vec3(&json["center_of_mass"]);
    assert!(
        (c - DVec3::new(1.0, 1.0, 0.5)).abs().max_element() <= 1e-15,
        "{c}"
    );
    let own = 2000.0 / 6.0;
    let expected = DMat3::from_cols(
        DVec3::new(own + 500.0, -500.0, 0.0),
        DVec3::new(-500.0, own + 500.0, 0.0),
        DVec3::new(0.0, 0.0, own + 1000.0),
    );
    let err = max_abs(rows(&json["inertia"]) - expected);
    assert!(err <= 1e-12, "{err}");
    let w = warnings(&json);
    assert!(
        w.iter()
            .any(|w| w.contains("shared by more than two triangles")),
        "{w:?}"
    );
}

#[test]
fn a_two_vertex_face_is_skipped_with_its_line_number() {
    let path = fixture("two_vertex_face.obj");
    let run = inertia(&path, &["--format", "json"]);
    let json = run.json();
    assert_unit_cube(&json);
    let w = warnings(&json);
    assert!(
        w.iter()
            .any(|w| w.contains("skipped 1 faces with fewer than 3 vertices (line 10)")),
        "{w:?}"
    );
    // Every output format carries the warning.
    let text = inertia(&path, &[]).stdout;
    assert!(text.contains("(line 10)"), "{text}");
    let xml = inertia(&path, &["--format", "urdf"]).stdout;
    assert!(
        xml.contains("<!-- warning: ") && xml.contains("(line 10)"),
        "{xml}"
    );
}

#[test]
fn a_millimetre_part_without_units_gets_a_warning_naming_units_mm() {
    let path = fixture("mm_part.stl");
    let run = inertia(&path, &["--format", "json"]);
    let json = run.json();
    // 50 x 20 x 10 "m" of water: the number the warning is about.
    assert!(rel(num(&json["mass"]), 1e7) <= 1e-14, "{}", json["mass"]);
    let w = warnings(&json);
    assert!(
        w.iter().any(|w| w.contains("50 m across (50 x 20 x 10 m)")
            && w.contains("rerun with --units mm (0.05 m across)")),
        "{w:?}"
    );
    assert!(run.stderr.contains("--units mm"), "{}", run.stderr);
    assert!(inertia(&path, &[]).stdout.contains("--units mm"));
    // With the right units: 1e-5 m³ of water, no warning.
    let json = inertia(&path, &["--units", "mm", "--format", "json"]).json();
    assert!(rel(num(&json["mass"]), 0.01) <= 1e-14, "{}", json["mass"]);
    assert!(warnings(&json).is_empty(), "{:?}", warnings(&json));
}
