//! The `World` as an engine, measured against rapier3d-f64 in the same run
//! (issue 13's benchmarks):
//!
//! ```text
//! cargo bench --bench world
//! cargo bench --bench world -- world_10k_100s     # one group
//! ```
//!
//! 1. `world_10k_100s_read_every_1s`: 10⁴ free bodies, 100 s at
//!    dt = 1/60, every body's state read every 1 s (what `kreisel simulate`
//!    writes): kreisel's `World::advance_to` (auto) on asymmetric bodies,
//!    spheres and resting bodies, and rapier stepping the same asymmetric
//!    bodies (one rapier world, full `PhysicsWorld::step` pipeline, one
//!    thread, `tests/common/rapier.rs`). Throughput in body-steps of 1/60 s,
//!    so 1/throughput is the time per body-step. One kreisel iteration is
//!    the whole 100 s (100 `advance_to` and 100 reads of every body); one
//!    rapier iteration is 1 s (60 steps and one read of every body), since
//!    its 100 s take tens of seconds. `kreisel_advance_to_unread`: the
//!    same 100 `advance_to` without the reads (the World's own work).
//!    `rapier3d_f64/asymmetric_first_tenth`: a rapier world of the first
//!    10³ of the bodies (rapier's cost per body-step grows with its world).
//! 2. `world_setup_10k`: making the world of 10⁴ asymmetric bodies (one
//!    exact solution per body, outside the timings of 1), per body.
//! 3. `world_step_1_60_1k`: the game pattern, `World::step(1/60)` once per
//!    frame on 10³ asymmetric bodies (auto, and the world under pdmv6),
//!    next to a pdmv6 propagator step (`FreeBodyMethod::Pdmv6.integrator()
//!    .propagator(..).advance(h)`) on the same bodies; one iteration is one
//!    frame, 1/throughput the time per body-step.
//! 4. `world_step_1_60_10k`: the same frame on 10⁴ asymmetric bodies,
//!    spheres and resting bodies: `world_step` alone, and
//!    `world_step_read_all`, the frame followed by a read of every body's
//!    state (`World::states`, what a game or robotics loop reads each
//!    frame), the same work for every kind; and the asymmetric frame on
//!    two threads (`World::set_threads`).
//! 5. `world_heavy_tops_1k_step_1_60`: 10³ heavy tops (the Brüls top and the
//!    asymmetric fast top of `tests/data/heavy_top/`) through the World
//!    (auto), one frame per iteration, on one thread (`world_step`, the
//!    baseline) and on two (`world_step_2_threads`, `World::set_threads`).
//!
//! The bodies (shared by kreisel and rapier): body k of N has the moments
//! of rapier's Dzhanibekov scenario scaled, I = (1, 2, 3)·(1 + 0.1 k/N),
//! ω₀ = (0.01, 1, 0) in body axes, and its own attitude R_k. Euler's
//! equations are unchanged by I → s I at fixed ω, and a rotation of the
//! world frame maps solutions to solutions, so body k's exact attitude is
//! R_k ⊗ q_ref(t) with q_ref the committed 60-digit reference
//! (`tests/data/free_body/rapier.csv`): an independent reference for every
//! body. Spheres: I = 2·(1 + 0.1 k/N)·(1, 1, 1), same ω₀ and R_k; resting
//! bodies: the asymmetric moments with ω₀ = 0. The heavy tops are turned
//! about the vertical (the gravity axis) by R_k, which again maps the
//! reference trajectory to theirs.
//!
//! Before timing, the attitude errors at the end (t = 100 s; 2 s for the
//! tops) are printed on stderr: every kreisel body against its reference
//! (and against `ExactSolution::state_at`), rapier on a sub-world of 8 of
//! the bodies (rapier bodies without colliders never interact, so a body's
//! motion does not depend on the others).
//!
//! Under `cargo test --benches` (criterion's test mode, each point run
//! once, usually a debug build) the sizes shrink to 100 bodies, 10 tops and
//! 10 s so the run takes seconds.

use std::hint::black_box;
use std::num::NonZeroUsize;
use std::time::Duration;

use criterion::{
    BenchmarkGroup, BenchmarkId, Criterion, SamplingMode, Throughput, criterion_group,
    criterion_main, measurement::WallTime,
};
use kreisel::dynamics::{
    Body, BodyId, BodyState, ExactSolution, FreeBodyMethod, Plan, PrincipalState, Propagator, World,
};
use kreisel::kinematics::glam::{DQuat, DVec3};
use kreisel::kinematics::rotation_angle_between;

