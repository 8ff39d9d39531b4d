//! Bad input: one `kreisel: error:` line naming the file and exit status 1
//! for bad files, clap's usage error and status 2 for bad option values;
//! never a panic.

use crate::support::{cube_obj, inertia, scratch, workspace};

/// A closed tetrahedron whose first vertex is `first`.
fn tetra(first: &str) -> String {
    format!("v {first}\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
}

#[test]
fn bad_files_give_one_line_naming_the_file() {
    let cases: Vec<(std::path::PathBuf, &[&str])> = vec![
        (
            workspace("tests/data/no_such_mesh.obj"),
            &["no_such_mesh.obj", "cannot read"],
        ),
        (scratch("empty.obj", ""), &["empty.obj"]),
        (scratch("empty.stl", ""), &["empty.stl", "empty"]),
        (
            scratch("garbage.stl", "this is not a mesh at all"),
            &["garbage.stl", "STL"],
        ),
        (scratch("noise.stl", [0xa7_u8; 300]), &["noise.stl", "STL"]),
        (
            scratch("points.xyz", "0 0 0\n"),
            &["points.xyz", "unknown mesh format"],
        ),
        (
            scratch("nan.obj", tetra("nan 0 0")),
            &["nan.obj", "non-finite"],
        ),
        (scratch("inf.obj", tetra("0 inf 0")), &["inf.obj"]),
        (
            scratch("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n"),
            &["bad_index.obj", "99"],
        ),
        (
            scratch("no_faces.obj", "v 0 0 0\nv 1 0 0\n"),
            &["no_faces.obj"],
        ),
        (
            scratch("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n"),
            &["flat.obj"],
        ),
    ];
    for (path, words) in cases {
        let run = inertia(&path, &[]);
        let line = run.error_line(1);
        for w in words {
            assert!(line.contains(w), "{w:?} in {line}");
        }
    }
}

#[test]
fn bad_values_are_usage_errors_before_loading() {
    // The file does not exist: the values are rejected before it is opened.
    let missing = workspace("tests/data/no_such_mesh.obj");
    for (args, quantity) in [
        (&["--density", "-1"][..], "density"),
        (&["--density", "0"], "density"),
        (&["--density", "nan"], "density"),
        (&["--mass", "inf"], "mass"),
        (&["--mass", "-2"], "mass"),
        (&["--scale", "0"], "scale"),
        (&["--scale", "-1e-3"], "scale"),
        (&["--shell", "--thickness", "0"], "thickness"),
        (&["--shell", "--thickness", "x"], "thickness"),
    ] {
        let run = inertia(&missing, args);
        assert_eq!(run.code, Some(2), "{args:?}: {}", run.stderr);
        assert!(
            !run.stderr.contains("panicked") && run.stdout.is_empty(),
            "{args:?}"
        );
        let first = run.stderr.lines().next().unwrap_or_default();
        assert!(
            first.starts_with("error: invalid value"),
            "{args:?}: {first}"
        );
        assert!(
            first.contains(quantity) && first.contains("positive finite"),
            "{first}"
        );
    }
}

#[test]
fn scaling_that_overflows_is_an_error() {
    let path = scratch("far_cube.obj", cube_obj("far", 2.0, 1, false, false));
    let line = inertia(&path, &["--scale", "1e308"])
        .error_line(1)
        .to_owned();
    assert!(
        line.contains("far_cube.obj") && line.contains("overflow"),
        "{line}"
    );
    // Finite coordinates whose volume overflows: still one line, no panic.
    let run = inertia(&path, &["--scale", "1e200"]);
    run.error_line(1);
}

#[test]
fn meshes_whose_mass_properties_leave_f64_say_so_and_name_the_units() {
    // Were "mesh is empty (1 vertices, 0 triangles)", "mesh encloses zero
    // volume", "inertia tensor is not physical" and "mesh is empty (8
    // vertices, 0 triangles)": a unit cube scaled to sizes f64 cannot integrate.
    let cube = scratch(
        "unit_cube_for_scales.obj",
        cube_obj("cube", 0.0, 1, false, false),
    );
    let cases: [(&str, &[&str]); 5] = [
        (
            "1e200",
            &["mesh 1e200 m across overflow f64 (volume ≈ 1e600 m^3"],
        ),
        (
            "1e120",
            &["mesh 1e120 m across overflow f64 (volume ≈ 1e360 m^3"],
        ),
        // I = ρ a⁵/6 = 1000 · 1e350 / 6.
        (
            "1e70",
            &["mesh 1e70 m across overflow f64 (inertia tensor ≈ 1.67e352 kg m^2"],
        ),
        (
            "1e-70",
            &["mesh 1e-70 m across underflow f64 (inertia tensor ≈ 1.67e-348 kg m^2"],
        ),
        (
            "1e-200",
            &["mesh 1e-200 m across underflow f64 (volume ≈ 1e-600 m^3"],
        ),
    ];
    for (scale, words) in cases {
        let run = inertia(&cube, &["--scale", scale]);
        let line = run.error_line(1);
        for w in words
            .iter()
            .chain(&["unit_cube_for_scales.obj", "--units or --scale"])
        {
            assert!(line.contains(w), "{w:?} in {line}");
        }
    }
    // Within range the same cube is exact: m = ρ a³ at a = 1e-60 (3 digits of
    // the shortest form are enough to tell it from an underflowed 0).
    let json = inertia(&cube, &["--scale", "1e-60", "--format", "json"]).json();
    let mass = crate::support::num(&json["mass"]);
    assert!((mass / 1e-177 - 1.0).abs() < 1e-12, "{mass:e}");
    // A total mass on a cube whose moments at unit density would underflow:
    // I = m a²/6 = 2 · 1e-140 / 6.
    let json = inertia(
        &cube,
        &["--scale", "1e-70", "--mass", "2", "--format", "json"],
    )
    .json();
    let i = crate::support::rows(&json["inertia"]);
    assert!((i.x_axis.x / (2e-140 / 6.0) - 1.0).abs() < 1e-12, "{i}");
}
