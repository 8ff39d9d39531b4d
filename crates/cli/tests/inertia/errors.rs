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