#[path = "../crates/dynamics/tests/common/free_body.rs"]
mod free_body;
#[path = "../crates/dynamics/tests/common/heavy_top.rs"]
mod heavy_top;
#[path = "../tests/common/rapier.rs"]
mod rapier;

/// The frame, s.
const H: f64 = 1.0 / 60.0;
const STEPS_PER_SECOND: usize = 60;
/// rapier bodies run over the whole time for their errors.
const RAPIER_ERROR_BODIES: usize = 8;

/// The sizes of a run.
#[derive(Clone, Copy)]
struct Scale {
    /// Bodies of the 100 s worlds and of the 10⁴-body frames.
    bodies: usize,
    /// Bodies of the game pattern.
    frame_bodies: usize,
    /// Heavy tops.
    tops: usize,
    /// Simulated seconds of a run (one read per second).
    seconds: usize,
}

const FULL: Scale = Scale {
    bodies: 10_000,
    frame_bodies: 1_000,
    tops: 1_000,
    seconds: 100,
};

const QUICK: Scale = Scale {
    bodies: 100,
    frame_bodies: 100,
    tops: 10,
    seconds: 10,
};

/// criterion's own rule: without `--bench`, or with `--test`, each point
/// runs once (`cargo test --benches`).
fn scale() -> Scale {
    let args: Vec<String> = std::env::args().collect();
    let has = |flag: &str| args.iter().any(|a| a == flag);
    if !has("--bench") || has("--test") {
        QUICK
    } else {
        FULL
    }
}

/// Which family of free bodies.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Asymmetric,
    Sphere,
    Resting,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Asymmetric => "asymmetric",
            Kind::Sphere => "sphere",
            Kind::Resting => "resting",
        }
    }

    /// The plan every body of the family must get.
    fn plan(self) -> Plan {
        match self {
            Kind::Asymmetric => Plan::Asymmetric,
            Kind::Sphere => Plan::Sphere,
            Kind::Resting => Plan::Resting,
        }
    }
}

/// Body `k` of `n`: principal moments, attitude R_k, body-axis ω₀.
#[derive(Clone, Copy)]
struct Spec {
    moments: DVec3,
    world_from_body: DQuat,
    omega_body: DVec3,
}

/// R_k: an axis on the spherical Fibonacci lattice, an angle from the
/// golden-ratio sequence.
fn attitude(k: usize, n: usize) -> DQuat {
    let golden = 0.5 * (5f64.sqrt() - 1.0);
    let z = 1.0 - 2.0 * (k as f64 + 0.5) / n as f64;
    let phi = std::f64::consts::TAU * (k as f64 * golden).fract();
    let r = (1.0 - z * z).sqrt();
    let axis = DVec3::new(r * phi.cos(), r * phi.sin(), z);
    let angle = std::f64::consts::PI * ((k as f64 + 1.0) * golden * 2f64.sqrt()).fract();
    DQuat::from_axis_angle(axis, angle)
}

fn spec(kind: Kind, k: usize, n: usize) -> Spec {
    let s = 1.0 + 0.1 * k as f64 / n as f64;
    let (moments, omega_body) = match kind {
        Kind::Asymmetric => (DVec3::new(1.0, 2.0, 3.0) * s, DVec3::new(0.01, 1.0, 0.0)),
        Kind::Sphere => (DVec3::splat(2.0 * s), DVec3::new(0.01, 1.0, 0.0)),
        Kind::Resting => (DVec3::new(1.0, 2.0, 3.0) * s, DVec3::ZERO),
    };
    Spec {
        moments,
        world_from_body: attitude(k, n),
        omega_body,
    }
}

fn specs(kind: Kind, n: usize) -> Vec<Spec> {
    (0..n).map(|k| spec(kind, k, n)).collect()
}

fn body(s: &Spec) -> Body {
    Body::from_principal_moments(1.0, s.moments)
        .world_from_body(s.world_from_body)
        .omega_body(s.omega_body)
        .try_build()
        .expect("a valid body")
}

/// (q, L) in principal axes (the body axes here).
fn principal_state(s: &Spec) -> PrincipalState {
    let b = body(s);
    PrincipalState::try_from_omega_body(b.rigid_body(), b.world_from_body(), b.omega_body())
        .expect("a valid state")
}

