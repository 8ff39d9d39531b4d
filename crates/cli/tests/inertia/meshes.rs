//! Meshes that need care: open surfaces (an error for a solid, fine as a
//! shell or hull), inside-out surfaces (repaired with a warning), and files
//! with several bodies (each reported, and their assembly).

use glam::DVec3;

use crate::support::{cube_obj, inertia, num, rel, rows, scratch, vec3};

/// Mass properties of the unit cube at density 1000: I = m (1² + 1²) / 12.
const CUBE_MASS: f64 = 1000.0;
const CUBE_I: f64 = 1000.0 / 6.0;

#[test]
fn open_mesh_is_an_error_that_names_file_and_options() {
    let path = scratch("open_cube.obj", cube_obj("lidless", 0.0, 1, false, true));
    let run = inertia(&path, &[]);
    let line = run.error_line(1);
    for words in [
        "open_cube.obj",
        "lidless",
        "4 boundary edges",
        "--shell",
        "--hull",
    ] {
        assert!(line.contains(words), "{words:?} in {line}");
    }
}

#[test]
fn open_mesh_as_shell_or_hull() {
    let path = scratch("open_cube_ok.obj", cube_obj("lidless", 0.0, 1, false, true));
    // Five faces of area 1, 1 mm of water.
    let shell = inertia(&path, &["--shell", "--format", "json"]).json();
    assert!(rel(num(&shell["mass"]), 5.0) <= 1e-14, "{}", shell["mass"]);
    assert!(rel(num(&shell["area"]), 5.0) <= 1e-14);
    // The open top pulls the centre of mass down: z = (4 · 0.5 + 0) / 5.
    let c = vec3(&shell["center_of_mass"]);
    assert!(
        (c - DVec3::new(0.5, 0.5, 0.4)).abs().max_element() <= 1e-15,
        "{c}"
    );
    let hull = inertia(&path, &["--hull", "--format", "json"]).json();
    assert!(
        rel(num(&hull["mass"]), CUBE_MASS) <= 1e-14,
        "{}",
        hull["mass"]
    );
    let c = vec3(&hull["center_of_mass"]);
    assert!((c - DVec3::splat(0.5)).abs().max_element() <= 1e-15, "{c}");
}

#[test]
fn inside_out_cube_is_repaired_with_a_warning() {
    let path = scratch("inside_out.obj", cube_obj("inverted", 0.0, 1, true, false));
    let run = inertia(&path, &["--format", "json"]);
    let json = run.json();
    assert!(
        rel(num(&json["mass"]), CUBE_MASS) <= 1e-14,
        "{}",
        json["mass"]
    );
    let tensor = rows(&json["inertia"]);
    assert!(rel(tensor.x_axis.x, CUBE_I) <= 1e-13, "{tensor}");
    let lines: Vec<&str> = run.stderr.lines().collect();
    assert_eq!(lines.len(), 1, "{}", run.stderr);
    let line = lines[0];
    assert!(line.starts_with("kreisel: warning: "), "{line}");
    for words in ["inside_out.obj", "body 'inverted'", "inside-out"] {
        assert!(line.contains(words), "{words:?} in {line}");
    }
    let warnings = json["warnings"].as_array().expect("warnings");
    assert_eq!(warnings.len(), 1);
    assert!(
        warnings[0]
            .as_str()
            .is_some_and(|w| w.contains("inside-out")),
        "{warnings:?}"
    );
    let body = &json["bodies"][0]["warnings"][0];
    assert!(
        body.as_str().is_some_and(|w| w.contains("inside-out")),
        "{body}"
    );
}

/// Two unit cubes, `a` at x ∈ [0, 1] and `b` at x ∈ [2, 3].
fn two_cubes(name: &str) -> std::path::PathBuf {
    let text = cube_obj("a", 0.0, 1, false, false) + &cube_obj("b", 2.0, 9, false, false);
    scratch(name, text)
}

