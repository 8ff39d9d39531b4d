//! `kreisel inertia --urdf` on the committed toy robot
//! (tests/data/robot/, from tests/data/gen/urdf_robot.py): every filled
//! inertial against the exact reference, the rest of the file byte for
//! byte, and `--check` on the filled file and on one with a wrong inertial.

use std::path::{Path, PathBuf};

use glam::DVec3;
use serde_json::Value;

use super::support::{Run, num, run, workspace};

/// Largest relative error accepted against the exact reference.
const TOLERANCE: f64 = 1e-12;

/// A fresh copy of the toy robot package in the scratch directory `name`;
/// returns the copied URDF.
pub fn robot_copy(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("kreisel-cli-urdf")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    let source = workspace("tests/data/robot/toy_robot");
    for sub in ["urdf", "meshes"] {
        let to = dir.join("toy_robot").join(sub);
        std::fs::create_dir_all(&to).expect("scratch dir");
        for entry in std::fs::read_dir(source.join(sub)).expect("robot files") {
            let entry = entry.expect("robot file");
            std::fs::copy(entry.path(), to.join(entry.file_name())).expect("copy");
        }
    }
    dir.join("toy_robot/urdf/toy.urdf")
}

/// The row of link `name` in the table on standard error.
pub fn table_row<'a>(stderr: &'a str, name: &str) -> &'a str {
    stderr
        .lines()
        .find(|l| l.split_whitespace().next() == Some(name))
        .unwrap_or_else(|| panic!("no table row for {name} in {stderr}"))
}

/// Runs `kreisel inertia --urdf URDF ARGS...`.
pub fn urdf(path: &Path, args: &[&str]) -> Run {
    let path = path.to_str().expect("test paths are UTF-8");
    let mut all = vec!["inertia", "--urdf", path];
    all.extend_from_slice(args);
    run::kreisel(&all, Vec::new())
}

/// The numbers of an attribute.
fn numbers(node: roxmltree::Node, name: &str) -> Vec<f64> {
    node.attribute(name)
        .unwrap_or_else(|| panic!("no {name}"))
        .split_whitespace()
        .map(|w| w.parse().expect("a number"))
        .collect()
}

/// The `<inertial>` of link `name`: (mass, com, [ixx ixy ixz iyy iyz izz]).
fn inertial(doc: &roxmltree::Document, name: &str) -> Option<(f64, DVec3, Vec<f64>)> {
    let link = doc
        .descendants()
        .find(|n| n.has_tag_name("link") && n.attribute("name") == Some(name))
        .unwrap_or_else(|| panic!("no link {name}"));
    let inertial = link.children().find(|n| n.has_tag_name("inertial"))?;
    let child = |tag: &str| {
        inertial
            .children()
            .find(|n| n.has_tag_name(tag))
            .unwrap_or_else(|| panic!("{name}: no <{tag}>"))
    };
    let origin = child("origin");
    assert_eq!(numbers(origin, "rpy"), [0.0; 3], "{name}");
    let c = numbers(origin, "xyz");
    let i = child("inertia");
    let six = ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]
        .iter()
        .map(|k| numbers(i, k)[0])
        .collect();
    Some((
        numbers(child("mass"), "value")[0],
        DVec3::new(c[0], c[1], c[2]),
        six,
    ))
}

/// The text without its `<inertial>` elements (and the whitespace before
/// each, back to the line break).
fn without_inertials(text: &str) -> String {
    let doc = roxmltree::Document::parse(text).expect("valid XML");
    let mut ranges: Vec<_> = doc
        .descendants()
        .filter(|n| n.has_tag_name("inertial"))
        .map(|n| n.range())
        .collect();
    ranges.sort_by_key(|r| r.start);
    let mut out = String::new();
    let mut done = 0;
    for r in ranges {
        let before = &text[done..r.start];
        let trimmed = before.trim_end_matches([' ', '\t']);
        out.push_str(trimmed.strip_suffix('\n').unwrap_or(trimmed));
        done = r.end;
    }
    out.push_str(&text[done..]);
    out
}

fn expected() -> Value {
    let text = std::fs::read_to_string(workspace("tests/data/robot/expected.json"))
        .expect("expected.json");
    serde_json::from_str(&text).expect("valid JSON")
}

