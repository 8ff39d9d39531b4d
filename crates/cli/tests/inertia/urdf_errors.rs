//! `kreisel inertia --urdf` on broken robots: one clear line, exit status
//! 1, no output file; a link whose mesh cannot be integrated keeps its old
//! inertial in a file that is still written whole.

use std::path::Path;

use super::support::mass_of;
use super::urdf::{robot_copy, table_row, urdf};

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

/// The toy robot with `from` replaced by `to`, filled to stdout.
fn filled_with(name: &str, from: &str, to: &str) -> super::support::Run {
    let input = robot_copy(name);
    let text = std::fs::read_to_string(&input).unwrap();
    assert_eq!(text.matches(from).count(), 1, "{from}");
    std::fs::write(&input, text.replacen(from, to, 1)).unwrap();
    urdf(&input, &[])
}

#[test]
fn an_unknown_geometry_keeps_that_links_inertial() {
    let run = filled_with(
        "plane",
        "<sphere radius=\"0.02\"/>",
        "<plane normal=\"0 0 1\"/>",
    );
    assert_eq!(run.code, Some(1), "{}", run.stderr);
    let row = table_row(&run.stderr, "hand");
    assert!(
        row.contains("<plane> geometry cannot be integrated"),
        "{row}"
    );
    assert!(
        run.stderr
            .trim_end()
            .ends_with("could not be integrated: hand")
    );
    assert!(mass_of(&run.stdout, "arm") > 0.0, "the others are filled");
}

#[test]
fn a_capsule_is_a_cylinder_between_two_half_spheres() {
    // Length 0: the sphere of the reference (hand = pyramid + sphere).
    let sphere = filled_with(
        "sphere",
        "<sphere radius=\"0.02\"/>",
        "<sphere radius=\"0.02\"/>",
    );
    let ball = filled_with(
        "ball",
        "<sphere radius=\"0.02\"/>",
        "<capsule radius=\"0.02\" length=\"0\"/>",
    );
    let capsule = filled_with(
        "capsule",
        "<sphere radius=\"0.02\"/>",
        "<capsule radius=\"0.02\" length=\"0.1\"/>",
    );
    for run in [&sphere, &ball, &capsule] {
        assert_eq!(run.code, Some(0), "{}", run.stderr);
    }
    let inertial = |text: &str| {
        let doc = roxmltree::Document::parse(text).expect("XML");
        let node = doc
            .descendants()
            .find(|n| n.has_tag_name("link") && n.attribute("name") == Some("hand"))
            .and_then(|l| l.children().find(|n| n.has_tag_name("inertial")))
            .expect("hand's inertial");
        text[node.range()].to_owned()
    };
    assert_eq!(inertial(&ball.stdout), inertial(&sphere.stdout));
    // The cylinder adds ρ π r² L at 1000 kg/m³.
    let added = mass_of(&capsule.stdout, "hand") - mass_of(&sphere.stdout, "hand");
    let want = 1000.0 * std::f64::consts::PI * 0.02 * 0.02 * 0.1;
    assert!(
        (added - want).abs() <= 1e-14 * want.max(1.0),
        "{added} {want}"
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
    let row = table_row(&run.stderr, "forearm");
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
        &["--mass", "1"][..],
        &["--units", "mm"],
        &["--check", "--output", "x.urdf"],
    ] {
        let run = urdf(&input, extra);
        assert_eq!(run.code, Some(2), "{extra:?}: {}", run.stderr);
    }
}

#[test]
fn an_xml_version_other_than_one_is_refused() {
    let line = broken(
        "version",
        "<?xml version=\"1.0\"?>",
        "<?xml version=\"1 2\"?>",
    );
    assert!(
        line.contains("toy.urdf:1: the XML declaration says version=\"1 2\""),
        "{line}"
    );
}

#[test]
fn two_links_of_one_name_are_refused() {
    let line = broken(
        "duplicate",
        "<link name=\"tool_tip\"/>",
        "<link name=\"hand\"/>",
    );
    assert!(
        line.contains("a second link named 'hand' (the first is at line 74)"),
        "{line}"
    );
}