/// A world of these bodies under no gravity, dt = 1/60, and their ids.
fn world_of(specs: &[Spec], method: FreeBodyMethod) -> (World, Vec<BodyId>) {
    let mut world = World::try_new(DVec3::ZERO, H).expect("a valid world");
    world.set_free_body_method(method).expect("a method");
    let ids = specs
        .iter()
        .map(|s| world.add(body(s)).expect("a body"))
        .collect();
    (world, ids)
}

/// A world of one family under auto, its plans checked: the bench must
/// measure what it names.
fn auto_world(kind: Kind, n: usize) -> (World, Vec<BodyId>) {
    let (world, ids) = world_of(&specs(kind, n), FreeBodyMethod::Auto);
    let wrong = world.plans().filter(|(_, p)| **p != kind.plan()).count();
    assert_eq!(
        wrong,
        0,
        "{} bodies not planned as {:?}",
        wrong,
        kind.plan()
    );
    (world, ids)
}

/// Every field of a state read, summed (as a balanced tree, so the sum
/// adds little latency to the read): a read must compute them all.
fn consume(s: &BodyState) -> f64 {
    let q = s.world_from_body;
    let v = (s.omega_body + s.l_world) + (s.position + s.velocity);
    ((s.time + s.energy) + (q.w + q.x)) + ((q.y + q.z) + (v.x + (v.y + v.z)))
}

/// Reads every body's state (as a writer of rows does); a sum to keep it.
fn read_all(world: &World, ids: &[BodyId]) -> f64 {
    ids.iter()
        .filter_map(|&id| world.state(id))
        .map(|s| consume(&s))
        .sum()
}

/// `seconds` more seconds, every state read after each one (none when
/// `ids` is empty).
fn simulate(world: &mut World, ids: &[BodyId], seconds: usize) -> f64 {
    let t0 = world.time();
    let mut sum = 0.0;
    for s in 1..=seconds {
        world.advance_to(t0 + s as f64).expect("no divergence");
        sum += read_all(world, ids);
    }
    sum + world.time()
}

fn rapier_states(specs: &[Spec]) -> Vec<(DVec3, DQuat, DVec3)> {
    specs
        .iter()
        .map(|s| {
            let p = principal_state(s);
            (s.moments, p.world_from_principal, p.l_principal)
        })
        .collect()
}

/// 60 rapier steps (1 s), then every attitude read.
fn rapier_second(world: &mut rapier::RapierBodies) -> f64 {
    world.steps(STEPS_PER_SECOND);
    (0..world.len()).map(|i| world.attitude(i).w).sum()
}

/// The errors at the end of the run, printed once: kreisel's every body,
/// rapier's on a sub-world.
fn print_free_body_errors(scale: Scale) {
    let n = scale.bodies;
    let reference = free_body::load("rapier");
    let t_end = scale.seconds as f64;
    let q_ref = reference
        .samples
        .iter()
        .find(|s| s.0 == t_end)
        .expect("a reference sample at the end")
        .1;
    let expected = |k: usize| attitude(k, n) * q_ref;
    let all = specs(Kind::Asymmetric, n);
    let (mut world, ids) = auto_world(Kind::Asymmetric, n);
    simulate(&mut world, &ids, scale.seconds);
    let (mut worst, mut worst_exact) = ((0.0f64, 0), 0.0f64);
    for (k, &id) in ids.iter().enumerate() {
        let q = world.state(id).expect("a body").world_from_body;
        let e = rotation_angle_between(q, expected(k));
        if e > worst.0 {
            worst = (e, k);
        }
        let exact = ExactSolution::try_new(all[k].moments, principal_state(&all[k]))
            .expect("an exact solution")
            .state_at(t_end);
        worst_exact = worst_exact.max(rotation_angle_between(q, exact.world_from_principal));
    }
    eprintln!(
        "kreisel World::advance_to (auto), {n} asymmetric bodies, t = {t_end} s: \
         attitude error max {:.2e} rad (body {}) against the 60-digit reference; \
         max {worst_exact:.2e} rad from ExactSolution::state_at",
        worst.0, worst.1,
    );
    let picked: Vec<usize> = (0..n).step_by(n / RAPIER_ERROR_BODIES).collect();
    let sub: Vec<Spec> = picked.iter().map(|&k| all[k]).collect();
    let mut rapier = rapier::RapierBodies::from_states(&rapier_states(&sub), H);
    rapier.steps(scale.seconds * STEPS_PER_SECOND);
    let errors: Vec<String> = picked
        .iter()
        .enumerate()
        .map(|(i, &k)| {
            format!(
                "{k}: {:.2e}",
                rotation_angle_between(rapier.attitude(i), expected(k))
            )
        })
        .collect();
    eprintln!(
        "rapier3d-f64 dt = 1/60, t = {t_end} s, attitude error (rad) of bodies {}",
        errors.join(", ")
    );
}

