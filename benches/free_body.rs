//! Work–precision set of the free-body integrators and rapier3d-f64 on
//! rapier's Dzhanibekov scenario (I = (1, 2, 3), ω₀ = (0.01, 1, 0), 100 s),
//! in one criterion run: every registered method
//! (`kreisel::dynamics::FreeBodyMethod::ALL` except `auto`, whatever the list holds)
//! and rapier, at dt = 1/10, 1/20, 1/60, 1/100, 1/1000. The attitude error
//! at t = 100 s against the 60-digit reference is printed once per point
//! (stderr); criterion times the run.
//!
//! ```text
//! cargo bench --bench free_body
//! cargo bench --bench free_body -- rapier      # only rapier's points
//! ```
//!
//! - kreisel point `free_body_rapier_100s/METHOD/STEPS_PER_SECOND`: one
//!   iteration integrates the whole 100 s of one body; criterion's
//!   throughput is in steps, so 1/throughput is the time per step. A point
//!   whose one run takes over 1 s is skipped (printed as such).
//! - rapier point `free_body_rapier_100s/rapier_1000_bodies/STEPS_PER_SECOND`:
//!   one iteration is 10 steps of a world of 1000 identical bodies (full
//!   `PhysicsWorld::step` pipeline, one thread, `tests/common/rapier.rs`);
//!   throughput in body-steps, so 1/throughput is the time per body-step.
//!   Its error comes from a one-body world run over the whole 100 s.
//!
//! Sample size 10 and 1 s of measurement per point keep the whole set to
//! a few minutes. `examples/free_body_work_precision.rs` prints the same
//! set as the Markdown table and CSV of BENCHMARKS.md.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use kreisel::dynamics::{FreeBodyMethod, PrincipalState, integrate};
use kreisel::kinematics::rotation_angle_between;

#[path = "../crates/dynamics/tests/common/free_body.rs"]
mod free_body;
#[path = "../tests/common/rapier.rs"]
mod rapier;

const STEPS_PER_SECOND: [u32; 5] = [10, 20, 60, 100, 1000];
/// Points whose one run takes longer than this are skipped.
const TOO_LONG: Duration = Duration::from_secs(1);
const RAPIER_BODIES: usize = 1000;
const RAPIER_STEPS_PER_ITER: usize = 10;

fn work_precision(c: &mut Criterion) {
    let r = free_body::load("rapier");
    let (_, q0, l0) = r.samples[0];
    let &(t_end, q_ref, _) = r.samples.last().unwrap_or(&r.samples[0]);
    let mut group = c.benchmark_group("free_body_rapier_100s");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    for method in FreeBodyMethod::ALL
        .into_iter()
        .filter(|&m| m != FreeBodyMethod::Auto)
    {
        let (name, m) = (method.name(), method.integrator());
        for steps_per_second in STEPS_PER_SECOND {
            let h = 1.0 / f64::from(steps_per_second);
            let steps = (t_end * f64::from(steps_per_second)).round() as usize;
            let run = || {
                let mut s = PrincipalState {
                    world_from_principal: q0,
                    l_principal: l0,
                };
                let _ = integrate(m, r.moments, &mut s, h, steps);
                s
            };
            let start = Instant::now();
            let error = rotation_angle_between(run().world_from_principal, q_ref);
            let once = start.elapsed();
            if once > TOO_LONG {
                eprintln!(
                    "{name} dt = 1/{steps_per_second}: attitude error at t = {t_end} s: \
                     {error:.2e} rad (not timed: one run takes {once:.1?})"
                );
                continue;
            }
            eprintln!(
                "{name} dt = 1/{steps_per_second}: attitude error at t = {t_end} s: {error:.2e} rad"
            );
            group.throughput(Throughput::Elements(steps as u64));
            group.bench_function(BenchmarkId::new(name, steps_per_second), |b| {
                b.iter(|| black_box(run()))
            });
        }
    }
    for steps_per_second in STEPS_PER_SECOND {
        let h = 1.0 / f64::from(steps_per_second);
        let steps = (t_end * f64::from(steps_per_second)).round() as usize;
        let mut one = rapier::RapierBodies::single(r.moments, q0, l0, h);
        one.steps(steps);
        let error = rotation_angle_between(one.attitude(0), q_ref);
        eprintln!(
            "rapier3d-f64 dt = 1/{steps_per_second}: attitude error at t = {t_end} s: {error:.2e} rad"
        );
        let mut world = rapier::RapierBodies::new(r.moments, q0, l0, h, RAPIER_BODIES);
        group.throughput(Throughput::Elements(
            (RAPIER_BODIES * RAPIER_STEPS_PER_ITER) as u64,
        ));
        group.bench_function(
            BenchmarkId::new("rapier_1000_bodies", steps_per_second),
            |b| {
                b.iter(|| {
                    world.steps(RAPIER_STEPS_PER_ITER);
                    black_box(world.attitude(0))
                })
            },
        );
    }
    group.finish();
}

criterion_group!(benches, work_precision);
criterion_main!(benches);
