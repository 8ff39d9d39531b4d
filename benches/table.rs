//! Criterion timings of the nonsmooth table (`kreisel::dynamics::TableMotion`,
//! issue 26) on the shared test problems: Leine & Glocker's tippe top with
//! its stem (Coulomb–Contensou friction, plastic impacts) run for 8 s of
//! game frames (480 calls of 1/60 s) at two tolerances, and a ball dropped
//! from 1 m with e = 0.9 run to rest (≈ 130 bounces, the Zeno point).
//!
//! ```text
//! cargo bench --bench table
//! ```
//!
//! The real-time factor is 8 s over the measured time; the MuJoCo side by
//! side is `benches/mujoco_table.py` (BENCHMARKS.md, "Tops on a table,
//! start to finish (issue #26)").

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};

#[allow(dead_code)]
#[path = "../crates/dynamics/tests/common/tippe_top.rs"]
mod tippe_top;

use tippe_top::{contensou_law, table_motion};

#[allow(dead_code)]
#[path = "../crates/dynamics/tests/common/bouncing_ball.rs"]
mod bouncing_ball;

use bouncing_ball::dropped_ball;

fn tippe_top_frames(c: &mut Criterion) {
    let mut group = c.benchmark_group("table_tippe_top_stem_8s_at_1_60");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    for rtol in [1e-8, 1e-9, 1e-10] {
        group.bench_function(format!("rtol_{rtol:e}"), |b| {
            b.iter(|| {
                let mut run = table_motion(contensou_law(), black_box(rtol));
                for frame in 1..=480 {
                    run.try_advance_to(f64::from(frame) / 60.0).unwrap();
                }
                run
            })
        });
    }
    group.finish();
}

fn ball_to_rest(c: &mut Criterion) {
    let mut group = c.benchmark_group("table_ball_e0.9_to_rest");
    group.sample_size(20);
    group.bench_function("rtol_1e-12", |b| {
        b.iter(|| {
            let mut run = dropped_ball(black_box(1e-12));
            run.try_advance_to(10.0).unwrap();
            assert!(run.is_resting());
            run
        })
    });
    group.finish();
}

criterion_group!(benches, tippe_top_frames, ball_to_rest);
criterion_main!(benches);
