//! What the fuzz targets run: one function per parser, each asserting the
//! contract "an error, or a result of finite numbers; never a panic".
//!
//! The scene parser comes from the scene layer (`kreisel_scene`), the
//! convert line reader from the CLI's library (`kreisel_cli`). The CLI's
//! test `crates/cli/tests/fuzz/` compiles this file in by path, so the
//! in-CI pass and the fuzz targets check one contract.

use std::path::Path;

use kreisel_inertia::io::{MeshFormat, load_bodies_from_bytes};
use kreisel_inertia::{MassModel, MassProperties, Material, mesh_mass_properties};

use kreisel_cli::convert::Conversion;
use kreisel_scene::representation::Representation;
use kreisel_scene::scene_file;

/// Panics unless every number of `p` is finite (an `Ok` must never hold NaN or inf).
fn assert_finite(p: &MassProperties, what: &str) {
    assert!(
        p.mass.is_finite() && p.center_of_mass.is_finite() && p.inertia.is_finite(),
        "{what}: Ok holding a non-finite value: {p:?}"
    );
}

/// A mesh file: loaded, then every body under the solid, shell and hull models.
pub fn mesh_file(bytes: &[u8], format: MeshFormat) {
    let name = format!("fuzz.{}", format.to_string().to_ascii_lowercase());
    let Ok(bodies) = load_bodies_from_bytes(bytes, format, &name, None) else {
        return;
    };
    for body in bodies {
        for model in [
            MassModel::Solid,
            MassModel::Shell { thickness: 1e-3 },
            MassModel::ConvexHull,
        ] {
            let material = Material::Density(1000.0);
            if let Ok(report) = mesh_mass_properties(body.mesh.clone(), model, material) {
                assert_finite(&report.properties, &format!("{model:?}"));
                let principal = report.properties.principal();
                assert!(
                    principal.moments.is_finite() && principal.axes.is_finite(),
                    "principal axes of {report:?}: {principal:?}"
                );
            }
        }
    }
}

/// A `kreisel simulate` scene file at `path`, parsed (the meshes it names
/// are looked up beside `path`).
pub fn scene_toml(bytes: &[u8], path: &Path) {
    if let Ok(text) = std::str::from_utf8(bytes) {
        let _ = scene_file::parse(path, text);
    }
}

/// The 29 representation names `kreisel convert` accepts, in the order
/// [`convert_lines`] picks them.
pub fn representation_names() -> Vec<String> {
    let mut names: Vec<String> = ["quat", "quat-xyzw", "matrix", "rotvec", "axis-angle"]
        .map(String::from)
        .to_vec();
    for seq in [
        "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ",
    ] {
        names.push(format!("euler:{seq}"));
        names.push(format!("euler:{}", seq.to_ascii_lowercase()));
    }
    names
}

/// The representations of [`representation_names`].
fn representations() -> Vec<Representation> {
    representation_names()
        .iter()
        .map(|n| n.parse().expect("valid representation name"))
        .collect()
}

/// `kreisel convert` lines: the first two bytes pick `--from` and `--to`
/// (and the low bit of the third `--degrees`); every line after them is
/// converted as `convert_stream` does.
pub fn convert_lines(bytes: &[u8]) {
    let [from, to, flags, lines @ ..] = bytes else {
        return;
    };
    let all = representations();
    let conversion = Conversion {
        from: all[usize::from(*from) % all.len()],
        to: all[usize::from(*to) % all.len()],
        degrees: flags & 1 == 1,
    };
    for line in lines.split(|&b| b == b'\n') {
        let Ok(text) = std::str::from_utf8(line) else {
            continue;
        };
        if let Ok(Some(numbers)) = conversion.convert_line(text) {
            assert!(
                numbers.as_slice().iter().all(|x| x.is_finite()),
                "{conversion:?} of {text:?} gave {numbers:?}"
            );
        }
    }
}