#[test]
fn two_bodies_and_their_assembly() {
    let json = inertia(&two_cubes("two.obj"), &["--format", "json"]).json();
    let bodies = json["bodies"].as_array().expect("bodies");
    assert_eq!(bodies.len(), 2);
    assert_eq!(
        (&bodies[0]["name"], &bodies[1]["name"]),
        (&"a".into(), &"b".into())
    );
    let (ma, mb) = (num(&bodies[0]["mass"]), num(&bodies[1]["mass"]));
    assert!(rel(ma, CUBE_MASS) <= 1e-14 && rel(mb, CUBE_MASS) <= 1e-14);
    assert!(rel(num(&json["mass"]), ma + mb) <= 1e-15);
    assert!(rel(num(&json["volume"]), 2.0) <= 1e-14);
    assert_eq!(json["triangles"], 24);
    let c = vec3(&json["center_of_mass"]);
    assert!(
        (c - DVec3::new(1.5, 0.5, 0.5)).abs().max_element() <= 1e-14,
        "{c}"
    );
    // Parallel axes: each cube is 1 m from the common centre along x.
    let i = rows(&json["inertia"]);
    assert!(rel(i.x_axis.x, 2.0 * CUBE_I) <= 1e-13, "{i}");
    assert!(rel(i.y_axis.y, 2.0 * (CUBE_I + CUBE_MASS)) <= 1e-13, "{i}");
    assert!(rel(i.z_axis.z, 2.0 * (CUBE_I + CUBE_MASS)) <= 1e-13, "{i}");
    assert!(i.y_axis.x.abs() <= 1e-10, "{i}");
    let c_b = vec3(&bodies[1]["center_of_mass"]);
    assert!((c_b - DVec3::new(2.5, 0.5, 0.5)).abs().max_element() <= 1e-14);
}

#[test]
fn two_bodies_share_one_density_for_total_mass() {
    let json = inertia(
        &two_cubes("two_mass.obj"),
        &["--mass", "3", "--format", "json"],
    )
    .json();
    assert!(rel(num(&json["mass"]), 3.0) <= 1e-14, "{}", json["mass"]);
    for body in json["bodies"].as_array().expect("bodies") {
        assert!(rel(num(&body["mass"]), 1.5) <= 1e-14, "{body}");
        assert!(rel(num(&body["density"]), 1.5) <= 1e-14, "{body}");
    }
}

#[test]
fn two_bodies_in_text_and_xml() {
    let path = two_cubes("two_text.obj");
    let text = inertia(&path, &[]).stdout;
    for words in [
        "bodies                  2 (a, b)",
        "body 'a'",
        "body 'b'",
        "assembly (sum of 2 bodies)",
    ] {
        assert!(text.contains(words), "{words:?} in\n{text}");
    }
    for format in ["urdf", "sdf", "mjcf"] {
        let xml = inertia(&path, &["--format", format]).stdout;
        assert!(xml.contains("assembly of 2 bodies"), "{format}: {xml}");
        assert!(xml.contains("'a' (mass 1000 kg)"), "{format}: {xml}");
        assert_eq!(
            xml.matches("<inertial").count() - xml.matches("principal form").count(),
            1
        );
    }
}

#[test]
fn odd_names_stay_valid_json_and_xml() {
    let name = r#"we"ird\name--x"#;
    let path = scratch("odd--name.obj", cube_obj(name, 0.0, 1, true, false));
    let run = inertia(&path, &["--format", "json"]);
    let json = run.json();
    assert_eq!(json["bodies"][0]["name"], name);
    assert!(
        json["file"]
            .as_str()
            .is_some_and(|f| f.ends_with("odd--name.obj"))
    );
    let path = two_cubes("odd--two.obj");
    let xml = inertia(&path, &["--format", "urdf"]).stdout;
    for line in xml.lines().filter(|l| l.starts_with("<!--")) {
        let inner = &line[4..line.len() - 3];
        assert!(!inner.contains("--"), "{line}");
    }
}
