//! Mass properties of triangle meshes: kreisel's exact integration against
//! parry3d's `MassProperties::from_trimesh`, on the same UV spheres of 1k to
//! 5M triangles, in one run.
//!
//! ```text
//! cargo bench --bench inertia
//! ```
//!
//! Criterion's throughput line gives triangles per second; BENCHMARKS.md
//! reports ns per triangle.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use kreisel::inertia::{MeshMoments, TriMesh, to_parry};
use parry3d_f64::mass_properties::MassProperties as ParryMassProperties;

#[path = "../tests/common/shapes.rs"]
mod shapes;

/// Segment counts giving ≈ 1k, 10k, 100k, 1M and 5M triangles (n² each).
const SEGMENTS: [usize; 5] = [32, 100, 316, 1000, 2236];

fn mesh_mass_properties(c: &mut Criterion) {
    let mut group = c.benchmark_group("mesh_mass_properties");
    for n in SEGMENTS {
        let mesh: TriMesh = shapes::sphere(1.0, n);
        let triangles = mesh.triangles().len();
        let points: Vec<_> = mesh.vertices().iter().map(|&v| to_parry(v)).collect();
        group.throughput(Throughput::Elements(triangles as u64));
        if triangles > 200_000 {
            group.sample_size(10);
        }
        group.bench_with_input(BenchmarkId::new("kreisel", triangles), &mesh, |b, mesh| {
            b.iter(|| MeshMoments::solid(black_box(mesh)).mass_properties(1.0))
        });
        group.bench_with_input(BenchmarkId::new("parry", triangles), &mesh, |b, mesh| {
            b.iter(|| ParryMassProperties::from_trimesh(1.0, black_box(&points), mesh.triangles()))
        });
    }
    group.finish();
}

criterion_group!(benches, mesh_mass_properties);
criterion_main!(benches);