/// The heavy tops of `tests/data/heavy_top/NAME.csv`, top k turned about
/// the vertical by 2π k/n.
fn heavy_tops(name: &str, n: usize) -> (World, Vec<BodyId>, heavy_top::HeavyTopReference) {
    let r = heavy_top::load(name);
    let mut world = World::try_new(r.gravity, H).expect("a valid world");
    let ids = (0..n)
        .map(|k| {
            let turn = DQuat::from_rotation_z(std::f64::consts::TAU * k as f64 / n as f64);
            let top = Body::from_mass_properties(r.mass_properties)
                .world_from_body(turn * r.q0)
                .omega_body(r.omega0)
                .pivot(DVec3::ZERO, DVec3::ZERO)
                .try_build()
                .expect("a valid top");
            world.add(top).expect("a top")
        })
        .collect();
    (world, ids, r)
}

/// Each top's attitude error after 2 s of frames, printed once.
fn print_heavy_top_errors(n: usize) {
    for name in ["bruls", "asymmetric_fast"] {
        let (mut world, ids, r) = heavy_tops(name, n);
        let &(t_end, q_ref, _) = r.samples.last().expect("samples");
        let frames = (t_end / H).round() as usize;
        for _ in 0..frames {
            world.step(H).expect("no divergence");
        }
        let worst = ids
            .iter()
            .enumerate()
            .map(|(k, &id)| {
                let turn = DQuat::from_rotation_z(std::f64::consts::TAU * k as f64 / n as f64);
                let q = world.state(id).expect("a top").world_from_body;
                rotation_angle_between(q, turn * q_ref)
            })
            .fold(0.0, f64::max);
        eprintln!(
            "kreisel World::step(1/60) (auto), {n} heavy tops {name}, {frames} frames to \
             t = {t_end} s: attitude error max {worst:.2e} rad"
        );
    }
}

fn configure(group: &mut BenchmarkGroup<'_, WallTime>, long: bool) {
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    if long {
        group.sampling_mode(SamplingMode::Flat);
    }
}

/// 1: 100 s read every 1 s, 10⁴ bodies.
fn simulation(c: &mut Criterion) {
    let scale = scale();
    print_free_body_errors(scale);
    let n = scale.bodies;
    let mut group = c.benchmark_group("world_10k_100s_read_every_1s");
    configure(&mut group, true);
    group.throughput(Throughput::Elements(
        (n * scale.seconds * STEPS_PER_SECOND) as u64,
    ));
    for kind in [Kind::Asymmetric, Kind::Sphere, Kind::Resting] {
        let (mut world, ids) = auto_world(kind, n);
        group.bench_function(BenchmarkId::new("kreisel_advance_to", kind.name()), |b| {
            b.iter(|| black_box(simulate(&mut world, &ids, scale.seconds)))
        });
        // The same 100 advance_to without the reads: the World's own work.
        let id = BenchmarkId::new("kreisel_advance_to_unread", kind.name());
        group.bench_function(id, |b| {
            b.iter(|| black_box(simulate(&mut world, &[], scale.seconds)))
        });
    }
    // rapier's cost per body-step grows with its world: also the first
    // tenth of the bodies alone.
    for (count, name) in [(n, "asymmetric"), (n / 10, "asymmetric_first_tenth")] {
        let states = rapier_states(&specs(Kind::Asymmetric, n)[..count]);
        let mut rapier = rapier::RapierBodies::from_states(&states, H);
        group.throughput(Throughput::Elements((count * STEPS_PER_SECOND) as u64));
        group.bench_function(BenchmarkId::new("rapier3d_f64", name), |b| {
            b.iter(|| black_box(rapier_second(&mut rapier)))
        });
    }
    group.finish();
}

