//! Every build of the solid-integration kernel gives the same bits
//! (issue 25: a fresh clone prints the README's digits on any machine).
//! The builds this CPU runs are compared with the portable one on the
//! meshes in `assets/` and the test fixtures, on the same meshes rotated and
//! moved off the origin (round-off in every coordinate), and on a mesh big
//! enough for several threads; and `KREISEL_KERNEL` is checked to force the
//! build it names, in child processes of this test binary.

use std::path::{Path, PathBuf};
use std::process::Command;

use glam::{DQuat, DVec3};
use kreisel_inertia::io::load_bodies;
use kreisel_inertia::{KERNEL_ENV, KernelError, MeshMoments, SolidKernel, TriMesh};

fn repo_file(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(path)
}

/// The bits of every number in the moments.
fn bits(m: &MeshMoments) -> Vec<u64> {
    let mut v = m.origin.to_array().to_vec();
    v.push(m.zeroth);
    v.extend(m.first.to_array());
    v.extend(m.second.to_cols_array());
    v.into_iter().map(f64::to_bits).collect()
}

/// The bodies of the committed meshes.
fn meshes() -> Vec<(String, TriMesh)> {
    let files = [
        "assets/t_handle.obj",
        "assets/top.stl",
        "assets/top_ascii.stl",
        "crates/inertia/tests/fixtures/cube.obj",
        "crates/inertia/tests/fixtures/two_cubes.obj",
        "crates/inertia/tests/fixtures/cube_binary.stl",
    ];
    let mut out = Vec::new();
    for file in files {
        for body in load_bodies(&repo_file(file)).unwrap() {
            out.push((format!("{file}: {}", body.name), body.mesh));
        }
    }
    out
}

/// `mesh` turned by an irrational rotation and moved far off the origin.
fn moved(mesh: &TriMesh) -> TriMesh {
    let turn = DQuat::from_axis_angle(DVec3::new(0.3, -0.7, 0.6).normalize(), 0.913);
    let offset = DVec3::new(123.456, -78.9, 1.0e3 / 3.0);
    let v = mesh.vertices().iter().map(|&p| turn * p + offset).collect();
    TriMesh::new(v, mesh.triangles().to_vec())
}

/// A torus of `2 n²` triangles.
fn torus(n: u32) -> TriMesh {
    let angle = |k: u32| std::f64::consts::TAU * f64::from(k) / f64::from(n);
    let mut v = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let r = 1.0 + 0.4 * angle(j).cos();
            v.push(DVec3::new(
                r * angle(i).cos(),
                r * angle(i).sin(),
                0.4 * angle(j).sin(),
            ));
        }
    }
    let at = |i: u32, j: u32| (i % n) * n + j % n;
    let mut t = Vec::new();
    for i in 0..n {
        for j in 0..n {
            t.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            t.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    TriMesh::new(v, t)
}

#[test]
fn every_build_gives_the_portable_bits() {
    let mut cases = meshes();
    let turned: Vec<_> = cases
        .iter()
        .map(|(name, mesh)| (format!("{name}, moved"), moved(mesh)))
        .collect();
    cases.extend(turned);
    // 2 × 140² = 39200 triangles: above the threshold for several threads.
    cases.push(("torus of 39200 triangles".into(), torus(140)));
    let builds = SolidKernel::supported();
    assert_eq!(builds[0], SolidKernel::Portable);
    for (name, mesh) in &cases {
        let portable = MeshMoments::solid_with(mesh, SolidKernel::Portable).unwrap();
        assert!(portable.zeroth > 0.0, "{name}");
        assert_eq!(bits(&MeshMoments::solid(mesh)), bits(&portable), "{name}");
        for &kernel in &builds {
            let m = MeshMoments::solid_with(mesh, kernel).unwrap();
            assert_eq!(bits(&m), bits(&portable), "{name}: {kernel} build");
        }
    }
}

#[test]
fn a_build_the_cpu_lacks_is_an_error() {
    let mesh = torus(8);
    for kernel in SolidKernel::ALL {
        let result = MeshMoments::solid_with(&mesh, kernel);
        if kernel.is_supported() {
            assert!(result.is_ok(), "{kernel}");
        } else {
            assert!(
                matches!(result, Err(KernelError::Unsupported { kernel: k, .. }) if k == kernel),
                "{kernel}"
            );
        }
    }
}

/// Run by [`kreisel_kernel_forces_a_build`] in a child process: prints the
/// active build and the T-handle's moments as bits.
#[test]
#[ignore = "run by kreisel_kernel_forces_a_build in a child process"]
fn child_prints_the_active_build() {
    let mesh = &meshes()[0].1;
    let m = MeshMoments::solid(mesh);
    println!("active={} bits={:?}", SolidKernel::active(), bits(&m));
}

/// The line the child prints for `KREISEL_KERNEL=value`.
fn child(value: &str) -> String {
    let out = Command::new(std::env::current_exe().unwrap())
        .args(["--ignored", "--exact", "child_prints_the_active_build"])
        .args(["--nocapture", "--test-threads=1"])
        .env(KERNEL_ENV, value)
        .output()
        .unwrap();
    assert!(out.status.success(), "{value}: {out:?}");
    let stdout = String::from_utf8(out.stdout).unwrap();
    // libtest prints the test's name before the report on the same line.
    let report = stdout
        .lines()
        .find_map(|l| l.find("active=").map(|at| &l[at..]));
    report
        .unwrap_or_else(|| panic!("{value}: no report in {stdout}"))
        .to_owned()
}

#[test]
fn kreisel_kernel_forces_a_build() {
    let portable = child("portable");
    let moments = portable.split_once(" bits=").unwrap().1.to_owned();
    assert_eq!(portable, format!("active=portable bits={moments}"));
    for kernel in SolidKernel::ALL {
        // A build this CPU lacks is never run: the fastest one runs instead.
        let expected = if kernel.is_supported() {
            kernel
        } else {
            SolidKernel::fastest()
        };
        assert_eq!(
            child(kernel.name()),
            format!("active={expected} bits={moments}")
        );
    }
    let fastest = format!("active={} bits={moments}", SolidKernel::fastest());
    assert_eq!(child(""), fastest);
    assert_eq!(child("avx-512"), fastest);
}