/// Fills the toy robot into `filled.urdf` beside it; returns its path and the run.
fn fill(name: &str) -> (PathBuf, Run) {
    let input = robot_copy(name);
    let output = input.with_file_name("filled.urdf");
    let run = urdf(&input, &["--output", output.to_str().unwrap()]);
    (output, run)
}

/// Asserts that the links `names` of the filled `text` hold the reference
/// inertials `want` (to [`TOLERANCE`]) and that the table on `stderr` names
/// their mass source.
fn assert_reference(text: &str, stderr: &str, want: &Value, names: &[&str]) {
    let doc = roxmltree::Document::parse(text).expect("the output is XML");
    for &name in names {
        let want = &want[name];
        let (mass, com, six) =
            inertial(&doc, name).unwrap_or_else(|| panic!("{name}: no inertial"));
        let list =
            |key: &str| -> Vec<f64> { want[key].as_array().unwrap().iter().map(num).collect() };
        let want_com = DVec3::from_slice(&list("com"));
        let want_six = list("inertia");
        let want_mass = num(&want["mass"]);
        // Lengths relative to the body's size (its centre of mass may be at 0).
        let size = (want_mass / num(&want["density"])).cbrt();
        let scale = want_six.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let e_mass = (mass - want_mass).abs() / want_mass;
        let e_com = (com - want_com).length() / want_com.length().max(size);
        let e_tensor = six
            .iter()
            .zip(&want_six)
            .fold(0.0_f64, |a, (x, y)| a.max((x - y).abs()))
            / scale;
        println!(
            "{name}: relative errors mass {e_mass:.1e}, com {e_com:.1e}, tensor {e_tensor:.1e}"
        );
        assert!(
            e_mass <= TOLERANCE && e_com <= TOLERANCE && e_tensor <= TOLERANCE,
            "{name}: mass {e_mass:e}, com {e_com:e}, tensor {e_tensor:e}"
        );
        let line = table_row(stderr, name);
        assert_eq!(
            line.contains("mass kept, density derived"),
            want["mass_source"] == "kept",
            "{line}"
        );
        assert_eq!(
            line.contains("was mass 0 (static in pybullet), now has mass"),
            name == "arm",
            "{line}"
        );
    }
}

#[test]
fn filled_inertials_equal_the_exact_reference() {
    let (output, run) = fill("exact");
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert!(run.stdout.is_empty());
    let text = std::fs::read_to_string(&output).expect("output written");
    let reference = expected();
    let names: Vec<&str> = reference["links"]
        .as_object()
        .expect("links")
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(names.len(), 4);
    assert_reference(&text, &run.stderr, &reference["links"], &names);
}

