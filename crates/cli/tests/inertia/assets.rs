//! The demo meshes in `assets/` in every output format.

use crate::support::{attribute, element, inertia, num, numbers, raw_number, rel, workspace};

const ASSETS: [&str; 3] = [
    "assets/t_handle.obj",
    "assets/top.stl",
    "assets/top_ascii.stl",
];

#[test]
fn assets_in_every_format() {
    for asset in ASSETS {
        let path = workspace(asset);
        let json = inertia(&path, &["--format", "json"]);
        assert!(json.stderr.is_empty(), "{asset}: {}", json.stderr);
        let mass = raw_number(&json.stdout, "mass");
        let json = json.json();
        assert!(rel(num(&json["mass"]), mass) <= 1e-15);
        assert!(mass > 0.0, "{asset}");
        let text = inertia(&path, &["--format", "text"]);
        assert_eq!(text.code, Some(0), "{asset}: {}", text.stderr);
        assert!(text.stdout.contains("principal moments"), "{asset}");
        for format in ["urdf", "sdf", "mjcf"] {
            let run = inertia(&path, &["--format", format]);
            assert_eq!(run.code, Some(0), "{asset} {format}: {}", run.stderr);
            assert!(run.stderr.is_empty(), "{asset} {format}: {}", run.stderr);
            let xml = &run.stdout;
            assert!(
                xml.starts_with("<!-- kreisel inertia "),
                "{asset} {format}: {xml}"
            );
            assert!(
                xml.contains(asset.rsplit('/').next().unwrap_or(asset)),
                "{xml}"
            );
            let m = match format {
                "urdf" => numbers(attribute(xml, "value"))[0],
                "sdf" => numbers(element(xml, "mass"))[0],
                _ => numbers(attribute(xml, "mass"))[0],
            };
            assert_eq!(m, mass, "{asset} {format}");
        }
    }
}

#[test]
fn binary_and_ascii_top_agree() {
    let binary = inertia(&workspace("assets/top.stl"), &["--format", "json"]).json();
    let ascii = inertia(&workspace("assets/top_ascii.stl"), &["--format", "json"]).json();
    assert!(rel(num(&binary["mass"]), num(&ascii["mass"])) <= 1e-12);
    assert_eq!(binary["triangles"], ascii["triangles"]);
}
