//! Against exact values: `tests/data/polyhedra_expected.csv` holds the mass
//! properties of the reference polyhedra at density 1, computed in rational
//! arithmetic; the rotated box has non-zero products of inertia, so its
//! off-diagonal signs are checked in every output format.

use std::path::PathBuf;

use glam::{DMat3, DVec3};

use crate::support::{
    Expected, attribute, element, inertia, max_abs, num, numbers, raw_list, rel, rows, vec3,
    workspace, wxyz,
};

/// The mesh file of a row of the reference table.
fn mesh_of(name: &str) -> PathBuf {
    match name {
        "t_handle" => workspace("assets/t_handle.obj"),
        "top" => workspace("assets/top.stl"),
        "top_ascii" => workspace("assets/top_ascii.stl"),
        _ => workspace(&format!("tests/data/polyhedra/{name}.obj")),
    }
}

/// The rotated box with exactly representable vertices and results.
const BOX: &str = "box_rotated_exact";

#[test]
fn rotated_box_json_matches_exact_values() {
    let expected = Expected::load();
    let json = inertia(&mesh_of(BOX), &["--density", "1", "--format", "json"]).json();
    let tol = 1e-13;
    let volume = expected.num(BOX, "volume");
    assert!(rel(num(&json["mass"]), volume) <= tol, "{}", json["mass"]);
    assert!(
        rel(num(&json["volume"]), volume) <= tol,
        "{}",
        json["volume"]
    );
    assert_eq!(num(&json["density"]), 1.0);
    assert_eq!(json["triangles"], 12);
    let com = vec3(&json["center_of_mass"]);
    let com_expected = expected.com(BOX, "");
    for k in 0..3 {
        assert!(
            rel(com[k], com_expected[k]) <= tol,
            "com {com} vs {com_expected}"
        );
    }
    let tensor = rows(&json["inertia"]);
    let tensor_expected = expected.tensor(BOX, "");
    for c in 0..3 {
        for r in 0..3 {
            let (a, b) = (tensor.col(c)[r], tensor_expected.col(c)[r]);
            assert!(rel(a, b) <= tol, "I[{r}][{c}] = {a} vs {b}");
            assert_eq!(a.signum(), b.signum(), "sign of I[{r}][{c}]");
        }
    }
    // The one body is the assembly.
    let body = &json["bodies"][0];
    assert_eq!(json["bodies"].as_array().map(Vec::len), Some(1));
    assert_eq!(body["name"], BOX);
    assert_eq!(body["inertia"], json["inertia"]);
}

#[test]
fn every_reference_mesh_matches_within_rounding() {
    let expected = Expected::load();
    let mut worst = (0.0_f64, String::new());
    for name in expected.names() {
        let json = inertia(&mesh_of(&name), &["--density", "1", "--format", "json"]).json();
        let volume = expected.num(&name, "volume");
        let size = volume.cbrt();
        let com_expected = expected.com(&name, "");
        let tensor_expected = expected.tensor(&name, "");
        let errors = [
            rel(num(&json["mass"]), volume),
            rel(num(&json["volume"]), volume),
            (vec3(&json["center_of_mass"]) - com_expected)
                .abs()
                .max_element()
                / (com_expected.abs().max_element() + size),
            max_abs(rows(&json["inertia"]) - tensor_expected) / max_abs(tensor_expected),
        ];
        let error = errors.iter().fold(0.0_f64, |a, &e| a.max(e));
        if error >= worst.0 {
            worst = (error, name.clone());
        }
        assert!(error <= 1e-12, "{name}: errors {errors:?}");
    }
    println!(
        "max relative error over the reference meshes: {:.3e} ({})",
        worst.0, worst.1
    );
}

#[test]
fn shells_match_exact_surface_values() {
    let expected = Expected::load();
    let mut checked = 0;
    for name in expected.names() {
        let Some(area) = expected.get(&name, "area") else {
            continue;
        };
        // ρ t = 2 · 0.5 = 1: the mass is the area, as in the table.
        let args = [
            "--shell",
            "--thickness",
            "0.5",
            "--density",
            "2",
            "--format",
            "json",
        ];
        let json = inertia(&mesh_of(&name), &args).json();
        assert_eq!(json["model"], "shell");
        assert_eq!(num(&json["thickness"]), 0.5);
        assert!(
            rel(num(&json["mass"]), area) <= 1e-12,
            "{name}: {}",
            json["mass"]
        );
        assert!(
            rel(num(&json["area"]), area) <= 1e-12,
            "{name}: {}",
            json["area"]
        );
        assert!(rel(num(&json["volume"]), 0.5 * area) <= 1e-12, "{name}");
        let com = expected.com(&name, "shell_");
        let scale = com.abs().max_element() + area.sqrt();
        let com_error = (vec3(&json["center_of_mass"]) - com).abs().max_element() / scale;
        assert!(com_error <= 1e-12, "{name}: {com_error:e}");
        let tensor = expected.tensor(&name, "shell_");
        let error = max_abs(rows(&json["inertia"]) - tensor) / max_abs(tensor);
        assert!(error <= 1e-12, "{name}: {error:e}");
        checked += 1;
    }
    assert!(checked >= 5, "only {checked} shells");
}

/// `|a − b| ≤ 1e-13 |b|` with the same sign.
fn assert_element(what: &str, a: f64, b: f64) {
    assert!(rel(a, b) <= 1e-13, "{what}: {a} vs {b}");
    assert_eq!(a.signum(), b.signum(), "{what}: sign of {a} vs {b}");
}

