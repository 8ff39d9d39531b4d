//! URDF, SDFormat and MJCF output of `kreisel inertia` always loads: strict
//! XML whatever the names in the mesh file, and inertia tensors whose
//! printed numbers satisfy the triangle inequality `A + B ≥ C` (which MuJoCo
//! and Gazebo check) even for flat bodies, where `A + B = C` exactly.
//!
//! The flat sheets are `tests/data/flat_shells/` (generator and MuJoCo check:
//! `tests/data/gen/flat_shells.py`; before the fix MuJoCo refused 14 of 40).

use std::path::{Path, PathBuf};
use std::process::Command;

use nalgebra::{Matrix3, SymmetricEigen};

fn kreisel_inertia(path: &Path, args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_kreisel"))
        .arg("inertia")
        .arg(path)
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn sheets() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/flat_shells");
    let mut all: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "obj"))
        .collect();
    all.sort();
    assert_eq!(all.len(), 40);
    all
}

fn numbers(text: &str) -> Vec<f64> {
    text.split_whitespace()
        .map(|t| t.parse().unwrap())
        .collect()
}

/// The tensor of the `<inertial>` element, from the attributes or children
/// each format uses.
fn tensor(format: &str, xml: &str) -> Matrix3<f64> {
    let doc = roxmltree::Document::parse(xml).unwrap_or_else(|e| panic!("{e}: {xml}"));
    let inertial = doc.root_element();
    assert_eq!(inertial.tag_name().name(), "inertial");
    let [xx, xy, xz, yy, yz, zz] = match format {
        "urdf" => {
            let e = inertial
                .children()
                .find(|n| n.has_tag_name("inertia"))
                .unwrap();
            ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]
                .map(|a| e.attribute(a).unwrap().parse().unwrap())
        }
        "sdf" => {
            let e = inertial
                .children()
                .find(|n| n.has_tag_name("inertia"))
                .unwrap();
            ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"].map(|a| {
                let c = e.children().find(|n| n.has_tag_name(a)).unwrap();
                c.text().unwrap().trim().parse().unwrap()
            })
        }
        _ => {
            let v = numbers(inertial.attribute("fullinertia").unwrap());
            [v[0], v[3], v[4], v[1], v[5], v[2]]
        }
    };
    Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz)
}

#[test]
fn flat_shells_satisfy_the_triangle_inequality_as_printed() {
    for path in sheets() {
        for format in ["mjcf", "urdf", "sdf"] {
            let xml = kreisel_inertia(&path, &["--shell", "--format", format]);
            let t = tensor(format, &xml);
            let mut m: Vec<f64> = SymmetricEigen::new(t).eigenvalues.iter().copied().collect();
            m.sort_by(f64::total_cmp);
            let slack = m[0] + m[1] - m[2];
            assert!(
                slack >= 0.0 && m[0] > 0.0,
                "{} {format}: A + B - C = {slack:e} ({m:?})",
                path.display()
            );
            // Snapped within rounding: the moments of a flat sheet still add up.
            assert!(
                slack <= 1e-13 * m[2],
                "{} {format}: {slack:e}",
                path.display()
            );
        }
        // The principal form in the MJCF comment holds the inequality in f64 too.
        let mjcf = kreisel_inertia(&path, &["--shell", "--format", "mjcf"]);
        let diag = mjcf.split("diaginertia=\"").nth(1).unwrap();
        let d = numbers(&diag[..diag.find('"').unwrap()]);
        assert!(d[0] + d[1] >= d[2], "{}: {d:?}", path.display());
    }
}

#[test]
fn control_characters_in_names_give_well_formed_xml() {
    // Regression: an OBJ object name with control characters made invalid
    // URDF/SDF/MJCF (XML 1.0 forbids them even in comments).
    let tet = |name: &str, dx: f64| {
        format!(
            "o {name}\nv {dx} 0 0\nv {} 0 0\nv {dx} 1 0\nv {dx} 0 1\n",
            dx + 1.0
        )
    };
    let obj = format!(
        "{}f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n{}f 5 7 6\nf 5 6 8\nf 5 8 7\nf 6 7 8\n",
        tet("part\u{1}\u{1b}[31m--x\u{7f}-", 0.0),
        tet("other\u{b}\u{c}", 3.0)
    );
    let dir = std::env::temp_dir().join(format!("kreisel-xml-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad--names\u{1}.obj");
    std::fs::write(&path, obj).unwrap();
    for format in ["mjcf", "urdf", "sdf"] {
        let xml = kreisel_inertia(&path, &["--format", format]);
        assert!(xml.contains("assembly of 2 bodies"), "{xml}");
        let doc = roxmltree::Document::parse(&xml).unwrap_or_else(|e| panic!("{e}: {xml:?}"));
        let comments: Vec<&str> = doc
            .root()
            .children()
            .filter(|n| n.is_comment())
            .map(|n| n.text().unwrap())
            .collect();
        assert!(
            comments
                .iter()
                .any(|c| c.contains("part\\u{1}\\u{1b}[31m- -x\\u{7f}-")),
            "{comments:?}"
        );
    }
}