/// 2: making the world.
fn setup(c: &mut Criterion) {
    let n = scale().bodies;
    let all = specs(Kind::Asymmetric, n);
    let mut group = c.benchmark_group("world_setup_10k");
    configure(&mut group, true);
    group.throughput(Throughput::Elements(n as u64));
    group.bench_function("kreisel_asymmetric", |b| {
        b.iter(|| black_box(world_of(&all, FreeBodyMethod::Auto).0.len()))
    });
    let states = rapier_states(&all);
    group.bench_function("rapier3d_f64_asymmetric", |b| {
        b.iter(|| black_box(rapier::RapierBodies::from_states(&states, H).len()))
    });
    group.finish();
}

/// One frame of `World::step(1/60)` per iteration, per body-step.
fn bench_frames(group: &mut BenchmarkGroup<'_, WallTime>, id: BenchmarkId, world: &mut World) {
    group.bench_function(id, |b| {
        b.iter(|| {
            world.step(H).expect("no divergence");
            black_box(world.time())
        })
    });
}

/// 3: the game pattern on 10³ bodies against pdmv6 propagators.
fn game(c: &mut Criterion) {
    let n = scale().frame_bodies;
    let all = specs(Kind::Asymmetric, n);
    let mut group = c.benchmark_group("world_step_1_60_1k");
    configure(&mut group, false);
    group.throughput(Throughput::Elements(n as u64));
    let (mut world, _) = auto_world(Kind::Asymmetric, n);
    bench_frames(
        &mut group,
        BenchmarkId::new("world_step", "auto"),
        &mut world,
    );
    let (mut world, _) = world_of(&all, FreeBodyMethod::Pdmv6);
    bench_frames(
        &mut group,
        BenchmarkId::new("world_step", "pdmv6"),
        &mut world,
    );
    let pdmv6 = FreeBodyMethod::Pdmv6.integrator();
    let mut propagators: Vec<Box<dyn Propagator + '_>> = all
        .iter()
        .map(|s| pdmv6.propagator(s.moments, principal_state(s)))
        .collect();
    group.bench_function(BenchmarkId::new("propagator_advance", "pdmv6"), |b| {
        b.iter(|| {
            for p in &mut propagators {
                p.advance(H);
            }
            black_box(propagators[0].state())
        })
    });
    group.finish();
}

/// 4: one frame of 10⁴ bodies of each family, without and with a read of
/// every body.
fn frames_by_kind(c: &mut Criterion) {
    let n = scale().bodies;
    let mut group = c.benchmark_group("world_step_1_60_10k");
    configure(&mut group, false);
    group.throughput(Throughput::Elements(n as u64));
    for kind in [Kind::Asymmetric, Kind::Sphere, Kind::Resting] {
        let (mut world, _) = auto_world(kind, n);
        bench_frames(
            &mut group,
            BenchmarkId::new("world_step", kind.name()),
            &mut world,
        );
        let id = BenchmarkId::new("world_step_read_all", kind.name());
        group.bench_function(id, |b| {
            b.iter(|| {
                world.step(H).expect("no divergence");
                let read: f64 = world.states().map(|(_, s)| consume(&s)).sum();
                black_box(read)
            })
        });
    }
    // The asymmetric frame's evaluations on two threads.
    let (mut world, _) = auto_world(Kind::Asymmetric, n);
    world.set_threads(NonZeroUsize::new(2).expect("2"));
    bench_frames(
        &mut group,
        BenchmarkId::new("world_step_2_threads", Kind::Asymmetric.name()),
        &mut world,
    );
    group.finish();
}

/// 5: heavy tops, one frame of 10³.
fn tops(c: &mut Criterion) {
    let n = scale().tops;
    print_heavy_top_errors(n);
    let mut group = c.benchmark_group("world_heavy_tops_1k_step_1_60");
    configure(&mut group, false);
    group.throughput(Throughput::Elements(n as u64));
    for name in ["bruls", "asymmetric_fast"] {
        for threads in [1, 2] {
            let (mut world, _, _) = heavy_tops(name, n);
            world.set_threads(NonZeroUsize::new(threads).expect("at least 1"));
            let id = match threads {
                1 => "world_step".to_owned(),
                _ => format!("world_step_{threads}_threads"),
            };
            bench_frames(&mut group, BenchmarkId::new(id, name), &mut world);
        }
    }
    group.finish();
}

criterion_group!(benches, simulation, setup, game, frames_by_kind, tops);
criterion_main!(benches);
