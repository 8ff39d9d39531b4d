//! The builds of the solid-integration kernel against each other
//! (`MeshMoments::solid_with`), interleaved so that a noisy machine still
//! gives trustworthy ratios: every round runs each build this CPU supports
//! once on the same mesh (the first build rotates), and the table gives
//! medians of ns per triangle and of the per-round ratios to the portable
//! build.
//!
//! ```text
//! KREISEL_THREADS=1 cargo bench -p kreisel-inertia --bench kernels
//! ```
//!
//! Meshes: closed tori of `2 n²` triangles, ≈ 1k to 1M.

use std::hint::black_box;
use std::time::Instant;

use glam::DVec3;
use kreisel_inertia::{MeshMoments, SolidKernel, TriMesh};

/// A torus (R = 1, r = 0.4) as an `n × n` grid of quads, two triangles each.
fn torus(n: u32) -> TriMesh {
    let angle = |k: u32| std::f64::consts::TAU * f64::from(k) / f64::from(n);
    let mut v = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (u, w) = (angle(i), angle(j));
            let r = 1.0 + 0.4 * w.cos();
            v.push(DVec3::new(r * u.cos(), r * u.sin(), 0.4 * w.sin()));
        }
    }
    let at = |i: u32, j: u32| (i % n) * n + j % n;
    let mut t = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    TriMesh::new(v, t)
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    // `cargo bench` passes `--bench`; a filter argument is not supported.
    let builds = SolidKernel::supported();
    let names: Vec<&str> = builds.iter().map(|k| k.name()).collect();
    println!("ns per triangle (median), and portable / build (median of rounds)");
    let ratio_names: Vec<String> = names.iter().map(|n| format!("portable/{n}")).collect();
    println!(
        "| triangles | {} | {} |",
        names.join(" | "),
        ratio_names.join(" | ")
    );
    for (n, rounds) in [(22, 2000), (70, 200), (224, 40), (707, 10)] {
        let mesh = torus(n);
        let triangles = mesh.triangles().len() as f64;
        let mut times = vec![Vec::new(); builds.len()];
        let mut ratios = vec![Vec::new(); builds.len()];
        for round in 0..rounds {
            let mut this = vec![0.0; builds.len()];
            for k in 0..builds.len() {
                let b = (k + round) % builds.len();
                let start = Instant::now();
                black_box(MeshMoments::solid_with(black_box(&mesh), builds[b]).ok());
                this[b] = start.elapsed().as_secs_f64() * 1e9 / triangles;
            }
            for b in 0..builds.len() {
                times[b].push(this[b]);
                ratios[b].push(this[0] / this[b]);
            }
        }
        let t: Vec<String> = times
            .iter_mut()
            .map(|v| format!("{:.2}", median(v)))
            .collect();
        let r: Vec<String> = ratios
            .iter_mut()
            .map(|v| format!("{:.2}", median(v)))
            .collect();
        println!("| {} | {} | {} |", triangles, t.join(" | "), r.join(" | "));
    }
}
