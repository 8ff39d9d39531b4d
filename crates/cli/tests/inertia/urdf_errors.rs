//! `kreisel inertia --urdf` on broken robots: one clear line, exit status
//! 1, no output file; a link whose mesh cannot be integrated keeps its old
//! inertial in a file that is still written whole.

use std::path::Path;

use super::urdf::{robot_copy, urdf};

/// The toy robot with `from` replaced by `to` in its URDF, run with
/// `--output`; asserts one error line, exit status 1, no output file, and
/// returns the line.
fn broken(name: &str, from: &str, to: &str) -> String {
    let input = robot_copy(name);
    let text = std::fs::read_to_string(&input).unwrap();
    assert_eq!(text.matches(from).count(), 1, "{from}");
    std::fs::write(&input, text.replacen(from, to, 1)).unwrap();
    let output = input.with_file_name("out.urdf");
    let run = urdf(&input, &["--output", output.to_str().unwrap()]);
    let line = run.error_line(1).to_owned();
    assert!(!output.exists(), "{line}");
    let dir: Vec<_> = std::fs::read_dir(input.parent().unwrap())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(dir, ["toy.urdf"], "no temporary file left");
    line
}

#[test]
fn a_missing_mesh_names_file_and_line() {
    let line = broken("missing", "meshes/wedge.stl\"", "meshes/nope.stl\"");
    assert!(
        line.contains("toy.urdf:43: mesh file not found: "),
        "{line}"
    );
    assert!(
        line.ends_with("(from 'package://toy_robot/meshes/nope.stl')"),
        "{line}"
    );
}

#[test]
fn an_unknown_package_says_how_to_give_it() {
    let line = broken(
        "package",
        "package://toy_robot/meshes/wedge.stl",
        "package://elsewhere/meshes/wedge.stl",
    );
    assert!(line.contains("package 'elsewhere' not found"), "{line}");
    assert!(line.ends_with("give --package elsewhere=DIR"), "{line}");
}

#[test]
fn a_malformed_urdf_names_the_line() {
    let line = broken(
        "malformed",
        "</joint>\n  <link name=\"tool_tip\"/>",
        "</joint>\n  <link name=\"tool_tip\">",
    );
    assert!(line.contains("toy.urdf:"), "{line}");
    assert!(line.contains("not a valid XML file"), "{line}");
}

#[test]
fn an_unknown_geometry_names_link_and_element() {
    let line = broken(
        "capsule",
        "<sphere radius=\"0.02\"/>",
        "<capsule radius=\"0.02\" length=\"0.1\"/>",
    );
    assert!(
        line.ends_with("link 'hand': unknown geometry <capsule> in <collision> (URDF knows box, cylinder, sphere, mesh)"),
        "{line}"
    );
}

#[test]
fn a_bad_number_names_the_attribute() {
    let line = broken("number", "radius=\"0.04\"", "radius=\"4 cm\"");
    assert!(
        line.ends_with("link 'base_link': <cylinder> radius=\"4 cm\" is not 1 finite number(s)"),
        "{line}"
    );
}

#[test]
fn a_missing_urdf_is_one_line() {
    let run = urdf(Path::new("no/such/robot.urdf"), &[]);
    let line = run.error_line(1);
    assert!(
        line.starts_with("kreisel: error: cannot read URDF file no/such/robot.urdf"),
        "{line}"
    );
}

#[test]
fn an_open_mesh_keeps_the_old_inertial_and_the_file_is_written() {
    let input = robot_copy("open");
    // A tetrahedron with one face missing.
    let open = "v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\nf 1 3 2\nf 1 2 4\nf 1 4 3\n";
    std::fs::write(input.parent().unwrap().join("../meshes/open.obj"), open).unwrap();
    let text = std::fs::read_to_string(&input).unwrap();
    let text = text.replacen(
        "../meshes/pyramid.obj\" scale=\"0.001 0.001",
        "../meshes/open.obj\" scale=\"0.001 0.001",
        1,
    );
    std::fs::write(&input, &text).unwrap();
    let output = input.with_file_name("out.urdf");
    let run = urdf(&input, &["--output", output.to_str().unwrap()]);
    assert_eq!(run.code, Some(1), "{}", run.stderr);
    let last = run.stderr.lines().last().unwrap();
    assert_eq!(
        last,
        "kreisel: error: 1 link(s) kept their old inertial, their geometry could not be integrated: forearm"
    );
    let row = run
        .stderr
        .lines()
        .find(|l| l.starts_with("forearm"))
        .unwrap();
    assert!(
        row.contains("cannot integrate, old inertial kept") && row.contains("open"),
        "{row}"
    );
    // Written whole: the forearm's old inertial is there, the others are filled.
    let out = std::fs::read_to_string(&output).unwrap();
    assert!(out.contains(
        "<inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/>"
    ));
    assert!(!out.contains("<mass value=\"0\"/>"), "the arm is filled");
}

#[test]
fn single_mesh_options_conflict_with_urdf() {
    let input = robot_copy("conflict");
    for extra in [
        &["--format", "json"][..],
        &["--units", "mm"],
        &["--check", "--output", "x.urdf"],
    ] {
        let run = urdf(&input, extra);
        assert_eq!(run.code, Some(2), "{extra:?}: {}", run.stderr);
    }
}
