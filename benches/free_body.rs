//! Work–precision of the free-body integrators on rapier's Dzhanibekov
//! scenario (I = (1, 2, 3), ω₀ = (0.01, 1, 0)): criterion times 10 s of
//! simulated motion per method and step size; the attitude error at
//! t = 10 s against the 60-digit reference is printed once per point.
//!
//! ```text
//! cargo bench --bench free_body
//! ```
//!
//! (rapier joins this set with the rapier cross-check, the next increment
//! of issue #4; `examples/free_body_work_precision.rs` prints the table for
//! BENCHMARKS.md.)

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use kreisel::dynamics::{PrincipalState, integrate, method};
use kreisel::kinematics::rotation_angle_between;

#[path = "../tests/common/free_body.rs"]
mod free_body;

fn work_precision(c: &mut Criterion) {
    let r = free_body::load("rapier");
    let (_, q0, l0) = r.samples[0];
    let t_end = 10.0;
    let q_ref = r.samples.iter().find(|s| s.0 == t_end).map_or(q0, |s| s.1);
    let mut group = c.benchmark_group("free_body_rapier_10s");
    for name in [
        "rk4",
        "strang",
        "splitting",
        "splitting4",
        "splitting6",
        "splitting8",
    ] {
        let Ok(m) = method(name) else { continue };
        for steps_per_second in [10u32, 60, 1000] {
            let h = 1.0 / f64::from(steps_per_second);
            let steps = (t_end * f64::from(steps_per_second)) as usize;
            let run = || {
                let mut s = PrincipalState {
                    world_from_principal: q0,
                    l_principal: l0,
                };
                let _ = integrate(m.as_ref(), r.moments, &mut s, h, steps);
                s
            };
            let error = rotation_angle_between(run().world_from_principal, q_ref);
            eprintln!(
                "{name} dt = 1/{steps_per_second}: attitude error at t = {t_end} s: {error:.2e} rad"
            );
            group.throughput(Throughput::Elements(steps as u64));
            group.bench_function(BenchmarkId::new(name, steps_per_second), |b| {
                b.iter(|| black_box(run()))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, work_precision);
criterion_main!(benches);
