//! What a tolerance saves: the same scenes with and without
//! `World::set_tolerance`, timed in one run (issue 13, "accuracy as an
//! input").
//!
//! ```text
//! cargo bench --bench tolerance
//! cargo bench --bench tolerance -- tolerance_tops     # one group
//! ```
//!
//! 1. `tolerance_driven_100`: 100 satellites (I = (0.8, 1.0, 1.3)·(1 + 0.1
//!    k/N), ω₀ = (0.3, 1, 0.2) rad/s, a body torque of 5 mN m about x), 60 s
//!    at dt = 0.1, read every 1 s; one iteration is the whole run.
//! 2. `tolerance_tops`: the Brüls top and the asymmetric fast top of
//!    `tests/data/heavy_top/`, 2 s at dt = 0.01, read every step; one
//!    iteration is the whole run of one top.
//! 3. `tolerance_game_1k`: 10³ asymmetric free bodies (rapier's scenario,
//!    moments scaled per body), `step(1/60)` and a read of every body per
//!    frame; one iteration is one frame.
//!
//! Each point: the default (no tolerance: rounding level) and tolerances of
//! 1e-3, 1e-6 and 1e-9 rad over the run. Before timing, the largest
//! attitude error of each is printed on stderr, against the committed
//! 60-digit references for the tops and the free bodies, and against the
//! default run for the satellites (the default is at rounding level there:
//! ≤ 5.5e-12 rad on the mpmath references of `tests/data/forced/`).
//!
//! Under `cargo test --benches` each point runs once on smaller scenes.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use kreisel::dynamics::{Body, BodyId, Inputs, Tolerance, World};
use kreisel::kinematics::glam::{DQuat, DVec3};
use kreisel::kinematics::rotation_angle_between;

#[path = "../crates/dynamics/tests/common/free_body.rs"]
mod free_body;
#[path = "../crates/dynamics/tests/common/heavy_top.rs"]
mod heavy_top;

/// criterion's own rule: without `--bench`, or with `--test`, each point
/// runs once (`cargo test --benches`).
fn quick() -> bool {
    let args: Vec<String> = std::env::args().collect();
    let has = |flag: &str| args.iter().any(|a| a == flag);
    !has("--bench") || has("--test")
}

/// The tolerances compared with the default (`None`).
const TOLERANCES: [Option<f64>; 4] = [None, Some(1e-3), Some(1e-6), Some(1e-9)];

fn label(tol: Option<f64>) -> String {
    tol.map_or("default".to_owned(), |t| format!("{t:e}"))
}

/// A world of `bodies` under `tol` over `horizon`, read every `read` s.
fn world(
    gravity: DVec3,
    dt: f64,
    bodies: &[Body],
    tol: Option<f64>,
    (horizon, read): (f64, f64),
) -> (World, Vec<BodyId>) {
    let mut world = World::try_new(gravity, dt).unwrap();
    if let Some(tol) = tol {
        let tolerance = Tolerance::try_new(tol, horizon)
            .and_then(|t| t.try_reading_every(read))
            .unwrap();
        world.set_tolerance(Some(tolerance)).unwrap();
    }
    let ids = bodies
        .iter()
        .map(|b| world.add(b.clone()).unwrap())
        .collect();
    (world, ids)
}

/// The attitudes of every body at every read of a whole run.
fn run(world: &mut World, ids: &[BodyId], read: f64, reads: usize) -> Vec<DQuat> {
    let mut out = Vec::with_capacity(ids.len() * reads);
    for k in 1..=reads {
        world.advance_to(k as f64 * read).unwrap();
        out.extend(
            ids.iter()
                .map(|&id| world.state(id).unwrap().world_from_body),
        );
    }
    out
}

/// What the tolerance chose, or the plan if it chose nothing (a Lagrange
/// top's closed form).
fn plan_and_choice(world: &World, id: BodyId) -> String {
    match world.choice(id) {
        Some(c) => c.to_string(),
        None => format!("{:?}", world.plan(id)),
    }
}

fn worst(a: &[DQuat], b: &[DQuat]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(&x, &y)| rotation_angle_between(x, y))
        .fold(0.0, f64::max)
}

