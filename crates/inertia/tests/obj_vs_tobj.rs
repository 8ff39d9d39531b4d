//! Differential test of the OBJ parser against the `tobj` crate (its
//! predecessor): the same bodies, names, vertices (in order of first use per
//! body) and triangles, on the OBJ fixtures and on generated files with
//! groups, negative indices, `v/vt/vn` corners and polygons.
//!
//! `tobj` reads the text reduced to what the loader keeps (`v`, `o`, `g`
//! lines and faces of three or more corners, each corner's position index
//! only; `tobj` would otherwise split vertices by their `vt`/`vn` and start
//! a body per `usemtl`); it resolves negative indices and triangulates
//! itself. Both results go through the same exact weld, the one the loader
//! applies, so what is compared is what the parsers read.

use std::path::Path;

use glam::DVec3;
use kreisel_inertia::io::{LoadOptions, MeshFormat};
use kreisel_inertia::{TriMesh, Weld};

/// `(name, vertices, triangles)` per body.
type Bodies = Vec<(String, Vec<DVec3>, Vec<[u32; 3]>)>;

fn ours(text: &str) -> Bodies {
    let options = LoadOptions {
        weld: Weld::Exact,
        merge: false,
    };
    options
        .load_bytes(text.as_bytes(), MeshFormat::Obj, "file.obj", None)
        .unwrap()
        .into_iter()
        .map(|b| {
            let (v, t) = b.mesh.into_parts();
            (b.name, v, t)
        })
        .collect()
}

/// The text `tobj` reads: see the file header.
fn reduced(text: &str) -> String {
    let mut out = String::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v" | "o" | "g") => out.push_str(line.trim()),
            Some("f") => {
                let corners: Vec<&str> = words.map(|w| w.split('/').next().unwrap_or(w)).collect();
                if corners.len() < 3 {
                    continue;
                }
                out.push_str("f ");
                out.push_str(&corners.join(" "));
            }
            _ => continue,
        }
        out.push('\n');
    }
    out
}

fn theirs(text: &str) -> Bodies {
    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: true,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj_buf(&mut reduced(text).as_bytes(), &options, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .unwrap();
    models
        .into_iter()
        .filter(|m| !m.mesh.indices.is_empty())
        .map(|m| {
            let vertices = m
                .mesh
                .positions
                .chunks_exact(3)
                .map(DVec3::from_slice)
                .collect();
            let triangles = m
                .mesh
                .indices
                .chunks_exact(3)
                .map(|t| [t[0], t[1], t[2]])
                .collect();
            let (mesh, _) = TriMesh::try_new(vertices, triangles)
                .unwrap()
                .welded(Weld::Exact)
                .unwrap();
            let name = if m.name == "unnamed_object" {
                "file".to_owned()
            } else {
                m.name
            };
            let (v, t) = mesh.into_parts();
            (name, v, t)
        })
        .collect()
}

fn assert_same(label: &str, text: &str) {
    let (a, b) = (ours(text), theirs(text));
    assert!(!a.is_empty(), "{label}: no bodies");
    assert_eq!(a, b, "{label}");
}

#[test]
fn fixtures_read_as_tobj_reads_them() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures");
    let mut files = 0;
    for sub in ["", "closed_in_practice"] {
        for entry in std::fs::read_dir(dir.join(sub)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "obj") {
                assert_same(
                    &path.display().to_string(),
                    &std::fs::read_to_string(&path).unwrap(),
                );
                files += 1;
            }
        }
    }
    assert!(files >= 6, "{files} OBJ fixtures");
}

fn lcg(state: &mut u64) -> u64 {
    *state = state
        .wrapping_mul(6_364_136_223_846_793_005)
        .wrapping_add(1_442_695_040_888_963_407);
    *state >> 33
}

/// A file of `groups` groups, each a band of a sphere-like lattice: one
/// `v`/`vt`/`vn` per vertex, faces as triangles, quads and hexagons,
/// corners as `v`, `v/vt`, `v//vn`, `v/vt/vn`, absolute or negative.
fn generated(seed: u64, groups: usize) -> String {
    let mut s = seed;
    let mut text = String::from("# generated\r\nmtllib none.mtl\n");
    let mut count = 0i64;
    for g in 0..groups {
        match g % 3 {
            0 => text.push_str(&format!("o part {g}\n")),
            1 => text.push_str("g\n"),
            _ => text.push_str(&format!("  g  grp{g}  \r\n")),
        }
        let n = 3 + (lcg(&mut s) % 12) as usize;
        for i in 0..n {
            let x = (lcg(&mut s) as f64) / 7.3e8 - 1.0;
            let y = (g * 1000 + i) as f64 * 0.1;
            let z = f64::from(u32::try_from(lcg(&mut s) % 1000).unwrap()) * 1e-3;
            text.push_str(&format!("v {x} {y:e} {z}\nvt 0.5 0.5\nvn 0 0 1\n"));
        }
        let first = count + 1;
        count += n as i64;
        for _ in 0..2 * n {
            let corners = [3, 3, 4, 6][(lcg(&mut s) % 4) as usize];
            text.push_str(if lcg(&mut s).is_multiple_of(2) {
                "f"
            } else {
                "f\t"
            });
            for _ in 0..corners {
                let abs = first + (lcg(&mut s) % n as u64) as i64;
                let idx = if lcg(&mut s).is_multiple_of(3) {
                    abs - count - 1
                } else {
                    abs
                };
                let word = match lcg(&mut s) % 4 {
                    0 => format!("{idx}"),
                    1 => format!("{idx}/{idx}"),
                    2 => format!("{idx}//{idx}"),
                    _ => format!("{idx}/{idx}/{idx}"),
                };
                text.push(' ');
                text.push_str(&word);
            }
            text.push_str(if lcg(&mut s).is_multiple_of(5) {
                "\r\n"
            } else {
                "\n"
            });
        }
        text.push_str("f 1 2\nl 1 2\n");
    }
    text
}

#[test]
fn generated_files_read_as_tobj_reads_them() {
    for seed in 0..40 {
        let text = generated(seed, 1 + (seed as usize % 5));
        assert_same(&format!("seed {seed}:\n{text}"), &text);
    }
}