#[test]
fn visual_geometry_on_request() {
    let input = robot_copy("visual");
    let run = urdf(&input, &["--from", "visual"]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let reference = expected();
    assert_reference(
        &run.stdout,
        &run.stderr,
        &reference["visual"],
        &["base_link", "arm"],
    );
    // The forearm has no visual geometry: its inertial is unchanged.
    assert!(
        run.stdout
            .contains("<inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\"")
    );
    let row = table_row(&run.stderr, "forearm");
    assert!(
        row.ends_with("no <visual> geometry: inertial unchanged"),
        "{row}"
    );
}

#[test]
fn convex_meshes_are_their_own_hulls() {
    // The wedge and the pyramid (mirrored, stretched) are convex: --hull
    // gives their exact values too.
    let input = robot_copy("hull");
    let run = urdf(&input, &["--hull"]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let reference = expected();
    assert_reference(
        &run.stdout,
        &run.stderr,
        &reference["links"],
        &["base_link", "arm", "hand"],
    );
}

#[test]
fn only_the_inertials_change() {
    let (output, run) = fill("bytes");
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let input = std::fs::read_to_string(output.with_file_name("toy.urdf")).unwrap();
    let text = std::fs::read_to_string(&output).unwrap();
    assert_eq!(without_inertials(&text), without_inertials(&input));
    // The links without collision geometry keep their inertial (or none).
    let doc = roxmltree::Document::parse(&text).unwrap();
    let before = roxmltree::Document::parse(&input).unwrap();
    for name in expected()["untouched"].as_array().unwrap() {
        let name = name.as_str().unwrap();
        let find = |d: &roxmltree::Document| {
            d.descendants()
                .find(|n| n.has_tag_name("link") && n.attribute("name") == Some(name))
                .map(|n| text_of(d, n))
        };
        assert_eq!(find(&doc), find(&before), "{name}");
    }
    // Filling the filled file again changes nothing but the last digits of
    // the kept masses' links (the masses are now all kept).
    let again = urdf(&output, &[]);
    assert_eq!(again.code, Some(0), "{}", again.stderr);
    let doc2 = roxmltree::Document::parse(&again.stdout).unwrap();
    for name in ["base_link", "arm", "forearm", "hand"] {
        let (m1, c1, _) = inertial(&doc, name).unwrap();
        let (m2, c2, _) = inertial(&doc2, name).unwrap();
        assert!(
            (m1 - m2).abs() <= 1e-15 * m1 && (c1 - c2).length() <= 1e-15,
            "{name}"
        );
    }
}

/// The source text of a node.
fn text_of(doc: &roxmltree::Document, node: roxmltree::Node) -> String {
    doc.input_text()[node.range()].to_owned()
}

#[test]
fn stdout_output_equals_the_file() {
    let (output, _) = fill("stdout");
    let run = urdf(&output.with_file_name("toy.urdf"), &["--from", "collision"]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert_eq!(run.stdout, std::fs::read_to_string(&output).unwrap());
}

#[test]
fn check_passes_on_the_filled_file_and_names_a_wrong_link() {
    let (output, run) = fill("check");
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let ok = urdf(&output, &["--check"]);
    assert_eq!(ok.code, Some(0), "{}", ok.stderr);
    assert!(ok.stdout.is_empty());
    for name in ["base_link", "arm", "forearm", "hand"] {
        let line = table_row(&ok.stderr, name);
        assert!(line.split_whitespace().any(|w| w == "ok"), "{line}");
    }
    // One wrong tensor element: the arm's ixx doubled.
    let text = std::fs::read_to_string(&output).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let (_, _, six) = inertial(&doc, "arm").unwrap();
    let arm = doc
        .descendants()
        .find(|n| n.has_tag_name("link") && n.attribute("name") == Some("arm"))
        .unwrap();
    let ixx = arm
        .descendants()
        .find(|n| n.has_tag_name("inertia"))
        .and_then(|n| n.attribute("ixx"))
        .unwrap();
    let old = format!("ixx=\"{ixx}\"");
    assert_eq!(text.matches(&old).count(), 1, "{old}");
    let wrong = output.with_file_name("wrong.urdf");
    std::fs::write(
        &wrong,
        text.replace(&old, &format!("ixx=\"{}\"", 2.0 * six[0])),
    )
    .unwrap();
    let bad = urdf(&wrong, &["--check"]);
    assert_eq!(bad.code, Some(1), "{}", bad.stderr);
    let last = bad.stderr.lines().last().unwrap();
    assert_eq!(last, "kreisel: error: 1 link(s) fail the check: arm");
    let row = table_row(&bad.stderr, "arm");
    assert!(
        row.contains("FAIL") && row.contains("tensor differs by"),
        "{row}"
    );
    // With an explicit density the kept mass of the forearm (2.5 kg on a few
    // cm^3) is far from density x volume.
    let dense = urdf(&output, &["--check", "--density", "1000"]);
    assert_eq!(
        dense.stderr.lines().last().unwrap(),
        "kreisel: error: 1 link(s) fail the check: forearm",
        "{}",
        dense.stderr
    );
}

#[test]
fn check_states_its_tolerances_in_the_help() {
    let help = run::kreisel(&["inertia", "--help"], Vec::new());
    assert_eq!(help.code, Some(0));
    for text in [
        "more than 10%",
        "5% of the geometry's bounding-box",
        "> 0.2",
        "--urdf <ROBOT.urdf>",
    ] {
        assert!(help.stdout.contains(text), "{text}: {}", help.stdout);
    }
}

#[test]
fn a_forgotten_mesh_scale_is_a_warning() {
    let input = robot_copy("unscaled");
    let text = std::fs::read_to_string(&input).unwrap();
    let from = "meshes/wedge.stl\" scale=\"0.001 0.001 0.001\"";
    assert_eq!(text.matches(from).count(), 1);
    std::fs::write(&input, text.replace(from, "meshes/wedge.stl\"")).unwrap();
    for args in [&[][..], &["--check"]] {
        let run = urdf(&input, args);
        let row = table_row(&run.stderr, "arm");
        assert!(
            row.contains("m across, implausible for a link: is each mesh's scale right?"),
            "{args:?}: {row}"
        );
    }
}

#[test]
fn filling_in_place_replaces_the_input_whole() {
    let input = robot_copy("in_place");
    let path = input.to_str().unwrap();
    let run = urdf(&input, &["--output", path]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let check = urdf(&input, &["--check"]);
    assert_eq!(check.code, Some(0), "{}", check.stderr);
    let dir: Vec<_> = std::fs::read_dir(input.parent().unwrap())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(dir, ["toy.urdf"], "no temporary file left");
}

/// `R = Rz(yaw) Ry(pitch) Rx(roll)`, multiplied out here (URDF's rpy).
fn rpy_matrix(rpy: &[f64]) -> glam::DMat3 {
    let (sr, cr) = rpy[0].sin_cos();
    let (sp, cp) = rpy[1].sin_cos();
    let (sy, cy) = rpy[2].sin_cos();
    let rx = glam::DMat3::from_cols_array(&[1.0, 0.0, 0.0, 0.0, cr, sr, 0.0, -sr, cr]);
    let ry = glam::DMat3::from_cols_array(&[cp, 0.0, -sp, 0.0, 1.0, 0.0, sp, 0.0, cp]);
    let rz = glam::DMat3::from_cols_array(&[cy, sy, 0.0, -sy, cy, 0.0, 0.0, 0.0, 1.0]);
    rz * ry * rx
}

#[test]
fn principal_form_rebuilds_the_exact_tensors() {
    let input = robot_copy("principal");
    for (digits, tolerance) in [(None, TOLERANCE), (Some("5"), 1e-4)] {
        let mut args = vec!["--principal"];
        args.extend(digits.iter().flat_map(|d| ["--digits", *d]));
        let run = urdf(&input, &args);
        assert_eq!(run.code, Some(0), "{}", run.stderr);
        let doc = roxmltree::Document::parse(&run.stdout).expect("the output is XML");
        let reference = expected();
        for (name, want) in reference["links"].as_object().expect("links") {
            let link = doc
                .descendants()
                .find(|n| n.has_tag_name("link") && n.attribute("name") == Some(name))
                .expect("the link");
            let inertial = link
                .children()
                .find(|n| n.has_tag_name("inertial"))
                .unwrap();
            let child = |tag: &str| inertial.children().find(|n| n.has_tag_name(tag)).unwrap();
            let i = child("inertia");
            let value = |k: &str| numbers(i, k)[0];
            assert_eq!(
                [value("ixy"), value("ixz"), value("iyz")],
                [0.0; 3],
                "{name}"
            );
            let diag =
                glam::DMat3::from_diagonal(DVec3::new(value("ixx"), value("iyy"), value("izz")));
            let r = rpy_matrix(&numbers(child("origin"), "rpy"));
            let full = r * diag * r.transpose();
            let got = [
                full.x_axis.x,
                full.y_axis.x,
                full.z_axis.x,
                full.y_axis.y,
                full.z_axis.y,
                full.z_axis.z,
            ];
            let want_six: Vec<f64> = want["inertia"]
                .as_array()
                .unwrap()
                .iter()
                .map(num)
                .collect();
            let scale = want_six.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
            let error = got
                .iter()
                .zip(&want_six)
                .fold(0.0_f64, |a, (x, y)| a.max((x - y).abs()))
                / scale;
            println!("{name} principal (digits {digits:?}): tensor relative error {error:.1e}");
            assert!(error <= tolerance, "{name}: {error:e} (digits {digits:?})");
        }
    }
}
