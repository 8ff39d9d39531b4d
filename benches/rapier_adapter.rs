//! kreisel-rapier's `ExactRotation` against rapier3d's own step (`f32`,
//! its default features, one thread), in the same run:
//!
//! ```text
//! cargo bench --bench rapier_adapter
//! cargo test --bench rapier_adapter      # test mode: 100 bodies, one pass
//! ```
//!
//! `rapier_adapter_1k_step_1_60`: 10³ free bodies, each a box collider
//! (half extents 0.1 × 0.2 × 0.3 m scaled by 1 + 0.1 k/N, density 1000:
//! three distinct moments), 10 m apart (no contacts), no gravity, ω₀ =
//! (0.01, 1, 0) rad/s turned by the body's own attitude. One iteration is
//! one frame of 1/60 s: `rapier` is `PhysicsWorld::step()`; `rapier_kreisel`
//! is `ExactRotation::step_world` with every body managed (rapier's step
//! plus the adapter); `rapier_kreisel_2_threads` the same with the
//! adapter's World on two threads. 1/throughput is the time per
//! body-step. The same for 10³ cubes (`…_cubes_…`: uniform rotations, the
//! World's batch) and 10³ cylinders (`…_cylinders_…`: symmetric bodies, two
//! commuting rotations). `manage_1k`: managing the 10³ boxes (one exact
//! solution each), per body.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use kreisel_rapier::ExactRotation;
use rapier3d::prelude::*;

/// criterion's own rule: without `--bench`, or with `--test`, each point
/// runs once (`cargo test --benches`).
fn bodies() -> usize {
    let args: Vec<String> = std::env::args().collect();
    let has = |flag: &str| args.iter().any(|a| a == flag);
    if !has("--bench") || has("--test") {
        100
    } else {
        1000
    }
}

/// The bodies' shapes.
#[derive(Clone, Copy, Debug)]
enum Shape {
    /// Boxes of three different side lengths: asymmetric bodies.
    Boxes,
    /// Cubes (dice): every axis principal, a uniform rotation.
    Cubes,
    /// Cylinders (coins, wheels): symmetric bodies.
    Cylinders,
}

/// A world of `n` free bodies of `shape`, and their handles.
fn world(n: usize, shape: Shape) -> (PhysicsWorld, Vec<RigidBodyHandle>) {
    let mut world = PhysicsWorld::new();
    world.gravity = Vector::ZERO;
    let side = (n as f64).cbrt().ceil() as usize;
    let golden = 0.618_034_f32;
    let handles = (0..n)
        .map(|k| {
            let s = 1.0 + 0.1 * k as f32 / n as f32;
            let (i, j, l) = (k % side, (k / side) % side, k / (side * side));
            let position = Vector::new(i as f32, j as f32, l as f32) * 10.0;
            let axis = Vector::new((k as f32 * golden).fract() - 0.5, 0.3, 0.5).normalize();
            let attitude = Rotation::from_axis_angle(axis, 6.0 * (k as f32 * golden).fract());
            let body = RigidBodyBuilder::dynamic()
                .pose(Pose::from_parts(position, attitude))
                .angvel(attitude * Vector::new(0.01, 1.0, 0.0))
                .can_sleep(false);
            let collider = match shape {
                Shape::Boxes => ColliderBuilder::cuboid(0.1 * s, 0.2 * s, 0.3 * s),
                Shape::Cubes => ColliderBuilder::cuboid(0.2 * s, 0.2 * s, 0.2 * s),
                Shape::Cylinders => ColliderBuilder::cylinder(0.05 * s, 0.3 * s),
            }
            .density(1000.0);
            world.insert(body, collider).0
        })
        .collect();
    (world, handles)
}

fn managed(n: usize, shape: Shape, threads: usize) -> (PhysicsWorld, ExactRotation) {
    let (mut world, handles) = world(n, shape);
    let mut exact = ExactRotation::new();
    exact.set_threads(std::num::NonZeroUsize::new(threads).unwrap());
    for h in handles {
        exact
            .manage(&mut world.bodies, &world.colliders, h)
            .unwrap();
    }
    (world, exact)
}

fn frames(c: &mut Criterion) {
    let n = bodies();
    for (group_name, shape) in [
        ("rapier_adapter_1k_step_1_60", Shape::Boxes),
        ("rapier_adapter_1k_cubes_step_1_60", Shape::Cubes),
        ("rapier_adapter_1k_cylinders_step_1_60", Shape::Cylinders),
    ] {
        let mut group = c.benchmark_group(group_name);
        group.throughput(Throughput::Elements(n as u64));
        let (mut alone, _) = world(n, shape);
        group.bench_function("rapier", |b| b.iter(|| alone.step()));
        for threads in [1, 2] {
            let (mut world, mut exact) = managed(n, shape, threads);
            let name = match threads {
                1 => "rapier_kreisel".to_owned(),
                _ => format!("rapier_kreisel_{threads}_threads"),
            };
            group.bench_function(name, |b| b.iter(|| exact.step_world(&mut world).unwrap()));
        }
        group.finish();
    }
    let mut group = c.benchmark_group("rapier_adapter_setup");
    group.throughput(Throughput::Elements(n as u64));
    group.sample_size(10);
    group.bench_function("manage_1k", |b| b.iter(|| managed(n, Shape::Boxes, 1)));
    group.finish();
}

criterion_group!(benches, frames);
criterion_main!(benches);
