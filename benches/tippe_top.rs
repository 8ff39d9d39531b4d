//! Criterion timings of the tippe top on the ground plane
//! (`kreisel::dynamics::GroundTop`): one RK4 step (`GroundTop::try_step`)
//! of Leine & Glocker's top with each friction model, and the whole run to
//! the inversion at dt = 1e-4 s (27 095 steps, where the inversion time is
//! converged to 7e-8 relative at ε = 1 mm/s; `examples/tippe_top_timing.rs`),
//! and the top in a `World` stepped at 1/60 s (error-controlled steps
//! within each frame, the default tolerance).
//!
//! ```text
//! cargo bench --bench tippe_top
//! ```
//!
//! The MuJoCo side by side is `benches/mujoco_tippe_top.py`; both are in
//! `BENCHMARKS.md` ("Tops on a table (issue #17)").

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec3;
use kreisel::dynamics::{Friction, GroundCheck, World};

#[allow(dead_code)]
#[path = "../crates/dynamics/tests/common/tippe_top.rs"]
mod tippe_top;

use tippe_top::leine_glocker;

fn frictions() -> [(&'static str, Friction); 3] {
    [
        ("none", Friction::None),
        ("viscous", Friction::try_viscous(0.3).unwrap()),
        ("sliding_eps1mm", Friction::try_sliding(0.3, 1e-3).unwrap()),
    ]
}

fn step(c: &mut Criterion) {
    let mut group = c.benchmark_group("tippe_top_step");
    group
        .sample_size(20)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .throughput(Throughput::Elements(1));
    for (name, friction) in frictions() {
        let (top, start) = leine_glocker(friction);
        group.bench_with_input(BenchmarkId::from_parameter(name), &start, |b, start| {
            b.iter(|| {
                let mut s = *start;
                top.try_step(&mut s, 0.0, black_box(1e-4)).unwrap();
                s
            })
        });
    }
    // The same sliding top watching its stem's ball for touchdown
    // (`GroundTop::try_with_other_contacts`): the cost of the gap checks.
    let (top, start) = leine_glocker(Friction::try_sliding(0.3, 1e-3).unwrap());
    let top = top.try_with_other_contacts(&[tippe_top::stem()]).unwrap();
    group.bench_with_input(
        BenchmarkId::from_parameter("sliding_eps1mm_stem_watched"),
        &start,
        |b, start| {
            b.iter(|| {
                let mut s = *start;
                top.try_step(&mut s, 0.0, black_box(1e-4)).unwrap();
                s
            })
        },
    );
    // The same sliding top with the guard the World runs after every step
    // (`GroundCheck`, issue 25): its cost over the bare step.
    let (top, start) = leine_glocker(Friction::try_sliding(0.3, 1e-3).unwrap());
    let guard = GroundCheck::new(&top, &start);
    group.bench_with_input(
        BenchmarkId::from_parameter("sliding_eps1mm_guarded"),
        &start,
        |b, start| {
            b.iter(|| {
                let (mut s, mut check) = (*start, guard);
                top.try_step(&mut s, 0.0, black_box(1e-4)).unwrap();
                check.check(&top, &s, 1e-4, 1e-4).unwrap();
                s
            })
        },
    );
    group.finish();
}

fn to_inversion(c: &mut Criterion) {
    let mut group = c.benchmark_group("tippe_top_to_inversion_dt1e-4");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2));
    let (top, start) = leine_glocker(Friction::try_sliding(0.3, 1e-3).unwrap());
    group.bench_function("sliding_eps1mm", |b| {
        b.iter(|| {
            let (mut s, h) = (start, black_box(1e-4));
            let mut n = 0usize;
            while (s.world_from_body.normalize() * DVec3::Z).z > 0.0 {
                top.try_step(&mut s, n as f64 * h, h).unwrap();
                n += 1;
            }
            assert_eq!(n, 27_095, "the inversion moved");
            s
        })
    });
    group.finish();
}

/// The tippe top in a `World` stepped at a game frame, 1/60 s: 240 frames
/// (4 s, through the inversion), each one `World::advance_steps(1)` —
/// error-controlled steps within the frame at the default tolerance
/// (issue 26). Throughput: frames; real-time factor = (1/60 s) / (time
/// per frame). Measured (this machine, shared, load ≈ 4 on 2 cores; 240
/// frames): none 16.1 ms, viscous 16.5 ms (69 µs a frame, real-time factor
/// 240), sliding ε = 1 mm/s 96.8 ms (403 µs a frame, factor 41: the
/// regularised Coulomb law is stiff while the contact nearly sticks); at a
/// tolerance of 1e-10 instead of 1e-11: 10.6, 11.0 and 67.9 ms.
fn world_frames(c: &mut Criterion) {
    let mut group = c.benchmark_group("tippe_top_world_dt_1_60");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(3))
        .throughput(Throughput::Elements(FRAMES));
    for (name, friction) in frictions() {
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut world =
                    World::try_new(DVec3::new(0.0, 0.0, -tippe_top::G), 1.0 / 60.0).unwrap();
                let id = world
                    .add(tippe_top::world_builder(friction).try_build().unwrap())
                    .unwrap();
                for _ in 0..FRAMES {
                    world.advance_steps(1).unwrap();
                }
                world.state(id).unwrap()
            })
        });
    }
    group.finish();
}

/// Frames of 1/60 s in [`world_frames`]: 4 s.
const FRAMES: u64 = 240;

criterion_group!(benches, step, to_inversion, world_frames);
criterion_main!(benches);
