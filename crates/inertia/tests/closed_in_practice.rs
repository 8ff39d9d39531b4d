//! The loader and checks on the patterns of real meshes that are closed in
//! practice (fixtures written by `fixtures/closed_in_practice/make.py`):
//! welding, slivers, non-manifold 2-cycles, merged objects, malformed faces.

use std::path::{Path, PathBuf};

use kreisel_inertia::io::{LoadOptions, LoadWarning};
use kreisel_inertia::{
    InertiaError, MassModel, Material, MeshWarning, Weld, mesh_mass_properties, prepare_solid,
};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/closed_in_practice")
        .join(name)
}

#[test]
fn default_weld_closes_near_duplicates_and_exact_weld_reports_the_gap() {
    let path = fixture("near_duplicates.stl");
    let bodies = LoadOptions::default().load(&path).unwrap();
    assert_eq!(bodies.len(), 1);
    assert!(
        matches!(
            bodies[0].warnings[..],
            [LoadWarning::Welded { vertices: 26, max_move, .. }] if (max_move - 1e-8).abs() < 1e-16
        ),
        "{:?}",
        bodies[0].warnings
    );
    assert_eq!(bodies[0].mesh.vertices().len(), 8);
    let report = mesh_mass_properties(
        bodies[0].mesh.clone(),
        MassModel::Solid,
        Material::Density(1.0),
    )
    .unwrap();
    // 0.2 x 0.1 x 0.05 m: the first occurrences are the exact corners.
    assert!((report.volume - 1e-3).abs() <= 1e-18, "{}", report.volume);

    let exact = LoadOptions {
        weld: Weld::Exact,
        merge: false,
    };
    let mesh = exact.load(&path).unwrap().remove(0).mesh;
    match prepare_solid(mesh) {
        Err(InertiaError::OpenMesh {
            weld_gap: Some(gap),
            ..
        }) => assert!((1e-9..=1e-8 * (1.0 + 1e-6)).contains(&gap), "{gap}"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn merged_objects_are_one_solid() {
    let path = fixture("two_halves.obj");
    let apart = LoadOptions::default().load(&path).unwrap();
    assert_eq!(apart.len(), 2);
    for body in apart {
        assert!(matches!(
            prepare_solid(body.mesh),
            Err(InertiaError::OpenMesh { .. })
        ));
    }
    let merged = LoadOptions {
        merge: true,
        ..LoadOptions::default()
    }
    .load(&path)
    .unwrap();
    assert_eq!(merged.len(), 1);
    assert_eq!(merged[0].mesh.vertices().len(), 8);
    let checked = prepare_solid(merged[0].mesh.clone()).unwrap();
    assert!(checked.warnings.is_empty(), "{:?}", checked.warnings);
}

#[test]
fn sliver_and_non_manifold_fixtures_are_solids() {
    let sliver = LoadOptions::default()
        .load(&fixture("sliver_cube.obj"))
        .unwrap()
        .remove(0);
    let checked = prepare_solid(sliver.mesh).unwrap();
    assert_eq!(
        checked.warnings,
        vec![MeshWarning::DegenerateTriangles { count: 1 }]
    );
    let cubes = LoadOptions::default()
        .load(&fixture("edge_cubes.obj"))
        .unwrap()
        .remove(0);
    let checked = prepare_solid(cubes.mesh).unwrap();
    assert_eq!(
        checked.warnings,
        vec![MeshWarning::NonManifoldEdges { edges: 1 }]
    );
}

#[test]
fn a_two_vertex_face_is_skipped_and_named() {
    let bodies = LoadOptions::default()
        .load(&fixture("two_vertex_face.obj"))
        .unwrap();
    assert_eq!(bodies[0].mesh.triangles().len(), 12);
    assert_eq!(
        bodies[0].warnings,
        vec![LoadWarning::MalformedFaces { lines: vec![10] }]
    );
}
