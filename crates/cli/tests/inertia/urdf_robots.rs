//! `kreisel inertia --urdf` on the robot items of issue 25 (4): `--check`
//! that could not compare, a filled URDF written to another folder, a
//! negative mass, the JSON report, and the notes' style.

use std::path::{Path, PathBuf};

use serde_json::Value;

use super::support::{mass_of, num};
use super::urdf::{robot_copy, table_row, urdf};

/// A tetrahedron with one face missing (mm): open, its hull closed.
const OPEN_OBJ: &str = "v 0 0 0\nv 10.123456789 0 0\nv 0 10.987654321 0\nv 0 0 10.5555555555\nf 1 3 2\nf 1 2 4\nf 1 4 3\n";

/// The toy robot filled in place (every inertial from its geometry), then
/// the forearm's pyramid swapped for an open mesh; returns the URDF.
fn filled_with_an_open_forearm(name: &str) -> PathBuf {
    let input = robot_copy(name);
    let run = urdf(&input, &["--output", input.to_str().unwrap()]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    std::fs::write(input.parent().unwrap().join("../meshes/open.obj"), OPEN_OBJ).unwrap();
    let text = std::fs::read_to_string(&input).unwrap();
    let from = "../meshes/pyramid.obj\" scale=\"0.001 0.001";
    assert_eq!(text.matches(from).count(), 1);
    std::fs::write(
        &input,
        text.replacen(from, "../meshes/open.obj\" scale=\"0.001 0.001", 1),
    )
    .unwrap();
    input
}

#[test]
fn check_fails_when_a_link_could_not_be_compared() {
    let input = filled_with_an_open_forearm("not_compared");
    let run = urdf(&input, &["--check"]);
    assert_eq!(run.code, Some(1), "{}", run.stderr);
    assert_eq!(
        run.stderr.lines().last().unwrap(),
        "kreisel: error: 1 link(s) not compared, their geometry could not be integrated: forearm (--hull compares open meshes as their convex hulls)"
    );
    let summary = run.stderr.lines().rev().nth(1).unwrap();
    assert!(
        summary.contains(": 6 links, 0 fail, 1 not compared"),
        "{summary}"
    );
    let row = table_row(&run.stderr, "forearm");
    assert!(
        row.contains("not compared") && row.contains("mesh is open"),
        "{row}"
    );
    // The others still pass.
    for name in ["base_link", "arm", "hand"] {
        assert!(table_row(&run.stderr, name).contains(" ok"), "{name}");
    }
    // With --hull the open mesh is compared (as its hull: no longer "not compared").
    let hull = urdf(&input, &["--check", "--hull"]);
    let row = table_row(&hull.stderr, "forearm");
    assert!(!row.contains("not compared"), "{row}");
    assert!(!hull.stderr.contains("not compared"), "{}", hull.stderr);
}

#[test]
fn notes_name_meshes_as_written_with_short_numbers() {
    let input = filled_with_an_open_forearm("notes");
    let run = urdf(&input, &["--check"]);
    let row = table_row(&run.stderr, "forearm");
    let scratch = input.parent().unwrap().parent().unwrap().to_str().unwrap();
    assert!(!row.contains(scratch), "no resolved path: {row}");
    assert!(row.contains("../meshes/open.obj: body"), "{row}");
    // Every decimal number in one style: at most six significant digits, no
    // padded exponent (`0e0`) or zeros before the digits.
    let mut decimals = 0;
    for token in row.split(|c: char| c.is_whitespace() || ",;()".contains(c)) {
        let token = token.trim_end_matches(['.', '%']);
        if token.parse::<f64>().is_ok() && token.contains(['.', 'e']) {
            decimals += 1;
            let mantissa = token.trim_start_matches('-').split('e').next().unwrap();
            let digits = mantissa.replace('.', "");
            let significant = digits.trim_start_matches('0').len();
            assert!(significant <= 6, "{token} in {row}");
            assert!(
                !token.ends_with("e0") && !mantissa.starts_with("0.0000"),
                "{token}"
            );
        }
    }
    assert!(decimals >= 2, "the open edge's point is in the note: {row}");
}

/// The `filename` of every `<mesh>` in `text`, in order.
fn mesh_names(text: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(text).expect("XML");
    doc.descendants()
        .filter(|n| n.has_tag_name("mesh"))
        .map(|n| n.attribute("filename").unwrap().to_owned())
        .collect()
}

#[test]
fn relative_mesh_paths_load_from_the_output_folder() {
    let input = robot_copy("relocate");
    let root = input.ancestors().nth(3).unwrap().to_path_buf();
    let elsewhere = root.join("elsewhere/deeper");
    std::fs::create_dir_all(&elsewhere).unwrap();
    let output = elsewhere.join("filled.urdf");
    let run = urdf(&input, &["--output", output.to_str().unwrap()]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert!(
        run.stderr.contains("2 relative mesh path(s) rewritten"),
        "{}",
        run.stderr
    );
    let before = mesh_names(&std::fs::read_to_string(&input).unwrap());
    let written = std::fs::read_to_string(&output).unwrap();
    let after = mesh_names(&written);
    assert_eq!(before.len(), after.len());
    let real = |dir: &Path, name: &str| std::fs::canonicalize(dir.join(name)).unwrap();
    let mut relative = 0;
    for (old, new) in before.iter().zip(&after) {
        if old.starts_with("package://") {
            assert_eq!(old, new, "package URIs are kept");
        } else {
            relative += 1;
            assert_ne!(old, new);
            assert!(Path::new(new).is_relative(), "{new}");
            assert_eq!(
                real(input.parent().unwrap(), old),
                real(&elsewhere, new),
                "{old} -> {new}"
            );
        }
    }
    assert_eq!(relative, 2);
    // The written file loads from where it is: filling it again changes nothing.
    let again = urdf(&output, &[]);
    assert_eq!(again.code, Some(0), "{}", again.stderr);
    assert_eq!(again.stdout, written);
    // Beside the input, nothing is rewritten.
    let beside = input.with_file_name("beside.urdf");
    let run = urdf(&input, &["--output", beside.to_str().unwrap()]);
    assert!(!run.stderr.contains("rewritten"), "{}", run.stderr);
    assert_eq!(
        mesh_names(&std::fs::read_to_string(&beside).unwrap()),
        before
    );
}

#[test]
fn a_negative_mass_is_refilled_and_said_so() {
    let input = robot_copy("negative");
    let text = std::fs::read_to_string(&input).unwrap();
    let mass = |value: &str| {
        std::fs::write(&input, text.replacen("<mass value=\"2.5\"/>", value, 1)).unwrap();
        urdf(&input, &[])
    };
    let negative = mass("<mass value=\"-3\"/>");
    assert_eq!(negative.code, Some(0), "{}", negative.stderr);
    let row = table_row(&negative.stderr, "forearm");
    assert!(
        row.contains("was mass -3 (negative, unphysical), now density x volume"),
        "{row}"
    );
    // The same mass as a link without one: density x volume.
    let absent = mass("");
    assert_eq!(
        mass_of(&negative.stdout, "forearm"),
        mass_of(&absent.stdout, "forearm")
    );
    assert!(!table_row(&absent.stderr, "forearm").contains("negative"));
}

#[test]
fn json_report_of_a_check() {
    let input = filled_with_an_open_forearm("json_check");
    let run = urdf(&input, &["--check", "--format", "json"]);
    assert_eq!(run.code, Some(1), "{}", run.stderr);
    assert_eq!(
        run.stderr.lines().collect::<Vec<_>>(),
        [
            "kreisel: error: 1 link(s) not compared, their geometry could not be integrated: forearm (--hull compares open meshes as their convex hulls)"
        ],
        "the table is replaced by the report"
    );
    let report: Value = serde_json::from_str(&run.stdout).expect("JSON");
    assert_eq!(report["mode"], "check");
    assert_eq!(report["urdf"], input.to_str().unwrap());
    let links = report["links"].as_array().unwrap();
    let names: Vec<&str> = links.iter().map(|l| l["name"].as_str().unwrap()).collect();
    assert_eq!(
        names,
        ["base_link", "arm", "forearm", "hand", "tool_tip", "sensor"]
    );
    let link = |name: &str| links.iter().find(|l| l["name"] == name).unwrap();
    assert_eq!(link("arm")["check"], "ok");
    assert_eq!(link("forearm")["check"], "not compared");
    assert_eq!(link("tool_tip")["check"], "not checked");
    assert!(link("forearm")["tensor_diff"].is_null());
    assert!(
        num(&link("arm")["tensor_diff"]) < 1e-9,
        "a filled link matches"
    );
    assert_eq!(link("arm")["inertia"].as_array().unwrap().len(), 3);
    let summary = &report["summary"];
    assert_eq!(
        (summary["fail"].as_u64(), summary["not_compared"].as_u64()),
        (Some(0), Some(1))
    );
    assert_eq!(summary["exit_status"].as_u64(), Some(1));
}

#[test]
fn json_report_of_a_fill() {
    let input = robot_copy("json_fill");
    let output = input.with_file_name("filled.urdf");
    let run = urdf(
        &input,
        &["--format", "json", "--output", output.to_str().unwrap()],
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert!(run.stderr.is_empty(), "{}", run.stderr);
    let report: Value = serde_json::from_str(&run.stdout).expect("JSON");
    assert_eq!(report["mode"], "fill");
    let written = std::fs::read_to_string(&output).unwrap();
    for link in report["links"].as_array().unwrap() {
        let name = link["name"].as_str().unwrap();
        match link["action"].as_str().unwrap() {
            "filled" => assert_eq!(num(&link["mass"]), mass_of(&written, name), "{name}"),
            "unchanged" => assert!(link["mass"].is_null(), "{name}"),
            other => panic!("{name}: {other}"),
        }
    }
    assert_eq!(report["summary"]["filled"].as_u64(), Some(4));
    assert_eq!(report["summary"]["exit_status"].as_u64(), Some(0));
    // Without --output the URDF would need standard output: refused.
    for args in [&["--format", "json"][..], &["--format", "urdf"]] {
        let run = urdf(&input, args);
        let line = run.error_line(1);
        assert!(line.starts_with("kreisel: error: --format: "), "{line}");
    }
}