#[test]
fn off_diagonal_signs_in_urdf_sdf_and_mjcf_are_tensor_elements() {
    let expected = Expected::load();
    let e = |c: &str| expected.num(BOX, c);
    let (mass, com) = (e("volume"), expected.com(BOX, ""));
    // The products of inertia Σ m x y have the opposite sign: make sure the
    // test data can tell them apart.
    assert!(e("ixy") < 0.0 && e("ixz") < 0.0 && e("iyz") > 0.0);
    let six = ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"];

    let urdf = inertia(&mesh_of(BOX), &["--density", "1", "--format", "urdf"]);
    assert_eq!(urdf.code, Some(0), "{}", urdf.stderr);
    let xml = &urdf.stdout;
    assert!(xml.starts_with("<!-- kreisel inertia "), "{xml}");
    assert!(
        xml.contains("mesh units m (scale 1), density 1 kg/m^3, solid;"),
        "{xml}"
    );
    assert!(
        xml.contains("about the centre of mass in mesh axes"),
        "{xml}"
    );
    assert_eq!(attribute(xml, "rpy"), "0 0 0");
    let origin = numbers(attribute(xml, "xyz"));
    for k in 0..3 {
        assert_element("urdf origin", origin[k], com[k]);
    }
    assert_element("urdf mass", numbers(attribute(xml, "value"))[0], mass);
    for name in six {
        assert_element(name, numbers(attribute(xml, name))[0], e(name));
    }

    let sdf = inertia(&mesh_of(BOX), &["--density", "1", "--format", "sdf"]);
    assert_eq!(sdf.code, Some(0), "{}", sdf.stderr);
    let xml = &sdf.stdout;
    let pose = numbers(element(xml, "pose"));
    assert_eq!(&pose[3..], &[0.0, 0.0, 0.0]);
    for k in 0..3 {
        assert_element("sdf pose", pose[k], com[k]);
    }
    assert_element("sdf mass", numbers(element(xml, "mass"))[0], mass);
    for name in six {
        assert_element(name, numbers(element(xml, name))[0], e(name));
    }

    let mjcf = inertia(&mesh_of(BOX), &["--density", "1", "--format", "mjcf"]);
    assert_eq!(mjcf.code, Some(0), "{}", mjcf.stderr);
    let xml = &mjcf.stdout;
    let element_line = xml
        .lines()
        .find(|l| l.starts_with("<inertial "))
        .expect("element");
    let pos = numbers(attribute(element_line, "pos"));
    for k in 0..3 {
        assert_element("mjcf pos", pos[k], com[k]);
    }
    assert_element(
        "mjcf mass",
        numbers(attribute(element_line, "mass"))[0],
        mass,
    );
    let full = numbers(attribute(element_line, "fullinertia"));
    // MuJoCo's order: M(1,1), M(2,2), M(3,3), M(1,2), M(1,3), M(2,3).
    for (value, name) in full.iter().zip(["ixx", "iyy", "izz", "ixy", "ixz", "iyz"]) {
        assert_element(name, *value, e(name));
    }
}

#[test]
fn principal_axes_form_a_right_handed_eigenframe() {
    for name in [
        BOX,
        "box_rotated",
        "l_shape",
        "prism_hex",
        "t_handle",
        "top",
    ] {
        let run = inertia(&mesh_of(name), &["--format", "json"]);
        let json = run.json();
        let tensor = rows(&json["inertia"]);
        let scale = max_abs(tensor);
        let moments = vec3(&json["principal_moments"]);
        assert!(
            moments.x <= moments.y && moments.y <= moments.z,
            "{name}: {moments}"
        );
        // Rows of principal_axes are the axes: columns of A.
        let a = rows(&json["principal_axes"]).transpose();
        let orthonormal = max_abs(a.transpose() * a - DMat3::IDENTITY);
        assert!(orthonormal <= 1e-15, "{name}: {orthonormal:e}");
        assert!(
            (a.determinant() - 1.0).abs() <= 1e-15,
            "{name}: det {}",
            a.determinant()
        );
        let back = a * DMat3::from_diagonal(moments) * a.transpose();
        let error = max_abs(back - tensor) / scale;
        assert!(error <= 1e-14, "{name}: reconstruction {error:e}");
        // The orientation maps principal coordinates to mesh coordinates.
        let q = wxyz(&json["principal_orientation"]);
        assert!(
            q.w >= 0.0 && (q.length() - 1.0).abs() <= 1e-15,
            "{name}: {q}"
        );
        for (e, axis) in [
            (DVec3::X, a.x_axis),
            (DVec3::Y, a.y_axis),
            (DVec3::Z, a.z_axis),
        ] {
            let error = (q * e - axis).abs().max_element();
            assert!(error <= 1e-15, "{name}: {e} ↦ {} vs {axis}", q * e);
        }
        // MJCF's principal form says the same.
        let mjcf = inertia(&mesh_of(name), &["--format", "mjcf"]).stdout;
        let principal = mjcf
            .lines()
            .find(|l| l.contains("principal form"))
            .expect("comment");
        let quat = numbers(attribute(principal, "quat"));
        assert_eq!(
            quat,
            raw_list(&run.stdout, "principal_orientation"),
            "{name}"
        );
        let diag = numbers(attribute(principal, "diaginertia"));
        assert_eq!(diag, raw_list(&run.stdout, "principal_moments"), "{name}");
    }
}
