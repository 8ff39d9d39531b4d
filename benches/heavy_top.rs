//! Criterion timings of one step of every heavy-top method on the two fast
//! tops of `tests/data/heavy_top/` (the shared test problems of
//! `crates/dynamics/tests/heavy_top_reference.rs` and `examples/heavy_top_work_precision.rs`):
//! `bruls` (symmetric: exact free flow) and `asymmetric_fast` (PDMV10 free
//! flow), at dt = 1e-3; and the Taylor series (`HeavyTopTaylor::DEFAULT`,
//! `taylor`) and one `state_at` of the closed form of the Lagrange top
//! `bruls` (`HeavyTopClosedForm`, `closed_form`, plus its set-up
//! `closed_form_setup`).
//!
//! ```text
//! cargo bench --bench heavy_top
//! ```
//!
//! One iteration is one step from the same state; 1/throughput is the time
//! per step. The accuracy of each method at this step is in
//! `BENCHMARKS.md` (work-precision table).

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use kreisel::dynamics::{HeavyTopClosedForm, HeavyTopIntegrator, HeavyTopMethod, HeavyTopTaylor};

#[path = "../crates/dynamics/tests/common/heavy_top.rs"]
mod heavy_top;

fn step(c: &mut Criterion) {
    let mut group = c.benchmark_group("heavy_top_step_1ms");
    group
        .sample_size(20)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1))
        .throughput(Throughput::Elements(1));
    for scenario in ["bruls", "asymmetric_fast"] {
        let r = heavy_top::load(scenario);
        for m in HeavyTopMethod::ALL {
            let (name, method) = (m.name(), m.integrator());
            group.bench_with_input(BenchmarkId::new(scenario, name), &r.start, |b, start| {
                b.iter(|| {
                    let mut s = *start;
                    method.step(&r.top, black_box(&mut s), 1e-3);
                    s
                });
            });
        }
        group.bench_with_input(
            BenchmarkId::new(scenario, "taylor"),
            &r.start,
            |b, start| {
                b.iter(|| {
                    let mut s = *start;
                    HeavyTopTaylor::DEFAULT.step(&r.top, black_box(&mut s), 1e-3);
                    s
                });
            },
        );
        if let Ok(closed) = HeavyTopClosedForm::try_new(&r.top, r.start) {
            group.bench_function(BenchmarkId::new(scenario, "closed_form"), |b| {
                b.iter(|| closed.state_at(black_box(1.234)));
            });
            group.bench_function(BenchmarkId::new(scenario, "closed_form_setup"), |b| {
                b.iter(|| HeavyTopClosedForm::try_new(&r.top, black_box(r.start)));
            });
        }
    }
    group.finish();
}

criterion_group!(benches, step);
criterion_main!(benches);