/// 1: driven satellites.
fn driven(c: &mut Criterion) {
    let (n, seconds) = if quick() { (10, 6) } else { (100, 60) };
    let bodies: Vec<Body> = (0..n)
        .map(|k| {
            let s = 1.0 + 0.1 * k as f64 / n as f64;
            Body::from_principal_moments(12.0, DVec3::new(0.8, 1.0, 1.3) * s)
                .omega_body(DVec3::new(0.3, 1.0, 0.2))
                .try_build()
                .unwrap()
                .with_inputs(Inputs::default().with_torque_body(DVec3::new(0.005, 0.0, 0.0)))
                .unwrap()
        })
        .collect();
    let span = (f64::from(seconds), 1.0);
    let reads = seconds as usize;
    let (mut w, ids) = world(DVec3::ZERO, 0.1, &bodies, None, span);
    let reference = run(&mut w, &ids, 1.0, reads);
    let mut group = c.benchmark_group("tolerance_driven_100");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(10));
    for tol in TOLERANCES {
        let (mut w, ids) = world(DVec3::ZERO, 0.1, &bodies, tol, span);
        let choice = tol.map(|_| plan_and_choice(&w, ids[0]));
        let err = worst(&run(&mut w, &ids, 1.0, reads), &reference);
        eprintln!(
            "tolerance_driven_100 {}: {err:.1e} rad against the default; {}",
            label(tol),
            choice.unwrap_or_default()
        );
        group.bench_function(BenchmarkId::new("whole_run", label(tol)), |b| {
            b.iter(|| {
                let (mut w, ids) = world(DVec3::ZERO, 0.1, &bodies, tol, span);
                black_box(run(&mut w, &ids, 1.0, reads))
            })
        });
    }
    group.finish();
}

/// 2: heavy tops, read every step.
fn tops(c: &mut Criterion) {
    let mut group = c.benchmark_group("tolerance_tops");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(10));
    for name in ["bruls", "asymmetric_fast"] {
        let r = heavy_top::load(name);
        let top = r.world_body();
        let reads = if quick() { 20 } else { r.samples.len() - 1 };
        let dt = r.samples[1].0 - r.samples[0].0;
        let reference: Vec<DQuat> = r.samples[1..=reads].iter().map(|s| s.1).collect();
        let span = (reads as f64 * dt, dt);
        for tol in TOLERANCES {
            let bodies = [top.clone()];
            let (mut w, ids) = world(r.gravity, dt, &bodies, tol, span);
            let choice = tol.map(|_| plan_and_choice(&w, ids[0]));
            let err = worst(&run(&mut w, &ids, dt, reads), &reference);
            eprintln!(
                "tolerance_tops {name} {}: {err:.1e} rad against the reference; {}",
                label(tol),
                choice.unwrap_or_default()
            );
            group.bench_function(BenchmarkId::new(name, label(tol)), |b| {
                b.iter(|| {
                    let (mut w, ids) = world(r.gravity, dt, &bodies, tol, span);
                    black_box(run(&mut w, &ids, dt, reads))
                })
            });
        }
    }
    group.finish();
}

/// 3: the game pattern, one frame per iteration.
fn game(c: &mut Criterion) {
    let n = if quick() { 100 } else { 1_000 };
    let h = 1.0 / 60.0;
    let r = free_body::load("rapier");
    let (_, q0, l0) = r.samples[0];
    let bodies: Vec<Body> = (0..n)
        .map(|k| {
            let s = 1.0 + 0.1 * k as f64 / n as f64;
            Body::from_principal_moments(1.0, r.moments * s)
                .world_from_body(q0)
                .omega_body(l0 / r.moments)
                .try_build()
                .unwrap()
        })
        .collect();
    let mut group = c.benchmark_group("tolerance_game_1k");
    group.measurement_time(Duration::from_secs(5));
    for tol in TOLERANCES {
        // The error over the 100 s of the reference, on the first body
        // (every body has the same attitude at every time).
        let (mut w, ids) = world(DVec3::ZERO, h, &bodies[..1], tol, (100.0, h));
        let mut err: f64 = 0.0;
        for &(t, q, _) in &r.samples[1..] {
            w.advance_to(t).unwrap();
            err = err.max(rotation_angle_between(
                w.state(ids[0]).unwrap().world_from_body,
                q,
            ));
        }
        let choice = tol.map(|_| plan_and_choice(&w, ids[0]));
        eprintln!(
            "tolerance_game_1k {}: {err:.1e} rad over 100 s against the reference; {}",
            label(tol),
            choice.unwrap_or_default()
        );
        let (mut w, ids) = world(DVec3::ZERO, h, &bodies, tol, (100.0, h));
        group.bench_function(BenchmarkId::new("frame", label(tol)), |b| {
            b.iter(|| {
                w.step(h).unwrap();
                black_box(
                    ids.iter()
                        .map(|&id| w.state(id).unwrap().world_from_body.w)
                        .sum::<f64>(),
                )
            })
        });
    }
    group.finish();
}

criterion_group!(benches, driven, tops, game);
criterion_main!(benches);
