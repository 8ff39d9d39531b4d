//! Vertex welding throughput on STL-like triangle soups (every triangle
//! with its own three corners, as binary STL stores them).
//!
//! ```text
//! cargo run --release -p kreisel-inertia --example weld_throughput [TRIANGLES]
//! ```
//!
//! A closed torus grid of about TRIANGLES triangles (default 2 M) is welded
//! three ways: exact duplicates only, the default relative tolerance on
//! exact duplicates, and the default tolerance with every repeated corner
//! moved by up to 1e-9 of the mesh size (each distinct vertex then has ~5
//! near-duplicates to merge). Prints the best of 5 runs in ns per input
//! vertex (three per triangle), as CPU time of this thread (Linux
//! `/proc/thread-self/schedstat`, so a loaded machine does not inflate it;
//! wall-clock elsewhere), and checks that the weld closed the torus.

use std::time::Instant;

use glam::DVec3;
use kreisel_inertia::{TriMesh, Weld, prepare_solid};

/// A torus grid of `rings × segments` quads as a triangle soup, each
/// repeated corner optionally moved by a deterministic jitter of size `noise`.
fn torus_soup(rings: usize, segments: usize, noise: f64) -> TriMesh {
    let point = |i: usize, j: usize| {
        let (u, v) = (
            (i % rings) as f64 / rings as f64 * std::f64::consts::TAU,
            (j % segments) as f64 / segments as f64 * std::f64::consts::TAU,
        );
        DVec3::new(
            (1.0 + 0.3 * v.cos()) * u.cos(),
            (1.0 + 0.3 * v.cos()) * u.sin(),
            0.3 * v.sin(),
        )
    };
    let mut vertices = Vec::with_capacity(6 * rings * segments);
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut jitter = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for i in 0..rings {
        for j in 0..segments {
            let quad = [
                point(i, j),
                point(i + 1, j),
                point(i + 1, j + 1),
                point(i, j + 1),
            ];
            for k in [0, 1, 2, 0, 2, 3] {
                let d = DVec3::new(jitter(), jitter(), jitter()) * noise;
                vertices.push(quad[k] + d);
            }
        }
    }
    let triangles = (0..vertices.len() as u32 / 3)
        .map(|t| [3 * t, 3 * t + 1, 3 * t + 2])
        .collect();
    TriMesh::new(vertices, triangles)
}

/// CPU time of this thread in ns, if the OS says (else wall-clock).
fn cpu_ns(wall: Instant) -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .unwrap_or_else(|| wall.elapsed().as_secs_f64() * 1e9)
}

fn best_ns_per_vertex(mesh: &TriMesh, weld: Weld) -> (f64, TriMesh) {
    let inputs = mesh.vertices().len() as f64;
    let epoch = Instant::now();
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..5 {
        let copy = mesh.clone();
        let start = cpu_ns(epoch);
        let (welded, _) = copy.welded(weld).expect("valid tolerance");
        best = best.min((cpu_ns(epoch) - start) / inputs);
        out = Some(welded);
    }
    (best, out.expect("five runs"))
}

fn main() {
    let triangles: usize = std::env::args()
        .nth(1)
        .map_or(2_000_000, |s| s.parse().expect("TRIANGLES is a number"));
    let rings = ((triangles / 2) as f64).sqrt().round().max(3.0) as usize;
    let segments = (triangles / 2 / rings).max(3);
    let exact = torus_soup(rings, segments, 0.0);
    let noisy = torus_soup(rings, segments, 1e-9 * 2.6);
    println!(
        "torus soup: {} triangles, {} input vertices, {} distinct",
        exact.triangles().len(),
        exact.vertices().len(),
        rings * segments
    );
    for (label, mesh, weld) in [
        ("exact duplicates, Weld::Exact", &exact, Weld::Exact),
        ("exact duplicates, Weld::default()", &exact, Weld::default()),
        (
            "near duplicates (1e-9), Weld::default()",
            &noisy,
            Weld::default(),
        ),
    ] {
        let (ns, welded) = best_ns_per_vertex(mesh, weld);
        let closed = prepare_solid(welded.clone()).is_ok();
        println!(
            "{label:<42} {ns:6.1} ns per input vertex -> {} vertices, closed: {closed}",
            welded.vertices().len()
        );
    }
}
